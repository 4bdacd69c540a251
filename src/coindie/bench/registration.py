"""The paper's registration benchmark (Riedones3D, section 4.2) on a hoard with known transforms.

For every pair of faces within each die of the registration test split, the source is turned by a random
rotation (x and y within ±25°, z within ±180°; seeded per pair) after grid sampling at 0.1 mm, registered
onto the target by each method, and scored by the Scaled Registration Error (Fontana et al. 2020): per die
the median SRE, then the mean over the dies of each family — reverses (R), obverses with beard (DB),
without (D) — and over all dies (All), SRE x 1000 as in the paper's Tables 1 and 2.

Outputs in ``out``: ``pairs.csv`` (one row per method and pair, appended as pairs finish, so an
interrupted run resumes where it stopped), ``per_die.csv`` (Table 2), ``summary.json`` and
``summary.md`` (Table 1, with time per pair, rotation/translation errors and success rate, and the errors in
the face's own plane: :func:`coindie.registration.planar_errors`), ``per_die.png``.
"""

from __future__ import annotations

import csv
import itertools
import json
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from coindie.bench.machine import describe_machine
from coindie.errors import CoinDieError, ParameterError
from coindie.io.truth import HoardTruth, load_truth
from coindie.project.backends import MAX_ATTEMPTS, WorkerLost, make_backend
from coindie.scan import Scan

#: The paper's benchmark: grid 0.1 mm, random rotations x, y in ±25°, z in ±180°.
GRID_MM = 0.1
TILT_DEG = 25.0
#: A pair counts as a success when the rotation error is below 2° and the translation error below 0.3 mm.
SUCCESS_ROTATION_DEG = 2.0
SUCCESS_TRANSLATION_MM = 0.3
#: A pair is laid right in its plane (what the relief features read) when the median in-plane displacement
#: of its points is below this (:func:`coindie.registration.planar_errors`). A third of the features' fine
#: band (0.3 mm): a relief detail of that band moved by 0.1 mm keeps about 97 % of its correlation
#: (exp(-d² / 4σ²) for a Gaussian band), by 0.3 mm about 78 %.
PLANAR_SUCCESS_MM = 0.1
#: The paper's Table 1 (SRE x 1000 and seconds per pair), for the report.
PAPER_TABLE_1 = {
    "Random Search ICP": (512.9, 70.7, 7.2, 302.2, 70.7),
    "FPFH (5000) + TEASER": (492.0, 448.1, 358.6, 452.6, 2.1),
    "FPFH (5000) + TEASER + ICP": (501.5, 378.1, 616.6, 499.6, 2.3),
    "DIP (5000) + TEASER": (370.4, 46.1, 21.9, 220.9, 61.2),
    "DIP (5000) + TEASER + ICP": (281.4, 73.4, 9.3, 174.7, 62.9),
    "FCGF (250) + TEASER": (126.0, 42.6, 19.3, 83.8, 0.6),
    "FCGF (5000) + TEASER": (96.7, 21.4, 10.3, 60.8, 2.1),
    "FCGF (250) + TEASER + ICP": (101.0, 11.0, 9.3, 60.6, 1.2),
    "FCGF (5000) + TEASER + ICP": (68.2, 8.7, 9.3, 41.9, 3.8),
}
FAMILIES = ("R", "DB", "D")
_NUMBER_FIELDS = (
    "sre", "rotation_error_deg", "translation_error_mm", "twist_error_deg", "planar_error_mm", "residual_mm",
    "time_s", "cpu_s",
)  # fmt: skip
PAIR_FIELDS = (
    "method", "die", "family", "source", "target", "sre", "rotation_error_deg", "translation_error_mm",
    "success", "twist_error_deg", "planar_error_mm", "valid", "residual_mm", "time_s", "cpu_s", "reason",
)  # fmt: skip


@dataclass(frozen=True)
class PairJob:
    """One registration to run: ``source`` (turned by ``T_turn``) onto ``target``."""

    method: str
    params: tuple[tuple[str, object], ...]
    die: str
    family: str
    source: str
    target: str
    source_path: str
    target_path: str
    T_true: tuple[float, ...]  # T_target_source of the unturned clouds, row-major 4x4
    T_turn: tuple[float, ...]


def plan_pairs(
    truth: HoardTruth, split: str = "registration_test", max_pairs: int | None = None, seed: int = 0
) -> list[tuple[str, str, str, np.ndarray]]:
    """(die, source, target, T_turn) for every pair within each die of ``split``; with ``max_pairs``,
    dies take turns so that every die is represented. The turn of a pair depends only on seed and ids."""
    by_die: dict[str, list[str]] = {}
    for face in truth.faces_in(split):
        by_die.setdefault(face.die, []).append(face.face_id)
    per_die = [
        [(die, a, b) for a, b in itertools.combinations(sorted(ids), 2)]
        for die, ids in sorted(by_die.items())
    ]
    ordered = [p for group in itertools.zip_longest(*per_die) for p in group if p is not None]
    chosen = ordered[:max_pairs] if max_pairs else ordered
    return [(die, a, b, random_turn(seed, a, b)) for die, a, b in chosen]


def random_turn(seed: int, source: str, target: str) -> np.ndarray:
    """The benchmark's random rotation for one pair (x, y in ±25°, z in ±180°), about the origin."""
    digest = int.from_bytes(f"{source}>{target}".encode(), "little") % (2**63)
    rng = np.random.default_rng([seed, digest])
    angles = [rng.uniform(-TILT_DEG, TILT_DEG), rng.uniform(-TILT_DEG, TILT_DEG), rng.uniform(-180.0, 180.0)]
    T = np.eye(4)
    T[:3, :3] = Rotation.from_euler("xyz", angles, degrees=True).as_matrix()
    return T


def run_pair(job: PairJob) -> dict[str, object]:
    """Register one pair and score it (runs in a worker process)."""
    from coindie.registration import (
        planar_errors,
        rotation_error_deg,
        scaled_registration_error,
        translation_error_mm,
    )

    T_turn = np.reshape(job.T_turn, (4, 4))
    source = _grid_scan(job.source_path).transformed(T_turn)
    target = _grid_scan(job.target_path)
    T_true = np.reshape(job.T_true, (4, 4)) @ np.linalg.inv(T_turn)
    registrar = _registrar(job.method, job.params)
    wall, cpu = time.perf_counter(), time.process_time()
    result = registrar.register(source, target)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    rotation = rotation_error_deg(T_true, result.T_target_source)
    translation = translation_error_mm(T_true, result.T_target_source)
    twist, planar = planar_errors(source.points, T_true, result.T_target_source)
    return {
        "method": job.method, "die": job.die, "family": job.family, "source": job.source,
        "target": job.target, "sre": scaled_registration_error(source.points, T_true, result.T_target_source),
        "rotation_error_deg": rotation, "translation_error_mm": translation,
        "success": rotation < SUCCESS_ROTATION_DEG and translation < SUCCESS_TRANSLATION_MM,
        "twist_error_deg": twist, "planar_error_mm": planar,
        "valid": result.valid, "residual_mm": result.residual, "time_s": wall, "cpu_s": cpu,
        "reason": result.reason,
    }  # fmt: skip


#: How a die study meets a pair (benchmarks/bench_registration_speed.py): both faces new to the method;
#: the target seen before (the benchmark's situation); both seen (an all-pairs study's pairs).
SITUATIONS = ("cold", "new source", "all-pairs")


def timed_in_situation(situation: str, method: Any, source: Any, target: Any) -> tuple[float, Any]:
    """Seconds ``method.register(source, target)`` takes in ``situation`` (one of :data:`SITUATIONS`:
    the faces it has seen are registered onto themselves first, untimed), and its result. The method
    should be fresh (nothing cached); any registration method of any version of the package."""
    if situation not in SITUATIONS:
        raise ParameterError(f"situation must be one of {', '.join(SITUATIONS)}, not {situation!r}")
    if situation in ("new source", "all-pairs"):
        method.register(target, target)
    if situation == "all-pairs":
        method.register(source, source)
    start = time.perf_counter()
    result = method.register(source, target)
    return time.perf_counter() - start, result


@lru_cache(maxsize=64)
def _grid_scan(path: str) -> Scan:
    from coindie.io import read_scan
    from coindie.preprocess import grid_sample

    return grid_sample(read_scan(path), GRID_MM)


@lru_cache(maxsize=8)
def _registrar(method: str, params: tuple[tuple[str, object], ...]):  # noqa: ANN202
    from coindie.registration import get_method

    name, in_label = parse_method(method)
    return get_method(name, **(in_label | dict(params)))


def parse_method(label: str) -> tuple[str, dict[str, object]]:
    """``"fcgf+icp[matcher.n_points=250]"`` -> ``("fcgf+icp", {"matcher.n_points": 250})``: a method
    with parameters written into its label, so that one run can compare variants of one method (the
    paper's FCGF (250) and FCGF (5000)). Values are parsed and checked by the method's parameters."""
    from coindie.registration import method_info

    name, _, rest = label.strip().partition("[")
    info = method_info(name.strip())
    if not rest:
        return info.name, {}
    if not rest.endswith("]"):
        raise ParameterError(f"Method {label!r}: parameters are written name[key=value;key=value].")
    items = filter(None, (part.strip() for part in rest[:-1].split(";")))
    return info.name, info.parse_items(items, lambda item: f"Method {label!r}: {item!r} is not key=value.")


def benchmark_registration(
    data: str | Path,
    methods: Iterable[str],
    out: str | Path,
    *,
    params: dict[str, dict[str, object]] | None = None,
    max_pairs: int | None = None,
    workers: int = 1,
    dask: str | None = None,
    seed: int = 0,
    split: str = "registration_test",
    transforms: str | Path | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> dict[str, dict[str, float]]:
    """Run the benchmark (resuming ``out/pairs.csv``), write every output, return the summary. Pairs run
    on ``workers`` local processes, or on a Dask cluster when ``dask`` is its address or ``local``
    (:mod:`coindie.project.backends`); a pair whose worker was lost is run again."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    truth = load_truth(data, transforms)
    methods = list(methods)
    jobs = _jobs(truth, methods, params or {}, split, max_pairs, seed)
    pairs_csv = out / "pairs.csv"
    done = {(r["method"], r["source"], r["target"]) for r in read_pairs(pairs_csv)}
    todo = [j for j in jobs if (j.method, j.source, j.target) not in done]
    if progress:
        progress(len(jobs) - len(todo), len(jobs))
    with _appender(pairs_csv) as append:
        for row in _results(todo, workers, dask):
            append(row)
            if progress:
                progress(1, 0)
    wanted = {(j.method, j.source, j.target) for j in jobs}
    rows = [r for r in read_pairs(pairs_csv) if (r["method"], r["source"], r["target"]) in wanted]
    return write_reports(rows, methods, out, machine=describe_machine(workers))


def _jobs(
    truth: HoardTruth,
    methods: list[str],
    params: dict[str, dict[str, object]],
    split: str,
    max_pairs: int | None,
    seed: int,
) -> list[PairJob]:
    jobs = []
    for die, a, b, T_turn in plan_pairs(truth, split, max_pairs, seed):
        face_a, face_b = truth.faces[a], truth.faces[b]
        T_true = truth.T_true(a, b)
        for method in methods:
            jobs.append(
                PairJob(
                    method,
                    tuple(sorted(params.get(method, {}).items())),
                    die,
                    face_a.family,
                    a,
                    b,
                    str(face_a.path),
                    str(face_b.path),
                    tuple(T_true.ravel()),
                    tuple(T_turn.ravel()),
                )  # fmt: skip
            )
    # Group by target face: each worker then reuses the target's per-face work (search tree, descriptors,
    # relief images) as in an all-pairs study, while every source is new (turned for its pair).
    return sorted(jobs, key=lambda j: (j.target, j.method, j.source))


def _results(jobs: list[PairJob], workers: int, dask: str | None) -> Iterator[dict[str, object]]:
    """The jobs' rows in the jobs' order (pairs.csv does not depend on the workers). Jobs go to the
    workers in chunks of consecutive jobs (one target face: its per-face work is reused). A chunk whose
    worker died ``MAX_ATTEMPTS`` times is left out of pairs.csv, the others go on, and the run then fails
    naming its pairs (a rerun tries them again)."""
    if (workers <= 1 and not dask) or len(jobs) <= 1:
        yield from map(run_pair, jobs)
        return
    size = max(1, min(8, len(jobs) // (4 * max(1, workers))))
    chunks = [tuple(jobs[i : i + size]) for i in range(0, len(jobs), size)]
    backend = make_backend(workers, dask)
    lost = []
    try:
        for chunk, rows in zip(chunks, backend.map_ordered(run_pairs, chunks), strict=True):
            if isinstance(rows, WorkerLost):
                lost += [f"{job.method} {job.source} -> {job.target}" for job in chunk]
            elif isinstance(rows, BaseException):
                raise rows
            else:
                yield from rows
    finally:
        backend.close()
    if lost:
        raise CoinDieError(
            f"{len(lost)} pair(s) lost their worker {MAX_ATTEMPTS} times; run again to retry them: "
            + ", ".join(lost)
        )


def run_pairs(jobs: tuple[PairJob, ...]) -> list[dict[str, object]]:
    """Register and score consecutive pairs (runs in a worker process)."""
    return [run_pair(job) for job in jobs]


class _appender:
    """Append rows to a CSV (header when new), flushed row by row so a killed run loses nothing done."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def __enter__(self) -> Callable[[dict[str, object]], None]:
        kept = read_pairs(self.path)
        # A run killed mid-row leaves a partial last line: rewrite the complete rows before appending.
        self.handle = self.path.open("w", newline="")
        self.writer = csv.DictWriter(self.handle, fieldnames=PAIR_FIELDS)
        self.writer.writeheader()
        self.writer.writerows(kept)
        self.handle.flush()
        return self._append

    def _append(self, row: dict[str, object]) -> None:
        self.writer.writerow(row)
        self.handle.flush()

    def __exit__(self, *exc: object) -> None:
        self.handle.close()


def read_pairs(path: Path) -> list[dict[str, object]]:
    """Rows of a pairs.csv with numbers and booleans parsed (a truncated last line is dropped)."""
    if not path.is_file():
        return []
    rows = []
    with path.open(newline="") as handle:
        for row in csv.DictReader(handle):
            if None in row.values() or row.get("reason") is None:
                continue
            parsed: dict[str, object] = dict(row)
            try:
                for key in _NUMBER_FIELDS:
                    # a pairs.csv written before the planar errors has no such column: unknown, not re-run
                    parsed[key] = float(row[key]) if key in row else float("nan")
            except ValueError:  # a damaged row: its pair is run again
                continue
            for key in ("success", "valid"):
                parsed[key] = row[key] == "True"
            rows.append(parsed)
    return rows


# ------------------------------------------------------------------------------------------------ reports


def per_die_medians(rows: list[dict[str, object]], method: str) -> dict[str, tuple[str, float]]:
    """die -> (family, median SRE x 1000) for one method."""
    by_die: dict[str, list[float]] = {}
    family: dict[str, str] = {}
    for r in rows:
        if r["method"] == method:
            by_die.setdefault(str(r["die"]), []).append(1000.0 * float(r["sre"]))  # type: ignore[arg-type]
            family[str(r["die"])] = str(r["family"])
    return {die: (family[die], float(np.median(v))) for die, v in sorted(by_die.items(), key=_die_order)}


def _die_order(item: tuple[str, object]) -> tuple[int, str]:
    die = item[0]
    rank = 0 if die.startswith("R") else 1 if die.startswith("DB") else 2
    digits = "".join(c for c in die if c.isdigit())
    return rank, f"{int(digits):06d}{die}" if digits else die


def summarize(rows: list[dict[str, object]], methods: list[str]) -> dict[str, dict[str, float]]:
    """Per method: "R", "DB", "D", "All" (mean over dies of the per-die median SRE x 1000), "time_s" and
    "cpu_s" (median per pair), "success" (share), median "rotation_error_deg" and "translation_error_mm",
    median "twist_error_deg" and "planar_error_mm" and "planar_success" (the share of pairs laid right in
    their plane, :data:`PLANAR_SUCCESS_MM`; NaN for pairs of a pairs.csv written before), "n_pairs",
    "n_dies"."""
    summary = {}
    for method in methods:
        mine = [r for r in rows if r["method"] == method]
        if not mine:
            continue
        dies = per_die_medians(rows, method)
        entry: dict[str, float] = {}
        for family in FAMILIES:
            values = [sre for fam, sre in dies.values() if fam == family]
            entry[family] = float(np.mean(values)) if values else float("nan")
        entry["All"] = float(np.mean([sre for _, sre in dies.values()]))
        entry["time_s"] = float(np.median([r["time_s"] for r in mine]))
        entry["cpu_s"] = float(np.median([r["cpu_s"] for r in mine]))
        entry["success"] = float(np.mean([bool(r["success"]) for r in mine]))
        entry["rotation_error_deg"] = float(np.median([r["rotation_error_deg"] for r in mine]))
        entry["translation_error_mm"] = float(np.median([r["translation_error_mm"] for r in mine]))
        twist = np.array([r["twist_error_deg"] for r in mine], dtype=np.float64)
        planar = np.array([r["planar_error_mm"] for r in mine], dtype=np.float64)
        known = np.isfinite(planar)
        entry["twist_error_deg"] = float(np.median(twist[known])) if known.any() else float("nan")
        entry["planar_error_mm"] = float(np.median(planar[known])) if known.any() else float("nan")
        laid = planar[known] < PLANAR_SUCCESS_MM
        entry["planar_success"] = float(np.mean(laid)) if known.any() else float("nan")
        entry["n_pairs"] = len(mine)
        entry["n_dies"] = len(dies)
        summary[method] = entry
    return summary


def write_reports(
    rows: list[dict[str, object]], methods: list[str], out: Path, machine: str = ""
) -> dict[str, dict[str, float]]:
    summary = summarize(rows, methods)
    (out / "summary.json").write_text(json.dumps(_json_ready(summary), indent=2) + "\n")
    (out / "summary.md").write_text(summary_markdown(summary, machine))
    dies = _write_per_die(rows, list(summary), out / "per_die.csv")
    if summary:
        _plot(rows, list(summary), dies, out / "per_die.png")
    return summary


def _json_ready(summary: dict[str, dict[str, float]]) -> dict[str, dict[str, float | None]]:
    return {m: {k: (v if np.isfinite(v) else None) for k, v in e.items()} for m, e in summary.items()}


def summary_markdown(summary: dict[str, dict[str, float]], machine: str = "") -> str:
    """Table 1 of the paper for our methods (SRE x 1000, lower is better), then the paper's own rows."""
    header = ["method", "R", "DB", "D", "All", "time per pair (s)", "CPU per pair (s)", "success"]
    header += ["rot. err. (°)", "transl. err. (mm)", "twist (°)", "in-plane err. (mm)"]
    header += [f"in plane < {PLANAR_SUCCESS_MM:g} mm", "pairs", "dies"]
    lines = [_row(header), _row(["---"] + ["---:"] * (len(header) - 1))]
    for method, e in summary.items():
        cells = [method, _f(e["R"]), _f(e["DB"]), _f(e["D"]), f"**{_f(e['All'])}**", f"{e['time_s']:.3f}"]
        cells += [f"{e['cpu_s']:.3f}", f"{e['success']:.1%}", f"{e['rotation_error_deg']:.2f}"]
        cells += [f"{e['translation_error_mm']:.3f}", _f(e["twist_error_deg"], "{:.2f}")]
        cells += [_f(e["planar_error_mm"], "{:.3f}"), _f(e["planar_success"], "{:.1%}")]
        cells += [str(int(e["n_pairs"])), str(int(e["n_dies"]))]
        lines.append(_row(cells))
    lines += ["", "The paper's Table 1 (real Riedones3D scans, GPU for FCGF):", ""]
    lines += [_row(["method", "R", "DB", "D", "All", "time per pair (s)"]), _row(["---"] + ["---:"] * 5)]
    lines += [_row([name, *map(str, values)]) for name, values in PAPER_TABLE_1.items()]
    if machine:
        lines += ["", f"Machine: {machine}."]
    return "\n".join(lines) + "\n"


def _row(cells: list[str]) -> str:
    return "| " + " | ".join(cells) + " |"


def _f(value: float, spec: str = "{:.1f}") -> str:
    return spec.format(value) if np.isfinite(value) else "–"


def _write_per_die(rows: list[dict[str, object]], methods: list[str], path: Path) -> list[str]:
    table = {m: per_die_medians(rows, m) for m in methods}
    dies = [d for d, _ in sorted({d: 0 for m in table.values() for d in m}.items(), key=_die_order)]
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["method", *dies, "Average"])
        for method, medians in table.items():
            values = [medians[d][1] if d in medians else float("nan") for d in dies]
            writer.writerow([method, *(f"{v:.1f}" for v in values), f"{np.nanmean(values):.1f}"])
    return dies


def _plot(rows: list[dict[str, object]], methods: list[str], dies: list[str], path: Path) -> None:
    import matplotlib
    import matplotlib.ticker

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(min(18.0, max(8.0, 2.0 + 0.1 * len(dies) * len(methods))), 5.0))
    width = 0.8 / len(methods)
    for k, method in enumerate(methods):
        medians = per_die_medians(rows, method)
        values = [medians[d][1] if d in medians else np.nan for d in dies]
        ax.bar(np.arange(len(dies)) + k * width, values, width, label=method)
    ax.set_yscale("log")
    ax.yaxis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda value, _: f"{value:g}"))
    ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.grid(axis="y", which="major", alpha=0.3)
    ax.set_xticks(np.arange(len(dies)) + 0.4 - width / 2, dies, rotation=90, fontsize=7)
    ax.set_ylabel("median SRE × 1000 (log)")
    ax.set_title("Registration error per die (lower is better)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
