"""Neighbourhood consensus: faces are alike when they are linked to the same faces (issue 13)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from coindie.clustering import ProbabilityGraph, cluster, evaluate, select_threshold_unsupervised
from coindie.clustering.consensus import (
    CONSENSUS_THRESHOLD,
    consensus_graph,
    consensus_matrix,
    light_pair_weight,
)
from coindie.errors import ParameterError


def _hoard_graph(sizes: list[int], seed: int, failed: float, weak: tuple[float, float]):
    """Dies of the given sizes. Each same-die pair is unscored (failed registration) with probability
    ``failed``, else scored uniformly in ``weak``; different-die pairs score in [0, 0.1] (calibrated: most
    pairs of a hoard are near 0). Returns the graph and the truth."""
    rng = np.random.default_rng(seed)
    truth = {f"L{k + 1:04d}D": f"D{d}" for k, d in enumerate(np.repeat(np.arange(len(sizes)), sizes))}
    edges = []
    for a, b in itertools.combinations(truth, 2):
        if truth[a] == truth[b]:
            if rng.random() >= failed:
                edges.append((a, b, rng.uniform(*weak)))
        else:
            edges.append((a, b, rng.uniform(0.0, 0.1)))
    return ProbabilityGraph.from_edges(edges, truth), truth


def test_consensus_of_clean_dies_is_one_inside_and_zero_across() -> None:
    P = np.kron(np.eye(3), np.ones((4, 4)))
    C = consensus_matrix(P)
    assert np.allclose(C, P)


def test_consensus_is_symmetric_bounded_and_one_on_the_diagonal() -> None:
    graph, _ = _hoard_graph([5, 4, 2, 1], seed=3, failed=0.3, weak=(0.2, 0.99))
    C = consensus_matrix(graph.matrix())
    assert np.allclose(C, C.T) and np.all((C >= 0) & (C <= 1)) and np.allclose(np.diag(C), 1.0)
    as_graph = consensus_graph(graph)
    assert as_graph.n_nodes == graph.n_nodes and as_graph.n_edges == graph.n_nodes * (graph.n_nodes - 1) // 2


def test_dies_with_failed_and_weak_links_are_kept_together_by_consensus_not_by_components() -> None:
    """Half of each die's pairs failed to register and the rest score 0.5-0.95: the coins link to each
    other through the rest of their die. Components at the mixture's 0.9 break the dies into pieces; the
    consensus, cut where the silhouette of its clusters is best (what coindie cluster --auto does first),
    keeps them."""
    consensus_fmi, component_fmi = [], []
    for seed in range(8):
        graph, truth = _hoard_graph([10, 8, 6, 1], seed=seed, failed=0.5, weak=(0.5, 0.95))
        components = evaluate(cluster(graph, "components", 0.9).labels, truth)
        cut = select_threshold_unsupervised(graph, "consensus").threshold
        consensus = evaluate(cluster(graph, "consensus", cut).labels, truth)
        assert components.n_clusters > components.n_dies + 10
        assert consensus.fmi > components.fmi + 0.3
        consensus_fmi.append(consensus.fmi)
        component_fmi.append(components.fmi)
    assert np.mean(consensus_fmi) > 0.85 > 0.5 > np.mean(component_fmi)


def test_consensus_keeps_a_singleton_apart() -> None:
    graph, truth = _hoard_graph([6, 1, 1], seed=1, failed=0.0, weak=(0.9, 0.99))
    labels = cluster(graph, "consensus", CONSENSUS_THRESHOLD).labels
    assert len(set(labels.values())) == 3


def test_a_one_coin_die_of_a_large_die_s_design_stays_apart() -> None:
    """One coin of another die of the design of a 15-coin die: linked to that die's coins at 0.05-0.7
    (wear and noise bring two dies of one design close), to nothing else. Its row points where theirs do,
    but it is linked far more weakly than they are to each other: the consensus keeps it apart, at the
    cut the silhouette chooses. Were the rows compared by direction alone (their cosine), it would join."""
    rng = np.random.default_rng(11)
    graph, truth = _hoard_graph([15, 8, 5], seed=11, failed=0.0, weak=(0.8, 0.99))
    lone = "L0029D"
    edges = list(graph.edges())
    edges += [(lone, f, rng.uniform(0.05, 0.7) if truth[f] == "D0" else rng.uniform(0.0, 0.1)) for f in truth]
    truth[lone] = "D3"
    graph = ProbabilityGraph.from_edges(edges, truth)
    cut = select_threshold_unsupervised(graph, "consensus").threshold
    labels = cluster(graph, "consensus", cut).labels
    assert sum(labels[lone] == labels[face] for face in truth) == 1
    assert evaluate(labels, truth).fmi == 1.0
    P = graph.matrix()
    die = [k for k, face in enumerate(graph.nodes) if truth[face] == "D0"]
    k = graph.nodes.index(lone)
    assert consensus_matrix(P)[k, die].mean() < 0.5 < consensus_matrix(P, "cosine")[k, die].mean()


def test_the_two_measures_compare_rows_by_direction_and_by_shared_weight() -> None:
    """Two faces linked to the same two faces, one three times as strongly as the other: the cosine reads
    the direction of their rows, the shared measure also how strongly each is linked."""
    P = np.eye(6)
    P[0, 2] = P[2, 0] = P[0, 3] = P[3, 0] = 0.9
    P[1, 2] = P[2, 1] = P[1, 3] = P[3, 1] = 0.3
    a, b = P[0], P[1]  # the typical pair's probability (the median off the diagonal) is 0 here
    cosine = a @ b / np.linalg.norm(a) / np.linalg.norm(b)
    shared = a @ b / max(a @ a, b @ b)
    assert consensus_matrix(P, "cosine")[0, 1] == pytest.approx(cosine)
    assert consensus_matrix(P)[0, 1] == pytest.approx(shared) and shared < cosine
    with pytest.raises(ParameterError, match="measure"):
        consensus_matrix(P, "jaccard")


def test_the_cut_by_silhouette_follows_the_hoard() -> None:
    """Clean dies: a cut anywhere between the two populations, and the dies found; dies held together
    only by their neighbourhoods: a lower cut."""
    clean, truth = _hoard_graph([8, 6, 4, 1], seed=2, failed=0.0, weak=(0.9, 0.99))
    weak, _ = _hoard_graph([8, 6, 4, 1], seed=2, failed=0.5, weak=(0.5, 0.95))
    clean_cut = select_threshold_unsupervised(clean, "consensus").threshold
    weak_cut = select_threshold_unsupervised(weak, "consensus").threshold
    assert evaluate(cluster(clean, "consensus", clean_cut).labels, truth).fmi == 1.0
    assert weak_cut < clean_cut


def _light_faces_beside_a_die(seed: int, own: tuple[float, float]):
    """A 6-coin die, a 10-coin die, and three light faces: each linked to the 6-coin die's coins at
    0.15-0.35 (a die of that design, worn or coarsely scanned), to each other in ``own``, to nothing else:
    what the independent generator's coarse-7 hoard held (BENCHMARK.md)."""
    rng = np.random.default_rng(seed)
    graph, truth = _hoard_graph([6, 10], seed=seed, failed=0.0, weak=(0.8, 0.99))
    light = ["L0017D", "L0018D", "L0019D"]
    edges = list(graph.edges())
    for face in light:
        for f in truth:
            edges.append((face, f, rng.uniform(0.15, 0.35) if truth[f] == "D0" else rng.uniform(0.0, 0.02)))
    edges += [(a, b, rng.uniform(*own)) for a, b in itertools.combinations(light, 2)]
    return ProbabilityGraph.from_edges(edges, [*truth, *light]), light


def test_light_faces_are_not_joined_by_the_links_they_share_with_another_die() -> None:
    """Three one-coin dies of the 6-coin die's design, linked to each other (0.05-0.12) more weakly than
    each is to that die's coins. Their rows are light and point the same way, so the rows alone put two
    of them together (seeds 0-2: what the consensus did before it weighed light pairs by their own link);
    each stays alone, and off the die."""
    for seed in range(5):
        graph, light = _light_faces_beside_a_die(seed, own=(0.05, 0.12))
        cut = select_threshold_unsupervised(graph, "consensus").threshold
        labels = cluster(graph, "consensus", cut).labels
        assert len({labels[face] for face in light}) == 3
        assert all(labels[face] != labels["L0001D"] for face in light)


def test_light_pairs_are_weighed_by_their_own_link_against_their_best() -> None:
    P = np.eye(4)
    P[0, 1] = P[1, 0] = 0.1  # two light faces ...
    P[0, 2] = P[2, 0] = 0.3  # ... each linked more strongly elsewhere
    P[1, 2] = P[2, 1] = 0.2
    P[2, 3] = P[3, 2] = 0.9  # a face with a strong link is not light
    weight = light_pair_weight(P)
    assert weight[0, 1] == pytest.approx(0.1 / 0.3)
    assert weight[0, 2] == weight[2, 3] == weight[1, 3] == 1.0
    assert np.allclose(weight, weight.T) and np.allclose(np.diag(weight), 1.0)


def test_light_faces_whose_own_links_are_their_best_are_one_die() -> None:
    """The same three light faces, now coins of one worn die: their links to each other (0.36-0.45) are
    their strongest. The consensus joins them, apart from the 6-coin die."""
    for seed in range(5):
        graph, light = _light_faces_beside_a_die(seed, own=(0.36, 0.45))
        cut = select_threshold_unsupervised(graph, "consensus").threshold
        labels = cluster(graph, "consensus", cut).labels
        assert len({labels[face] for face in light}) == 1
        assert labels[light[0]] != labels["L0001D"]
