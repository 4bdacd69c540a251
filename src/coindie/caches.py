"""A least-recently-used cache whose size is a constructor parameter.

Registration pipelines keep a few faces' prepared clouds, the histogram its grid-sampled faces; a project's
worker builds its own caches sized for the faces one batch touches and passes them down explicitly.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from threading import Lock
from typing import Generic, TypeVar

from coindie.errors import ParameterError

K = TypeVar("K", bound=Hashable)
V = TypeVar("V")


class LRUCache(Generic[K, V]):
    """At most ``size`` values, the least recently used dropped first; safe to share between threads (a
    value is computed outside the lock, so two threads may both compute a missing one)."""

    def __init__(self, size: int) -> None:
        if size < 1:
            raise ParameterError(f"The 'size' parameter of LRUCache must be an int >= 1. Got {size}.")
        self.size = size
        self._items: OrderedDict[K, V] = OrderedDict()
        self._lock = Lock()

    def get(self, key: K, compute: Callable[[], V]) -> V:
        """The value stored under ``key``, computed (and stored) when it is not there."""
        with self._lock:
            if key in self._items:
                self._items.move_to_end(key)
                return self._items[key]
        value = compute()
        with self._lock:
            self._items[key] = value
            while len(self._items) > self.size:
                self._items.popitem(last=False)
        return value

    def clear(self) -> None:
        with self._lock:
            self._items.clear()

    def __len__(self) -> int:
        return len(self._items)

    # A cache travels with what holds it (a pipeline sent to a worker process): its values, a new lock.
    def __getstate__(self) -> dict[str, object]:
        return {"size": self.size, "_items": self._items}

    def __setstate__(self, state: dict[str, object]) -> None:
        self.__dict__.update(state)
        self._lock = Lock()
