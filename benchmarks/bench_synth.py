"""Time hoard generation: planning the full ``riedones`` preset, and generating a hoard.

    .venv/bin/python benchmarks/bench_synth.py [--preset riedones] [--scale 0.1] [--workers 2]
        [--spacing 0.05] [--seed 0] [--out DIR]

Prints one table (no pass/fail): planning time of the full preset, generation time of the chosen hoard,
seconds per face, and the time the full ``riedones`` preset would take at that rate (an extrapolation
from the measured hoard, which starts workers and builds dies like the full run but fewer of them).
Run with ``--scale 1`` to measure the full preset itself (about 2,070 PLYs, 8-9 GB at 0.05 mm).
"""

from __future__ import annotations

import argparse
import os
import shutil
import tempfile
import time
from pathlib import Path

from coindie.synth import get_preset, plan_hoard
from coindie.synth.hoard import PhysicsParams, synthesize
from coindie.synth.scanner import ScanParams

FULL_FACES = 2070


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--preset", default="riedones")
    parser.add_argument("--scale", type=float, default=0.1)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--spacing", type=float, default=0.05)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, default=None, help="keep the hoard here (default: a temp dir)")
    args = parser.parse_args()

    started = time.perf_counter()
    plan_hoard(get_preset("riedones"), args.seed)
    planning = time.perf_counter() - started

    out = args.out or Path(tempfile.mkdtemp(prefix="bench_synth_"))
    physics = PhysicsParams(scan=ScanParams(spacing_mm=args.spacing))
    try:
        report = synthesize(
            out, preset=args.preset, scale=args.scale, seed=args.seed, physics=physics, workers=args.workers
        )
        size_mb = sum(p.stat().st_size for p in out.glob("*.ply")) / 2**20
    finally:
        if args.out is None:
            shutil.rmtree(out, ignore_errors=True)
    per_face = report.seconds / max(report.n_made, 1)
    rows = [
        ("machine", f"{os.cpu_count()} cores, load {os.getloadavg()[0]:.2f}"),
        ("plan riedones (2,070 faces)", f"{planning:.3f} s"),
        (f"generate {args.preset} x{args.scale} ({report.n_made} faces)", f"{report.seconds:.1f} s"),
        ("workers / spacing", f"{args.workers} / {args.spacing} mm"),
        ("seconds per face (wall)", f"{per_face:.3f} s"),
        ("PLY size per face", f"{size_mb / max(report.n_faces, 1):.2f} MiB"),
        ("full riedones at this rate", f"{per_face * FULL_FACES / 60:.1f} min (extrapolated)"),
    ]
    width = max(len(name) for name, _ in rows)
    for name, value in rows:
        print(f"{name:<{width}}  {value}")


if __name__ == "__main__":
    main()
