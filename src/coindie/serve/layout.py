"""Node positions for the graph view, computed once on the server (the browser only draws).

Each cluster at the start (:meth:`coindie.serve.source.ReviewSource.clusters`) is laid out on its own by
networkx's spring layout (Fruchterman–Reingold) of its scored links weighted by probability, scaled by the
square root of its size, and the clusters are packed on rows, largest first, so that they stay apart
whatever the slider does.
"""

from __future__ import annotations

import math

import networkx as nx
import numpy as np

from coindie.clustering import ProbabilityGraph

#: Empty space between two packed clusters (layout units; a singleton is 1 wide).
GAP = 0.6


def cluster_layout(
    graph: ProbabilityGraph, groups: list[list[str]], seed: int = 0
) -> dict[str, tuple[float, float]]:
    """Face -> (x, y) for the faces of ``groups`` (clusters, largest first); clusters apart, on rows about
    as wide as the whole is tall."""
    label = {face: k for k, members in enumerate(groups) for face in members}
    g = nx.Graph()
    g.add_nodes_from(graph.nodes)
    names = graph.nodes
    g.add_weighted_edges_from(
        (names[i], names[j], float(p))
        for i, j, p in zip(graph.i, graph.j, graph.probability, strict=True)
        if label.get(names[i], -1) == label.get(names[j], -2)
    )
    blocks = []
    for members in groups:
        if len(members) == 1:
            blocks.append(({members[0]: np.zeros(2)}, 1.0))
            continue
        radius = math.sqrt(len(members))
        positions = nx.spring_layout(g.subgraph(members), weight="weight", seed=seed, scale=radius)
        blocks.append((positions, 2.0 * radius + 1.0))
    total = sum(size * size for _, size in blocks) or 1.0
    row_width = max(math.sqrt(total) * 1.2, max((size for _, size in blocks), default=1.0))
    out: dict[str, tuple[float, float]] = {}
    x = y = row_height = 0.0
    for positions, size in blocks:  # shelf packing, largest first
        if x > 0 and x + size > row_width:
            x, y, row_height = 0.0, y + row_height + GAP, 0.0
        centre = np.array([x + size / 2, y + size / 2])
        for face, xy in positions.items():
            px, py = np.asarray(xy, dtype=np.float64) + centre
            out[face] = (round(float(px), 4), round(float(-py), 4))
        x += size + GAP
        row_height = max(row_height, size)
    return out
