"""How often `relief`'s planar search puts same-die pairs in the ICP's reach, per variant, and its cost.

    .venv/bin/python benchmarks/bench_planar_search.py HOARD [HOARD ...] \
        --variants "relief,relief[relief.coarse_step=3],relief[relief.angle_step=10]" [--pairs 50] \
        [--split registration_test]

The planar search (the turn sweep and the masked correlations of
:mod:`coindie.registration.relief_search`) is most of a pair's time and what the hard rows' FMI rests on:
a pair whose planar pose is wrong is lost to the ICP. For the same-die pairs of each hoard's
``cluster_test`` split (``--split``: the hoards of ``benchmarks/outsider_hoards.py`` have
``registration_test`` alone; every face; dies take turns, ``--pairs`` per hoard; the source turned as in
``coindie bench registration``), each variant's planar pose, lifted to 3-D through both canonical frames,
is compared with the truth: *right* is within 5° and 1 mm (the ICP's basin, which the translation of a
wrong turn leaves by millimetres). The table gives the share right, the pairs a variant gets right that
the first gets wrong and the reverse, and the median time of the planar search alone (one core; on a
loaded machine, a guide). Faces are prepared once per variant (canonical frame, relief image), as in a
study. No pass/fail.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np
from rich.progress import track
from threadpoolctl import threadpool_limits

from coindie.bench.registration import _grid_scan, parse_method, plan_pairs
from coindie.io.truth import load_truth
from coindie.registration import get_method, rotation_error_deg, translation_error_mm
from coindie.registration.clouds import Cloud
from coindie.registration.relief import ReliefRegistration

#: The ICP's basin: a planar pose within these of the truth converges (BENCHMARK.md, "Registration on
#: the all-hard mix").
RIGHT_DEG, RIGHT_MM = 5.0, 1.0


def planar_right(
    estimator: ReliefRegistration, source: Cloud, target: Cloud, T_true: np.ndarray
) -> tuple[bool, float]:
    """Whether the planar pose of ``source`` onto ``target`` is within the basin, and its seconds."""
    prepared_source, prepared_target = estimator.prepare(source), estimator.prepare(target)
    start = time.perf_counter()
    _, T = estimator.planar_pose(prepared_source, prepared_target)
    seconds = time.perf_counter() - start
    return rotation_error_deg(T_true, T) < RIGHT_DEG and translation_error_mm(T_true, T) < RIGHT_MM, seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("hoards", type=Path, nargs="+")
    parser.add_argument("--variants", default="relief", help="comma-separated relief labels")
    parser.add_argument("--pairs", type=int, default=50, help="same-die pairs per hoard")
    parser.add_argument(
        "--split",
        default="cluster_test",
        help="the split whose same-die pairs are drawn",
    )
    args = parser.parse_args()
    labels = [label.strip() for label in args.variants.split(",") if label.strip()]
    if not labels:
        raise SystemExit("--variants: give at least one relief label, e.g. relief")
    estimators = {}
    for label in labels:
        name, params = parse_method(label)
        if name != "relief":
            raise SystemExit(f"{label}: the planar search is relief's; give relief variants")
        estimators[label] = get_method(name, **params).estimator
    pairs = []
    for hoard in args.hoards:
        truth = load_truth(hoard)
        for _, a, b, T_turn in plan_pairs(truth, args.split, args.pairs):
            pairs.append((truth, a, b, T_turn))
    right = {label: [] for label in labels}
    seconds = {label: [] for label in labels}
    with threadpool_limits(limits=1):
        for truth, a, b, T_turn in track(pairs, description="pairs"):
            source = Cloud.canonical(_grid_scan(str(truth.faces[a].path)).transformed(T_turn))
            target = Cloud.canonical(_grid_scan(str(truth.faces[b].path)))
            T_true = truth.T_true(a, b) @ np.linalg.inv(T_turn)
            for label, estimator in estimators.items():
                ok, spent = planar_right(estimator, source, target, T_true)
                right[label].append(ok)
                seconds[label].append(spent)
    first = np.array(right[labels[0]])
    basin = f"within {RIGHT_DEG}° and {RIGHT_MM} mm"
    print(f"\n{len(pairs)} same-die pairs of {len(args.hoards)} hoards; right: {basin}\n")
    print(f"| variant | right | gained on {labels[0]} | lost | planar search (ms, median) |")
    print("|---|---:|---:|---:|---:|")
    for label in labels:
        mine = np.array(right[label])
        print(
            f"| {label} | {mine.mean():.3f} ({mine.sum()}/{len(mine)}) | {int((mine & ~first).sum())} | "
            f"{int((~mine & first).sum())} | {1000 * statistics.median(seconds[label]):.1f} |"
        )


if __name__ == "__main__":
    main()
