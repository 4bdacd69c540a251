"""One side's share of the experts' log, and the components of a set of links (coindie.clustering)."""

from __future__ import annotations

import numpy as np

from coindie.clustering import ProbabilityGraph, cluster
from coindie.clustering.algorithms import get_algorithm, link_components
from coindie.clustering.corrections import (
    Corrections,
    Edit,
    corrected_clusters,
    corrected_graph,
    corrected_tree_links,
    pair,
    side_corrections,
)


def _side(letter: str, n: int, seed: int) -> ProbabilityGraph:
    rng = np.random.default_rng(seed)
    names = [f"L{k + 1:04d}{letter}" for k in range(n)]
    edges = [(names[a], names[b], float(rng.random())) for a in range(n) for b in range(a + 1, n)]
    return ProbabilityGraph.from_edges(edges, names)


def test_each_side_replays_its_own_edits_whatever_the_id_spelling():
    obverses, reverses = _side("D", 8, 0), _side("R", 8, 1)
    log = [
        Edit(1, "cut", "L0001D", "L0002D"),
        Edit(2, "link", "L3R", "L004R"),  # short ids, as a user types them: the reverses' edit all the same
        Edit(3, "split", "L0005D", None, {"group": ["L0005D"], "rest": ["L0006D", "L7D"]}),
        Edit(4, "undo", payload={"target": 1}),
    ]
    d, r = side_corrections(obverses, log), side_corrections(reverses, log)
    assert d.active == [3] and d.undone == {1}
    assert d.cut == {pair("L0005D", "L0006D"), pair("L0005D", "L0007D")} and not d.forced
    assert r.active == [2] and r.forced == {("L0003R", "L0004R")} and not r.cut
    # an edit across the two sides belongs to neither (a face never links across sides)
    across = [Edit(1, "link", "L0001D", "L0001R")]
    assert side_corrections(obverses, across).active == [] == side_corrections(reverses, across).active


def test_link_components_are_the_papers_components():
    for seed in range(5):
        graph = _side("D", 30, seed)
        for tau in (0.5, 0.9, 0.97):
            kept = graph.probability > tau
            got = link_components(graph.nodes, graph.i[kept], graph.j[kept], "components", tau)
            assert got.labels == cluster(graph, "components", tau).labels, (seed, tau)
    assert link_components((), np.zeros(0, np.int64), np.zeros(0, np.int64), "components", 0.5).labels == {}
    alone = link_components(("L0001D", "L0002D"), np.zeros(0, np.int64), np.zeros(0, np.int64), "x", 0.5)
    assert alone.labels == {"L0001D": 0, "L0002D": 1}


def test_no_merge_of_the_corrected_tree_is_carried_by_a_cut_pair():
    graph = _side("D", 20, 4)
    start = corrected_clusters(graph, Corrections(), 0.5, "average")
    big = max(start.clusters(), key=len)
    assert len(big) >= 3
    log = [Edit(k + 1, "cut", big[0], other) for k, other in enumerate(big[1:])]
    corrections = side_corrections(graph, log)
    corrected = corrected_graph(graph, corrections)
    links = corrected_tree_links(corrected, corrections, get_algorithm("average", threshold=0.5))
    names = corrected.nodes
    carried = {pair(names[i], names[j]) for i, j in zip(links.i, links.j, strict=True)}
    assert not carried & corrections.cut
    # two faces whose only pair is cut: their merge has no pair left to carry it, so no link at all
    two = ProbabilityGraph.from_edges([("L0001D", "L0002D", 0.9)], ["L0001D", "L0002D"])
    cut = side_corrections(two, [Edit(1, "cut", "L0001D", "L0002D")])
    for method in ("average", "consensus"):
        algorithm = get_algorithm(method, threshold=0.5)
        assert corrected_tree_links(corrected_graph(two, cut), cut, algorithm).i.size == 0, method
    # cut from every face of its cluster, the face leaves it
    after = corrected_clusters(graph, corrections, 0.5, "average")
    assert all(after.labels[big[0]] != after.labels[f] for f in big[1:])
