"""``coindie register`` (align two scans) and ``coindie methods`` (the registration methods and their
parameters)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from coindie.cli.common import MethodParams, Unit, exits_cleanly, method_params
from coindie.errors import ParameterError

if TYPE_CHECKING:
    from coindie.registration.base import MethodInfo, RegistrationResult
    from coindie.scan import Scan

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()

#: Exit code of ``coindie register`` when the registration ran but its result is not valid.
EXIT_INVALID = 1


@commands.command("register")
@exits_cleanly
def register(
    source: Annotated[Path, typer.Argument(help="Source scan (PLY, STL, OBJ): the one that is moved.")],
    target: Annotated[Path, typer.Argument(help="Target scan: the one the source is aligned onto.")],
    method: Annotated[
        str, typer.Option("--method", "-m", help="Method name (see `coindie methods`).")
    ] = "relief",
    param: MethodParams = None,
    grid: Annotated[
        float, typer.Option(help="Grid-sampling cell (mm) applied to both scans; 0: none.")
    ] = 0.1,
    as_json: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
    unit: Unit = None,
) -> None:
    """Align SOURCE onto TARGET: print T_target_source (4x4, mm) and the figures.

    Exit code 1 when the result is not valid (the reason is printed), 2 on bad input.
    """
    from coindie.registration import method_info

    registrar = method_info(method).build(method_params(method, param))  # checked before any file is read
    source_scan, target_scan = _prepared(source, grid, unit), _prepared(target, grid, unit)
    result = registrar.register(source_scan, target_scan)
    if as_json:
        typer.echo(json.dumps(_json(result, source_scan, target_scan), indent=2))
    else:
        typer.echo(_text(result, source_scan, target_scan))
    if not result.valid:
        raise typer.Exit(code=EXIT_INVALID)


def _prepared(path: Path, grid: float, unit: str | None) -> Scan:
    from coindie.io.reader import read_scan
    from coindie.preprocess.sampling import grid_sample

    if grid < 0:
        raise ParameterError(f"--grid must be >= 0 mm (0: no grid sampling). Got {grid}.")
    scan = read_scan(path, unit=unit)
    return grid_sample(scan, grid) if grid > 0 else scan


def _json(result: RegistrationResult, source: Scan, target: Scan) -> dict[str, Any]:
    return {
        "source": {"path": str(source.path), "id": str(source.id), "n_points": source.n_points},
        "target": {"path": str(target.path), "id": str(target.id), "n_points": target.n_points},
        **result.to_dict(),
    }


def _text(result: RegistrationResult, source: Scan, target: Scan) -> str:
    rows = "\n".join("  " + " ".join(f"{x:+12.6f}" for x in row) for row in result.T_target_source)
    status = "yes" if result.valid else f"NO: {result.reason}"
    timings = ", ".join(f"{stage} {seconds:.2f} s" for stage, seconds in result.timings.items())
    lines = [
        f"{result.method}: {source.id} ({source.n_points} points) -> {target.id} ({target.n_points} points)",
        f"valid            {status}",
        "T_target_source (mm)",
        rows,
        f"fitness          {result.fitness:.3f}",
        f"residual         {result.residual:.4f} mm (median point-to-plane)",
        f"inlier RMSE      {result.inlier_rmse:.4f} mm",
        f"correspondences  {result.n_correspondences} ({result.n_inliers} inliers)",
        f"timings          {timings}",
        *(f"note             {note}" for note in result.notes),
    ]
    return "\n".join(lines)


@commands.command("methods")
@exits_cleanly
def methods(
    name: Annotated[str | None, typer.Argument(help="Show only this method.")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print as JSON.")] = False,
) -> None:
    """List the registration methods with their parameters (defaults, accepted values, units)."""
    from coindie.registration import list_methods, method_info

    infos = [method_info(name)] if name else [method_info(n) for n in list_methods()]
    if as_json:
        typer.echo(json.dumps([_method_json(info) for info in infos], indent=2))
        return
    typer.echo("\n\n".join(_method_text(info) for info in infos))


def _method_json(info: MethodInfo) -> dict[str, Any]:
    params = {
        key: {"default": p.default, "accepts": p.describe(), "unit": p.unit, "doc": p.doc}
        for key, p in info.params().items()
    }
    return {"name": info.name, "summary": info.summary, "params": params}


def _method_text(info: MethodInfo) -> str:
    lines = [f"{info.name}: {info.summary}"]
    for key, p in info.params().items():
        lines.append(f"  {key:<26} = {p.default!r:<10} {p.doc}; {p.describe()}")
    return "\n".join(lines)
