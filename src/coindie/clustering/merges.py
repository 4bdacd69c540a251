"""A linkage tree as links: one pair of faces for each merge, so that its cuts are connected components.

``average`` and ``consensus`` clustering cut an average-linkage tree (:mod:`coindie.clustering.algorithms`).
Its flat clusters at τ are the connected components of the links :func:`merge_links` returns (one per
merge of the tree, between the most alike pair of faces across the two merged groups, weighted by the
merge's similarity ``1 - height``) whose similarity is above τ: the heights of average linkage never
decrease up the tree, so a cut keeps exactly the merges below it. With these links, the experts'
corrections (:mod:`coindie.clustering.corrections`) act on a linkage's clusters as they act on the paper's
components (a split cuts every pair between the two groups, so the merge between them too), and the
review app redraws a cut anywhere on the slider without asking the server.

scipy gives the tree; which pair of faces stands for each merge is ours (no library names one).
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

import numpy as np

from coindie.arrays import FloatArray, IntArray
from coindie.clustering.algorithms import AverageLinkage, ClusteringAlgorithm, ConsensusLinkage, _average_tree
from coindie.clustering.consensus import consensus_graph
from coindie.clustering.graph import ProbabilityGraph

#: The methods whose clusters are cuts of an average-linkage tree.
LINKAGE_METHODS = (AverageLinkage.NAME, ConsensusLinkage.NAME)


@dataclass(frozen=True)
class MergeLinks:
    """One link per merge of the tree, between nodes ``i`` and ``j`` of the graph (its node order): the
    merge's ``distance`` (``1 -`` the average similarity of the two groups it joins)."""

    i: IntArray
    j: IntArray
    distance: FloatArray

    def kept(self, threshold: float) -> np.ndarray:
        """The merges of the cut at τ (similarity strictly above it; the exact test of
        :func:`~coindie.clustering.algorithms._average_linkage`)."""
        return self.distance <= np.nextafter(1.0 - threshold, -np.inf)


def linkage_similarity(graph: ProbabilityGraph, algorithm: ClusteringAlgorithm) -> ProbabilityGraph:
    """The graph whose average-linkage tree ``algorithm`` cuts: the probabilities themselves
    (``average``) or their consensus (``consensus``)."""
    if isinstance(algorithm, ConsensusLinkage):
        return consensus_graph(graph, algorithm.depth, algorithm.measure)
    if isinstance(algorithm, AverageLinkage):
        return graph
    raise ValueError(
        f"{algorithm.NAME!r} clusters are not cuts of a linkage tree ({', '.join(LINKAGE_METHODS)})"
    )


def merge_links(
    graph: ProbabilityGraph, algorithm: ClusteringAlgorithm, excluded: Collection[tuple[int, int]] = ()
) -> MergeLinks:
    """The tree of ``algorithm`` (``average`` or ``consensus``) on ``graph`` as links.

    Each merge is carried by the pair of the two groups that is most alike in the similarity the tree was
    built on, leaving out the pairs of ``excluded`` (node index pairs, either order: the links an expert
    cut); a merge whose every pair is excluded carries no link.
    """
    n = graph.n_nodes
    if n < 2:
        return MergeLinks(np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0))
    similar = linkage_similarity(graph, algorithm)
    tree = _average_tree(similar)
    S = similar.matrix()
    for a, b in excluded:
        S[a, b] = S[b, a] = -np.inf
    members: list[list[int]] = [[k] for k in range(n)]
    i, j, distance = [], [], []
    for left, right, height, _ in tree:
        A, B = members[int(left)], members[int(right)]
        block = S[np.ix_(A, B)]
        best = int(np.argmax(block))
        if np.isfinite(block.flat[best]):
            i.append(A[best // len(B)])
            j.append(B[best % len(B)])
            distance.append(float(height))
        members.append(A + B)
    return MergeLinks(np.asarray(i, np.int64), np.asarray(j, np.int64), np.asarray(distance, np.float64))


__all__ = ["LINKAGE_METHODS", "MergeLinks", "linkage_similarity", "merge_links"]
