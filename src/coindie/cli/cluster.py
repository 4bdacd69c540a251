"""``coindie cluster`` and ``coindie eval``: die clusters from a probability graph, and their quality."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import exits_cleanly
from coindie.errors import ParameterError

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()


@commands.command("cluster")
@exits_cleanly
def cluster_command(
    source: Annotated[
        Path,
        typer.Argument(
            metavar="PAIRS_OR_GRAPH",
            help="A pairs CSV (source,target,probability), a node-link graph.json, or a die-study project.",
        ),
    ],
    out: Annotated[Path, typer.Option("-o", "--out", help="Cluster CSV to write (the paper's name, die).")],
    threshold: Annotated[
        float | None, typer.Option(help="Links with a probability above it count (paper: 0.95).")
    ] = None,
    auto: Annotated[
        bool,
        typer.Option(
            "--auto",
            help="Choose the threshold without labels: consensus clustering cut where the silhouette of "
            "its clusters is best (a project: each side, again with each face's pull taken off where the "
            "clusters do not stand out); other methods: a project's own score populations, else the best "
            "silhouette on 1 - p.",
        ),
    ] = False,
    method: Annotated[
        str | None,
        typer.Option(
            help="components (the paper's), average, consensus or leiden; default: consensus with --auto, "
            "components with a threshold.",
        ),
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
) -> None:
    """Cluster faces into dies: threshold the same-die probabilities, then group."""
    from coindie.clustering import PAPER_THRESHOLD, get_algorithm, select_threshold_unsupervised

    if threshold is not None and auto:
        raise ParameterError("give --threshold or --auto, not both")
    if method is None:
        # without labels, the clusters come from the consensus of the hoard's calibrated probabilities;
        # a threshold given by hand (the paper's τ) is one on the probabilities themselves
        method = "consensus" if auto else "components"
    graph = _graph(source)
    if auto and source.is_dir():
        clusters, tau, how = _project_sides(source, method)
        _report(clusters, out, method, tau, how, graph.n_nodes, as_json)
        return
    if auto:
        choice = select_threshold_unsupervised(graph, method)
        tau, how = choice.threshold, f"chosen by {choice.criterion} {choice.score:.3f}"
    else:
        tau = PAPER_THRESHOLD if threshold is None else threshold
        how = "given" if threshold is not None else "the paper's"
    corrections = _corrections(source, graph)
    if corrections is None:
        clusters = get_algorithm(method, threshold=tau).fit(graph).clustering_
    else:  # the experts' edits (coindie serve), replayed by the same function as the browser's
        from coindie.clustering.corrections import corrected_clusters

        clusters = corrected_clusters(graph, corrections, tau, method)
        how += f", with {len(corrections.active)} expert edits"
    _report(clusters, out, method, tau, how, graph.n_nodes, as_json)


def _report(clusters, out: Path, method: str, tau, how: str, n_faces: int, as_json: bool) -> None:  # noqa: ANN001
    """Write the clusters and say what was done (``tau``: a number, or one per side)."""
    from coindie.clustering import write_clusters

    write_clusters(clusters, out)
    sizes = [len(c) for c in clusters.clusters()]
    if as_json:
        report = {"out": str(out), "method": method, "threshold": tau, "threshold_from": how,
                  "n_faces": n_faces, "n_clusters": clusters.n_clusters, "sizes": sizes}  # fmt: skip
        typer.echo(json.dumps(report))
        return
    shown = tau if isinstance(tau, dict) else f"{tau:g}"
    typer.echo(
        f"{out}: {n_faces} faces in {clusters.n_clusters} clusters ({method}, threshold {shown}, "
        f"{how}); largest {', '.join(map(str, sizes[:8]))}"
    )


def _project_sides(folder: Path, method: str):  # noqa: ANN202
    """A project's clusters without labels, side by side (:func:`coindie.numismatics.sources.project_dies`:
    each side's own threshold, its experts' edits replayed). Returns the clusters, the thresholds by side
    and how they were chosen."""
    from coindie.clustering import Clustering, combined
    from coindie.numismatics.sources import project_dies

    sides = project_dies(folder, method, auto=True)
    parts = []
    for one in sides.values():
        order = {die: k for k, die in enumerate(dict.fromkeys(sorted(one.dies.values())))}
        parts.append(Clustering({face: order[die] for face, die in one.dies.items()}, method))
    how = "; ".join(f"{side}: {one.source}" for side, one in sides.items())
    return combined(parts, method), {side: one.threshold for side, one in sides.items()}, how


def _graph(source: Path):  # noqa: ANN202
    from coindie.clustering import read_graph

    if source.is_dir():
        from coindie.project import open_project  # a die-study project (coindie init / run)

        return open_project(source).probability_graph()
    return read_graph(source)


def _corrections(source: Path, graph):  # noqa: ANN001, ANN202
    """The replayed edit log of a project, or of a graph file's sidecar; None when there is none."""
    from coindie.project.edits import EditLog, sidecar_path

    if source.is_dir():
        log = EditLog.of_project(source)
    elif sidecar_path(source).is_file():
        log = EditLog(sidecar_path(source))
    else:
        return None
    try:
        return log.corrections(graph) if log.last_seq() else None
    finally:
        log.close()


@commands.command("eval")
@exits_cleanly
def eval_command(
    clusters: Annotated[Path, typer.Argument(help="Cluster CSV (name, die) to judge.")],
    labels: Annotated[Path, typer.Argument(help="True dies: labels.csv (coin_id,die_id) or name, die.")],
    as_json: Annotated[bool, typer.Option("--json", help="Print the scores as JSON.")] = False,
    mistakes: Annotated[bool, typer.Option(help="List the dies split and the clusters merged.")] = False,
) -> None:
    """FMI, ARI (as the paper), AMI, pairwise precision/recall, clusters vs dies, and the mistakes."""
    from coindie.clustering import evaluate, read_clusters

    predicted, truth = read_clusters(clusters), read_clusters(labels)
    result = evaluate(predicted, truth)
    if as_json:
        report = result.to_dict() if mistakes else result.scores()
        typer.echo(json.dumps(report))
        return
    s = result.scores()
    typer.echo(
        f"FMI {s['fmi']:.4f}  ARI {s['ari']:.4f}  AMI {s['ami']:.4f}  precision {s['precision']:.4f}  "
        f"recall {s['recall']:.4f}  clusters {s['n_clusters']} for {s['n_dies']} dies ({s['n_faces']} faces)"
    )
    if result.missing:
        typer.echo(
            f"{len(result.missing)} labelled faces are not in the clustering: "
            f"{', '.join(result.missing[:10])}"
        )
    if mistakes:
        for m in result.mistakes:
            parts = "; ".join(f"{k}: {' '.join(v)}" for k, v in m.members.items())
            typer.echo(f"{m.kind} {m.name}: {parts}")
