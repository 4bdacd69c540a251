"""Clustering methods, evaluation and threshold choice on graphs whose dies are known."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from sklearn import metrics

from coindie.clustering import (
    METHODS,
    ProbabilityGraph,
    cluster,
    evaluate,
    read_graph,
    select_threshold,
    select_threshold_unsupervised,
)
from coindie.errors import ParameterError
from real_data import real_file


def _dies_graph(
    sizes: list[int], seed: int = 0, bridge: float | None = None
) -> tuple[ProbabilityGraph, dict]:
    """Faces of dies of the given sizes: same-die pairs p in [0.9, 0.99], other pairs p in [0, 0.5];
    ``bridge``: one pair of the first two dies gets that probability (a wrong link)."""
    rng = np.random.default_rng(seed)
    truth = {f"L{k + 1:04d}R": f"R{d}" for k, d in enumerate(np.repeat(np.arange(len(sizes)), sizes))}
    faces = list(truth)
    edges = []
    for a, b in itertools.combinations(faces, 2):
        p = rng.uniform(0.9, 0.99) if truth[a] == truth[b] else rng.uniform(0.0, 0.5)
        edges.append((a, b, p))
    if bridge is not None:
        first, second = faces[0], faces[sizes[0]]
        edges = [(a, b, bridge if {a, b} == {first, second} else p) for a, b, p in edges]
    return ProbabilityGraph.from_edges(edges), truth


@pytest.mark.parametrize("method", METHODS)
def test_every_method_recovers_well_separated_dies(method: str) -> None:
    graph, truth = _dies_graph([6, 4, 3, 1, 1])
    clusters = cluster(graph, method, threshold=0.7)
    result = evaluate(clusters.labels, truth)
    assert result.fmi == 1.0 and result.n_clusters == 5 == result.n_dies and not result.mistakes


def test_one_wrong_link_merges_components_but_not_average_consensus_or_leiden() -> None:
    graph, truth = _dies_graph([8, 8, 3], bridge=0.97)
    merged = evaluate(cluster(graph, "components", 0.7).labels, truth)
    assert merged.n_clusters == 2
    assert [(m.kind, sorted(m.members)) for m in merged.mistakes] == [("merged", ["R0", "R1"])]
    for method in ("average", "leiden"):
        assert evaluate(cluster(graph, method, 0.7).labels, truth).fmi == 1.0, method
    assert evaluate(cluster(graph, "consensus", 0.3).labels, truth).fmi == 1.0


def test_components_keep_links_strictly_above_the_threshold() -> None:
    graph = ProbabilityGraph.from_edges([("a", "b", 0.5), ("b", "c", 0.9)])
    assert cluster(graph, "components", 0.5).n_clusters == 2
    assert cluster(graph, "components", 0.49).n_clusters == 1
    assert cluster(graph, "average", 0.5).labels["a"] != cluster(graph, "average", 0.5).labels["b"]


def test_scores_match_scikit_learn() -> None:
    rng = np.random.default_rng(3)
    faces = [f"L{k:04d}D" for k in range(1, 61)]
    true = rng.integers(0, 8, 60)
    pred = np.where(rng.random(60) < 0.8, true, rng.integers(0, 10, 60))
    result = evaluate(dict(zip(faces, pred, strict=True)), dict(zip(faces, true, strict=True)))
    assert result.fmi == pytest.approx(metrics.fowlkes_mallows_score(true, pred))
    assert result.ari == pytest.approx(metrics.adjusted_rand_score(true, pred))
    assert result.ami == pytest.approx(metrics.adjusted_mutual_info_score(true, pred))
    assert result.fmi == pytest.approx(np.sqrt(result.precision * result.recall))
    assert result.n_clusters == len(set(pred)) and result.n_dies == len(set(true))
    # Pairs counted by hand, as the paper defines them.
    same_true = true[:, None] == true[None, :]
    same_pred = pred[:, None] == pred[None, :]
    upper = np.triu(np.ones((60, 60), dtype=bool), 1)
    tp = np.sum(same_true & same_pred & upper)
    assert result.precision == pytest.approx(tp / np.sum(same_pred & upper))
    assert result.recall == pytest.approx(tp / np.sum(same_true & upper))


def test_mistakes_name_split_dies_and_merged_clusters() -> None:
    truth = {"L0001D": "A", "L0002D": "A", "L0003D": "A", "L0004D": "B", "L0005D": "C"}
    pred = {"L0001D": 0, "L0002D": 0, "L0003D": 1, "L0004D": 2, "L0005D": 2, "L0006D": 3}
    result = evaluate(pred, truth)
    kinds = {(m.kind, m.name): m.members for m in result.mistakes}
    assert kinds[("split", "A")] == {"0": ["L0001D", "L0002D"], "1": ["L0003D"]}
    assert kinds[("merged", "2")] == {"B": ["L0004D"], "C": ["L0005D"]}
    assert result.unlabelled == ["L0006D"] and result.n_faces == 5


def test_threshold_chosen_on_a_validation_set() -> None:
    # Same-die links in [0.9, 0.99], other links below 0.5, one wrong link at 0.8: any tau in [0.8, 0.9)
    # is perfect; below 0.8 the wrong link merges two dies, from 0.9 up same-die links drop.
    graph, truth = _dies_graph([6, 5, 4, 2], seed=1, bridge=0.8)
    choice = select_threshold(graph, truth)
    assert 0.8 <= choice.threshold < 0.9 and choice.score == 1.0
    assert choice.criterion == "fmi" and len(choice.thresholds) == len(choice.scores) == len(
        choice.n_clusters
    )
    unsupervised = select_threshold_unsupervised(graph)
    assert evaluate(cluster(graph, "components", unsupervised.threshold).labels, truth).fmi > 0.9


def test_real_beard_graph_cluster_counts() -> None:
    """The paper reports 7 dies (one coin misplaced) for the 81 obverses with beard."""
    graph = read_graph(real_file("beard_probability_graph.json"))
    counts = {m: cluster(graph, m, 0.95).n_clusters for m in METHODS}
    assert counts["components"] == 10  # at the paper's tau = 0.95
    choice = select_threshold_unsupervised(graph)
    n = cluster(graph, "components", choice.threshold).n_clusters
    assert 7 <= n <= 9
    sizes = [len(c) for c in cluster(graph, "components", choice.threshold).clusters()]
    assert sum(sizes) == 81 and sizes[0] >= 20


def test_bad_parameters_are_refused() -> None:
    graph, _ = _dies_graph([2, 2])
    with pytest.raises(ParameterError, match="method"):
        cluster(graph, "kmeans")
    with pytest.raises(ParameterError, match=r"\[0, 1\]"):
        cluster(graph, threshold=1.5)
    with pytest.raises(ParameterError, match="no face in common"):
        evaluate({"a": 1}, {"b": 1})
