"""Newman's modularity of a clustering of a probability graph, and the consensus cut it chooses."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from coindie.clustering.modularity import link_weights, modularity


def _probabilities(sizes: list[int], seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    die = np.repeat(np.arange(len(sizes)), sizes)
    same = die[:, None] == die[None, :]
    P = np.where(same, rng.uniform(0.5, 1.0, same.shape), rng.uniform(0.0, 0.3, same.shape))
    P = np.triu(P, 1)
    return P + P.T + np.eye(len(die)), die


def test_modularity_matches_networkx() -> None:
    P, die = _probabilities([5, 4, 3], seed=0)
    W = link_weights(P)
    graph = nx.from_numpy_array(W)
    rng = np.random.default_rng(0)
    for labels in (die, rng.integers(0, 3, len(die)), np.zeros(len(die), dtype=int)):
        communities = [set(np.flatnonzero(labels == c)) for c in np.unique(labels)]
        assert modularity(W, labels) == pytest.approx(nx.community.modularity(graph, communities), abs=1e-9)


def test_the_dies_score_above_merges_and_splits() -> None:
    P, die = _probabilities([6, 5, 4, 2], seed=1)
    W = link_weights(P)
    merged = np.where(die == 1, 0, die)
    split = np.where((die == 0) & (np.arange(len(die)) % 2 == 0), 9, die)
    assert modularity(W, die) > max(modularity(W, merged), modularity(W, split))


def test_weights_are_the_links_above_the_typical_pair() -> None:
    P = np.array([[1.0, 0.9, 0.1], [0.9, 1.0, 0.2], [0.1, 0.2, 1.0]])
    W = link_weights(P)
    np.testing.assert_allclose(np.diag(W), 0.0)
    np.testing.assert_allclose(W, W.T)
    assert W[0, 1] == pytest.approx(0.7) and W[0, 2] == 0.0
    assert modularity(np.zeros((3, 3)), [0, 1, 2]) == 0.0


def test_the_modularity_cut_keeps_dies_with_weak_links_together() -> None:
    """Dies whose faces link only weakly, half their pairs failed: the cut by modularity of the consensus
    clusters finds them; an unknown criterion is refused."""
    from coindie.clustering import ProbabilityGraph, cluster, evaluate, select_threshold_unsupervised
    from coindie.errors import ParameterError

    rng = np.random.default_rng(3)
    die = np.repeat(np.arange(4), [10, 8, 6, 4])
    i, j = np.triu_indices(len(die), k=1)
    same = die[i] == die[j]
    p = np.where(same, rng.uniform(0.3, 0.9, len(i)), rng.uniform(0.0, 0.2, len(i)))
    p[same & (rng.random(len(i)) < 0.5)] = 0.0
    names = [f"L{k:04d}D" for k in range(len(die))]
    sources, targets = [names[k] for k in i], [names[k] for k in j]
    graph = ProbabilityGraph.from_edges(list(zip(sources, targets, p, strict=True)), names)
    choice = select_threshold_unsupervised(graph, "consensus", criterion="modularity")
    assert choice.criterion == "modularity"
    truth = dict(zip(names, die, strict=True))
    assert evaluate(cluster(graph, "consensus", choice.threshold).labels, truth).fmi > 0.9
    with pytest.raises(ParameterError):
        select_threshold_unsupervised(graph, "consensus", criterion="aic")
