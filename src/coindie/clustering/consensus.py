"""Neighbourhood consensus: how alike two faces' links are, beside how likely their own link is.

A die study has many coins per die, and the coins of one die are linked to each other. A pair's own
probability can fail where its registration did (a broken flan, a crust over the only shared part) or
where wear and noise bring two coins of one die close to two dies of one design; the rest of the die still
knows. So each face is described by its row of same-die probabilities (1 to itself, 0 to unscored faces),
and two faces ``a``, ``b`` are compared by the weight their rows share, ``a·b / max(|a|², |b|²)``: the
cosine of the rows (near 1 when they are linked to the same faces, near 0 when their strong links go to
different faces) times the ratio of their norms (near 1 when they are linked as strongly). The measure is
dimensionless and reads calibrated probabilities, so it carries no scale of one scanner; it is the
shared-neighbour similarity of graph clustering, weighted by the probabilities.

Why the norms count (``measure="shared"``, the first pass): a coin of a one-coin die of the same design
as a large die is linked to that die's coins, weakly, and to nothing else. Its row points the same way as
theirs, so the cosine alone made it one of them (on a `study` hoard of the default physics, seed 1022, a
one-coin obverse die whose calibrated probabilities to a 20-coin die's coins were 0.0-1.0, mean 0.64, had
a cosine of 0.83 with them, and four one-coin dies were joined to other dies: FMI 0.948); the coins of
that die are linked to each other strongly, to it weakly, and the ratio of the norms says so (the four
kept apart, FMI 1.000 with the per-hoard calibration's t components). Where the dies do not stand out
(worn, crusted hoards: :mod:`coindie.clustering.second_pass`), a face's link strength is its wear more
than its die, and the ratio splits worn faces off their dies (an all-hard hoard, seed 2000: FMI 0.93 with
the cosine in the second pass, 0.86 with the ratio): there the rows are compared by direction alone
(``measure="cosine"``).

On the all-hard synthetic mix (every axis of the wide world at its extreme), the consensus separates the
reverses' same-die pairs from the others with a pair AUC of 0.999 where their own probabilities give 0.93
(see BENCHMARK.md, "Generalisation").

Light faces (stop 36). A face none of whose links reaches :data:`LIGHT_LINK` has a light row: a 1 on the
diagonal and weak links. The ratio of norms keeps such a face off a large die of its design, whose coins
are linked strongly to each other; it does not keep two such faces off each other. Their rows are
equally light and point the same way, at that die, so they share most of their weight. On the
independent generator's coarse-7 hoard, three one-coin obverse dies were joined this way. Their own
links were 0.07-0.12. Each one's links to a coin of another die were 0.16-0.34. Their consensus was
0.22-0.65. So between two light faces, the consensus steps count only as far as the pair's own link
holds up against the stronger of the two faces' best links (:func:`light_pair_weight`). Coins of one
worn die are each other's best links and keep most of their consensus; a weak coin of a strong die is
not light on both sides and keeps all of it. On the stored projects of 20 single-axis rows, an all-hard
hoard, ten held-out hoards of seeds 7 and 8 and coarse-5, and on the real beard graph, only two hoards'
clusters changed: coarse-7 (FMI 0.971 to 0.977, the three dies apart) and mixed-8, made after the rule
was chosen (0.993 to 0.996, one of three joined dies apart; BENCHMARK.md).

Written by hand: a cosine of the rows of a symmetric matrix is one matrix product; no library offers it
over a probability graph.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from coindie.arrays import FloatArray
from coindie.clustering.graph import ProbabilityGraph
from coindie.errors import ParameterError

#: Average consensus above which two clusters of faces merge (``consensus`` clustering) when no cut is
#: chosen: the two faces' strong links overlap in more than about 0.4 of their weight. Without labels,
#: coindie chooses the cut on each hoard by the silhouette of its clusters (:func:`coindie.clustering.
#: select_threshold_unsupervised`; 0.25 on the real beard graph), and in the second pass of
#: :mod:`coindie.clustering.second_pass` by their modularity (0.10-0.25 on synthetic all-hard hoards).
CONSENSUS_THRESHOLD = 0.4
#: Consensus steps averaged with the probabilities (:func:`consensus_similarity`). One step (the mean of
#: the probabilities and their consensus) left the all-hard synthetic hoards at FMI 0.79-0.80; two reach
#: 0.85-0.96 and keep the single-axis rows at 0.98-1.00; three merged dies of one design (0.87 on a cupped
#: hoard with the consensus alone).
CONSENSUS_DEPTH = 2
#: A face whose strongest link is below this probability has a light row (the module's docstring): the
#: consensus of two such faces is weighed by their own link (:func:`light_pair_weight`). The probability
#: at which a link says "more likely one die than two"; 0.35 gave the same clusters on the stored projects.
LIGHT_LINK = 0.5
#: How two rows are compared: ``shared`` (their cosine times the ratio of their norms) or ``cosine``.
SHARED, COSINE = "shared", "cosine"
MEASURES = (SHARED, COSINE)


def consensus_matrix(P: FloatArray, measure: str = SHARED) -> FloatArray:
    """The weight shared by the rows of a symmetric probability matrix ``P`` (n, n) whose diagonal is 1,
    ``a·b / max(|a|², |b|²)`` (the cosine of the rows times the ratio of their norms; ``measure="cosine"``:
    the cosine alone), once the typical pair's probability (the median off the diagonal: most pairs of a
    hoard are of different dies) is taken off every entry: (n, n), 1 on the diagonal, in [0, 1]."""
    if measure not in MEASURES:
        raise ParameterError(f"The consensus measure must be one of {', '.join(MEASURES)}. Got {measure!r}.")
    P = np.asarray(P, dtype=np.float64)
    n = len(P)
    if n > 1:
        typical = float(np.median(P[~np.eye(n, dtype=bool)]))
        P = np.clip(P - typical, 0.0, None) / max(1.0 - typical, 1e-12)
        np.fill_diagonal(P, 1.0)
    squared = np.einsum("ij,ij->i", P, P)
    squared = np.where(squared > 0, squared, 1.0)
    if measure == SHARED:
        C = (P @ P.T) / np.maximum(squared[:, None], squared[None, :])
    else:
        C = (P @ P.T) / np.sqrt(squared[:, None] * squared[None, :])
    C = np.clip(0.5 * (C + C.T), 0.0, 1.0)
    np.fill_diagonal(C, 1.0)
    return C


def consensus_similarity(P: FloatArray, depth: int = CONSENSUS_DEPTH, measure: str = SHARED) -> FloatArray:
    """The mean of the probabilities ``P`` and of their consensus taken ``depth`` times over (the
    consensus of the consensus, ...): the evidence that two faces share a die at one step (their own
    pair), two (common neighbours) and more (neighbours of neighbours), each in [0, 1]. Between two light
    faces the consensus steps are weighed by :func:`light_pair_weight`."""
    P = np.array(P, dtype=np.float64)
    np.fill_diagonal(P, 1.0)
    layers = [P]
    for _ in range(depth):
        layers.append(consensus_matrix(layers[-1], measure))
    weight = light_pair_weight(P)
    return np.mean([P, *(weight * layer for layer in layers[1:])], axis=0)


def light_pair_weight(P: FloatArray) -> FloatArray:
    """How much of their consensus two faces keep (n, n): 1, except between two light faces (neither has
    a link of :data:`LIGHT_LINK` or more), where it is their own link over the stronger of their two best
    links, at most 1. Two light faces whose consensus comes from links each has more strongly elsewhere
    keep little of it."""
    P = np.asarray(P, dtype=np.float64)
    n = len(P)
    if n < 2:
        return np.ones_like(P)
    best = np.where(np.eye(n, dtype=bool), -np.inf, P).max(axis=1)
    stronger = np.maximum(best[:, None], best[None, :])  # the stronger of the two faces' best links
    held_up = np.clip(P / np.maximum(stronger, 1e-12), 0.0, 1.0)
    weight = np.where(stronger < LIGHT_LINK, held_up, 1.0)  # both light: neither best reaches it
    np.fill_diagonal(weight, 1.0)
    return weight


def consensus_graph(
    graph: ProbabilityGraph, depth: int = CONSENSUS_DEPTH, measure: str = SHARED
) -> ProbabilityGraph:
    """The complete graph over ``graph``'s faces weighted by :func:`consensus_similarity` (faces with a
    common neighbour get a link even where their own pair was never scored). Kept for the last four graphs
    (by identity): choosing the cut and clustering at it read the same consensus, and its average-linkage
    tree (cached in turn) is cut once per candidate."""
    # one cache key however the caller spells the arguments (graph alone, or graph, depth, measure)
    return _consensus_graph(graph, depth, measure)


@lru_cache(maxsize=4)
def _consensus_graph(graph: ProbabilityGraph, depth: int, measure: str) -> ProbabilityGraph:
    n = graph.n_nodes
    C = consensus_similarity(graph.matrix(), depth, measure)
    i, j = np.triu_indices(n, k=1)
    return ProbabilityGraph(graph.nodes, i.astype(np.int64), j.astype(np.int64), C[i, j])
