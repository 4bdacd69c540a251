"""Helpers of the review app's tests: a small scored project built once, and a served process."""

from __future__ import annotations

import fcntl
import os
import shutil
import sqlite3
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

#: The demo hoard's share of the riedones preset: a few dozen faces, exhaustive pairs.
SCALE = 0.02
SRC = Path(__file__).resolve().parents[1] / "src"


def build_project(root: Path) -> Path:
    """``root/project``: a synthetic hoard (riedones preset, scaled down) made a project and run
    exhaustively; built once per machine session (a lock lets pytest-xdist workers share it)."""
    from coindie.project import init_project
    from coindie.project.run import RunConfig, run_project
    from coindie.synth.hoard import synthesize

    root.mkdir(parents=True, exist_ok=True)
    done = root / "built"
    with open(root / "lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not done.exists():
            synthesize(root / "hoard", preset="riedones", scale=SCALE, seed=1, workers=2)
            project, _ = init_project(root / "project", root / "hoard", root / "hoard" / "labels.csv")
            run_project(project, RunConfig(workers=2, mode="exhaustive"), echo=lambda *_: None)
            project.close()
            done.touch()
    return root / "project"


def copy_project(project: Path, to: Path) -> Path:
    """A copy of the project (its database checkpointed first), for tests that write edits."""
    db = sqlite3.connect(project / "project.sqlite")
    db.execute("PRAGMA wal_checkpoint(TRUNCATE)")
    db.close()
    shutil.copytree(project, to, ignore=shutil.ignore_patterns("*-wal", "*-shm"))
    return to


@contextmanager
def served(path: Path, *args: str) -> Iterator[str]:
    """``coindie serve PATH --port 0 --no-browser ARGS`` in a subprocess; yields the URL it prints."""
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    command = [
        sys.executable,
        "-c",
        "from coindie.cli import main; main()",
        "serve",
        str(path),
        "--port",
        "0",
        "--no-browser",
        *args,
    ]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        url = process.stdout.readline().strip() if process.stdout else ""
        if not url.startswith("http://"):
            raise RuntimeError(
                f"coindie serve did not start: {url} {process.stderr.read() if process.stderr else ''}"
            )
        yield url
    finally:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:  # still rendering an image: no need to wait for it
            process.kill()
            process.wait(timeout=10)


def corresponding_pixels(source, target: str, moved: str, n: int = 4) -> tuple[list, list]:  # noqa: ANN001
    """``n`` pixels of ``target``'s own-frame relief image and the pixels of the same points on ``moved``'s,
    found through the pair's stored transform (what an expert's clicks on a well-registered pair give)."""
    import numpy as np

    from coindie.serve import images
    from coindie.transforms import apply

    record = source.pair_record(target, moved)
    grid_t, values_t, _ = images.own_frame(source.scan_paths[target])
    grid_s, _, frame_s = images.own_frame(source.scan_paths[moved])
    rows, cols = np.nonzero(np.isfinite(values_t))
    r0, r1, c0, c1 = rows.min(), rows.max(), cols.min(), cols.max()
    target_pixels = []
    for fr, fc in [(0.3, 0.3), (0.3, 0.7), (0.7, 0.5), (0.6, 0.25), (0.45, 0.6)][:n]:
        target_pixels.append((float(c0 + fc * (c1 - c0)), float(r0 + fr * (r1 - r0))))
    points_t = images.picked_points(source.scan_paths[target], target_pixels)
    points_s = apply(frame_s.T_canonical_scan @ np.linalg.inv(record.T_target_source), points_t)
    source_pixels = [
        (float((x - grid_s.x0) / grid_s.resolution), float((grid_s.y0 - y) / grid_s.resolution))
        for x, y, _ in points_s
    ]
    return target_pixels, source_pixels
