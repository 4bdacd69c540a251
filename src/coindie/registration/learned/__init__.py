"""Learned descriptors for registration (FCGF, DIP), in plain PyTorch.

Nothing here imports torch until a network is built or loaded, so that cataloguing the methods
(:mod:`coindie.registration.catalogue`) costs nothing. ``coindie.registration.learned.fcgf.FCGFDescriptor``
is FCGF's feature extractor; ``coindie.registration.learned.train`` trains it
(``coindie train fcgf HOARD --out DIR``).
"""
