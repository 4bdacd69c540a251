"""A small least-recently-used store of descriptors, per process.

An all-pairs study (and the registration benchmark, whose jobs are grouped by target face) describes the
same face again and again; the networks cost far more than the rest of a registration on a CPU, so each
process keeps the descriptors of the last few clouds it described, keyed by what determines them.
"""

from __future__ import annotations

from collections.abc import Hashable

from coindie.arrays import FloatArray
from coindie.caches import LRUCache

#: Every descriptor cache of the process (a handful, one per descriptor module).
_CACHES: list[DescriptorCache] = []


def clear_caches() -> None:
    """Forget every descriptor kept in this process (timings of faces new to a method)."""
    for cache in _CACHES:
        cache.clear()


class DescriptorCache(LRUCache[Hashable, FloatArray]):
    """An :class:`~coindie.caches.LRUCache` of descriptors that :func:`clear_caches` empties."""

    def __init__(self, size: int = 8) -> None:
        super().__init__(size)
        _CACHES.append(self)
