"""Choosing the clustering threshold τ: on a labelled validation split, or without labels.

- :func:`select_threshold` (the paper's way, section 4.3): the τ whose clusters of a labelled validation
  graph have the best Fowlkes-Mallows index (the paper found 0.95 on its obverses without beard).
- :func:`select_threshold_unsupervised`, for a new hoard with no labels: the τ whose clusters have the best
  mean silhouette on the distance ``1 - p`` (as Auto-Die-Studies does); for ``consensus`` clustering, the
  cut of the consensus with the best silhouette on ``1 - consensus``; or, with ``criterion="modularity"``,
  the best modularity on the probability graph (:mod:`coindie.clustering.modularity`). The silhouette of
  one-face clusters is 0 (scikit-learn's convention), so over-splitting is not rewarded; one cluster, or
  one per face, has no silhouette and is never chosen.

Both scan a grid of τ: 0.01 steps, refined near 0 and 1 where calibrated probabilities crowd (down to
1 - 1e-6), and keep the best; when a range of τ ties for the best, its centre (the widest range, in τ).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import FloatArray
from coindie.clustering.algorithms import AverageLinkage, ConsensusLinkage, get_algorithm, method_params
from coindie.clustering.consensus import SHARED, consensus_graph
from coindie.clustering.evaluation import evaluate
from coindie.clustering.graph import ProbabilityGraph
from coindie.clustering.modularity import link_weights, modularity
from coindie.errors import ParameterError

#: Cuts of the consensus tried without labels.
CONSENSUS_GRID = np.round(np.arange(0.10, 0.901, 0.01), 2)


def threshold_grid() -> FloatArray:
    """τ candidates: 0.01 ... 0.99 in steps of 0.01, plus 1 - 10^-k and 10^-k for k = 2.5 ... 6."""
    fine = 10.0 ** -np.arange(2.5, 6.01, 0.5)
    grid = np.concatenate([np.round(np.arange(0.01, 1.0, 0.01), 2), 1.0 - fine, fine, [0.995]])
    return np.unique(grid)


@dataclass(frozen=True)
class ThresholdChoice:
    """The chosen τ, its score, and the whole curve (τ, score, number of clusters)."""

    threshold: float
    score: float
    criterion: str
    thresholds: FloatArray
    scores: FloatArray
    n_clusters: NDArray[np.int64]

    def to_dict(self) -> dict[str, object]:
        return {"threshold": self.threshold, "score": self.score, "criterion": self.criterion}


def select_threshold(
    graph: ProbabilityGraph,
    truth: Mapping[str, object],
    method: str = "components",
    thresholds: Sequence[float] | None = None,
    metric: str = "fmi",
) -> ThresholdChoice:
    """The τ whose clustering of ``graph`` best matches the dies ``truth`` (face id -> die) by ``metric``
    (``fmi``, ``ari`` or ``ami``)."""
    if metric not in ("fmi", "ari", "ami"):
        raise ParameterError(f"The threshold metric must be 'fmi', 'ari' or 'ami'. Got {metric!r}.")
    grid = threshold_grid() if thresholds is None else np.asarray(thresholds, dtype=np.float64)
    scores, counts = [], []
    for tau in grid:
        result = evaluate(get_algorithm(method, threshold=float(tau)).fit(graph).clustering_.labels, truth)
        scores.append(getattr(result, metric))
        counts.append(result.n_clusters)
    return _best(grid, np.asarray(scores), np.asarray(counts), metric)


def select_threshold_unsupervised(
    graph: ProbabilityGraph,
    method: str = "components",
    thresholds: Sequence[float] | None = None,
    criterion: str = "silhouette",
    measure: str = SHARED,
) -> ThresholdChoice:
    """The τ whose clustering of ``graph`` has the best mean silhouette on ``1 - p``, without labels.

    ``consensus``: the cut on the consensus (:mod:`coindie.clustering.consensus`, rows compared by
    ``measure``) whose clusters have the best silhouette on ``1 - consensus``, over :data:`CONSENSUS_GRID`.

    ``criterion="modularity"``: the τ whose clusters have the best modularity on ``graph``'s probabilities
    (:mod:`coindie.clustering.modularity`) instead. Where the dies stand out the silhouette is right and
    the modularity merges small dies into large ones (its resolution limit: a cupped synthetic hoard, FMI
    0.978 against 0.937); where they do not, the silhouette splits the dies of worn hoards whose faces hold
    together only through some of their neighbours, and the modularity keeps them (eight sides of four
    all-hard hoards: mean FMI 0.929 against 0.888). :mod:`coindie.clustering.second_pass` uses each where it
    holds."""
    from sklearn.metrics import silhouette_score

    if criterion not in ("silhouette", "modularity"):
        raise ParameterError(f"The criterion must be 'silhouette' or 'modularity'. Got {criterion!r}.")
    if criterion == "modularity":
        default = CONSENSUS_GRID if method == ConsensusLinkage.NAME else threshold_grid()
        params = method_params(method, measure=measure)
        return _modularity_cut(graph, method, default if thresholds is None else thresholds, params)
    if method == ConsensusLinkage.NAME:
        grid = CONSENSUS_GRID if thresholds is None else thresholds
        return select_threshold_unsupervised(
            consensus_graph(graph, measure=measure), AverageLinkage.NAME, grid
        )
    grid = threshold_grid() if thresholds is None else np.asarray(thresholds, dtype=np.float64)
    distance = 1.0 - graph.matrix()
    np.fill_diagonal(distance, 0.0)
    scores, counts = [], []
    for tau in grid:
        labels = get_algorithm(method, threshold=float(tau)).fit(graph).labels_
        n = len(np.unique(labels))
        counts.append(n)
        valid = 2 <= n <= graph.n_nodes - 1
        scores.append(silhouette_score(distance, labels, metric="precomputed") if valid else -np.inf)
    return _best(grid, np.asarray(scores, dtype=np.float64), np.asarray(counts), "silhouette")


def _modularity_cut(
    graph: ProbabilityGraph, method: str, thresholds: Sequence[float], params: Mapping[str, Any]
) -> ThresholdChoice:
    grid = np.asarray(thresholds, dtype=np.float64)
    weights = link_weights(graph.matrix())
    scores, counts = [], []
    for tau in grid:
        labels = get_algorithm(method, threshold=float(tau), **params).fit(graph).labels_
        counts.append(len(np.unique(labels)))
        scores.append(modularity(weights, labels))
    return _best(grid, np.asarray(scores, dtype=np.float64), np.asarray(counts), "modularity")


def _best(grid: FloatArray, scores: FloatArray, counts: NDArray[np.int64], criterion: str) -> ThresholdChoice:
    """The centre of the widest run of consecutive grid τ that share the best score: a τ at the edge of
    the plateau (the lowest or the highest that scores best) is one step from a merge or a split on
    another set of faces; the centre is the farthest from both."""
    if len(grid) == 0:
        raise ParameterError("no threshold to choose from")
    order = np.argsort(grid, kind="stable")
    grid, scores, counts = grid[order], scores[order], counts[order]
    top = scores >= np.max(scores) - 1e-12
    runs, start = [], None
    for k, is_top in enumerate([*top, False]):
        if is_top and start is None:
            start = k
        elif not is_top and start is not None:
            runs.append((grid[k - 1] - grid[start], start, k - 1))
            start = None
    _, first, last = max(runs, key=lambda r: (r[0], -r[1]))
    centre = 0.5 * (grid[first] + grid[last])
    best = first + int(np.argmin(np.abs(grid[first : last + 1] - centre)))
    return ThresholdChoice(float(grid[best]), float(scores[best]), criterion, grid, scores, counts)
