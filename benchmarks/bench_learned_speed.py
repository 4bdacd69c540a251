"""Feature extraction speed of the learned descriptors per coin face, on the CPU (and on CUDA if present).

    .venv/bin/python benchmarks/bench_learned_speed.py HOARD [--faces 10] [--threads 1]

Faces of the registration test split, grid-sampled at 0.1 mm as the benchmark gives them. For each face:
FCGF's descriptors of every voxel as a source (one pass of the sparse U-Net) and as a target (one pass per
turn its model searches: ``spins`` views), and DIP's descriptors of 5000 random points (5000 patches
through the PointNet), with the shipped weights (a method without shipped weights is
listed as such; ``--fcgf-weights FILE`` times FCGF with any model file, trained or not: the cost does not
depend on the weights). Prints the median seconds per face and the points per face (no pass/fail).
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np
import torch
from rich.progress import track

from coindie.bench.registration import _grid_scan
from coindie.io.truth import load_truth
from coindie.registration.clouds import Cloud
from coindie.registration.learned.dip import DIPDescriptor
from coindie.registration.learned.fcgf import FCGFDescriptor


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("hoard", type=Path)
    parser.add_argument("--faces", type=int, default=10)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--fcgf-weights", default="", help="an FCGF model file (default: the shipped one)")
    args = parser.parse_args()
    torch.set_num_threads(args.threads)

    truth = load_truth(args.hoard)
    faces = truth.faces_in("registration_test")[: args.faces]
    clouds = [Cloud.of(_grid_scan(str(f.path))) for f in track(faces, description="reading")]
    devices = ["cpu"] + (["cuda"] if torch.cuda.is_available() else [])
    print("| device | descriptor | median s per face | points per face | faces | threads |")
    print("| --- | --- | ---: | ---: | ---: | ---: |")
    for device in devices:
        extractors = {
            "FCGF (every voxel)": FCGFDescriptor(
                weights=args.fcgf_weights, device=device, threads=args.threads
            ),
            "DIP (5000 points)": DIPDescriptor(),
        }
        fcgf = extractors["FCGF (every voxel)"]
        if fcgf.weights_path.is_file() and fcgf.model().config.spins > 1:
            extractors[f"FCGF (every voxel, {fcgf.model().config.spins} views)"] = fcgf
        if device == "cuda":
            extractors.pop("DIP (5000 points)")  # DIP runs on the CPU here
        if not extractors["FCGF (every voxel)"].weights_path.is_file():
            print(f"| {device} | FCGF | no shipped weights | | | |")
            extractors.pop("FCGF (every voxel)")
        for label, extractor in extractors.items():
            seconds, sizes = [], []
            for cloud in track(clouds, description=f"{label} on {device}"):
                support = extractor.support(cloud)
                n = len(support.points)
                at = (
                    np.arange(n)
                    if label.startswith("FCGF")
                    else np.sort(np.random.default_rng(0).choice(n, min(n, 5000), replace=False))
                )
                start = time.perf_counter()
                # Each face is new to the descriptor cache.
                if "views" in label:
                    extractor.describe_views(support, at)
                else:
                    extractor.describe(support, at)
                seconds.append(time.perf_counter() - start)
                sizes.append(len(at))
            print(
                f"| {device} | {label} | {statistics.median(seconds):.3f} | {int(statistics.median(sizes))} "
                f"| {len(clouds)} | {args.threads} |"
            )


if __name__ == "__main__":
    main()
