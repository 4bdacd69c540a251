"""One contract for every registered clustering algorithm: the estimator shape and what any die
clustering must do on graphs whose dies are known."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from coindie.clustering import (
    ClusteringAlgorithm,
    ProbabilityGraph,
    cluster,
    evaluate,
    get_algorithm,
    list_algorithms,
    register_algorithm,
)
from coindie.errors import ParameterError

ALGORITHMS = list_algorithms()


def _cliques(sizes: list[int], seed: int = 0, singletons: int = 0) -> tuple[ProbabilityGraph, dict]:
    """Dies of the given sizes (same-die pairs p in [0.9, 0.99], others in [0, 0.3]), then ``singletons``
    faces linked to nothing above 0.3."""
    rng = np.random.default_rng(seed)
    dies = [d for d, size in enumerate(sizes) for _ in range(size)] + [
        len(sizes) + k for k in range(singletons)
    ]
    truth = {f"L{k + 1:04d}R": f"D{d}" for k, d in enumerate(dies)}
    edges = [
        (a, b, rng.uniform(0.9, 0.99) if truth[a] == truth[b] else rng.uniform(0.0, 0.3))
        for a, b in itertools.combinations(truth, 2)
    ]
    return ProbabilityGraph.from_edges(edges), truth


def test_the_registry_holds_the_four_algorithms_in_order() -> None:
    assert ALGORITHMS[:4] == ["components", "average", "consensus", "leiden"]


@pytest.mark.parametrize("name", ALGORITHMS)
def test_fit_returns_the_estimator_with_labels_in_node_order(name: str) -> None:
    graph, _ = _cliques([4, 3])
    algorithm = get_algorithm(name, threshold=0.7)
    assert isinstance(algorithm, ClusteringAlgorithm) and algorithm.NAME == name
    assert algorithm.fit(graph) is algorithm
    labels = algorithm.labels_
    assert labels.shape == (graph.n_nodes,) and labels.dtype == np.int64
    assert list(algorithm.clustering_.labels) == list(graph.nodes)
    assert algorithm.clustering_.labels == dict(zip(graph.nodes, labels.tolist(), strict=True))
    # Labels are 0, 1, ... in order of each cluster's first node.
    first_seen = list(dict.fromkeys(labels.tolist()))
    assert first_seen == list(range(len(first_seen)))
    assert algorithm.clustering_.method == name and algorithm.clustering_.threshold == 0.7


@pytest.mark.parametrize("name", ALGORITHMS)
def test_parameters_are_stored_with_their_defaults(name: str) -> None:
    algorithm = get_algorithm(name)
    declared = type(algorithm).declared()
    assert "threshold" in declared
    assert algorithm.values() == {key: p.default for key, p in declared.items()}
    assert all(p.doc for p in declared.values())


@pytest.mark.parametrize("name", ALGORITHMS)
def test_two_well_separated_cliques_give_two_clusters(name: str) -> None:
    graph, truth = _cliques([5, 4])
    result = evaluate(get_algorithm(name, threshold=0.7).fit(graph).clustering_.labels, truth)
    assert result.n_clusters == 2 and result.fmi == 1.0


@pytest.mark.parametrize("name", ALGORITHMS)
def test_singletons_stay_singletons(name: str) -> None:
    graph, truth = _cliques([4, 3], singletons=3)
    labels = get_algorithm(name, threshold=0.7).fit(graph).clustering_.labels
    lonely = [face for face, die in truth.items() if die in {"D2", "D3", "D4"}]
    assert len({labels[face] for face in lonely}) == 3
    assert all(sum(label == labels[face] for label in labels.values()) == 1 for face in lonely)


@pytest.mark.parametrize("name", ALGORITHMS)
def test_fitting_is_deterministic(name: str) -> None:
    graph, _ = _cliques([6, 5, 2, 1], seed=3)
    first = get_algorithm(name, threshold=0.5).fit(graph).labels_
    second = get_algorithm(name, threshold=0.5).fit(graph).labels_
    np.testing.assert_array_equal(first, second)


@pytest.mark.parametrize("name", ALGORITHMS)
def test_an_empty_graph_has_no_cluster(name: str) -> None:
    algorithm = get_algorithm(name).fit(ProbabilityGraph.from_edges([]))
    assert algorithm.labels_.shape == (0,) and algorithm.clustering_.n_clusters == 0


@pytest.mark.parametrize("name", ALGORITHMS)
def test_the_shortcut_gives_the_estimator_result(name: str) -> None:
    graph, _ = _cliques([4, 4, 1])
    assert cluster(graph, name, 0.8) == get_algorithm(name, threshold=0.8).fit(graph).clustering_


@pytest.mark.parametrize("name", ALGORITHMS)
@pytest.mark.parametrize("threshold", [-0.1, 1.5, float("nan"), "high", None, True])
def test_bad_parameters_are_refused_naming_them(name: str, threshold: object) -> None:
    with pytest.raises(ParameterError, match=rf"The 'threshold' parameter of {name} must be a float"):
        get_algorithm(name, threshold=threshold)
    with pytest.raises(ParameterError, match="has no parameter 'k'. Its parameters: threshold"):
        get_algorithm(name, k=3)


def test_unknown_algorithms_are_refused_listing_the_known_ones() -> None:
    with pytest.raises(ParameterError, match="'method' parameter of cluster must be one of 'components'"):
        get_algorithm("kmeans")
    with pytest.raises(ValueError, match="already registered"):
        register_algorithm(type(get_algorithm("components")))
