"""What the expert should check first: pairs ranked by how uncertain the current clusters are about them.

Three kinds of pair, each with an uncertainty in [0, 1]:

- ``near-threshold``: a link whose probability is close to τ (1 at τ, 0 at a distance of ``BAND``);
- ``bridge``: a kept link whose removal splits its cluster in two (networkx's bridges), the weaker the
  more uncertain; a cluster held by one weak bridge is the paper's chaining error;
- ``runner-up``: a singleton's most probable partner, the closer to τ the more uncertain.

Pairs the expert already decided (cut, linked, re-registered) and clusters marked verified are left out.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import networkx as nx

from coindie.clustering import ProbabilityGraph
from coindie.clustering.corrections import Corrections, corrected_clusters, corrected_graph, kept_links, pair

#: Probability distance from τ at which a link is no longer uncertain.
BAND = 0.25


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
    graph: ProbabilityGraph, corrections: Corrections, threshold: float, limit: int = 200
) -> list[QueueItem]:
    """The pairs to check, most uncertain first (one entry per pair: its most uncertain reason)."""
    corrected = corrected_graph(graph, corrections)
    clusters = corrected_clusters(graph, corrections, threshold)
    verified = {f for group in corrections.verified if corrections.is_verified(group) for f in group}
    decided = corrections.cut | corrections.forced | set(corrections.probability)
    items: dict[tuple[str, str], QueueItem] = {}

    def offer(item: QueueItem) -> None:
        key = pair(item.a, item.b)
        if key in decided or (item.a in verified and item.b in verified):
            return
        if key not in items or items[key].uncertainty < item.uncertainty:
            items[key] = item

    for a, b, p in corrected.edges():
        u = 1.0 - abs(p - threshold) / BAND
        if u > 0:
            side = "above" if p > threshold else "below"
            offer(QueueItem(a, b, p, "near-threshold", u, f"p = {p:.3f}, just {side} τ = {threshold:.2f}"))
    kept = kept_links(graph, corrections, threshold)
    g = nx.Graph()
    names = corrected.nodes
    g.add_weighted_edges_from(
        (names[i], names[j], float(p))
        for i, j, p, k in zip(corrected.i, corrected.j, corrected.probability, kept, strict=True)
        if k
    )
    for a, b in nx.bridges(g):
        h = g.copy()
        h.remove_edge(a, b)
        small = min(len(nx.node_connected_component(h, a)), len(nx.node_connected_component(h, b)))
        if small < 2:
            continue  # a leaf: not a chain between two groups
        p = g[a][b]["weight"]
        u = 0.5 + 0.5 * max(0.0, 1.0 - (p - threshold) / max(1.0 - threshold, 1e-6))
        offer(
            QueueItem(a, b, p, "bridge", u, f"the only link between two groups ({small}+ faces), p = {p:.3f}")
        )
    sizes: dict[int, int] = {}
    for label in clusters.labels.values():
        sizes[label] = sizes.get(label, 0) + 1
    best: dict[str, tuple[float, str]] = {}
    for a, b, p in corrected.edges():
        for x, y in ((a, b), (b, a)):
            if sizes[clusters.labels[x]] == 1 and p > best.get(x, (-1.0, ""))[0]:
                best[x] = (p, y)
    for face, (p, other) in best.items():
        u = max(0.0, 1.0 - abs(p - threshold) / (2 * BAND))
        if u > 0:
            offer(
                QueueItem(
                    face, other, p, "runner-up", u, f"singleton; its best partner {other} has p = {p:.3f}"
                )
            )
    return sorted(items.values(), key=lambda it: (-it.uncertainty, it.a, it.b))[:limit]
