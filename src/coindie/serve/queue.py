"""What the expert should check first: pairs ranked by how uncertain the current clusters are about them.

The clusters are the components of the links the slider cuts at t (:mod:`coindie.serve.cuts`: the
probabilities at the paper's τ, or the merges of each side's tree, every side's own cut at the start).
Three kinds of pair, each with an uncertainty in [0, 1]:

- ``near-threshold``: a link whose value is close to t (1 at t, 0 at a distance of ``BAND``): a
  probability near τ, or a merge of two groups just above or below the side's cut;
- ``bridge`` (probability links only): a kept link whose removal splits its cluster in two (networkx's
  bridges), the weaker the more uncertain; a cluster held by one weak bridge is the paper's chaining
  error (every merge of a tree is a bridge: there the merges near the cut are the doubtful ones);
- ``runner-up``: a singleton's most probable partner not yet decided, the closer its link to t the more
  uncertain, and never under :data:`SINGLETON_FLOOR` (each face left alone is offered; when the expert
  cuts that pair, the next partner is);
- ``apart``: a pair standing apart above the rest of its side that the scorer judges different-die all
  the same (:attr:`coindie.similarity.HoardCalibration.apart`: on scans that lower every score, the
  hoard's few same-die pairs may be these), first in the queue, until decided.

Pairs the expert already decided (cut, linked, re-registered) and clusters marked verified are left out.
Each item carries the pair's probability in the graph under review.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import asdict, dataclass

import networkx as nx

from coindie.clustering import ProbabilityGraph
from coindie.clustering.corrections import Corrections, corrected_graph, pair
from coindie.serve.cuts import ReviewLinks, components_at

#: Distance from t (on the slider's scale) at which a link is no longer uncertain.
BAND = 0.25

#: Least uncertainty of a singleton's most probable partner (times 1 + its probability, so that these
#: come by probability): every face left alone is offered once, after the pairs near the cut. A weak face
#: (worn, crusted, a scanner the scorer does not know) scores low with every face, its die-mates first.
SINGLETON_FLOOR = 0.01


@dataclass(frozen=True)
class QueueItem:
    a: str
    b: str
    probability: float
    kind: str
    uncertainty: float
    why: str

    def to_dict(self) -> dict[str, object]:
        return asdict(self)


def review_queue(
    graph: ProbabilityGraph,
    links: ReviewLinks,
    corrections: Corrections,
    threshold: float,
    limit: int = 200,
    apart: Mapping[tuple[str, str], str] | None = None,
) -> list[QueueItem]:
    """The pairs to check, most uncertain first (one entry per pair: its most uncertain reason).

    ``graph``: the graph under review (the items' probabilities); ``links``: what the slider cuts, the
    edits applied; ``threshold``: the slider's value; ``apart``: pairs standing apart (each with why).
    """
    probability = {pair(a, b): p for a, b, p in corrected_graph(graph, corrections).edges()}
    clusters = components_at(links, threshold, "")
    verified = {f for group in corrections.verified if corrections.is_verified(group) for f in group}
    decided = corrections.cut | corrections.forced | set(corrections.probability)
    items: dict[tuple[str, str], QueueItem] = {}
    what = "merge" if links.tree else "p"

    def offer(a: str, b: str, kind: str, u: float, why: str) -> None:
        key = pair(a, b)
        if key in decided or (a in verified and b in verified):
            return
        if key not in items or items[key].uncertainty < u:
            items[key] = QueueItem(a, b, probability.get(key, 0.0), kind, float(u), why)

    for (a, b), why in (apart or {}).items():
        offer(a, b, "apart", 1.0, why)
    for (a, b), v in zip(links.pairs, links.value, strict=True):
        u = 1.0 - abs(v - threshold) / BAND
        if u > 0:
            side = "above" if v > threshold else "below"
            offer(a, b, "near-threshold", u, f"{what} {v:.3f}, just {side} the cut at {threshold:.2f}")
    if not links.tree:
        g = nx.Graph()
        g.add_weighted_edges_from(
            (a, b, float(v)) for (a, b), v in zip(links.pairs, links.value, strict=True) if v > threshold
        )
        g.add_weighted_edges_from((a, b, 1.0) for a, b in links.forced)
        for a, b in nx.bridges(g):
            h = g.copy()
            h.remove_edge(a, b)
            small = min(len(nx.node_connected_component(h, a)), len(nx.node_connected_component(h, b)))
            if small < 2:
                continue  # a leaf: not a chain between two groups
            v = g[a][b]["weight"]
            u = 0.5 + 0.5 * max(0.0, 1.0 - (v - threshold) / max(1.0 - threshold, 1e-6))
            offer(a, b, "bridge", u, f"the only link between two groups ({small}+ faces), p = {v:.3f}")
    sizes: dict[int, int] = {}
    for label in clusters.labels.values():
        sizes[label] = sizes.get(label, 0) + 1
    value = {key: float(v) for key, v in zip(links.pairs, links.value, strict=True)}
    best: dict[str, tuple[float, str]] = {}
    for (a, b), p in probability.items():
        if (a, b) in decided:
            continue
        for x, y in ((a, b), (b, a)):
            if sizes[clusters.labels[x]] == 1 and p > best.get(x, (-1.0, ""))[0]:
                best[x] = (p, y)
    for face, (p, other) in best.items():
        v = value.get(pair(face, other), 0.0 if links.tree else p)
        u = max(1.0 - abs(v - threshold) / (2 * BAND), SINGLETON_FLOOR * (1.0 + p))
        offer(face, other, "runner-up", u, f"singleton; its most probable partner left, {other}: p = {p:.3g}")
    return sorted(items.values(), key=lambda it: (-it.uncertainty, it.a, it.b))[:limit]
