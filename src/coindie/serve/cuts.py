"""The links the review app cuts with its slider, and the clusters they give.

Two ways to start a review:

- **at a threshold τ** (``coindie serve --threshold``, and every bare graph file): the paper's connected
  components of the probabilities above τ, the slider moving τ itself;
- **as ``coindie cluster --auto`` cuts each side** (a project served without ``--threshold``): each side's
  graph, clustering and cut chosen without labels (:meth:`coindie.project.Project.auto_graph`), its
  linkage tree given as one link per merge (:func:`coindie.clustering.merges.merge_links`). A link's value
  is its merge's similarity put on the slider's scale, piecewise linearly, so that every side's own cut
  falls at :data:`START`: at the start the app shows exactly the clusters of ``coindie cluster --auto``,
  and the slider makes every side stricter (right) or looser (left) together.

Either way the clusters at slider value t are the connected components of the links above t and the
forced links, without the cut ones (:func:`components_at`), in the browser and on the server alike, and
on the start they are those of :func:`coindie.clustering.corrections.corrected_clusters`, the command
line's.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from coindie.arrays import FloatArray
from coindie.clustering import Clustering, ProbabilityGraph, get_algorithm
from coindie.clustering.algorithms import link_components
from coindie.clustering.corrections import (
    Corrections,
    Edit,
    corrected_graph,
    corrected_tree_links,
    pair,
    side_corrections,
)
from coindie.clustering.merges import LINKAGE_METHODS

#: Where each side's own cut sits on the slider when the app starts from ``coindie cluster --auto``.
START = 0.5

#: Decimals of the link values the server uses and sends (the browser compares the same numbers).
DECIMALS = 5

Pair = tuple[str, str]


@dataclass(frozen=True)
class SideCut:
    """One side's clusters as ``coindie cluster --auto`` makes them: its graph (calibrated on the hoard,
    each face's pull taken off where the second pass ran), the method, its cut and parameters."""

    side: str
    graph: ProbabilityGraph
    method: str
    threshold: float
    params: dict[str, Any] = field(default_factory=dict)
    how: str = ""


@dataclass(frozen=True)
class ReviewLinks:
    """The links the slider cuts: face pairs with their values on the slider's scale (a link is kept
    above t), the forced links (kept at any t) and whether the links are a linkage tree's merges."""

    nodes: tuple[str, ...]
    pairs: list[Pair]
    value: FloatArray
    forced: list[Pair]
    tree: bool


def threshold_links(graph: ProbabilityGraph, corrections: Corrections) -> ReviewLinks:
    """The paper's start: every scored link not cut, valued by its (corrected) probability."""
    corrected = corrected_graph(graph, corrections)
    pairs, values = [], []
    for a, b, p in corrected.edges():
        key = pair(a, b)
        if key not in corrections.cut:
            pairs.append(key)
            values.append(p)
    return ReviewLinks(graph.nodes, pairs, np.asarray(values, np.float64), sorted(corrections.forced), False)


def auto_links(cuts: Sequence[SideCut], nodes: tuple[str, ...], edits: Sequence[Edit]) -> ReviewLinks:
    """Each side's cut tree, every side's own cut at :data:`START`; ``edits``: the log, each side
    replaying the edits about its own faces (:func:`coindie.clustering.corrections.side_corrections`)."""
    pairs: list[Pair] = []
    values: list[FloatArray] = []
    forced: list[Pair] = []
    for cut in cuts:
        corrections = side_corrections(cut.graph, edits)
        forced += sorted(corrections.forced)
        if cut.method not in LINKAGE_METHODS:  # the paper's components on this side, at its own τ
            side = threshold_links(cut.graph, corrections)
            pairs += side.pairs
            values.append(_on_slider(side.value, cut.threshold, side.value > cut.threshold))
            continue
        corrected = corrected_graph(cut.graph, corrections)
        algorithm = get_algorithm(cut.method, threshold=cut.threshold, **cut.params)
        links = corrected_tree_links(corrected, corrections, algorithm)
        names = corrected.nodes
        pairs += [pair(names[i], names[j]) for i, j in zip(links.i, links.j, strict=True)]
        values.append(_on_slider(1.0 - links.distance, cut.threshold, links.kept(cut.threshold)))
    value = np.concatenate(values) if values else np.zeros(0)
    return ReviewLinks(nodes, pairs, value, forced, True)


def _on_slider(similarity: FloatArray, threshold: float, kept: np.ndarray) -> FloatArray:
    """Similarities cut at ``threshold`` put on the slider's scale (``threshold`` -> :data:`START`,
    0 -> 0, 1 -> 1, linear between), rounded to :data:`DECIMALS`; the links of the cut (``kept``) stay
    above :data:`START` and the others at or below it whatever the rounding."""
    tau = min(max(threshold, 1e-9), 1.0 - 1e-9)
    x = np.clip(similarity, 0.0, 1.0)
    value = np.where(x <= tau, START * x / tau, START + (1.0 - START) * (x - tau) / (1.0 - tau))
    value = np.round(value, DECIMALS)
    step = 10.0**-DECIMALS
    return np.where(kept, np.maximum(value, START + step), np.minimum(value, START))


def components_at(links: ReviewLinks, t: float, method: str) -> Clustering:
    """The clusters at slider value ``t``: components of the links above ``t`` and the forced links."""
    index = {face: k for k, face in enumerate(links.nodes)}
    kept = [p for p, v in zip(links.pairs, links.value, strict=True) if v > t] + list(links.forced)
    kept = [(a, b) for a, b in kept if a in index and b in index]
    i = np.array([index[a] for a, _ in kept], np.int64)
    j = np.array([index[b] for _, b in kept], np.int64)
    return link_components(links.nodes, i, j, method, t)


__all__ = [
    "DECIMALS",
    "START",
    "ReviewLinks",
    "SideCut",
    "auto_links",
    "components_at",
    "threshold_links",
]
