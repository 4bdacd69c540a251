"""``coindie synth``: generate a synthetic hoard (PLYs, labels, splits, exact truth)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import Dask, exits_cleanly
from coindie.errors import ParameterError

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()


@commands.command("synth")
@exits_cleanly
def synth(
    out: Annotated[
        Path,
        typer.Argument(
            help="Folder for the hoard (created; a finished or interrupted run of "
            "the same settings is resumed)."
        ),
    ],
    preset: Annotated[
        str, typer.Option(help="riedones (the real study's counts), study (80 faces, 12 dies) or tiny.")
    ] = "riedones",
    scale: Annotated[float, typer.Option(help="Shrink the preset proportionally (0 < S <= 1).")] = 1.0,
    seed: Annotated[int, typer.Option(help="Seed of the whole hoard.")] = 0,
    workers: Annotated[int, typer.Option(help="Worker processes (the output does not depend on it).")] = 1,
    dask: Dask = None,
    physics: Annotated[
        str,
        typer.Option(
            help="default, wide (every axis of the wide world drawn per hoard), hard (every axis at its "
            "hard end), or AXIS:LEVEL (e.g. noise:high), each followed by any ,AXIS:LEVEL; "
            "see docs/synthetic.md."
        ),
    ] = "default",
    spacing: Annotated[
        float | None,
        typer.Option(
            help="Scanner vertex spacing (mm; default 0.05, or the physics'); sets every scanner's."
        ),
    ] = None,
    overwrite: Annotated[bool, typer.Option(help="Replace a hoard of other settings found in OUT.")] = False,
    quiet: Annotated[bool, typer.Option(help="No progress bar.")] = False,
) -> None:
    """Generate a synthetic hoard: one PLY per face, labels.csv, splits.csv, truth.json, hoard.json."""
    from dataclasses import replace

    from coindie.synth.hoard import synthesize
    from coindie.synth.physics import physics_by_name

    if seed < 0:
        raise ParameterError(f"--seed must be >= 0, got {seed}")
    named = physics_by_name(physics)
    params = named.resolve(seed)
    if spacing is not None:
        params = replace(
            params,
            scan=replace(params.scan, spacing_mm=spacing),
            scanners=tuple(replace(s, spacing_mm=spacing) for s in params.scanners),
        )
    with _progress_bar(quiet) as progress:
        report = synthesize(
            out,
            preset=preset,
            scale=scale,
            seed=seed,
            physics=params,
            physics_name=named.name if spacing is None else f"{named.name} (spacing {spacing} mm)",
            workers=workers,
            dask=dask,
            progress=progress,
            overwrite=overwrite,
        )
    typer.echo(
        f"{report.n_faces} faces in {report.out_dir} ({report.n_made} made, {report.n_reused} reused) "
        f"in {report.seconds:.1f} s with {report.workers} worker(s)"
    )


@contextmanager
def _progress_bar(quiet: bool) -> Iterator[Callable[[int, int], None] | None]:
    """The shared progress bar (ETA) as a ``progress(done, total)`` callback; None when quiet."""
    if quiet:
        yield None
        return
    from coindie.cli.progress import counting_progress

    with counting_progress("faces") as update:
        yield update
