"""The backends every parallel job runs on: results in the tasks' order, a dead worker's task run again,
a task that always kills its worker reported as lost (and a batch of pairs goes on past it)."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from coindie.errors import WorkerLost
from coindie.project.backends import MAX_ATTEMPTS, LocalProcesses


def _slow_square(n: int) -> int:
    time.sleep(0.05 * (4 - n % 4))  # the first tasks finish last
    return n * n


def _dies_once(marker: str) -> str:
    """Kills its worker the first time (leaving ``marker``), then succeeds: a pure task on a bad worker."""
    if not Path(marker).exists():
        Path(marker).write_text("died")
        os._exit(1)
    return "done"


def _always_dies(_: int) -> None:
    os._exit(1)


def _fails(n: int) -> int:
    raise ValueError(f"task {n} fails")


@pytest.fixture(scope="module")
def backend():
    processes = LocalProcesses(workers=2)
    yield processes
    processes.close()


def test_results_come_back_in_the_tasks_order_whichever_finishes_first(backend) -> None:
    tasks = list(range(8))
    assert list(backend.map_ordered(_slow_square, tasks)) == [n * n for n in tasks]
    assert sorted(backend.map_unordered(_slow_square, tasks)) == [(n, n * n) for n in tasks]


def test_a_task_whose_worker_died_runs_again_on_a_fresh_one(backend, tmp_path) -> None:
    restarts = backend.restarts
    assert list(backend.map_ordered(_dies_once, [str(tmp_path / "marker")])) == ["done"]
    assert backend.restarts == restarts + 1


def test_a_task_that_always_kills_its_worker_is_reported_lost_and_the_others_finish(backend) -> None:
    results = list(backend.map_ordered(_always_dies, [0]))
    assert len(results) == 1 and isinstance(results[0], WorkerLost)
    assert f"{MAX_ATTEMPTS} times" in str(results[0])
    assert list(backend.map_ordered(_slow_square, [1, 2])) == [1, 4]  # the backend still works


def test_a_task_error_is_handed_back_in_place_of_its_result(backend) -> None:
    results = list(backend.map_ordered(_fails, [0, 1]))
    assert [type(r) for r in results] == [ValueError, ValueError] and "task 1 fails" in str(results[1])


def test_one_local_worker_runs_in_this_process() -> None:
    assert list(LocalProcesses(workers=1).map_ordered(lambda _: os.getpid(), [0, 1])) == [os.getpid()] * 2
