"""A small least-recently-used store of descriptors, per process.

An all-pairs study (and the registration benchmark, whose jobs are grouped by target face) describes the
same face again and again; the networks cost far more than the rest of a registration on a CPU, so each
process keeps the descriptors of the last few clouds it described, keyed by what determines them.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable

from coindie.arrays import FloatArray

#: Every descriptor cache of the process (a handful, one per descriptor module).
_CACHES: list[DescriptorCache] = []


def clear_caches() -> None:
    """Forget every descriptor kept in this process (timings of faces new to a method)."""
    for cache in _CACHES:
        cache.clear()


class DescriptorCache:
    def __init__(self, size: int = 8) -> None:
        self.size = size
        self._items: OrderedDict[Hashable, FloatArray] = OrderedDict()
        _CACHES.append(self)

    def get(self, key: Hashable, compute: Callable[[], FloatArray]) -> FloatArray:
        """The descriptors stored under ``key``, computed (and stored) when they are not there."""
        if key not in self._items:
            self._items[key] = compute()
            if len(self._items) > self.size:
                self._items.popitem(last=False)
        self._items.move_to_end(key)
        return self._items[key]

    def clear(self) -> None:
        self._items.clear()
