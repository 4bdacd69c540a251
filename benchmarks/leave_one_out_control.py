"""The control of `coindie bench generalization --leave-one-out`: models trained like the held-out ones, on
hoards of the whole wide world (no axis held at its middle), judged on the same all-hard row.

    .venv/bin/python benchmarks/leave_one_out_control.py OUT --seeds 3014,3015,3016

OUT is the leave-one-out folder, holding the all-hard row's project and hoard (``OUT/projects/hard``,
``OUT/hoards/hard``). Each seed's training hoard is a ``study`` hoard at ``--scale`` (0.5: 40 faces, as
``--training-scale``'s default), made and registered under ``OUT/control``. A held-out model whose FMI
or AUC on the all-hard row falls below these controls' lost something by not seeing its axis's extremes;
one within their spread lost only what any training hoard that small loses against the shipped model.
No pass/fail.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from coindie.bench.generalization import evaluate_row, row_project
from coindie.bench.leave_one_out import ALL_HARD, train_on_project
from coindie.project import open_project
from coindie.similarity.scorers import default_scorer
from coindie.synth.hoard import synthesize
from coindie.synth.physics import physics_by_name


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", type=Path, help="the --leave-one-out folder")
    parser.add_argument("--seeds", default="3014,3015,3016", help="comma-separated seeds of the hoards")
    parser.add_argument("--scale", type=float, default=0.5, help="scale of each study hoard")
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args()
    try:
        seeds = [int(s) for s in args.seeds.split(",") if s.strip()]
    except ValueError:
        parser.error(f"--seeds: comma-separated integers, not {args.seeds!r}")
    if not seeds:
        parser.error("--seeds: give at least one seed")
    folder = args.out / "projects" / ALL_HARD
    if not (folder / "project.sqlite").exists():
        raise SystemExit(
            f"{folder}: no project of the all-hard row (coindie bench generalization --rows hard)"
        )
    hard, hard_hoard = open_project(folder), args.out / "hoards" / ALL_HARD
    shipped = default_scorer("relief")
    print("| training hoard | training pairs (same-die) | FMI on the all-hard row | AUC |")
    print("|---|---|---|---|")
    for seed in seeds:
        hoard = args.out / "control" / "hoards" / f"wide-{seed}"
        synthesize(hoard, preset="study", scale=args.scale, physics=physics_by_name("wide"), seed=seed,
                   workers=args.workers)  # fmt: skip
        project = row_project(
            args.out / "control" / "projects" / f"wide-{seed}", hoard, args.workers, histograms=False
        )
        model, n_pairs, n_same = train_on_project(project, hoard, like=shipped)
        r = evaluate_row(ALL_HARD, "relief", model, hard, hard_hoard)
        print(f"| wide, seed {seed} | {n_pairs} ({n_same}) | {r.fmi:.3f} | {r.auc:.3f} |", flush=True)


if __name__ == "__main__":
    main()
