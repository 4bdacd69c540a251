"""A run of a project: per-face work once, then the pairs of each side in batches, committed as they come.

1. **Faces** (O(n)): every new or changed scan is hashed, grid-sampled and described by a worker
   (:func:`coindie.project.workers.prepare_face`); a bad scan is recorded with its error and left out.
2. **Plan**: per side (obverses with and without beard together, reverses), either every pair
   (exhaustive) or the candidate pairs of :mod:`coindie.candidates` (each face's K nearest faces by
   descriptor). ``auto`` (the default) is exhaustive up to ``AUTO_EXHAUSTIVE_MAX_FACES`` faces per side
   and says so when it switches. Planned pairs are rows of ``pairs`` (status ``todo``), keyed by the faces
   and a hash of every parameter the result depends on: a rerun, or a run after new scans were added,
   plans only what is not there yet.
3. **Pairs**: the todo pairs are ordered so that linked faces are close (reverse Cuthill–McKee on the
   pair graph), cut into tiles of at most ``batch_faces`` x ``batch_faces`` faces, and scored by the
   workers (:func:`coindie.project.workers.score_batch`). Each batch's results are committed in one
   transaction: killing the run at any moment loses at most the batches in flight, and no committed pair
   is ever computed again.
4. **Relays** (:mod:`coindie.project.relay`): the pairs that the chains through a third face score higher
   than their own registration are registered again from the pose composed through it, in a few rounds;
   a pair keeps the result only where it scores higher. Committed as the pairs are, each attempt recorded
   (the ``relays`` table): a rerun tries only new chains.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import platform
import socket
import time
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, contextmanager
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from coindie import __version__
from coindie.errors import CoinDieError
from coindie.params import Configurable, param
from coindie.project.backends import Backend, WorkerLost, make_backend
from coindie.project.relay import DEFAULT_NEIGHBOURS, DEFAULT_ROUNDS, MIN_GAIN, Relay, plan_relays
from coindie.project.store import Project, ProjectError
from coindie.project.workers import (
    PAIR_FUNCTION_VERSION,
    FaceTask,
    PairBatch,
    RelayBatch,
    face_params_hash,
    prepare_face,
    relay_batch,
    score_batch,
)
from coindie.similarity.scorers import SCORERS

#: ``auto`` plans every pair of a side up to this many faces (2 x 19,900 pairs for two such sides: about
#: 35 min on 2 idle cores at the 0.10 CPU-s a pair measured on an all-hard hoard, registration and relief
#: features, BENCHMARK.md); above it, the candidate search.
AUTO_EXHAUSTIVE_MAX_FACES = 200
#: Candidates per face in candidate mode (see BENCHMARK.md, "Candidate search", for the recall vs K).
DEFAULT_K = 20
#: Faces per side of a batch's tile: a batch touches at most 2 x this many faces, each loaded once.
DEFAULT_BATCH_FACES = 16
MODES = ("auto", "exhaustive", "candidates")

Progress = Callable[[str], AbstractContextManager[Callable[[int, int], None]]]
Echo = Callable[[str], None]


@dataclass(frozen=True)
class RunConfig(Configurable):
    """The settings of a run (stored with it). The grid of the per-face cache is the histogram's finest."""

    method: str = param("relief", doc="the registration method (coindie methods lists them)")
    method_params: dict[str, Any] = field(default_factory=dict)
    mode: str = param("auto", doc="which pairs are scored", choices=MODES)
    k: int = param(DEFAULT_K, doc="candidates per face in candidate mode", low=1)
    workers: int = param(0, doc="worker processes (0: one per core)", low=0)
    dask: str | None = param(None, str, doc="a Dask scheduler address, or 'local'", optional=True)
    batch_faces: int = param(DEFAULT_BATCH_FACES, doc="faces per side of a batch's tile", low=1)
    classifier: str | None = param(
        None, str, doc="a classifier file (else the scorer's shipped model)", optional=True
    )
    scorer: str = param(
        "relief", doc="the shipped model used when no classifier file is given", choices=tuple(SCORERS)
    )
    registration_grid_mm: float = param(
        0.1, doc="grid of the clouds registered (0: none)", unit="mm", low=0.0
    )
    retry_failed: bool = param(False, doc="score again the pairs that failed")
    histograms: bool = param(
        False,
        doc="measure the paper's distance histogram of every pair, not only where the scorer reads it "
        "(the paper scorer's input; the review app measures a pair's histogram when it is opened)",
    )
    plan_only: bool = param(False, doc="prepare the faces and plan the pairs, score none")
    relay_neighbours: int = param(
        DEFAULT_NEIGHBOURS, doc="partners per face the relays go through (0: no relays)", low=0
    )
    relay_rounds: int = param(DEFAULT_ROUNDS, doc="rounds of relays", low=0)
    max_seconds: float | None = param(
        None, float, doc="stop scoring (cleanly, resumable) after this long", unit="s", low=0.0, optional=True
    )
    coin_diameter_mm: float | None = param(
        None,
        float,
        doc="the hoard's coin diameter, which the shipped scorer's design lengths follow "
        "(None: the median of the faces' diameters; coindie.preprocess.coin_size)",
        unit="mm",
        low=0.0,
        low_open=True,
        optional=True,
    )


@dataclass
class SidePlan:
    side: str
    n_faces: int
    mode: str
    n_pairs: int
    n_new: int


@dataclass
class RunReport:
    run_id: int
    backend: str
    faces_prepared: int = 0
    faces_failed: list[str] = field(default_factory=list)
    plans: list[SidePlan] = field(default_factory=list)
    pairs_done: int = 0
    pairs_failed: int = 0
    batches_lost: int = 0
    relays_tried: int = 0
    relays_kept: int = 0
    stopped_early: bool = False
    seconds: float = 0.0
    stage_seconds: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class _Scorer:
    """The parameters every pair result depends on, and their hash."""

    config_text: str
    params_hash: str
    populations: str  # JSON: the scorer's training populations, where the per-hoard calibration starts
    face_params: str  # the hash of the prepared faces' parameters (their cache files)


def run_project(
    project: Project, config: RunConfig | None = None, *, progress: Progress | None = None, echo: Echo = print
) -> RunReport:
    """Run the project to completion (see the module docstring); returns what was done."""
    config = config or RunConfig()
    progress = progress or _no_progress
    start = time.perf_counter()
    classifier = _classifier(config)
    scorer = _scorer(config, classifier)
    _refresh_scans(project, echo)
    run_id = _start_run(project, config, scorer.params_hash)
    project.set_meta(f"populations:{scorer.params_hash}", scorer.populations)
    backend = make_backend(config.workers, config.dask)
    report = RunReport(run_id, backend.description)
    echo(f"run {run_id} on {backend.description}")
    status, message = "failed", ""
    try:
        with _stage(report, "faces"):
            _prepare_faces(
                project, config, _cache_grid(classifier), scorer.face_params, backend, report, progress, echo
            )
        scale = _coin_scale(project, config, classifier, scorer.face_params, echo)
        if scale != 1.0:
            scorer = _scorer(config, classifier, scale)
            project.set_run_params(run_id, scorer.params_hash, _effective(config, scale))
            project.set_meta(f"populations:{scorer.params_hash}", scorer.populations)
        with _stage(report, "plan"):
            report.plans = _plan(project, config, scorer, run_id, echo)
        if not config.plan_only:
            scoring = _Scoring(project, config, scorer, backend, report, progress, echo, time.perf_counter())
            with _stage(report, "pairs"):
                _score_pairs(scoring)
            if not report.stopped_early:
                with _stage(report, "relays"):
                    _relay_pairs(scoring)
        status = "finished"
    except KeyboardInterrupt:
        status, message = "interrupted", "interrupted by the user"
        raise
    except CoinDieError as error:
        message = str(error)
        raise
    finally:
        _close_run(project, backend, report, status, message, echo)
        report.seconds = time.perf_counter() - start
    return report


def _refresh_scans(project: Project, echo: Echo) -> None:
    """Add the new and changed scans of the project's folders."""
    refreshed = project.refresh()
    if refreshed.added or refreshed.changed:
        echo(f"{len(refreshed.added)} new and {len(refreshed.changed)} changed scan(s) found")
    for skipped in refreshed.skipped:
        echo(f"skipped: {skipped}")


@contextmanager
def _stage(report: RunReport, name: str) -> Iterator[None]:
    """Time one stage into ``report.stage_seconds`` (a stage that raises records no time)."""
    mark = time.perf_counter()
    yield
    report.stage_seconds[name] = time.perf_counter() - mark


def _close_run(
    project: Project, backend: Backend, report: RunReport, status: str, message: str, echo: Echo
) -> None:
    restarts = getattr(backend, "restarts", 0)
    if restarts:
        echo(f"worker processes died and were replaced {restarts} time(s); their batches were run again")
    backend.close()
    project.end_run(report.run_id, status, message)


@contextmanager
def _no_progress(what: str) -> Iterator[Callable[[int, int], None]]:
    yield lambda advance, total: None


# ------------------------------------------------------------------------------------------------ config


def _scorer(config: RunConfig, classifier: Any, coin_scale: float = 1.0) -> _Scorer:
    """Resolve the method's full parameters; hash everything a pair depends on (the method, its
    parameters, ``classifier``: :func:`_classifier`). On coins ``coin_scale`` times the size the defaults
    were set for, the method's design lengths and the shipped scorer's follow (:func:`_coin_scale`); the
    faces are prepared once for every scale (the classifier's grids are not design lengths)."""
    from coindie.registration import get_method, method_info

    method_params = method_info(config.method).for_coins(config.method_params, coin_scale)
    registrar = get_method(config.method, **method_params)
    face_params = face_params_hash(_cache_grid(classifier), config.registration_grid_mm)
    if coin_scale != 1.0:
        classifier = classifier.for_coins(coin_scale)
    classifier_dict = classifier.to_dict()
    payload = {
        "method": config.method,
        "method_params": method_params,
        "registration_grid_mm": config.registration_grid_mm,
        "classifier": classifier_dict,
        # not part of the pairs' identity: a histogram adds to a pair's figures and changes none of them
        "histograms": config.histograms,
    }
    identity = {
        "pair_function": PAIR_FUNCTION_VERSION,
        "method": config.method,
        "resolved_params": {k: repr(v) for k, v in sorted(registrar.params.items())},
        "registration_grid_mm": config.registration_grid_mm,
        "classifier": classifier_dict,
        "faces": face_params,
    }
    digest = hashlib.sha256(json.dumps(identity, sort_keys=True, default=str).encode()).hexdigest()[:16]
    populations = json.dumps(getattr(classifier, "populations", {}) or {})
    return _Scorer(json.dumps(payload, sort_keys=True), digest, populations, face_params)


def _classifier(config: RunConfig) -> Any:
    """The run's same-die classifier: ``--classifier``'s file, else the shipped model of ``--scorer``
    (loaded once a run)."""
    from coindie.similarity.scorers import default_scorer, load_scorer

    try:
        return load_scorer(config.classifier) if config.classifier else default_scorer(config.scorer)
    except CoinDieError:
        raise
    except (OSError, ValueError) as error:
        where = config.classifier or f"the shipped {config.scorer} model"
        raise ProjectError(f"cannot load the same-die classifier ({where}): {error}") from None


def _cache_grid(classifier: Any) -> float:
    """The per-face cache keeps the finest grid the histogram samples (paper's text: target 0.05 mm)."""
    settings = classifier.settings
    return float(min(settings.source_grid_mm, settings.target_grid_mm))


def _start_run(project: Project, config: RunConfig, params_hash: str) -> int:
    _check_no_other_run(project)
    effective = json.dumps(_effective(config), sort_keys=True)
    return project.start_run(params_hash, effective, __version__, os.getpid(), socket.gethostname())


def _effective(config: RunConfig, coin_scale: float = 1.0) -> dict[str, Any]:
    effective = {**asdict(config), "python": platform.python_version(), "cpu_count": os.cpu_count()}
    return effective if coin_scale == 1.0 else {**effective, "coin_scale": coin_scale}


def _coin_scale(project: Project, config: RunConfig, classifier: Any, face_params: str, echo: Echo) -> float:
    """The scale of the hoard's coins against those the shipped scorer was trained on and the method's
    defaults set for (1: the same, or a scorer of the user's own, ``--classifier``, whose lengths are the
    user's), said when it is not 1.

    Measured on ``benchmarks/outsider_hoards.py --kinds ordinary --seed 26 --scale 0.55`` (coins of
    10-12 mm): FMI 0.679 with the lengths of 20 mm coins, 0.959 with the scorer's scaled, 1.000 with the
    registration's too (BENCHMARK.md, "Coins of other sizes")."""
    from coindie.preprocess.coin_size import REFERENCE_DIAMETER_MM, SCALE_RANGE, coin_scale, hoard_diameter

    if config.classifier is not None or not hasattr(classifier, "for_coins"):
        return 1.0
    if config.coin_diameter_mm is not None:
        diameter, told = config.coin_diameter_mm, "as given"
    else:
        diameters = _face_diameters(project, face_params)
        median = hoard_diameter(diameters)
        if median is None:
            return 1.0
        diameter, told = median, f"the median of {len(diameters)} faces"
    scale = coin_scale(diameter)
    if scale != 1.0:
        low, high = (REFERENCE_DIAMETER_MM * bound for bound in SCALE_RANGE)
        outside = (
            f" (as far as they go: coins outside {low:.1f}-{high:.0f} mm are rare; check the scans' unit, "
            "coindie init --unit)"
            if not low <= diameter <= high
            else ""
        )
        echo(
            f"coins of {diameter:.1f} mm ({told}): the lengths of the design's details (registration "
            f"and relief features) are scaled by {scale:.3g} from those set for {REFERENCE_DIAMETER_MM:g} "
            f"mm coins{outside}"
        )
    return scale


def _face_diameters(project: Project, face_params: str) -> list[float]:
    """Each prepared face's diameter (:func:`coindie.preprocess.coin_size.face_diameter`), measured once
    from its cache file and kept in the project's meta table."""
    from coindie.preprocess.coin_size import face_diameter

    diameters, measured = [], {}
    for face in project.prepared_faces(face_params):
        key = f"diameter:{face['file']}"
        known = project.meta(key)
        if known is None:
            with np.load(project.cache_dir / face["file"]) as data:
                known = measured[key] = repr(face_diameter(data["points"]))
        diameters.append(float(known))
    if measured:
        project.set_metas(measured)  # one transaction, not one a face
    return diameters


def _check_no_other_run(project: Project) -> None:
    """Two runs writing one project would compute the same pairs twice: refuse while another lives."""
    for row in project.running_runs():
        alive = row["host"] == socket.gethostname() and pid_alive(row["pid"])
        if alive and row["pid"] != os.getpid():
            raise ProjectError(
                f"{project.folder}: run {row['run_id']} (process {row['pid']}) is still running"
            )
        project.mark_run_killed(row["run_id"])


def pid_alive(pid: int | None) -> bool:
    if not pid:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


# ------------------------------------------------------------------------------------------------- faces


def _prepare_faces(
    project: Project,
    config: RunConfig,
    grid: float,
    params: str,
    backend: Backend,
    report: RunReport,
    progress: Progress,
    echo: Echo,
) -> None:
    """Prepare the project's new and changed faces on ``grid`` (the classifier's cache grid), kept under
    ``params`` (their hash, :attr:`_Scorer.face_params`)."""
    unit = project.unit
    tasks = []
    for scan in project.scans():
        if scan.status == "error":
            continue
        if scan.status == "ok" and scan.content_hash and project.cached_file(scan.content_hash, params):
            continue
        tasks.append(
            FaceTask(
                scan.face_id,
                scan.path,
                str(project.cache_dir),
                params,
                grid,
                config.registration_grid_mm,
                unit,
            )
        )
    if not tasks:
        return
    with progress("faces") as update:
        update(0, len(tasks))
        for index, result in backend.map_unordered(prepare_face, tasks):
            if isinstance(result, BaseException):
                result = {"face_id": tasks[index].face_id, "error": f"{tasks[index].path}: {result}"}
            _record_face(project, params, result)
            if "error" in result:
                report.faces_failed.append(result["error"])
                echo(f"bad scan, left out: {result['error']}")
            else:
                report.faces_prepared += 1
            update(1, 0)


def _record_face(project: Project, params: str, result: dict[str, Any]) -> None:
    if "error" in result:
        project.record_face_error(result["face_id"], result["error"])
        return
    project.record_face(
        result["face_id"],
        params,
        content_hash=result["content_hash"],
        file=result["file"],
        n_points=result["n_points"],
        descriptor=result["descriptor"],
        seconds=result["seconds"],
    )


# -------------------------------------------------------------------------------------------------- plan


def _plan(project: Project, config: RunConfig, scorer: _Scorer, run_id: int, echo: Echo) -> list[SidePlan]:
    params_hash = scorer.params_hash
    rows = project.prepared_faces(scorer.face_params)
    plans = []
    for side in sorted({r["side"] for r in rows}):
        faces = [r["face_id"] for r in rows if r["side"] == side]
        mode = config.mode
        if mode == "auto":
            mode = "exhaustive" if len(faces) <= AUTO_EXHAUSTIVE_MAX_FACES else "candidates"
        if mode == "exhaustive":
            pairs: Iterator[tuple[str, str]] | list[tuple[str, str]] = itertools.combinations(faces, 2)
        else:
            descriptors = np.stack(
                [np.frombuffer(r["descriptor"], np.float32) for r in rows if r["side"] == side]
            )
            pairs = candidate_face_pairs(faces, descriptors, config.k)
        n_before = project.count_pairs(params_hash, side)
        project.plan_pairs(params_hash, side, mode, run_id, pairs)
        n_after = project.count_pairs(params_hash, side)
        plan = SidePlan(side, len(faces), mode, n_after, n_after - n_before)
        plans.append(plan)
        echo(_plan_line(plan, config))
    return plans


def candidate_face_pairs(faces: list[str], descriptors: np.ndarray, k: int) -> list[tuple[str, str]]:
    """(source, target) face ids, source < target, of the candidate pairs: each face's ``k`` nearest."""
    from coindie.candidates import candidate_pairs, nearest_neighbours

    if len(faces) < 2:
        return []
    neighbours, _ = nearest_neighbours(descriptors, k)
    pairs = {tuple(sorted((faces[i], faces[j]))) for i, j in candidate_pairs(neighbours)}
    return sorted(pairs)  # type: ignore[arg-type]


def _plan_line(plan: SidePlan, config: RunConfig) -> str:
    side = {"D": "obverses", "R": "reverses"}.get(plan.side, f"faces of side {plan.side}")
    full = plan.n_faces * (plan.n_faces - 1) // 2
    text = f"{side}: {plan.n_faces} faces, "
    if plan.mode == "exhaustive":
        text += f"every pair ({full:,})"
    else:
        text += f"candidate search, K = {config.k}: {plan.n_pairs:,} pairs instead of {full:,}"
        if config.mode == "auto":
            text += (
                f" (auto: exhaustive only up to {AUTO_EXHAUSTIVE_MAX_FACES} faces per side; "
                "mode 'exhaustive' forces it)"
            )
    return text + f"; {plan.n_new:,} newly planned"


# ------------------------------------------------------------------------------------------------- pairs


@dataclass(frozen=True)
class _Scoring:
    """What the scoring stages share: the project, the run's settings, where it runs and what it did."""

    project: Project
    config: RunConfig
    scorer: _Scorer
    backend: Backend
    report: RunReport
    progress: Progress
    echo: Echo
    started: float  # perf_counter at the first pair (max_seconds counts from it)

    def out_of_time(self) -> bool:
        limit = self.config.max_seconds
        return limit is not None and time.perf_counter() - self.started > limit


def _score_pairs(run: _Scoring) -> None:
    project, config, scorer, backend, report = run.project, run.config, run.scorer, run.backend, run.report
    statuses = ("todo", "failed") if config.retry_failed else ("todo",)
    todo = project.pairs_with_status(scorer.params_hash, statuses)
    if not todo:
        return
    files = _cache_files(project, scorer.face_params)
    batches = [
        PairBatch(
            tuple(pairs),
            tuple(sorted((face, files[face]) for face in {f for pair in pairs for f in pair})),
            scorer.config_text,
            2 * config.batch_faces,
        )
        for pairs in tile_batches(todo, config.batch_faces)
    ]
    with run.progress("pairs") as update:
        update(0, len(todo))
        for index, result in backend.map_unordered(score_batch, batches):
            if isinstance(result, BaseException):
                report.batches_lost += 1
                reason = f"batch lost: {result}"
                if isinstance(result, WorkerLost):
                    reason = f"worker lost: {result}"
                result = [
                    {"source": s, "target": t, "status": "failed", "reason": reason}
                    for s, t in batches[index].pairs
                ]
            _commit(project, scorer.params_hash, report.run_id, result)
            done = sum(r["status"] == "done" for r in result)
            report.pairs_done += done
            report.pairs_failed += len(result) - done
            update(len(result), 0)
            if run.out_of_time():
                report.stopped_early = True
                break  # the batches in flight are dropped: a rerun scores them


def _relay_pairs(run: _Scoring) -> None:
    """Rounds of relays (:mod:`coindie.project.relay`) over each side's done pairs."""
    from coindie.project.store import scored
    from coindie.registration import get_method

    project, config, scorer, backend, report = run.project, run.config, run.scorer, run.backend, run.report

    if config.relay_neighbours < 1 or config.relay_rounds < 1:
        return
    if not get_method(config.method, **config.method_params).refines_from_pose:
        run.echo(f"no relays: method {config.method!r} cannot start from a given pose")
        return
    files = _cache_files(project, scorer.face_params)
    for round_ in range(1, config.relay_rounds + 1):
        tried = project.tried_relays(scorer.params_hash)
        relays = []
        for side in project.scored_sides(scorer.params_hash):
            pairs = [
                {**pair, "scored": scored(pair)}
                for pair in project.scored_pairs(scorer.params_hash, side)
                if pair["source"] in files and pair["target"] in files
            ]
            relays += plan_relays(pairs, config.relay_neighbours, tried)
        if not relays:
            return
        batches = _relay_batches(relays, files, scorer, config.batch_faces)
        kept = 0
        with run.progress(f"relays, round {round_}") as update:
            update(0, len(relays))
            for _, result in backend.map_unordered(relay_batch, batches):
                if isinstance(result, BaseException):
                    report.batches_lost += 1  # tried again by the next round or run
                    continue
                kept += project.commit_relays(scorer.params_hash, report.run_id, result, MIN_GAIN)
                report.relays_tried += len(result)
                update(len(result), 0)
                if run.out_of_time():
                    report.stopped_early = True
                    break
        report.relays_kept += kept
        run.echo(f"relays, round {round_}: {len(relays):,} tried through a third face, {kept:,} scored more")
        if report.stopped_early or not kept:
            return


def _relay_batches(
    relays: list[Relay], files: dict[str, str], scorer: _Scorer, batch_faces: int
) -> list[RelayBatch]:
    """The relays in tiles of faces, as :func:`tile_batches` cuts pairs (a pair's relays in one batch)."""
    by_pair: dict[tuple[str, str], list[Relay]] = {}
    for relay in relays:
        by_pair.setdefault((relay.source, relay.target), []).append(relay)
    return [
        RelayBatch(
            tuple(
                (r.source, r.target, r.via, json.dumps(r.T_target_source.tolist()), r.before)
                for pair in pairs
                for r in by_pair[pair]
            ),
            tuple(sorted((face, files[face]) for face in {f for pair in pairs for f in pair})),
            scorer.config_text,
            2 * batch_faces,
            MIN_GAIN,
        )
        for pairs in tile_batches(list(by_pair), batch_faces)
    ]


def _cache_files(project: Project, face_params: str) -> dict[str, str]:
    rows = project.prepared_faces(face_params)
    return {r["face_id"]: str(project.cache_dir / r["file"]) for r in rows}


def tile_batches(pairs: list[tuple[str, str]], batch_faces: int) -> list[list[tuple[str, str]]]:
    """Cut pairs into batches touching at most ``2 * batch_faces`` faces each, so a worker loads each
    face once per batch: faces are ordered by reverse Cuthill–McKee on the pair graph (linked faces get
    close positions), pairs grouped by tile of that order, small tiles merged. Within a batch pairs are
    sorted by source, then target: a source's turned relief transforms are the costliest per-face work
    a registration can reuse (``relief_search._SWEPT``), and they are kept for the last few sources only;
    every face of a batch stays in the worker's face cache whatever the order."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import reverse_cuthill_mckee

    faces = sorted({face for pair in pairs for face in pair})
    index = {face: i for i, face in enumerate(faces)}
    rows = np.array([index[a] for a, _ in pairs], dtype=np.int64)
    cols = np.array([index[b] for _, b in pairs], dtype=np.int64)
    graph = coo_matrix((np.ones(len(pairs), dtype=np.int8), (rows, cols)), shape=(len(faces), len(faces)))
    graph = (graph + graph.T).tocsr()
    order = reverse_cuthill_mckee(graph, symmetric_mode=True)
    position = np.empty(len(faces), dtype=np.int64)
    position[order] = np.arange(len(faces))
    tiles: dict[tuple[int, int], list[tuple[str, str]]] = {}
    for (a, b), i, j in zip(pairs, rows, cols, strict=True):
        p, q = sorted((int(position[i]), int(position[j])))
        tiles.setdefault((p // batch_faces, q // batch_faces), []).append((a, b))
    batches: list[list[tuple[str, str]]] = []
    current: list[tuple[str, str]] = []
    current_faces: set[str] = set()
    for key in sorted(tiles):
        tile = tiles[key]
        tile_faces = {face for pair in tile for face in pair}
        if current and len(current_faces | tile_faces) > 2 * batch_faces:
            batches.append(current)
            current, current_faces = [], set()
        current += tile
        current_faces |= tile_faces
    if current:
        batches.append(current)
    return [sorted(batch) for batch in batches]


def _commit(project: Project, params_hash: str, run_id: int, rows: list[dict[str, Any]]) -> None:
    """One batch, atomically; a pair already done (by an earlier run) is never overwritten."""
    seconds = sum(json.loads(r["timings"]).get("total", 0.0) for r in rows if r.get("timings"))
    project.commit_pairs(params_hash, run_id, rows, seconds)
