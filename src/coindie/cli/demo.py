"""``coindie demo``: the whole die study on the embedded default — synthetic hoard, project, run, clusters.

It generates a small hoard with the ``riedones`` preset (scaled down), makes it a project (SQLite in
``OUT/project``), runs it on local processes (per-face work, then the pairs of each side: the candidate
search by default, ``--exhaustive`` for every pair), clusters each side with the threshold chosen without
labels (best silhouette) and the shipped same-die classifier, and prints the evaluation against the hoard's
labels (FMI and ARI as in the paper, clusters vs dies). Run it again and nothing is recomputed.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import exits_cleanly
from coindie.errors import ParameterError

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()

#: Candidates per face in the demo (a small hoard: recall is ~99 % of faces at K = 10, BENCHMARK.md).
DEMO_K = 10


@commands.command()
@exits_cleanly
def demo(
    out: Annotated[Path, typer.Argument(help="Folder for the hoard, the project and the clusters (reused).")],
    scale: Annotated[
        float, typer.Option(help="Share of the riedones preset to generate (0 < S <= 1).")
    ] = 0.05,
    seed: Annotated[int, typer.Option(help="Seed of the hoard.")] = 0,
    workers: Annotated[int, typer.Option(help="Worker processes (0: one per core).")] = 0,
    exhaustive: Annotated[bool, typer.Option("--exhaustive", help="Score every pair of each side.")] = False,
    candidates: Annotated[int, typer.Option(help="Candidates per face (candidate search).")] = DEMO_K,
    method: Annotated[
        str, typer.Option(help="Clustering: consensus, components (the paper's), average, leiden.")
    ] = "consensus",
) -> None:
    """Synthetic hoard -> project -> run -> clusters per side (threshold without labels) -> evaluation."""
    import os

    from rich.console import Console

    from coindie.cli.progress import counting_progress
    from coindie.project import init_project
    from coindie.project.run import RunConfig, run_project
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

    console.rule("2. the die-study project (coindie init)")
    project, added = init_project(out / "project", hoard, hoard / "labels.csv")
    console.print(
        f"{project.folder}: {len(project.scans())} faces ({len(added.added)} new), "
        f"{len(project.labels())} labels kept for the evaluation only"
    )

    console.rule("3. per-face work and pairs (coindie run)")
    config = RunConfig(workers=workers, mode="exhaustive" if exhaustive else "candidates", k=candidates)
    run = run_project(project, config, progress=counting_progress, echo=console.print)
    console.print(
        f"run {run.run_id}: {run.faces_prepared} faces prepared, {run.pairs_done} pairs scored "
        f"in {run.seconds:.1f} s on {run.backend}"
    )

    console.rule("4. clusters per side, threshold chosen without labels; evaluation against the labels")
    for line in cluster_and_evaluate(project, out, method):
        console.print(line)


def cluster_and_evaluate(project, out: Path, method: str) -> list[str]:  # noqa: ANN001 (Project)
    """Per side: the unsupervised threshold, the clusters (written to ``out/clusters_<side>.csv``) and,
    when the project has labels, FMI / ARI and clusters vs dies; one line per side."""
    from coindie.clustering import evaluate, get_algorithm, write_clusters

    labels = project.labels()
    lines = []
    for side, name in (("D", "obverses"), ("R", "reverses")):
        graph, tau, how, params = project.auto_graph(side, method)
        if graph.n_nodes < 3:
            continue
        clusters = get_algorithm(method, threshold=tau, **params).fit(graph).clustering_
        path = write_clusters(clusters, out / f"clusters_{side}.csv")
        line = f"{name}: {graph.n_nodes} faces, {clusters.n_clusters} clusters at threshold {tau:g} ({how})"
        truth = {face: die for face, die in labels.items() if face in clusters.labels}
        if truth:
            s = evaluate(clusters.labels, truth).scores()
            line += f" — FMI {s['fmi']:.3f}, ARI {s['ari']:.3f}, "
            line += f"{s['n_clusters']} clusters for {s['n_dies']} dies"
        lines.append(f"{line} ({path})")
    return lines
