"""Commands that look at one scan: ``coindie info`` and ``coindie render``.

Both must answer in well under a second on a 200k-point scan, so each imports only what it uses.
"""

from __future__ import annotations

from contextlib import AbstractContextManager
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Literal

import typer

from coindie.cli.common import Unit, exits_cleanly

if TYPE_CHECKING:
    from coindie.preprocess.summary import ScanSummary

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()

ScanArgument = Annotated[
    Path, typer.Argument(help="A scan file (.ply point cloud or mesh, .stl, .obj).", show_default=False)
]


@commands.command()
@exits_cleanly
def info(
    scan: ScanArgument,
    json: Annotated[bool, typer.Option("--json", help="Print the facts as one JSON object.")] = False,
    unit: Unit = None,
) -> None:
    """Points, extent, diameter, spacing, normals and colours of a scan (lengths in mm)."""
    from coindie.io import read_scan
    from coindie.preprocess.summary import summarize_scan

    with _one_blas_thread():
        summary = summarize_scan(read_scan(scan, unit=unit))
    if json:
        import json as json_module

        typer.echo(json_module.dumps(summary.to_dict()))
    else:
        typer.echo(_as_text(summary))


@commands.command()
@exits_cleanly
def render(
    scan: ScanArgument,
    output: Annotated[
        Path | None,
        typer.Option("--output", "-o", help="PNG to write. Default: the scan's name + .png here."),
    ] = None,
    width: Annotated[int, typer.Option("--width", min=16, max=8192, help="Image width (pixels).")] = 800,
    azimuth: Annotated[
        float, typer.Option("--azimuth", help="Light direction, degrees clockwise from up (315: upper left).")
    ] = 315.0,
    altitude: Annotated[
        float, typer.Option("--altitude", min=1.0, max=90.0, help="Light height above the face (degrees).")
    ] = 45.0,
    tone: Annotated[Literal["bronze", "grey"], typer.Option("--tone", help="Colour ramp.")] = "bronze",
    unit: Unit = None,
) -> None:
    """A shaded relief image of the face, lit from the upper left like a coin photograph."""
    from coindie.io import read_scan
    from coindie.render import save_render

    path = output if output is not None else Path(f"{scan.stem}.png")
    options = {"width_px": width, "light_azimuth_deg": azimuth, "light_altitude_deg": altitude, "tone": tone}
    with _one_blas_thread():
        typer.echo(save_render(read_scan(scan, unit=unit), path, **options))


def _one_blas_thread() -> AbstractContextManager[object]:
    """Limit BLAS to one thread: these commands only multiply (N, 3) by 3x3 matrices, which OpenBLAS
    threads slow down 10-50x when the cores are busy (measured: 65 ms instead of 1.3 ms for 230k points).
    """
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1, user_api="blas")


def _as_text(summary: ScanSummary) -> str:
    x, y, z = summary.extent_mm
    size = "?" if summary.file_size_bytes is None else f"{summary.file_size_bytes / 2**20:.1f} MiB"
    rows = [
        ("id", f"{summary.id} ({summary.face})"),
        ("file", f"{summary.path} ({size})"),
        ("points", f"{summary.points:,}"),
        ("normals", "yes" if summary.has_normals else "no"),
        ("colours", "yes" if summary.has_colors else "no"),
        ("extent", f"x {x:.2f}  y {y:.2f}  z {z:.2f} mm"),
        ("diameter", f"{summary.diameter_mm:.2f} mm"),
        ("spacing", f"{summary.spacing_mm:.4f} mm (median nearest-neighbour distance)"),
    ]
    return "\n".join(f"{name:<10}{value}" for name, value in rows)
