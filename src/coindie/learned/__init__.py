"""Learned descriptors for registration (FCGF, DIP), in plain PyTorch.

Nothing here imports torch until a network is built or loaded, so that registering the methods costs
nothing. ``coindie.learned.fcgf.FCGFDescriptor`` is FCGF's feature extractor; ``coindie.learned.train``
trains it (``coindie train fcgf HOARD --out DIR``).
"""

# The registration package registers this package's methods (coindie.learned.methods), which import the
# descriptor modules, which import coindie.registration: load it first so that the cycle resolves the
# same way whichever module a program imports first.
import coindie.registration  # noqa: E402, F401
