"""The second pass of unsupervised clustering: once more after each face's pull is taken off.

A worn, crusted or coarsely scanned face scores lower with every face of its design than a well-kept one,
whatever the die (:mod:`coindie.similarity.face_effects`). A first clustering says which pairs are
mostly of different dies (those across its clusters, cut where their modularity is best: see
:func:`cluster_twice`); each face's pull is fitted on them and taken off, the hoard is calibrated again by
the caller, and clustered again.

Only where the first clusters do not stand out in the probabilities themselves (their mean silhouette on
``1 - p`` below :data:`CLEAR_SILHOUETTE`). On a hoard whose dies are already clear, a face's pull is mostly
its *type* apart: a coin of a second type scores low with every coin of the first, and taking that pull
off would join the dies of the second type (on the ``riedones`` synthetic preset, FMI 1.000 down to 0.905).
Measured (BENCHMARK.md, "Generalisation"), with the per-hoard calibration's t components: the sides of
the all-hard synthetic hoards have first-pass silhouettes of 0.26-0.44, where the second pass raises the
FMI; the single-axis rows 0.80-0.94, and the ``riedones`` obverses 0.71: its 49 faces hold one-coin dies
next to a 4-coin die of their design, which the modularity of the second pass joins (its resolution
limit), so the gate sits below them, at 0.6. (With Gaussian components the probabilities were sharper and
every silhouette higher: 0.05-0.66 on all-hard sides, 0.88 on ``riedones``; the gate was 0.75.)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from coindie.clustering.algorithms import Clustering, cluster, method_params
from coindie.clustering.consensus import COSINE, SHARED
from coindie.clustering.graph import ProbabilityGraph
from coindie.clustering.threshold import ThresholdChoice, select_threshold_unsupervised

#: Mean silhouette on ``1 - p`` of the first clusters at or above which they stand out and the second
#: pass is not run.
CLEAR_SILHOUETTE = 0.6


#: In the second pass, the silhouette at or above which the clusters of the hoard's own mixture (the
#: scorer's veto set aside, each face's pull taken off) are kept. Below the first pass's gate: there the
#: mixture of raw scores may split kinds of different-die pairs, and its clusters must stand out as the
#: scorer's would; here the pulls are off and the split stands (Ashman's D at least 2, :data:`coindie.
#: similarity.calibration.OVERRULE_SEPARATION_AFTER_PULLS`; 3 before stop 51). Chosen on
#: the independent generator's hard hoards of seeds 1-3, whose second-pass mixtures stood at 0.47-0.54 and
#: gave FMI 0.84-0.99 on those sides, against 0.35-0.54 with the veto; checked on seed 4 and on coindie's
#: own all-hard and riedones hoards, none of which had a side in between (BENCHMARK.md, "Relays, and the
#: veto asked again").
OVERRULE_AFTER_PULLS_SILHOUETTE = 0.45


#: How the consensus compares two faces' rows in each pass (:mod:`coindie.clustering.consensus`): by the
#: weight they share where the dies may stand out, by direction alone once each face's pull is taken off
#: (its remaining link strength is still more its wear than its die).
FIRST_MEASURE, SECOND_MEASURE = SHARED, COSINE


@dataclass(frozen=True)
class TwoPassResult:
    """The graph clustered last, its cut, the clusters, the first pass's silhouette, and the parameters
    the clusters were made with (``cluster(graph, method, choice.threshold, **params)`` gives them)."""

    graph: ProbabilityGraph
    choice: ThresholdChoice
    clusters: Clustering
    first_silhouette: float
    second_pass: bool
    params: dict[str, Any]
    #: the graph is the hoard's own mixture's, which the scorer had vetoed (see :func:`cluster_twice`)
    overruled_scorer: bool = False
    #: where ``overruled_scorer``: the mean silhouette of that mixture's clusters (they stand out)
    overrule_silhouette: float = 0.0


def clusters_stand_out(graph: ProbabilityGraph, labels: Mapping[str, int]) -> float:
    """Mean silhouette of the clusters ``labels`` on the distance ``1 - p`` of ``graph``; 0 when every
    face is in one cluster or each face alone (no cluster stands out: a hard hoard whose calibrated
    probabilities are all near 0 leaves each face alone)."""
    from sklearn.metrics import silhouette_score

    codes = np.unique([labels[face] for face in graph.nodes], return_inverse=True)[1]
    if not 2 <= codes.max() + 1 <= graph.n_nodes - 1:
        return 0.0
    distance = 1.0 - graph.matrix()
    np.fill_diagonal(distance, 0.0)
    return float(silhouette_score(np.clip(distance, 0.0, None), codes, metric="precomputed"))


def cluster_twice(
    calibrated_graph: Callable[[Mapping[str, int] | None], ProbabilityGraph],
    method: str,
    vetoed_mixture: Callable[[Mapping[str, int] | None], ProbabilityGraph | None] | None = None,
) -> TwoPassResult:
    """Cluster ``calibrated_graph(None)`` (the hoard's calibrated probabilities) at the cut of best
    silhouette; when those clusters do not stand out, cluster ``calibrated_graph(across)`` (the same with
    each face's pull, fitted across the clusters ``across``, taken off before the calibration) again, at
    the cut of best modularity (:func:`coindie.clustering.select_threshold_unsupervised`: the silhouette
    splits the dies of murky hoards, the modularity merges the small dies of clear ones).

    ``across`` are the first graph's clusters at its own cut of best modularity, not the silhouette's: the
    pulls are fitted on the pairs across them, which should be of other dies, and the silhouette's murky
    clusters split dies, leaving same-die pairs across. On such hoards the silhouette's curve is flat and
    its cut jumps: two registrations of the all-hard hoard of seed 3000 (the last ICP stage on 6,000 or
    2,000 points: half the poses identical, nine in ten within 0.34°) cut its obverses into 17 clusters
    (FMI 0.57) or 10 (0.86), and the second pass gave 0.78 or 0.89; fitted across the modularity's
    clusters, 0.90 and 0.89 (BENCHMARK.md, "Generalisation").

    ``vetoed_mixture(across)``: where the scorer vetoed the hoard's own calibration (its mixture split the
    scores clearly, but the scorer judges the upper population different-die: :attr:`coindie.similarity.
    calibration.HoardCalibration.vetoed`), the graph calibrated by that mixture all the same (with each
    face's pull taken off first, fitted across the clusters ``across``, unless None); None where the
    calibration was not vetoed. When the first clusters do not
    stand out, its own first clusters are tried, and kept if *they* stand out: the scorer's sense of scale
    comes from its training scans, the clusters from this hoard. So is the second pass: its mixture, once
    each face's pull is off, cut where its clusters' silhouette is best and kept if they stand out
    (:data:`OVERRULE_AFTER_PULLS_SILHOUETTE`). On the
    independent generator's hard hoard (seed 1) the pulls take the obverses' pair AUC from 0.85 to 0.94,
    but the scorer vetoed the split there too and left every probability under 0.01, which no cut of the
    consensus reads (FMI 0.56); the mixture's clusters stand out (0.70) and give 0.93.

    On hoards of an independent generator (a coarse, noisy scanner; two scanners in one hoard) the veto left
    FMI 0.60 and 0.94; the mixture's clusters stood out (silhouettes 0.60-0.78) and gave 0.99 and 0.97. On
    six all-hard hoards of coindie's own generator, three reverses were vetoed clear splits whose clusters
    stood out (0.69-0.77): FMI 0.946 -> 0.950, 0.913 -> 0.953 and 0.909 -> 0.931 for the hoards; the vetoed
    splits that are not clear (:data:`coindie.similarity.calibration.OVERRULE_SEPARATION`) are not tried
    in the first pass (BENCHMARK.md, "An independent generator"); in the second, every split is
    (:data:`coindie.similarity.calibration.OVERRULE_SEPARATION_AFTER_PULLS`)."""
    graph = calibrated_graph(None)
    params = method_params(method, measure=FIRST_MEASURE)
    choice, first, clear = _first_pass(graph, method, params)
    if clear >= CLEAR_SILHOUETTE:
        return TwoPassResult(graph, choice, first, clear, False, params)
    mixture = vetoed_mixture(None) if vetoed_mixture is not None else None
    if mixture is not None:
        own, clusters, standing = _first_pass(mixture, method, params)
        if standing >= CLEAR_SILHOUETTE:
            return TwoPassResult(mixture, own, clusters, clear, False, params, True, standing)
    merged = select_threshold_unsupervised(graph, method, criterion="modularity", **params)
    across = cluster(graph, method, merged.threshold, **params).labels
    graph = calibrated_graph(across)
    params = method_params(method, measure=SECOND_MEASURE)
    mixture = vetoed_mixture(across) if vetoed_mixture is not None else None
    if mixture is not None:
        own, clusters, standing = _first_pass(mixture, method, params)
        if standing >= OVERRULE_AFTER_PULLS_SILHOUETTE:
            return TwoPassResult(mixture, own, clusters, clear, True, params, True, standing)
    choice = select_threshold_unsupervised(graph, method, criterion="modularity", **params)
    return TwoPassResult(
        graph, choice, cluster(graph, method, choice.threshold, **params), clear, True, params
    )


def _first_pass(
    graph: ProbabilityGraph, method: str, params: dict[str, Any]
) -> tuple[ThresholdChoice, Clustering, float]:
    """A graph clustered at its cut of best silhouette, and how far those clusters stand out."""
    choice = select_threshold_unsupervised(graph, method, **params)
    clusters = cluster(graph, method, choice.threshold, **params)
    return choice, clusters, clusters_stand_out(graph, clusters.labels)
