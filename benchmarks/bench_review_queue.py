"""The review queue against random order: pair checks a simulated expert needs to reach FMI 1.0.

    python benchmarks/bench_review_queue.py PROJECT OUT [--threshold 0.95 | --auto] [--side D] [--seeds 5]

PROJECT is a scored project with labels (given at ``coindie init``, or ``--labels CSV``; ``coindie demo
OUT`` makes one in OUT/project: a synthetic hoard, whose labels are the truth). The simulated expert (an
oracle reading the true labels) checks one pair at a time and records the answer as an edit through the
same edit log as the browser: ``link`` when the two faces share a die, ``cut`` when not. After each
check the clusters are the replay of the log (components at τ; with ``--auto``, the side as ``coindie
serve`` opens a project: ``coindie cluster --auto``'s cut of its graph, :mod:`coindie.serve.cuts`),
scored by FMI against the labels. Orders:

- ``queue``: :func:`coindie.serve.queue.review_queue` recomputed after each answer; when it is empty, the
  other scored pairs, closest to τ first;
- ``random``: the scored pairs in a random order (``--seeds`` orders; median reported).

Writes ``OUT/review_queue.json`` and ``OUT/review_queue.png`` (FMI against checks) and prints a table.
"""

from __future__ import annotations

import argparse
import json
import tempfile
from pathlib import Path

import numpy as np

from coindie.clustering import evaluate, read_clusters
from coindie.clustering.corrections import corrected_clusters, pair
from coindie.project import open_project
from coindie.project.edits import EditLog
from coindie.serve.cuts import START, SideCut, auto_links, components_at, threshold_links
from coindie.serve.queue import review_queue


def simulate(graph, truth: dict[str, str], tau: float, order: str, seed: int = 0, cut=None) -> list[float]:  # noqa: ANN001
    """FMI after 0, 1, 2, ... checks, until 1.0 or every scored pair was checked. ``cut``: the side's
    :class:`~coindie.serve.cuts.SideCut` (the app's start as ``coindie cluster --auto``; ``tau`` is then
    the slider's value) or None (components at ``tau``)."""
    rng = np.random.default_rng(seed)
    edges = list(graph.edges())
    if order == "random":
        edges = [edges[k] for k in rng.permutation(len(edges))]
    else:
        edges.sort(key=lambda e: abs(e[2] - (tau if cut is None else cut.threshold)))
    with tempfile.TemporaryDirectory() as folder:
        log = EditLog(Path(folder) / "log.sqlite")
        checked: set[tuple[str, str]] = set()
        curve = []
        while True:
            corrections = log.corrections(graph)
            if cut is None:
                links = threshold_links(graph, corrections)
                clusters = corrected_clusters(graph, corrections, tau)
            else:
                links = auto_links([cut], graph.nodes, log.edits())
                clusters = components_at(links, tau, cut.method)
            fmi = evaluate(clusters.labels, truth).scores()["fmi"]
            curve.append(float(fmi))
            if fmi >= 1.0 - 1e-12 or len(checked) == len(edges):
                return curve
            nxt = None
            if order == "queue":
                items = review_queue(graph, links, corrections, tau, limit=1)
                nxt = (items[0].a, items[0].b) if items else None
            if nxt is None or pair(*nxt) in checked:
                nxt = next((a, b) for a, b, _ in edges if pair(a, b) not in checked)
            checked.add(pair(*nxt))
            action = "link" if truth[nxt[0]] == truth[nxt[1]] else "cut"
            log.append(graph, action, nxt[0], nxt[1], base_seq=log.last_seq(), author="oracle")


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("project", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--threshold", type=float, default=0.95)
    parser.add_argument("--auto", action="store_true", help="start as coindie serve opens a project")
    parser.add_argument("--labels", type=Path, help="the true dies (default: the labels given at init)")
    parser.add_argument("--side", default="D")
    parser.add_argument("--seeds", type=int, default=5)
    args = parser.parse_args()
    project = open_project(args.project)
    cut = None
    if args.auto:
        graph, tau, how, params = project.auto_graph(args.side, "consensus")
        cut = SideCut(args.side, graph, "consensus", tau, params, how)
        args.threshold = START
    else:
        graph = project.probability_graph(args.side)
    labels = read_clusters(args.labels) if args.labels else project.labels()
    truth = {f: d for f, d in labels.items() if f in set(graph.nodes)}
    queue = simulate(graph, truth, args.threshold, "queue", cut=cut)
    randoms = [simulate(graph, truth, args.threshold, "random", seed, cut) for seed in range(args.seeds)]
    reached = [len(c) - 1 if c[-1] >= 1.0 - 1e-12 else None for c in randoms]
    result = {
        "project": str(args.project),
        "side": args.side,
        "threshold": args.threshold,
        "start": "coindie cluster --auto" if cut else "components at the threshold",
        "faces": graph.n_nodes,
        "pairs": graph.n_edges,
        "fmi_start": queue[0],
        "queue_checks": len(queue) - 1,
        "queue_reached_1": queue[-1] >= 1.0 - 1e-12,
        "random_checks": reached,
        "random_median_checks": float(np.median([r if r is not None else graph.n_edges for r in reached])),
        "queue_curve": queue,
        "random_curves": randoms,
    }
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "review_queue.json").write_text(json.dumps(result, indent=1) + "\n")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4))
    for k, curve in enumerate(randoms):
        ax.plot(curve, color="0.6", lw=1, label="random order" if k == 0 else None)
    ax.plot(queue, color="C3", lw=2, label="review queue")
    ax.set_xlabel("pair checks by the simulated expert")
    ax.set_ylabel("FMI of the corrected clusters")
    start = "coindie cluster --auto's cut" if cut else f"τ = {args.threshold}"
    ax.set_title(f"{graph.n_nodes} faces ({args.side}), {graph.n_edges} scored pairs, {start}")
    ax.legend()
    ax.set_xscale("symlog", linthresh=10)
    fig.tight_layout()
    fig.savefig(args.out / "review_queue.png", dpi=120)
    print("| faces | pairs | τ | FMI at start | checks to FMI 1.0: queue | random order (median of seeds) |")
    print("| ---: | ---: | ---: | ---: | ---: | ---: |")
    print(
        f"| {graph.n_nodes} | {graph.n_edges} | {args.threshold} | {queue[0]:.3f} | "
        f"{result['queue_checks']}{'' if result['queue_reached_1'] else ' (not reached)'} | "
        f"{result['random_median_checks']:.0f} ({', '.join(str(r) for r in reached)}) |"
    )


if __name__ == "__main__":
    main()
