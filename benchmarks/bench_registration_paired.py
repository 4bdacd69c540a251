"""Time a registration method per pair against another commit of coindie, pair by pair in one process.

    git worktree add /tmp/base 149e3ad
    .venv/bin/python benchmarks/bench_registration_paired.py /tmp/base HOARD [--method relief] [--pairs 60]
    git worktree remove /tmp/base

A shared machine's speed drifts by a fifth over a minute, more than most changes worth timing; two runs
of ``bench_registration_speed.py`` one after the other compare the drift as much as the code. Here both
versions register each pair in turn (which goes first alternates), in the three situations of
``bench_registration_speed.py``, so that each pair's difference is measured under the same conditions;
the table gives the median of those differences beside each version's median time. The other commit's
package is copied and imported under another name (``coindie_base``). Same pairs and turns as
``coindie bench registration``; BLAS held to one thread; no pass/fail.

``--study N`` times a die study instead: every pair of the first N faces of each side, as the scans lie,
in the order a project's batch runs them (by source, then target), one method per version kept for the
whole study as a worker keeps it (its caches warm as they would be). Most of these pairs are of
different dies, which the same-die pairs above leave out; this is the time per pair a user meets.
"""

from __future__ import annotations

import argparse
import importlib
import inspect
import re
import shutil
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType

import numpy as np
from rich.progress import track
from threadpoolctl import threadpool_limits

import coindie.registration
from coindie.bench.registration import SITUATIONS, _grid_scan, parse_method, plan_pairs, timed_in_situation
from coindie.io.truth import load_truth
from coindie.registration.clouds import freeze
from coindie.registration.learned.cache import clear_caches
from coindie.scan import Scan


def import_base(checkout: Path, into: Path) -> ModuleType:
    """The ``coindie`` package of another checkout, importable as ``coindie_base`` (its own imports
    renamed), for the length of this process."""
    source = checkout / "src" / "coindie"
    if not (source / "__init__.py").is_file():
        raise SystemExit(f"{checkout}: no src/coindie package (give a checkout, e.g. a git worktree)")
    package = into / "coindie_base"
    shutil.copytree(source, package, ignore=shutil.ignore_patterns("__pycache__"))
    pattern = re.compile(r"\b(from|import) coindie\b")
    for path in package.rglob("*.py"):
        path.write_text(pattern.sub(r"\1 coindie_base", path.read_text()))
    sys.path.insert(0, str(into))
    importlib.invalidate_caches()
    return importlib.import_module("coindie_base.registration")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("base", type=Path, help="a checkout of the commit to compare with")
    parser.add_argument("hoard", type=Path)
    parser.add_argument("--method", default="relief", help="a method, or a benchmark label")
    parser.add_argument("--pairs", type=int, default=60)
    parser.add_argument("--study", type=int, default=0, help="time all pairs of N faces a side instead")
    args = parser.parse_args()
    if args.study == 1 or args.study < 0:
        parser.error(f"--study needs at least 2 faces a side (0: time same-die pairs). Got {args.study}.")
    name, params = parse_method(args.method)
    if args.study:
        time_study(args.base, args.hoard, name, params, args.study)
        return
    with tempfile.TemporaryDirectory() as folder:
        base = import_base(args.base, Path(folder))
        base_scan = importlib.import_module("coindie_base.scan").Scan
        truth = load_truth(args.hoard)
        pairs = plan_pairs(truth, max_pairs=args.pairs)
        clouds = [
            (_grid_scan(str(truth.faces[a].path)).transformed(T_turn), _grid_scan(str(truth.faces[b].path)))
            for _, a, b, T_turn in track(pairs, description="reading")
        ]
        versions = {
            "base": (base, [tuple(base_scan(points=s.points, normals=s.normals) for s in p) for p in clouds]),
            "this": (coindie.registration, clouds),
        }
        seconds: dict[tuple[str, str], list[float]] = {(v, s): [] for v in versions for s in SITUATIONS}
        stages: dict[tuple[str, str], dict[str, list[float]]] = {
            (v, s): {} for v in versions for s in SITUATIONS
        }
        poses: dict[str, list[np.ndarray | None]] = {v: [] for v in versions}
        with threadpool_limits(limits=1):
            for k in track(range(len(clouds)), description="pairs"):
                order = ("base", "this") if k % 2 == 0 else ("this", "base")
                for situation in SITUATIONS:
                    for version in order:
                        package, scans = versions[version]
                        source, target = scans[k]
                        method = package.get_method(name, **params)  # a fresh method: nothing cached
                        clear_caches()
                        spent, result = timed_in_situation(situation, method, source, target)
                        seconds[version, situation].append(spent)
                        for stage, value in result.timings.items():
                            stages[version, situation].setdefault(stage, []).append(value)
                        if situation == SITUATIONS[-1]:
                            poses[version].append(result.T_target_source)
    print(f"\n{args.method}: seconds per pair over {len(clouds)} pairs, one core; base = {args.base}\n")
    print("| situation | base | this | difference (median of pairs) | pairs faster |")
    print("|---|---:|---:|---:|---:|")
    for situation in SITUATIONS:
        old, new = np.array(seconds["base", situation]), np.array(seconds["this", situation])
        print(
            f"| {situation} | {np.median(old):.4f} | {np.median(new):.4f} | {np.median(new - old):+.4f} "
            f"| {np.mean(new < old):.0%} |"
        )
    print_pose_differences(poses["base"], poses["this"])
    names = [k for k in stages["this", SITUATIONS[0]] if k != "total"]
    print("\nStage medians (s): base / this\n")
    print("| situation | " + " | ".join(names) + " |")
    print("|---|" + "---:|" * len(names))
    for situation in SITUATIONS:
        cells = []
        for stage in names:
            old_stage = np.median(stages["base", situation].get(stage, [np.nan]))
            new_stage = np.median(stages["this", situation].get(stage, [np.nan]))
            cells.append(f"{old_stage:.4f} / {new_stage:.4f}")
        print(f"| {situation} | " + " | ".join(cells) + " |")


def time_study(checkout: Path, hoard: Path, name: str, params: dict[str, object], n_faces: int) -> None:
    """Both versions register every pair of ``n_faces`` faces a side, pair by pair in turn."""
    import itertools

    with tempfile.TemporaryDirectory() as folder:
        base = import_base(checkout, Path(folder))
        base_scan = importlib.import_module("coindie_base.scan").Scan
        truth = load_truth(hoard)
        pairs = []
        for side in sorted({face_id[-1] for face_id in truth.faces}):  # L0001D: obverse
            faces = sorted(f for f in truth.faces if f[-1] == side)[:n_faces]
            pairs += [
                (a, b, truth.faces[a].die == truth.faces[b].die) for a, b in itertools.combinations(faces, 2)
            ]
        scans = {f: _grid_scan(str(truth.faces[f].path)) for f in track(truth.faces, description="reading")}
        base_scans = {f: base_scan(points=s.points, normals=s.normals) for f, s in scans.items()}
        # this version's worker freezes the faces it loads (read-only arrays: their digests are kept)
        scans = {f: freeze(Scan(points=s.points.copy(), normals=s.normals.copy())) for f, s in scans.items()}
        # every face of the study stays cached, as a project's worker sizes its caches for a batch
        size = 2 * n_faces + 2
        if "cloud_cache_size" in inspect.signature(base.get_method).parameters:
            base_method = base.get_method(name, cloud_cache_size=size, **params)
        else:  # older versions: a module-wide size, which their workers widened
            importlib.import_module("coindie_base.registration.base").CLOUD_CACHE_SIZE = size
            base_method = base.get_method(name, **params)
        versions = {
            "base": (base_method, base_scans),
            "this": (coindie.registration.get_method(name, cloud_cache_size=size, **params), scans),
        }
        seconds: dict[str, list[float]] = {v: [] for v in versions}
        poses: dict[str, list[np.ndarray | None]] = {v: [] for v in versions}
        with threadpool_limits(limits=1):
            for k, (a, b, _) in enumerate(track(pairs, description="pairs")):
                for version in ("base", "this") if k % 2 == 0 else ("this", "base"):
                    method, faces = versions[version]
                    start = time.perf_counter()
                    result = method.register(faces[a], faces[b])
                    seconds[version].append(time.perf_counter() - start)
                    poses[version].append(result.T_target_source)
    same_die = np.array([same for _, _, same in pairs])
    print(f"\n{name}: a study of {n_faces} faces a side, {len(pairs)} pairs, one core; base = {checkout}\n")
    print("| pairs | base (s) | this (s) | difference (median of pairs) | pairs faster |")
    print("|---|---:|---:|---:|---:|")
    for label, chosen in (
        ("all", np.ones_like(same_die)),
        ("same die", same_die),
        ("different dies", ~same_die),
    ):
        old, new = np.array(seconds["base"])[chosen], np.array(seconds["this"])[chosen]
        print(
            f"| {label} ({chosen.sum()}) | {np.mean(old):.4f} mean, {np.median(old):.4f} median "
            f"| {np.mean(new):.4f} mean, {np.median(new):.4f} median | {np.median(new - old):+.4f} "
            f"| {np.mean(new < old):.0%} |"
        )
    print_pose_differences(poses["base"], poses["this"])


def print_pose_differences(base: list[np.ndarray | None], this: list[np.ndarray | None]) -> None:
    """How far the two versions' poses are apart (the last situation's): a change meant to be only faster
    should leave them equal up to rounding."""
    from coindie.registration import rotation_error_deg, translation_error_mm

    both = [(a, b) for a, b in zip(base, this, strict=True) if a is not None and b is not None]
    rotation = np.array([rotation_error_deg(a, b) for a, b in both])
    translation = np.array([translation_error_mm(a, b) for a, b in both])
    same = sum(float(np.abs(a - b).max()) < 1e-9 for a, b in both)
    print(
        f"\nPoses: {same} of {len(base)} pairs the same (matrices within 1e-9), {len(base) - len(both)} "
        f"refused by either; largest difference {rotation.max(initial=0):.2e}° and "
        f"{translation.max(initial=0):.2e} mm"
    )


if __name__ == "__main__":
    main()
