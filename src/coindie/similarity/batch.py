"""Many pairs measured (registration + histogram) in worker processes, into a resumable CSV.

A batch is what training and the clustering benchmark need: every pair registered once and its histogram
stored, so that a classifier can be fitted on, or applied to, the stored histograms without registering
again. Rows are appended as pairs finish and flushed, so an interrupted run resumes where it stopped. A bad
scan or a failing pair never stops the batch: its row says why (``valid`` False, ``reason``).

Pairs are handed to the workers in tiles: all pairs between two blocks of faces, so that each worker's
per-face caches (the registrar's and the histogram's, keyed by content) see each face many times in a row.

The workers are the caller's: ``parallel_map`` maps :func:`measure_tile` over the tiles and hands the
results back in order, as ``map`` does (the default: in this process). This layer sits below
:mod:`coindie.project`, so it does not build the pool itself; callers pass a backend's
``map_ordered`` (:mod:`coindie.project.backends`: local processes or Dask, a tile whose worker died run
again). A :class:`~coindie.errors.WorkerLost` in place of a tile's rows (its worker died every time) makes
its pairs failed rows (``reason`` says so) and the batch goes on; any other exception is raised.
"""

from __future__ import annotations

import csv
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from functools import lru_cache, partial
from pathlib import Path
from typing import Any

import numpy as np

from coindie.errors import CoinDieError, WorkerLost
from coindie.scan import Scan
from coindie.similarity.histogram import HistogramSettings
from coindie.similarity.relief_features import FEATURE_NAMES, ReliefFeatureSettings
from coindie.similarity.score import PairScore

#: Faces per block of a tile: a tile's pairs touch at most twice this many faces, within the caches.
BLOCK_FACES = 12
FIELDS = (
    "source", "target", "method", "valid", "reason", "residual", "register_s", "histogram_s", "total_s",
    "T_target_source", "histogram", "features",
)  # fmt: skip
#: ``map``'s shape: a function over tasks, its results (or an exception for a lost task) in order.
ParallelMap = Callable[[Callable[[Any], Any], Sequence[Any]], Iterable[Any]]


@dataclass(frozen=True)
class PairTask:
    """One pair to measure: ``source`` registered onto ``target`` (face ids and scan files)."""

    source: str
    target: str
    source_path: str
    target_path: str


@dataclass(frozen=True)
class BatchConfig:
    """How every pair of a batch is measured (the same in every worker)."""

    method: str = "relief"
    params: tuple[tuple[str, Any], ...] = ()
    settings: HistogramSettings = HistogramSettings()
    features: ReliefFeatureSettings = ReliefFeatureSettings()


def tiles(tasks: Sequence[PairTask], block: int = BLOCK_FACES) -> list[list[PairTask]]:
    """The tasks grouped into cache-friendly tiles: faces in blocks of ``block`` (in order of first
    appearance), one tile per pair of blocks."""
    order: dict[str, int] = {}
    for task in tasks:
        order.setdefault(task.target, len(order))
        order.setdefault(task.source, len(order))
    grouped: dict[tuple[int, int], list[PairTask]] = {}
    for task in tasks:
        a, b = sorted((order[task.source] // block, order[task.target] // block))
        grouped.setdefault((a, b), []).append(task)
    return [sorted(grouped[key], key=lambda t: (t.target, t.source)) for key in sorted(grouped)]


def measure_pairs(
    tasks: Sequence[PairTask],
    out_csv: str | Path,
    config: BatchConfig | None = None,
    *,
    parallel_map: ParallelMap = map,
    progress: Callable[[int, int], None] | None = None,
) -> dict[tuple[str, str], PairScore]:
    """Measure every task not yet in ``out_csv`` (appending), and return all of the tasks' rows,
    ``(source, target) -> PairScore`` (probability NaN: no classifier is applied here). The tiles are
    measured through ``parallel_map`` (see the module's docstring)."""
    config = config or BatchConfig()
    out_csv = Path(out_csv)
    out_csv.parent.mkdir(parents=True, exist_ok=True)
    done = read_scores(out_csv)
    todo = [t for t in tasks if (t.source, t.target) not in done]
    if progress:
        progress(len(tasks) - len(todo), len(tasks))
    with _Appender(out_csv, list(done.values())) as append:
        for rows in _run(tiles(todo), config, parallel_map):
            for score in rows:
                append(score)
                # What the CSV holds (histograms to 6 digits): a resumed run then gives the same results.
                done[(score.source_id, score.target_id)] = _score({k: str(v) for k, v in _row(score).items()})
            if progress:
                progress(len(rows), 0)
    return {(t.source, t.target): done[(t.source, t.target)] for t in tasks}


def measure_tile(tile: list[PairTask], config: BatchConfig) -> list[PairScore]:
    """Measure the pairs of one tile (runs in a worker process)."""
    from coindie.similarity.score import measure_pair

    registrar = _registrar(config.method, config.params)
    rows = []
    for task in tile:
        try:
            score = measure_pair(
                _scan(task.source_path), _scan(task.target_path), registrar, config.settings, config.features
            )
        except (CoinDieError, OSError, ValueError, np.linalg.LinAlgError) as error:
            # One bad scan or pair: recorded and skipped, the batch goes on.
            score = _failed(task, config, f"{type(error).__name__}: {error}")
        rows.append(_named(score, task))
    return rows


def _named(score: PairScore, task: PairTask) -> PairScore:
    from dataclasses import replace

    return replace(score, source_id=task.source, target_id=task.target)


def _failed(task: PairTask, config: BatchConfig, reason: str) -> PairScore:
    return PairScore(
        np.eye(4), False, reason.splitlines()[0] if reason else "failed", np.zeros(config.settings.bins), 0.0,
        {}, task.source, task.target, config.method, features=np.zeros(len(FEATURE_NAMES)),
    )  # fmt: skip


def _run(
    batches: list[list[PairTask]], config: BatchConfig, parallel_map: ParallelMap
) -> Iterator[list[PairScore]]:
    if len(batches) <= 1:
        parallel_map = map  # one tile: in this process, as with one worker
    for tile, rows in zip(batches, parallel_map(partial(measure_tile, config=config), batches), strict=True):
        if isinstance(rows, BaseException):
            if not isinstance(rows, WorkerLost):
                raise rows
            rows = [_failed(task, config, f"worker lost: {rows}") for task in tile]
            rows = [_named(score, task) for score, task in zip(rows, tile, strict=True)]
        yield rows


@lru_cache(maxsize=2 * BLOCK_FACES + 4)
def _scan(path: str) -> Scan:
    from coindie.io import read_scan

    return read_scan(path)


@lru_cache(maxsize=4)
def _registrar(method: str, params: tuple[tuple[str, Any], ...]):  # noqa: ANN202
    from coindie.registration import get_method

    return get_method(method, **dict(params))


# ------------------------------------------------------------------------------------------------ the CSV


def _row(score: PairScore) -> dict[str, object]:
    t = score.timings
    return {
        "source": score.source_id, "target": score.target_id, "method": score.method, "valid": score.valid,
        "reason": score.reason, "residual": repr(float(score.residual)),
        "register_s": f"{t.get('register', 0.0):.4f}", "histogram_s": f"{t.get('histogram', 0.0):.4f}",
        "total_s": f"{t.get('total', 0.0):.4f}",
        "T_target_source": " ".join(repr(float(v)) for v in np.ravel(score.T_target_source)),
        "histogram": " ".join(f"{v:.6g}" for v in score.histogram),
        "features": " ".join(f"{v:.6g}" for v in score.features),
    }  # fmt: skip


def _score(row: dict[str, str]) -> PairScore:
    valid = row["valid"] == "True"
    return PairScore(
        T_target_source=np.array(row["T_target_source"].split(), dtype=np.float64).reshape(4, 4),
        valid=valid,
        reason=row["reason"],
        histogram=np.array(row["histogram"].split(), dtype=np.float64),
        probability=float("nan") if valid else 0.0,
        timings={k: float(row[f"{k}_s"]) for k in ("register", "histogram", "total")},
        source_id=row["source"],
        target_id=row["target"],
        method=row["method"],
        residual=float(row["residual"]),
        features=np.array(row["features"].split(), dtype=np.float64),
    )


def read_scores(path: str | Path) -> dict[tuple[str, str], PairScore]:
    """The rows of a batch CSV, ``(source, target) -> PairScore``; a damaged or truncated row is dropped
    (its pair is measured again)."""
    path = Path(path)
    if not path.is_file():
        return {}
    scores = {}
    with path.open(newline="") as handle:
        for row in csv.DictReader(handle):
            if None in row.values() or None in row:
                continue
            try:
                score = _score(row)
            except (KeyError, ValueError):
                continue
            scores[(score.source_id, score.target_id)] = score
    return scores


class _Appender:
    """Append rows to the CSV (rewriting the complete ones first: a killed run may leave half a line)."""

    def __init__(self, path: Path, kept: Iterable[PairScore]) -> None:
        self.path, self.kept = path, list(kept)

    def __enter__(self) -> Callable[[PairScore], None]:
        self.handle = self.path.open("w", newline="")
        self.writer = csv.DictWriter(self.handle, fieldnames=FIELDS)
        self.writer.writeheader()
        self.writer.writerows(_row(s) for s in self.kept)
        self.handle.flush()
        return self._append

    def _append(self, score: PairScore) -> None:
        self.writer.writerow(_row(score))
        self.handle.flush()

    def __exit__(self, *exc: object) -> None:
        self.handle.close()
