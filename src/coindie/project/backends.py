"""Where tasks run: local worker processes (the default) or a Dask cluster.

Both hand results back as they finish, in any order, as ``(index, result)``; a task whose worker died is
tried again on a fresh worker (``MAX_ATTEMPTS`` in all) and then reported as a :class:`WorkerLost` instead
of a result, so that one poisonous batch cannot stop a run. Tasks must be pure: running one twice gives
the same result, which is what makes retrying safe. ``map_ordered`` hands the same results back in the
tasks' order (for outputs that must not depend on which worker finished first).

Every parallel job of coindie runs through a backend: the project's runs, the synthetic hoards
(:mod:`coindie.synth.hoard`), the benchmarks (:mod:`coindie.bench`) and the measured pair batches of
:mod:`coindie.similarity.batch`, which sit below this layer and so take ``backend.map_ordered`` from
their caller.
"""

from __future__ import annotations

import multiprocessing
import os
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from typing import Any, Protocol

from coindie.errors import CoinDieError, WorkerLost

#: A task whose worker died this many times is given up (reported as WorkerLost).
MAX_ATTEMPTS = 3


__all__ = [
    "MAX_ATTEMPTS",
    "Backend",
    "BackendError",
    "DaskCluster",
    "LocalProcesses",
    "WorkerLost",
    "default_workers",
    "make_backend",
]


class BackendError(CoinDieError):
    """The backend cannot start (no such Dask scheduler, dask.distributed not installed...)."""


class Backend(Protocol):
    description: str

    def map_unordered(
        self, function: Callable[[Any], Any], tasks: Sequence[Any]
    ) -> Iterator[tuple[int, Any]]: ...

    def map_ordered(self, function: Callable[[Any], Any], tasks: Sequence[Any]) -> Iterator[Any]: ...

    def close(self) -> None: ...


class _InOrder:
    """``map_ordered`` for a backend that has ``map_unordered``: each result as soon as it and every
    earlier task's result are in."""

    def map_unordered(
        self, function: Callable[[Any], Any], tasks: Sequence[Any]
    ) -> Iterator[tuple[int, Any]]:
        raise NotImplementedError

    def map_ordered(self, function: Callable[[Any], Any], tasks: Sequence[Any]) -> Iterator[Any]:
        """The tasks' results in order: a task that raised gives its exception (one local worker: raised
        here), one whose worker was lost ``MAX_ATTEMPTS`` times a :class:`WorkerLost`."""
        waiting: dict[int, Any] = {}
        following = 0
        for index, result in self.map_unordered(function, tasks):
            waiting[index] = result
            while following in waiting:
                yield waiting.pop(following)
                following += 1


def default_workers() -> int:
    return max(1, os.cpu_count() or 1)


class LocalProcesses(_InOrder):
    """A pool of ``workers`` spawned processes (one BLAS thread each: ``import coindie`` sets it). With one
    worker the tasks run in this process (no pickling, easiest to debug)."""

    def __init__(self, workers: int = 0) -> None:
        self.workers = workers or default_workers()
        self.description = f"{self.workers} local process(es)"
        self._pool: ProcessPoolExecutor | None = None
        self.restarts = 0

    def _new_pool(self) -> ProcessPoolExecutor:
        return ProcessPoolExecutor(max_workers=self.workers, mp_context=multiprocessing.get_context("spawn"))

    def map_unordered(
        self, function: Callable[[Any], Any], tasks: Sequence[Any]
    ) -> Iterator[tuple[int, Any]]:
        if self.workers == 1:
            for index, task in enumerate(tasks):
                yield index, function(task)
            return
        attempts = [0] * len(tasks)
        queue = deque(range(len(tasks)))
        window = 4 * self.workers  # in flight at once: on a worker's death only these are run again
        while queue:
            pool = self._pool = self._pool or self._new_pool()
            futures: dict[Future[Any], int] = {}
            lost: list[int] = []
            while (queue or futures) and not lost:
                while queue and len(futures) < window:
                    index = queue.popleft()
                    try:
                        futures[pool.submit(function, tasks[index])] = index
                    except BrokenProcessPool:
                        lost.append(index)
                        break
                if not futures:
                    break
                done, _ = wait(futures, return_when=FIRST_COMPLETED)
                for future in done:
                    index = futures.pop(future)
                    error = future.exception()
                    if isinstance(error, BrokenProcessPool):
                        lost.append(index)
                    else:
                        yield index, error if error is not None else future.result()
            if not lost:
                continue
            # A worker died and took the pool with it: every task still in the pool is run again.
            for future, index in futures.items():
                error = future.exception() if future.done() else BrokenProcessPool()
                if isinstance(error, BrokenProcessPool):
                    lost.append(index)
                else:
                    yield index, error if error is not None else future.result()
            self._restart()
            for index in sorted(lost, reverse=True):
                attempts[index] += 1
                if attempts[index] >= MAX_ATTEMPTS:
                    yield index, WorkerLost(f"its worker process died {attempts[index]} times")
                else:
                    queue.appendleft(index)

    def _restart(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=False, cancel_futures=True)
        self._pool = None
        self.restarts += 1

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None


class DaskCluster(_InOrder):
    """A Dask ``distributed`` client: to a running scheduler (``tcp://host:8786``) or, with ``local``, to a
    ``LocalCluster`` of ``workers`` single-threaded processes started here and stopped at ``close``.

    Workers elsewhere need coindie installed and the project folder at the same path (a shared file
    system): tasks carry paths, not clouds."""

    def __init__(self, address: str, workers: int = 0) -> None:
        try:
            from dask.distributed import Client, LocalCluster
        except ImportError as error:
            raise BackendError(f"the 'dask' backend needs dask[distributed] installed ({error})") from None
        self.cluster = None
        try:
            if address == "local":
                n = workers or default_workers()
                self.cluster = LocalCluster(
                    n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None
                )
                self.client = Client(self.cluster)
                self.description = f"Dask LocalCluster of {n} worker process(es)"
            else:
                self.client = Client(address, timeout=30)
                n = len(self.client.scheduler_info().get("workers", {}))
                self.description = f"Dask cluster at {address} ({n} worker(s))"
        except OSError as error:
            raise BackendError(f"cannot reach the Dask scheduler at {address}: {error}") from None

    def map_unordered(
        self, function: Callable[[Any], Any], tasks: Sequence[Any]
    ) -> Iterator[tuple[int, Any]]:
        from dask.distributed import as_completed

        if not tasks:
            return
        futures = self.client.map(function, list(tasks), pure=False, retries=MAX_ATTEMPTS - 1)
        index = {future.key: i for i, future in enumerate(futures)}
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as error:  # KilledWorker after the retries, or the task's own error
                result = WorkerLost(f"{type(error).__name__}: {error}")
            yield index[future.key], result
            future.release()

    def close(self) -> None:
        self.client.close()
        if self.cluster is not None:
            self.cluster.close()


def make_backend(workers: int = 0, dask: str | None = None) -> Backend:
    """Local processes by default; a Dask client when ``dask`` is an address or ``local``."""
    if dask:
        return DaskCluster(dask, workers)
    return LocalProcesses(workers)
