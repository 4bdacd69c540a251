"""``coindie init``, ``coindie run``, ``coindie status``: a die study as a resumable project."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import Dask, MethodParams, Unit, exits_cleanly, method_params
from coindie.project.relay import DEFAULT_NEIGHBOURS, DEFAULT_ROUNDS

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()


@commands.command("init")
@exits_cleanly
def init(
    project: Annotated[
        Path, typer.Argument(help="Project folder (created; an existing one gets the new scans).")
    ],
    scans_dir: Annotated[Path, typer.Argument(help="Folder of scan files (PLY, STL, OBJ).")],
    labels: Annotated[
        Path | None, typer.Option(help="Die labels (coin_id,die_id or name, die), for evaluation only.")
    ] = None,
    unit: Unit = None,
) -> None:
    """Create a project from a folder of scans (files are listed now, read by `coindie run`)."""
    from coindie.project import init_project

    created, report = init_project(project, scans_dir, labels, unit=unit)
    n = len(created.scans())
    declared = created.unit
    typer.echo(
        f"{created.folder}: {n} faces ({len(report.added)} new, {len(report.changed)} changed, "
        f"{report.unchanged} unchanged)"
        + (f", {len(created.labels())} labels" if labels else "")
        + (f", scans in {declared}" if declared else "")
    )
    for skipped in report.skipped:
        typer.echo(f"skipped: {skipped}")


@commands.command("run")
@exits_cleanly
def run(
    project: Annotated[Path, typer.Argument(help="Project folder made by coindie init.")],
    method: Annotated[str, typer.Option(help="Registration method (see coindie methods).")] = "relief",
    param: MethodParams = None,
    workers: Annotated[int, typer.Option(help="Worker processes (0: one per core).")] = 0,
    dask: Dask = None,
    exhaustive: Annotated[bool, typer.Option("--exhaustive", help="Score every pair of each side.")] = False,
    candidates: Annotated[
        int | None, typer.Option(help="Score only each face's K nearest faces by descriptor.")
    ] = None,
    classifier: Annotated[
        Path | None, typer.Option(help="Same-die classifier JSON (default: the shipped model of --scorer).")
    ] = None,
    scorer: Annotated[
        str,
        typer.Option(help="relief (scale-free relief features) or paper (the paper's distance histogram)."),
    ] = "relief",
    batch_faces: Annotated[int, typer.Option(help="Faces per side of a batch's tile.")] = 16,
    retry_failed: Annotated[bool, typer.Option(help="Score again the pairs that failed before.")] = False,
    histograms: Annotated[
        bool,
        typer.Option(
            help="Measure the paper's distance histogram of every pair (a fifth of a pair's time; the "
            "paper scorer always does, the review app measures an opened pair's)."
        ),
    ] = False,
    relay_neighbours: Annotated[
        int,
        typer.Option(help="Register pairs again through each face's N best partners (0: no relays)."),
    ] = DEFAULT_NEIGHBOURS,
    relay_rounds: Annotated[int, typer.Option(help="Rounds of relays.")] = DEFAULT_ROUNDS,
    max_minutes: Annotated[
        float | None, typer.Option(help="Stop scoring after this long (resume later with coindie run).")
    ] = None,
    plan_only: Annotated[
        bool, typer.Option(help="Prepare the faces and plan the pairs, score none (see coindie status).")
    ] = False,
    coin_diameter: Annotated[
        float | None,
        typer.Option(
            help="The coins' diameter in mm, which the shipped scorer's design lengths follow (default: "
            "measured, the median of the faces'; 20 keeps the lengths it was trained with)."
        ),
    ] = None,
) -> None:
    """Prepare new faces, plan the pairs, score them in batches (resumable: kill it, run it again)."""
    from coindie.cli.progress import counting_progress
    from coindie.errors import ParameterError
    from coindie.project import open_project
    from coindie.project.run import DEFAULT_K, RunConfig, run_project

    if exhaustive and candidates is not None:
        raise ParameterError("--exhaustive and --candidates K exclude each other")
    mode = "exhaustive" if exhaustive else "candidates" if candidates is not None else "auto"
    config = RunConfig(
        method=method,
        method_params=method_params(method, param),
        mode=mode,
        k=candidates or DEFAULT_K,
        workers=workers,
        dask=dask,
        batch_faces=batch_faces,
        classifier=str(classifier) if classifier else None,
        scorer=scorer,
        retry_failed=retry_failed,
        histograms=histograms,
        relay_neighbours=relay_neighbours,
        relay_rounds=relay_rounds,
        plan_only=plan_only,
        max_seconds=None if max_minutes is None else 60.0 * max_minutes,
        coin_diameter_mm=coin_diameter,
    )
    report = run_project(open_project(project), config, progress=counting_progress, echo=typer.echo)
    rate = report.pairs_done / report.stage_seconds["pairs"] if report.stage_seconds.get("pairs") else 0.0
    typer.echo(
        f"run {report.run_id} finished in {report.seconds:.1f} s: {report.faces_prepared} faces prepared "
        f"({len(report.faces_failed)} bad), {report.pairs_done} pairs scored ({rate:.2f} pairs/s), "
        f"{report.pairs_failed} failed"
    )
    if report.stopped_early:
        typer.echo(f"stopped after --max-minutes {max_minutes:g}; `coindie run {project}` goes on from here")
    from coindie.project.status import separation_lines

    for line in separation_lines(open_project(project)):
        typer.echo(line)


@commands.command("status")
@exits_cleanly
def status(
    project: Annotated[Path, typer.Argument(help="Project folder.")],
    json_output: Annotated[bool, typer.Option("--json", help="Machine-readable output.")] = False,
) -> None:
    """Counts of faces and pairs, progress of the last run, its ETA, and every error."""
    import json

    from coindie.project import open_project
    from coindie.project.status import project_status

    summary = project_status(open_project(project))
    typer.echo(json.dumps(summary.to_dict(), indent=2) if json_output else summary.text())
