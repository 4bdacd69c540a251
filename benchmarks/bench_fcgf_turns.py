"""How much turn about the coin's axis FCGF can learn to ignore on a CPU: short trainings, one per tolerance.

    .venv/bin/python benchmarks/bench_fcgf_turns.py HOARD --out DIR [--epochs 2] [--pairs 250]

Each run trains a fresh FCGF (16-32-64-128, the paper's loss, SGD and augmentation, 4 mm crops) for
``epochs x pairs`` steps through ``coindie.registration.learned.train``, with the two faces of each training
pair turned alike within ±180°/spins (``FCGFConfig.spins``), and measures after each epoch the held-out
inlier ratio (mutual nearest neighbours of 2000 random points per face, within 0.3 mm of the truth) on
held-out pairs turned within the same tolerance. ``paper``: the paper's recipe (faces turned apart by up to
±180°, tilted apart by up to ±25°, no levelling). Writes ``turns.md`` (the table) and ``turns.png`` into DIR.
Nothing passes or fails: it measures why coindie's FCGF searches turns instead of learning them.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from rich.progress import Progress  # noqa: E402

from coindie.bench.machine import describe_machine  # noqa: E402
from coindie.registration.learned.fcgf import FCGFConfig  # noqa: E402
from coindie.registration.learned.train import TrainOptions, train_fcgf  # noqa: E402

#: (label, level, spins): the tolerance is ±180°/spins.
RUNS = (
    ("paper: ±180°, tilts ±25°, not levelled", False, 1),
    ("levelled, ±180°", True, 1),
    ("levelled, ±45°", True, 4),
    ("levelled, ±11.25° (the shipped model's)", True, 16),
    ("levelled, ±1° (turned alike)", True, 180),
)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("hoard", type=Path)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--epochs", type=int, default=2)
    parser.add_argument("--pairs", type=int, default=250, help="training pairs (steps) per epoch")
    parser.add_argument("--val-pairs", type=int, default=4)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    results: dict[str, list[float]] = {}
    with Progress() as progress:
        for label, level, spins in RUNS:
            task = progress.add_task(label, total=None)
            options = TrainOptions(
                model=FCGFConfig(level=level, spins=spins),
                epochs=args.epochs,
                max_pairs=args.pairs,
                max_val_pairs=args.val_pairs,
                fmr_points=2000,
                crop_radius=4.0,
                threads=args.threads,
            )
            run = args.out / f"spins{spins}{'-level' if level else ''}"

            def advance(done: int, total: int, task=task) -> None:
                progress.update(task, advance=done, total=total or None)

            log = train_fcgf(
                args.hoard, run, options, resume=(run / "checkpoint.safetensors").is_file(), progress=advance
            )
            results[label] = [r["val"]["inlier_ratio"] for r in log]

    steps = [args.pairs * (e + 1) for e in range(args.epochs)]
    lines = [
        f"FCGF trained {args.epochs} x {args.pairs} steps per run; held-out inlier ratio after each epoch "
        f"({args.val_pairs} pairs of unseen dies), {args.threads} torch threads. {describe_machine(1)}",
        "",
        "| faces of a pair turned apart by | " + " | ".join(f"{s} steps" for s in steps) + " |",
        "| --- | " + " | ".join("---:" for _ in steps) + " |",
    ]
    lines += [
        f"| {label} | " + " | ".join(f"{r:.1%}" for r in ratios) + " |" for label, ratios in results.items()
    ]
    (args.out / "turns.md").write_text("\n".join(lines) + "\n")
    (args.out / "turns.json").write_text(json.dumps({"steps": steps, "inlier_ratio": results}, indent=1))
    figure, axis = plt.subplots(figsize=(7, 4))
    for label, ratios in results.items():
        axis.plot(steps, ratios, "o-", label=label)
    axis.set(
        xlabel="training steps (pairs)", ylabel="held-out inlier ratio (0.3 mm)", title="What FCGF learns"
    )
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(args.out / "turns.png", dpi=100)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
