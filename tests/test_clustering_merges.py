"""A linkage tree as links (coindie.clustering.merges): its cuts are components, and experts' edits hold."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.clustering import ProbabilityGraph, cluster, get_algorithm
from coindie.clustering.corrections import Corrections, Edit, corrected_clusters, pair, replay
from coindie.clustering.merges import merge_links


def _hoard_graph(seed: int, n: int = 40, dies: int = 6) -> tuple[ProbabilityGraph, dict[str, int]]:
    """Faces of ``dies`` dies; same-die pairs mostly probable, a few wrong both ways; 70 % of pairs scored."""
    rng = np.random.default_rng(seed)
    die = rng.integers(0, dies, n)
    names = [f"L{k + 1:04d}D" for k in range(n)]
    edges = []
    for a in range(n):
        for b in range(a + 1, n):
            if rng.random() < 0.7:
                p = rng.beta(6, 2) if die[a] == die[b] else rng.beta(1, 8)
                edges.append((names[a], names[b], float(p)))
    return ProbabilityGraph.from_edges(edges, names), dict(zip(names, die.tolist(), strict=True))


def _groups(clustering) -> list[list[str]]:  # noqa: ANN001
    return sorted(sorted(g) for g in clustering.clusters())


@pytest.mark.parametrize("method", ["average", "consensus"])
def test_merge_links_cut_at_any_threshold_are_the_methods_clusters(method):
    for seed in range(4):
        graph, _ = _hoard_graph(seed)
        for tau in (0.05, 0.2, 0.35, 0.5, 0.65, 0.8, 0.95):
            expected = _groups(cluster(graph, method, tau))
            # no edit: the components of the merges above τ are the tree's cut
            assert _groups(corrected_clusters(graph, Corrections(), tau, method)) == expected, (seed, tau)


def test_merge_links_one_per_merge_between_the_two_groups():
    graph, _ = _hoard_graph(7, n=25)
    links = merge_links(graph, get_algorithm("consensus", threshold=0.5))
    assert len(links.i) == graph.n_nodes - 1  # a spanning tree: every merge carried by one pair
    assert np.all(np.diff(links.distance) >= -1e-12)  # average linkage: heights never decrease up the tree
    # the links span all faces (one component when every merge is kept)
    assert _groups(corrected_clusters(graph, Corrections(), 0.0, "consensus")) == [sorted(graph.nodes)]


def test_split_and_move_hold_on_consensus_clusters():
    graph, _ = _hoard_graph(3)
    tau = 0.5
    start = corrected_clusters(graph, Corrections(), tau, "consensus")
    big = max(start.clusters(), key=len)
    assert len(big) >= 4
    group, rest = big[: len(big) // 2], big[len(big) // 2 :]
    split = Edit(1, "split", group[0], None, {"group": group, "rest": rest})
    after = corrected_clusters(graph, replay(graph, [split]), tau, "consensus")
    for a in group:
        for b in rest:
            assert after.labels[a] != after.labels[b]  # whatever the consensus of their rows says
    # a cut of one pair inside a cluster does not split it (as with the paper's components)
    one_cut = Edit(1, "cut", big[0], big[1])
    kept = corrected_clusters(graph, replay(graph, [one_cut]), tau, "consensus")
    assert len({kept.labels[f] for f in big}) == 1
    # move: a face of one cluster joins another's
    other = next(g for g in start.clusters() if g != big)
    move = Edit(1, "move", big[0], other[0])
    moved = corrected_clusters(graph, replay(graph, [move]), tau, "consensus")
    assert moved.labels[big[0]] == moved.labels[other[0]]
    assert all(moved.labels[f] != moved.labels[big[0]] for f in big[1:])
    assert pair(big[0], other[0]) in replay(graph, [move]).forced
