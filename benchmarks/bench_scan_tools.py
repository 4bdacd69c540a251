"""Time the scan tools on a synthetic ~200k-point coin face: read, info, render, preprocess.

    .venv/bin/python benchmarks/bench_scan_tools.py [--points 200000] [--repeats 3] [--blas-threads 1]

Prints one table (median of the repeats; no pass/fail). The library calls run in this process; the
``coindie ...`` rows are whole commands (interpreter start and imports included), as a user sees them.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from threadpoolctl import threadpool_limits

from coindie.io import read_scan, write_ply
from coindie.preprocess import PreprocessConfig, canonical_frame, height_map, preprocess, summarize_scan
from coindie.render import render_relief, save_render
from coindie.scan import Scan

RADIUS_MM = 10.0


def synthetic_face(n_points: int, seed: int = 0) -> Scan:
    """A domed 20 mm face with random bumps and scanner noise, tilted, with normals (~n_points)."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-RADIUS_MM, RADIUS_MM, (int(n_points * 4 / np.pi), 2))
    xy = xy[np.hypot(xy[:, 0], xy[:, 1]) <= RADIUS_MM]
    centres, heights, sigmas = (
        rng.uniform(-7, 7, (40, 2)),
        rng.uniform(0.05, 0.3, 40),
        rng.uniform(0.2, 1, 40),
    )
    z, gx, gy = -0.004 * (xy**2).sum(axis=1), -0.008 * xy[:, 0], -0.008 * xy[:, 1]
    for (cx, cy), h, s in zip(centres, heights, sigmas, strict=True):
        g = h * np.exp(-((xy[:, 0] - cx) ** 2 + (xy[:, 1] - cy) ** 2) / (2 * s * s))
        z, gx, gy = z + g, gx - g * (xy[:, 0] - cx) / s**2, gy - g * (xy[:, 1] - cy) / s**2
    points = np.column_stack([xy, z + rng.normal(0, 0.003, len(z))])
    normals = np.column_stack([-gx, -gy, np.ones_like(z)])
    tilt = np.radians(8.0)
    R = np.array([[1, 0, 0], [0, np.cos(tilt), -np.sin(tilt)], [0, np.sin(tilt), np.cos(tilt)]])
    return Scan(points=points @ R.T + [3.0, -2.0, 40.0], normals=normals @ R.T, id="L0001D")


def median_seconds(run: Callable[[], object], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def command(*args: str) -> Callable[[], object]:
    executable = Path(sys.executable).with_name("coindie")
    return lambda: subprocess.run([str(executable), *args], check=True, capture_output=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=200_000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--blas-threads", type=int, default=1, help="BLAS threads for the in-process rows")
    options = parser.parse_args()
    scan = synthetic_face(options.points)
    bare = Scan(points=scan.points, id=scan.id)
    with tempfile.TemporaryDirectory() as folder:
        ply = write_ply(Path(folder) / "L0001D.ply", scan)
        png = Path(folder) / "L0001D.png"
        cases = {
            "read_scan (binary PLY)": lambda: read_scan(ply),
            "summarize_scan (info)": lambda: summarize_scan(scan),
            "canonical_frame": lambda: canonical_frame(scan),
            "height_map (0.05 mm)": lambda: height_map(scan),
            "render_relief (800 px)": lambda: render_relief(scan),
            "save_render (800 px PNG)": lambda: save_render(scan, png),
            "preprocess (has normals)": lambda: preprocess(scan),
            "preprocess (estimates normals)": lambda: preprocess(bare),
            "preprocess canonical, no grid": lambda: preprocess(
                scan, PreprocessConfig(orientation="canonical", grid_size_mm=None)
            ),
        }
        with threadpool_limits(limits=options.blas_threads, user_api="blas"):
            rows = [(name, median_seconds(run, options.repeats)) for name, run in cases.items()]
        rows.append(
            ("coindie info (whole command)", median_seconds(command("info", str(ply)), options.repeats))
        )
        rows.append(
            ("coindie render (whole command)", median_seconds(command("render", str(ply), "-o", str(png)), 3))
        )
    threads, repeats = options.blas_threads, options.repeats
    print(f"scan: {scan.n_points:,} points, {ply.name}; BLAS threads {threads}; median of {repeats}")
    print(f"{'step':<34}{'seconds':>9}")
    for name, seconds in rows:
        print(f"{name:<34}{seconds:>9.3f}")


if __name__ == "__main__":
    main()
