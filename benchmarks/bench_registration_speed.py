"""Time one registration method per pair in the three situations a die study meets, on one core.

    .venv/bin/python benchmarks/bench_registration_speed.py HOARD [--method relief] [--pairs 60]

- *cold*: both faces are new to the method (nothing cached);
- *new source*: the target was seen before (the benchmark's situation: each source is turned for its pair);
- *all-pairs*: both faces were seen before (a die study registers every face against all others, so the
  per-face work is paid once per face and each pair costs only this).

Same-die pairs of the registration test split, turned as in ``coindie bench registration``; BLAS is held to
one thread. Prints a table of the median seconds per pair and the stage timings (no pass/fail). What a
process keeps whatever the faces (``relief``'s turn operators, one per image size; FFT plans) stays
from one pair to the next, as in a study. To compare two commits on a shared machine, whose speed drifts
between runs, use ``bench_registration_paired.py``.
"""

from __future__ import annotations

import argparse
import statistics
from pathlib import Path

import numpy as np
from rich.progress import track
from threadpoolctl import threadpool_limits

from coindie.bench.registration import SITUATIONS, _grid_scan, parse_method, plan_pairs, timed_in_situation
from coindie.io.truth import load_truth
from coindie.registration import get_method
from coindie.registration.learned.cache import clear_caches


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("hoard", type=Path)
    parser.add_argument(
        "--method", default="relief", help="a method, or a benchmark label: fcgf+icp[matcher.n_points=250]"
    )
    parser.add_argument("--pairs", type=int, default=60)
    args = parser.parse_args()
    name, params = parse_method(args.method)

    truth = load_truth(args.hoard)
    pairs = plan_pairs(truth, max_pairs=args.pairs)
    clouds = [
        (_grid_scan(str(truth.faces[a].path)).transformed(T_turn), _grid_scan(str(truth.faces[b].path)))
        for _, a, b, T_turn in track(pairs, description="reading")
    ]
    rows = []
    with threadpool_limits(limits=1):
        for situation in SITUATIONS:
            times, stages = [], {}
            for source, target in track(clouds, description=situation):
                method = get_method(name, **params)  # a fresh method: nothing cached
                clear_caches()  # nor kept by the learned descriptors from an earlier pair
                seconds, result = timed_in_situation(situation, method, source, target)
                times.append(seconds)
                for stage, seconds in result.timings.items():
                    stages.setdefault(stage, []).append(seconds)
            medians = {k: float(np.median(v)) for k, v in stages.items()}
            rows.append((situation, statistics.median(times), medians))
    print(f"\n{args.method}: median seconds per pair over {len(clouds)} pairs, one core\n")
    print("| situation | s per pair | " + " | ".join(k for k in rows[0][2] if k != "total") + " |")
    print("|---|---:|" + "---:|" * (len(rows[0][2]) - 1))
    for situation, median, stages in rows:
        cells = " | ".join(f"{v:.4f}" for k, v in stages.items() if k != "total")
        print(f"| {situation} | {median:.4f} | {cells} |")


if __name__ == "__main__":
    main()
