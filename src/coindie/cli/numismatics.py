"""``coindie estimate``, ``coindie dielinks``, ``coindie report`` and ``coindie export dies``: what the
numismatist does with the dies (see docs/numismatics.md)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import exits_cleanly
from coindie.errors import ParameterError

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()

export = typer.Typer(help="Export a project's results (aligned models per die).", no_args_is_help=True)

ThresholdOption = Annotated[
    float | None, typer.Option(help="For a project: links above it join faces (default: the paper's 0.95).")
]
AutoOption = Annotated[
    bool,
    typer.Option(
        "--auto", help="For a project: each side's threshold without labels (as coindie cluster --auto)."
    ),
]
MethodOption = Annotated[
    str, typer.Option(help="For a project: components (the paper's), average or leiden.")
]


def _fmt(value: float | None) -> str:
    if value is None:
        return "-"
    return "inf" if value == float("inf") else f"{value:.1f}"


@commands.command("estimate")
@exits_cleanly
def estimate_command(
    source: Annotated[
        Path, typer.Argument(metavar="CLUSTERS_OR_PROJECT", help="A cluster / label CSV, or a project.")
    ],
    as_json: Annotated[bool, typer.Option("--json", help="Print the estimates as JSON.")] = False,
    confidence: Annotated[float, typer.Option(help="Level of the intervals.")] = 0.95,
    threshold: ThresholdOption = None,
    method: MethodOption = "components",
    auto: AutoOption = False,
) -> None:
    """The original number of dies: n, d, d1, d2, coverage and every estimator with its interval, per side."""
    from rich.console import Console
    from rich.table import Table

    from coindie.numismatics.analysis import side_estimates
    from coindie.numismatics.sources import SIDES, load_dies

    sides = load_dies(source, method=method, threshold=threshold, auto=auto)
    estimates = side_estimates(sides, confidence)
    if as_json:
        typer.echo(json.dumps({SIDES.get(s, s): e.to_dict() for s, e in estimates.items()}))
        return
    console = Console()
    for side, est in estimates.items():
        c, cov = est.counts, est.coverage
        typer.echo(
            f"{SIDES.get(side, 'faces of no known side')} dies of {source}: n = {c.n} coins, d = {c.d} "
            f"dies, d1 = {c.d1}, d2 = {c.d2}; coverage {cov.value:.3f} ({cov.low:.3f}-{cov.high:.3f})"
        )
        table = Table()
        table.add_column("estimator")
        table.add_column("dies", justify="right")
        table.add_column(f"{confidence:.0%} interval", justify="right")
        table.add_column("source / note")
        for e in est.estimators:
            table.add_row(e.name, _fmt(e.value), f"{_fmt(e.low)} - {_fmt(e.high)}", e.note or e.source)
        console.print(table)


@commands.command("dielinks")
@exits_cleanly
def dielinks_command(
    obverse: Annotated[
        Path, typer.Argument(metavar="OBVERSE_CLUSTERS_OR_PROJECT", help="Obverse dies (CSV), or a project.")
    ],
    reverse: Annotated[
        Path | None,
        typer.Argument(metavar="[REVERSE_CLUSTERS]", help="Reverse dies (CSV); not needed with a project."),
    ] = None,
    out: Annotated[
        Path, typer.Option("-o", "--out", help="Folder for the CSV, GraphML, GEXF, SVG, PNG.")
    ] = Path("dielinks"),
    threshold: ThresholdOption = None,
    method: MethodOption = "components",
    auto: AutoOption = False,
    as_json: Annotated[bool, typer.Option("--json", help="Print the summary as JSON.")] = False,
) -> None:
    """The die-link network (obverse die <-> reverse die, weighted by coins), its chains in seriation order,
    the estimates and accumulation curves: written to OUT."""
    from coindie.numismatics.analysis import analyse
    from coindie.numismatics.sources import is_project, load_side

    if reverse is None:
        if not is_project(obverse):
            raise ParameterError("give the obverse and the reverse cluster CSVs, or one project")
        sides = {s: load_side(obverse, s, method=method, threshold=threshold, auto=auto) for s in "DR"}
    else:
        sides = {
            "D": load_side(obverse, "D", method=method, threshold=threshold, auto=auto),
            "R": load_side(reverse, "R", method=method, threshold=threshold, auto=auto),
        }
    result = analyse(sides, out)
    summary = result.links.summary() if result.links else {}
    if as_json:
        typer.echo(json.dumps({"die_links": summary, "files": {k: str(v) for k, v in result.files.items()}}))
        return
    typer.echo(
        f"{summary['obverse_dies']} obverse dies, {summary['reverse_dies']} reverse dies, "
        f"{summary['coins_with_both_faces']} coins with both faces, {summary['combinations']} combinations, "
        f"{summary['chains']} chains (largest: {summary['largest_chain']}); {summary['unlinked_dies']} dies "
        f"without a linked coin"
    )
    for path in result.files.values():
        typer.echo(f"  {path}")


@commands.command("report")
@exits_cleanly
def report_command(
    project: Annotated[Path, typer.Argument(help="A die-study project (coindie init / run).")],
    out: Annotated[Path, typer.Option("-o", "--out", help="The HTML report to write.")] = Path("report.html"),
    pdf: Annotated[
        Path | None, typer.Option("--pdf", help="Also print it to this PDF (headless Chromium).")
    ] = None,
    metadata: Annotated[
        Path | None, typer.Option("--metadata", help="Coin metadata CSV keyed by coin id (any columns).")
    ] = None,
    threshold: ThresholdOption = None,
    method: MethodOption = "components",
    auto: AutoOption = False,
    width_px: Annotated[int, typer.Option(help="Width of each relief on the plates.")] = 240,
) -> None:
    """The die catalogue as a self-contained HTML report (and PDF): per die a plate of its coins' reliefs
    aligned to a reference coin, the singletons, the die links, the estimates, the parameters."""
    from coindie.cli.progress import counting_progress
    from coindie.report import build_report, print_pdf

    with counting_progress("faces") as progress:
        path = build_report(
            project, out, metadata=metadata, threshold=threshold, method=method, auto=auto, width_px=width_px,
            progress=progress,
        )  # fmt: skip
    typer.echo(f"{path}: report written")
    if pdf is not None:
        typer.echo(f"{print_pdf(path, pdf)}: PDF printed by headless Chromium")


@export.command("dies")
@exits_cleanly
def export_dies_command(
    project: Annotated[Path, typer.Argument(help="A die-study project.")],
    out: Annotated[Path, typer.Argument(help="Folder: one sub-folder of aligned PLY models per die.")],
    threshold: ThresholdOption = None,
    method: MethodOption = "components",
    auto: AutoOption = False,
) -> None:
    """Every face of each die, moved into its reference coin's frame (transforms chained along the best
    links), as PLY files: OUT/<side>_<die>/<face>.ply."""
    from coindie.cli.progress import counting_progress
    from coindie.report.alignment import export_aligned_dies

    with counting_progress("faces") as progress:
        written = export_aligned_dies(
            project, out, threshold=threshold, method=method, auto=auto, progress=progress
        )
    typer.echo(f"{out}: {sum(len(v) for v in written.values())} faces of {len(written)} dies written")
