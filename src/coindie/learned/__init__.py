"""Learned descriptors for registration (FCGF, DIP), in plain PyTorch.

Nothing here imports torch until a network is built or loaded, so that registering the methods costs
nothing. ``coindie.learned.fcgf.FCGFDescriptor`` is FCGF's feature extractor; ``coindie.learned.train``
trains it (``coindie train fcgf HOARD --out DIR``).
"""
