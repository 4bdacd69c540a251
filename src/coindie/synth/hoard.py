"""Generate a hoard: plan it, make every face with the physics, write the files (in parallel, resumable).

Each face is made from seeds derived from (hoard seed, name) — ``("type", family)``, ``("die", die id)``,
``("spec", face id)``, ``("face", face id)`` — so the output does not depend on the number of worker
processes nor on the order in which faces are made. Work is cut into tasks of a few faces of one die so
that each worker builds a die once and reuses it (``functools.lru_cache``).

A run writes each finished face's record under ``.synth-parts/``; a later run with the same settings
skips faces whose PLY is still there with the same sha256, so an interrupted run resumes.
"""

from __future__ import annotations

import shutil
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from datetime import UTC, datetime
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
from threadpoolctl import threadpool_limits

from coindie import __version__
from coindie.errors import CoinDieError, ParameterError
from coindie.io import write_ply
from coindie.project.backends import WorkerLost, make_backend
from coindie.synth.design import DieParams, Family, make_die, make_type
from coindie.synth.face import make_face, sample_face_spec
from coindie.synth.life import LifeParams
from coindie.synth.physics import NamedPhysics, PhysicsParams, physics_by_name
from coindie.synth.plan import FacePlan, HoardPlan, derived_seed, plan_hoard
from coindie.synth.presets import get_preset
from coindie.synth.writer import (
    HOARD_FILE,
    PARTS_DIR,
    TRUTH_FILE,
    digest,
    file_sha256,
    read_json,
    to_jsonable,
    truth_document,
    write_json,
    write_tables,
)

#: Faces per task: small enough to balance the workers, large enough to reuse a die.
FACES_PER_TASK = 16

Progress = Callable[[int, int], None]


@dataclass(frozen=True)
class HoardReport:
    """What a run did: where, how many faces were made or found already made, how long it took."""

    out_dir: Path
    n_faces: int
    n_made: int
    n_reused: int
    seconds: float
    workers: int


@dataclass(frozen=True)
class _Task:
    seed: int
    family: str
    die_id: str
    faces: tuple[tuple[str, float], ...]  # (face id, die age)
    physics: PhysicsParams
    out_dir: str
    settings: str


def synthesize(
    out_dir: str | Path,
    *,
    preset: str = "riedones",
    scale: float = 1.0,
    seed: int = 0,
    physics: PhysicsParams | NamedPhysics | str | None = None,
    workers: int = 1,
    dask: str | None = None,
    progress: Progress | None = None,
    overwrite: bool = False,
    physics_name: str | None = None,
) -> HoardReport:
    """Plan and generate a hoard into ``out_dir`` (see :mod:`coindie.synth.writer` for the files).

    ``physics``: parameters, or a physics by name (``physics_by_name("wide")`` or the name itself, see
    :mod:`coindie.synth.physics`), resolved with the hoard's seed; its name (or ``physics_name``) goes to
    ``hoard.json``. The faces are made by ``workers`` local processes, or on a Dask cluster when ``dask``
    is its address or ``local`` (:mod:`coindie.project.backends`; the output depends on neither).
    """
    plan = plan_hoard(get_preset(preset, scale), seed)
    params, name = resolve_physics(physics, seed)
    name = physics_name or name
    return generate(
        out_dir, plan, params, workers=workers, dask=dask, progress=progress, overwrite=overwrite,
        physics_name=name,
    )  # fmt: skip


def resolve_physics(
    physics: PhysicsParams | NamedPhysics | str | None, seed: int
) -> tuple[PhysicsParams, str]:
    """The parameters of a hoard's physics and its name (``custom`` for parameters other than today's)."""
    if physics is None:
        return PhysicsParams(), "default"
    if isinstance(physics, str):
        physics = physics_by_name(physics)
    if isinstance(physics, NamedPhysics):
        return physics.resolve(seed), physics.name
    return physics, "default" if physics == PhysicsParams() else "custom"


def generate(
    out_dir: str | Path,
    plan: HoardPlan,
    physics: PhysicsParams,
    *,
    workers: int = 1,
    dask: str | None = None,
    progress: Progress | None = None,
    overwrite: bool = False,
    physics_name: str | None = None,
) -> HoardReport:
    """Make every face of ``plan`` and write the hoard's files (``physics_name`` goes to hoard.json;
    default: ``default`` for today's parameters, else ``custom``)."""
    if workers < 1:
        raise ParameterError(f"workers must be at least 1, got {workers}")
    out = Path(out_dir)
    settings = settings_of(plan, physics)
    _prepare(out, digest(settings), overwrite)
    started = time.perf_counter()
    records = _reusable_records(out, digest(settings), plan)
    todo = [f for f in plan.faces if f.face_id not in records]
    tasks = _tasks(plan, todo, physics, out, digest(settings))
    for made in _run(tasks, workers, dask, len(records), len(plan.faces), progress):
        records.update(made)
    write_tables(out, plan)
    write_json(out / TRUTH_FILE, {"settings": digest(settings), **truth_document(plan, records)})
    seconds = time.perf_counter() - started
    report = HoardReport(out, len(plan.faces), len(todo), len(plan.faces) - len(todo), seconds, workers)
    name = physics_name or resolve_physics(physics, plan.seed)[1]
    write_json(out / HOARD_FILE, {**_hoard_document(settings, report), "physics": name})
    shutil.rmtree(out / PARTS_DIR, ignore_errors=True)
    return report


def settings_of(plan: HoardPlan, physics: PhysicsParams) -> dict[str, Any]:
    """Everything that determines a hoard's content."""
    return {"preset": to_jsonable(plan.preset), "seed": plan.seed, "physics": to_jsonable(physics)}


def _hoard_document(settings: dict[str, Any], report: HoardReport) -> dict[str, Any]:
    return {
        "coindie_version": __version__,
        "preset": settings["preset"]["name"],
        "scale": settings["preset"]["scale"],
        "seed": settings["seed"],
        "parameters": settings,
        "settings": digest(settings),
        "n_faces": report.n_faces,
        "generated_at": datetime.now(UTC).isoformat(timespec="seconds"),
        "generation_seconds": round(report.seconds, 3),
        "workers": report.workers,
        "faces_made": report.n_made,
        "faces_reused": report.n_reused,
    }


# --- resuming --------------------------------------------------------------------------------------------


def _prepare(out: Path, settings: str, overwrite: bool) -> None:
    """Create ``out``; refuse to mix two hoards' faces in one folder unless told to overwrite."""
    out.mkdir(parents=True, exist_ok=True)
    previous = _previous_settings(out)
    if previous is not None and previous != settings:
        if not overwrite:
            raise ParameterError(
                f"{out} holds a hoard made with other settings; choose another folder or overwrite it"
            )
        for path in out.glob("*.ply"):
            path.unlink()
        shutil.rmtree(out / PARTS_DIR, ignore_errors=True)
        (out / TRUTH_FILE).unlink(missing_ok=True)
    (out / PARTS_DIR).mkdir(exist_ok=True)
    write_json(out / PARTS_DIR / "settings.json", {"settings": settings})


def _previous_settings(out: Path) -> str | None:
    for path in (out / PARTS_DIR / "settings.json", out / TRUTH_FILE):
        if path.exists():
            return read_json(path).get("settings")
    return None


def _reusable_records(out: Path, settings: str, plan: HoardPlan) -> dict[str, dict[str, Any]]:
    """Records of faces already made with these settings whose PLY is unchanged."""
    found: dict[str, dict[str, Any]] = {}
    if (out / TRUTH_FILE).exists() and read_json(out / TRUTH_FILE).get("settings") == settings:
        found.update(_physics_part(r) for r in read_json(out / TRUTH_FILE)["faces"].items())
    for path in sorted((out / PARTS_DIR).glob("L*.json")):
        record = read_json(path)
        if record.pop("settings", None) == settings:
            found[path.stem] = record
    wanted = {f.face_id for f in plan.faces}
    return {
        face_id: record
        for face_id, record in found.items()
        if face_id in wanted and _ply_unchanged(out / f"{face_id}.ply", record)
    }


def _physics_part(item: tuple[str, dict[str, Any]]) -> tuple[str, dict[str, Any]]:
    face_id, record = item
    return face_id, {k: record[k] for k in _RECORD_KEYS if k in record}


def _ply_unchanged(path: Path, record: dict[str, Any]) -> bool:
    return path.exists() and record.get("ply_sha256") == file_sha256(path)


# --- running ---------------------------------------------------------------------------------------------


def _tasks(
    plan: HoardPlan, faces: list[FacePlan], physics: PhysicsParams, out: Path, settings: str
) -> list[_Task]:
    by_die: dict[str, list[FacePlan]] = {}
    for face in faces:
        by_die.setdefault(face.die_id, []).append(face)
    tasks = []
    for die_id, members in by_die.items():
        for i in range(0, len(members), FACES_PER_TASK):
            chunk = tuple((f.face_id, f.die_age) for f in members[i : i + FACES_PER_TASK])
            tasks.append(_Task(plan.seed, members[0].family, die_id, chunk, physics, str(out), settings))
    return tasks


def _run(
    tasks: list[_Task], workers: int, dask: str | None, done: int, total: int, progress: Progress | None
) -> Iterator[dict[str, dict[str, Any]]]:
    if progress:
        progress(done, total)
    for made in _results(tasks, workers, dask):
        done += len(made)
        if progress:
            progress(done, total)
        yield made


def _results(tasks: list[_Task], workers: int, dask: str | None) -> Iterator[dict[str, dict[str, Any]]]:
    if (workers == 1 and not dask) or len(tasks) <= 1:
        yield from map(run_task, tasks)
        return
    # Spawned local processes (forking a process that runs threads, a progress bar, is unsafe) or Dask;
    # a task whose worker died is run again (its faces are pure functions of the seed).
    backend = make_backend(workers, dask)
    try:
        for index, made in backend.map_unordered(run_task, tasks):
            if isinstance(made, WorkerLost):
                faces = ", ".join(face_id for face_id, _ in tasks[index].faces)
                raise CoinDieError(f"faces {faces} of die {tasks[index].die_id}: {made}") from made
            if isinstance(made, BaseException):
                raise made
            yield made
    finally:
        backend.close()


def run_task(task: _Task) -> dict[str, dict[str, Any]]:
    """Make and write the faces of one task; returns their records (face id -> record)."""
    # One thread per task: each worker owns a core, and the arithmetic is the same in every process.
    with threadpool_limits(1):
        die = _die(task.seed, task.family, task.die_id, task.physics.die, task.physics.life)
        return {face_id: _make_face(task, die, face_id, age) for face_id, age in task.faces}


_RECORD_KEYS = ("T_scan_die", "face_seed", "physics", "n_points", "ply_sha256")


def _make_face(task: _Task, die: Any, face_id: str, die_age: float) -> dict[str, Any]:
    rng = np.random.default_rng(derived_seed(task.seed, "spec", face_id))
    physics = task.physics
    scanner = scanner_of(physics, task.seed, face_id)
    spec = sample_face_spec(
        rng,
        die_age,
        strike=physics.strike,
        circulation=physics.circulation,
        scan=physics.all_scanners()[scanner],
    )
    face_seed = derived_seed(task.seed, "face", face_id)
    face = make_face(die, spec, face_id, face_seed)
    path = write_ply(Path(task.out_dir) / f"{face_id}.ply", face.scan)
    record = {
        "T_scan_die": np.asarray(face.T_scan_die, dtype=np.float64),
        "face_seed": face_seed,
        "physics": face.info,
        "n_points": face.scan.n_points,
        "ply_sha256": file_sha256(path),
    }
    if physics.scanners:
        record["physics"] = {**face.info, "scanner": scanner}
    record = to_jsonable(record)
    write_json(Path(task.out_dir) / PARTS_DIR / f"{face_id}.json", {**record, "settings": task.settings})
    return record


def scanner_of(physics: PhysicsParams, seed: int, face_id: str) -> int:
    """Index into ``physics.all_scanners()`` of the scanner of a face (drawn per face; 0 with one)."""
    if not physics.scanners:
        return 0
    rng = np.random.default_rng(derived_seed(seed, "scanner", face_id))
    return int(rng.integers(len(physics.scanners) + 1))


@lru_cache(maxsize=4)
def _design(seed: int, family: str) -> Any:
    return make_type(Family(family), derived_seed(seed, "type", family))


@lru_cache(maxsize=4)
def _die(seed: int, family: str, die_id: str, params: DieParams, life: LifeParams) -> Any:
    return make_die(_design(seed, family), die_id, derived_seed(seed, "die", die_id), params, life=life)
