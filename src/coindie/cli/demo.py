"""``coindie demo``: the main job on the embedded default — a synthetic hoard, local processes.

It generates a small hoard with the ``riedones`` preset (scaled down), loads it as a dataset, renders a few
faces, and runs the paper's registration benchmark with our ``relief`` method on the registration test
split, printing SRE per family. Clustering and its evaluation join when the similarity stage exists.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from coindie.cli.app import app, exits_cleanly
from coindie.errors import ParameterError
from coindie.ids import FaceId


@app.command()
@exits_cleanly
def demo(
    out: Annotated[
        Path, typer.Argument(help="Folder for the hoard, renders and results (reused if present).")
    ],
    scale: Annotated[
        float, typer.Option(help="Share of the riedones preset to generate (0 < S <= 1).")
    ] = 0.05,
    seed: Annotated[int, typer.Option(help="Seed of the hoard.")] = 0,
    workers: Annotated[int, typer.Option(help="Worker processes (default: the cores, at most 4).")] = 0,
    methods: Annotated[
        str, typer.Option(help="Registration methods to benchmark (comma-separated).")
    ] = "relief",
) -> None:
    """Generate a synthetic hoard, load it, render faces, register every same-die pair, print SRE."""
    from rich.console import Console
    from rich.markdown import Markdown

    from coindie.bench.registration import benchmark_registration
    from coindie.cli.progress import counting_progress
    from coindie.io import open_dataset
    from coindie.preprocess.pipeline import preprocess
    from coindie.render import save_render
    from coindie.synth.hoard import synthesize

    if not 0 < scale <= 1:
        raise ParameterError(f"--scale must be in (0, 1], got {scale}")
    workers = workers or min(4, os.cpu_count() or 1)
    console = Console()

    console.rule("1. a synthetic hoard (preset riedones)")
    hoard = out / "hoard"
    with counting_progress("faces") as progress:
        report = synthesize(
            hoard, preset="riedones", scale=scale, seed=seed, workers=workers, progress=progress
        )
    console.print(f"{report.n_faces} faces in {hoard} ({report.n_made} made, {report.n_reused} reused)")

    console.rule("2. the hoard as a dataset, preprocessed (orientation, centring, grid 0.1 mm)")
    dataset = open_dataset(hoard)
    labels = dict(dataset.labels.items()) if dataset.labels is not None else {}
    points_in, points_out = [], []
    with counting_progress("scans") as progress:
        progress(0, len(dataset))
        for scan in dataset.iter_scans():
            result = preprocess(scan)
            points_in.append(result.n_input_points)
            points_out.append(len(result.scan.points))
            progress(1, 0)
    console.print(
        f"{len(points_in)} scans read, {len(set(labels.values()))} dies in labels.csv, "
        f"{len(dataset.failures)} unreadable; median {int(np.median(points_in))} points per scan, "
        f"{int(np.median(points_out))} after grid sampling"
    )

    console.rule("3. renders of one die (light from the upper left)")
    renders = out / "renders"
    renders.mkdir(parents=True, exist_ok=True)
    for face_id in _faces_of_one_die(labels, n=3):
        scan = dataset.read(face_id)
        console.print(f"{save_render(scan, renders / f'{face_id}.png')}  ({len(scan.points)} points)")

    console.rule("4. registration benchmark (paper section 4.2) on the registration test split")
    names = [m.strip() for m in methods.split(",") if m.strip()]
    with counting_progress("pairs") as progress:
        summary = benchmark_registration(
            hoard, names, out / "registration", workers=workers, progress=progress
        )
    table = (out / "registration" / "summary.md").read_text().split("\n\nThe paper's")[0]
    console.print(Markdown(table))
    pairs = sum(int(entry["n_pairs"]) for entry in summary.values())
    console.print(f"{pairs} registrations; tables and plot in {out / 'registration'}")


def _faces_of_one_die(labels: Mapping[FaceId, str], n: int) -> list[FaceId]:
    """Up to ``n`` face ids struck by the largest die (the faces one would compare first)."""
    by_die: dict[str, list[FaceId]] = {}
    for face_id, die in sorted(labels.items(), key=lambda item: str(item[0])):
        by_die.setdefault(die, []).append(face_id)
    if not by_die:
        return []
    return max(by_die.values(), key=len)[:n]
