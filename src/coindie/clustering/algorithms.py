"""Die clusters from a probability graph: four clustering algorithms with one estimator shape.

Each algorithm is a :class:`ClusteringAlgorithm` (scikit-learn's shape): its parameters are declared
through :mod:`coindie.params` and stored on construction, ``fit(graph)`` returns the estimator, with
``labels_`` (one label per node of the graph, in its node order) and ``clustering_`` (face id -> label).
They are registered by name (:func:`get_algorithm`, :func:`list_algorithms`); :func:`cluster` is the
one-call shortcut.

- ``components`` (the paper's, section 3.3): keep the links whose probability is above ``threshold`` (the
  authors' viewer keeps ``weight > threshold``); clusters are the connected components. One wrong link
  merges two whole dies, so errors chain.
- ``average``: average-linkage agglomerative clustering on the distance ``1 - p`` (unscored pairs at
  distance 1), cut at ``1 - threshold``: two clusters merge only when their faces are, on average, linked
  above the threshold, so one wrong link cannot merge two dies.
- ``consensus``: average-linkage clustering on the probabilities averaged with their *neighbourhood
  consensus* (:mod:`coindie.clustering.consensus`): two faces are alike when they are linked to the same
  faces (and to faces linked to the same faces), so
  a same-die pair whose own registration or score failed is still joined through its die's other coins,
  and two dies of one design whose coins share no strong neighbour stay apart. ``threshold`` is the
  average similarity above which two clusters merge (:data:`CONSENSUS_THRESHOLD`).
- ``leiden``: community detection (Leiden, modularity with a resolution) on the thresholded graph weighted
  by the probabilities: a component made of two dense groups joined by a few links is cut in two.

Faces without any kept link are clusters of their own. Cluster labels are 0, 1, ... in order of the first
face (in the graph's node order) of each cluster.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, Self

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import IntArray
from coindie.clustering.consensus import (
    CONSENSUS_DEPTH,
    CONSENSUS_THRESHOLD,
    MEASURES,
    SHARED,
    consensus_graph,
)
from coindie.clustering.graph import ProbabilityGraph
from coindie.errors import ParameterError
from coindie.ids import parse_face_id
from coindie.params import Configurable, Param, param

#: The threshold the paper found best on its validation split (obverses without beard).
PAPER_THRESHOLD = 0.95


@dataclass(frozen=True)
class Clustering:
    """Face id -> cluster label, with the method and threshold that made it."""

    labels: dict[str, int]
    method: str = ""
    threshold: float = float("nan")

    @property
    def n_clusters(self) -> int:
        return len(set(self.labels.values()))

    def clusters(self) -> list[list[str]]:
        """Faces of each cluster, largest first."""
        groups: dict[int, list[str]] = {}
        for face, label in self.labels.items():
            groups.setdefault(label, []).append(face)
        return sorted(groups.values(), key=lambda g: (-len(g), g[0]))


@dataclass(frozen=True, kw_only=True)
class ClusteringAlgorithm(Configurable):
    """Base of the clustering algorithms: declared parameters, ``fit(graph)`` -> self, ``labels_``.

    A subclass sets ``NAME`` (its registry name) and implements ``_raw_labels`` (any integer labels of the
    nodes of a non-empty graph); the base relabels them 0, 1, ... in order of first appearance.
    """

    NAME: ClassVar[str] = "clustering"

    threshold: float = param(
        PAPER_THRESHOLD, doc="links with a probability above it count", low=0.0, high=1.0
    )

    if TYPE_CHECKING:  # set by fit, not parameters (not dataclass fields)
        labels_: IntArray
        clustering_: Clustering

    def fit(self, graph: ProbabilityGraph) -> Self:
        """Cluster the faces of ``graph``; sets ``labels_`` (graph node order) and ``clustering_``."""
        raw = self._raw_labels(graph) if graph.n_nodes else np.zeros(0, dtype=np.int64)
        labels = np.asarray(_relabelled(raw), dtype=np.int64)
        # The parameters are frozen; what fit learns is set beside them, as scikit-learn's trailing "_".
        object.__setattr__(self, "labels_", labels)
        mapping = dict(zip(graph.nodes, labels.tolist(), strict=True))
        object.__setattr__(self, "clustering_", Clustering(mapping, self.NAME, self.threshold))
        return self

    def _raw_labels(self, graph: ProbabilityGraph) -> IntArray:
        raise NotImplementedError


_ALGORITHMS: dict[str, type[ClusteringAlgorithm]] = {}


def register_algorithm(algorithm: type[ClusteringAlgorithm]) -> type[ClusteringAlgorithm]:
    """Register a clustering algorithm under its ``NAME`` (usable as a class decorator)."""
    if algorithm.NAME in _ALGORITHMS:
        raise ValueError(f"a clustering algorithm is already registered as {algorithm.NAME!r}")
    _ALGORITHMS[algorithm.NAME] = algorithm
    return algorithm


def list_algorithms() -> list[str]:
    """The names of the registered clustering algorithms, in registration order."""
    return list(_ALGORITHMS)


def algorithm_class(name: str) -> type[ClusteringAlgorithm]:
    """The class registered as ``name`` (a ParameterError lists the known names)."""
    Param(str, "components", "the clustering algorithm", choices=tuple(_ALGORITHMS)).check(
        "cluster", "method", name
    )
    return _ALGORITHMS[name]


def get_algorithm(name: str, **params: Any) -> ClusteringAlgorithm:
    """The algorithm registered as ``name``, built with ``params`` (checked by their declarations)."""
    algorithm = algorithm_class(name)
    unknown = set(params) - set(algorithm.declared())
    if unknown:
        raise ParameterError(
            f"The clustering algorithm {name!r} has no parameter {sorted(unknown)[0]!r}. "
            f"Its parameters: {', '.join(algorithm.declared())}."
        )
    return algorithm(**params)


@register_algorithm
@dataclass(frozen=True, kw_only=True)
class ConnectedComponents(ClusteringAlgorithm):
    """The paper's: the connected components of the links above the threshold."""

    NAME: ClassVar[str] = "components"

    def _raw_labels(self, graph: ProbabilityGraph) -> IntArray:
        return _components(graph, self.threshold)


@register_algorithm
@dataclass(frozen=True, kw_only=True)
class AverageLinkage(ClusteringAlgorithm):
    """Average-linkage agglomerative clustering on ``1 - p``, cut at ``1 - threshold``."""

    NAME: ClassVar[str] = "average"

    def _raw_labels(self, graph: ProbabilityGraph) -> IntArray:
        return _average_linkage(graph, self.threshold)


@register_algorithm
@dataclass(frozen=True, kw_only=True)
class ConsensusLinkage(ClusteringAlgorithm):
    """Average-linkage clustering on ``1 -`` :func:`~coindie.clustering.consensus.consensus_similarity`
    (the probabilities averaged with their consensus, ``depth`` steps), cut at ``1 - threshold``."""

    NAME: ClassVar[str] = "consensus"

    threshold: float = param(
        CONSENSUS_THRESHOLD,
        doc="two clusters merge when the average consensus of their faces is above it",
        low=0.0,
        high=1.0,
    )

    depth: int = param(CONSENSUS_DEPTH, doc="consensus steps averaged with the probabilities", low=1, high=4)

    measure: str = param(
        SHARED,
        doc="how two faces' rows of probabilities are compared: 'shared' (cosine times the ratio of their "
        "norms), or 'cosine' (direction alone: the second pass of --auto, on hoards whose dies do not "
        "stand out)",
        choices=MEASURES,
    )

    def _raw_labels(self, graph: ProbabilityGraph) -> IntArray:
        return _average_linkage(consensus_graph(graph, self.depth, self.measure), self.threshold)


@register_algorithm
@dataclass(frozen=True, kw_only=True)
class Leiden(ClusteringAlgorithm):
    """Leiden communities (modularity with a resolution) of the links above the threshold."""

    NAME: ClassVar[str] = "leiden"

    resolution: float = param(1.0, doc="modularity resolution (higher: more, smaller clusters)", low=0.0)
    seed: int = param(0, doc="Leiden's random seed", low=0)

    def _raw_labels(self, graph: ProbabilityGraph) -> IntArray:
        return _leiden(graph, self.threshold, self.resolution, self.seed)


#: The registered algorithms' names.
METHODS = tuple(list_algorithms())


def cluster(
    graph: ProbabilityGraph,
    method: str = "components",
    threshold: float = PAPER_THRESHOLD,
    *,
    resolution: float = 1.0,
    seed: int = 0,
    measure: str = SHARED,
) -> Clustering:
    """Cluster the faces of ``graph`` into dies: ``get_algorithm(method, ...).fit(graph).clustering_``.

    Args:
        method: ``components``, ``average``, ``consensus`` or ``leiden`` (see the module's docstring).
        threshold: links with a probability above it count (for ``average``: the cut at distance
            ``1 - threshold``).
        resolution: Leiden's modularity resolution (higher: more, smaller clusters).
        seed: Leiden's random seed.
        measure: how ``consensus`` compares two faces' rows (``shared`` or ``cosine``).
    """
    extra = method_params(method, resolution=resolution, seed=seed, measure=measure)
    return get_algorithm(method, threshold=threshold, **extra).fit(graph).clustering_


def method_params(method: str, **params: Any) -> dict[str, Any]:
    """Of ``params``, those that ``method``'s algorithm declares (Leiden's resolution and seed, the
    consensus's measure), for :func:`get_algorithm`."""
    declared = algorithm_class(method).declared()
    return {name: value for name, value in params.items() if name in declared}


def _components(graph: ProbabilityGraph, threshold: float) -> IntArray:
    kept = graph.probability > threshold
    return _component_labels(graph.n_nodes, graph.i[kept], graph.j[kept])


def _component_labels(n: int, i: IntArray, j: IntArray) -> IntArray:
    """(n,) component of each of ``n`` nodes joined by the links ``i``–``j`` (scipy's labels)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    adjacency = coo_matrix((np.ones(len(i)), (i, j)), shape=(n, n))
    return connected_components(adjacency, directed=False)[1]


def link_components(
    nodes: Sequence[str], i: IntArray, j: IntArray, method: str, threshold: float
) -> Clustering:
    """The clusters that the links ``i``–``j`` (indices into ``nodes``) make: their connected components,
    labelled 0, 1, ... in order of first appearance in ``nodes``; ``method`` and ``threshold``: what made
    the links, for the record."""
    if not nodes:
        return Clustering({}, method, float(threshold))
    raw = _component_labels(len(nodes), np.asarray(i, np.int64), np.asarray(j, np.int64))
    return Clustering(dict(zip(nodes, _relabelled(raw), strict=True)), method, float(threshold))


def _average_linkage(graph: ProbabilityGraph, threshold: float) -> IntArray:
    from scipy.cluster.hierarchy import fcluster

    if graph.n_nodes == 1:
        return np.zeros(1, dtype=np.int64)
    # fcluster merges while the cophenetic distance is <= t: a hair below 1 - threshold keeps the strict
    # "probability above the threshold" of the other methods.
    t = np.nextafter(1.0 - threshold, -np.inf)
    return fcluster(_average_tree(graph), t=t, criterion="distance").astype(np.int64)


@lru_cache(maxsize=4)
def _average_tree(graph: ProbabilityGraph) -> NDArray[np.float64]:
    """The average-linkage tree of a graph (kept for a few graphs: choosing τ cuts one tree many times)."""
    from scipy.cluster.hierarchy import linkage
    from scipy.spatial.distance import squareform

    distance = 1.0 - graph.matrix()
    np.fill_diagonal(distance, 0.0)
    return linkage(squareform(distance, checks=False), method="average")


def _leiden(graph: ProbabilityGraph, threshold: float, resolution: float, seed: int) -> IntArray:
    import igraph
    import leidenalg

    kept = graph.probability > threshold
    edges = list(zip(graph.i[kept].tolist(), graph.j[kept].tolist(), strict=True))
    g = igraph.Graph(n=graph.n_nodes, edges=edges)
    g.es["weight"] = graph.probability[kept].tolist()
    partition = leidenalg.find_partition(
        g, leidenalg.RBConfigurationVertexPartition, weights="weight", resolution_parameter=resolution,
        seed=seed, n_iterations=-1,
    )  # fmt: skip
    return np.asarray(partition.membership, dtype=np.int64)


def _relabelled(raw: IntArray) -> list[int]:
    """Labels 0, 1, ... in order of first appearance."""
    first: dict[int, int] = {}
    return [first.setdefault(int(r), len(first)) for r in raw]


# ------------------------------------------------------------------------------------------------ files


def combined(parts: Iterable[Clustering], method: str = "") -> Clustering:
    """One clustering of disjoint sets of faces (a hoard's sides) clustered apart: each part's labels
    moved past the previous parts' so that no two parts share a label."""
    labels: dict[str, int] = {}
    for part in parts:
        offset = len(set(labels.values()))
        labels |= {face: offset + label for face, label in part.labels.items()}
    return Clustering(labels, method)


def write_clusters(clustering: Clustering | Mapping[str, int | str], path: str | Path) -> Path:
    """Write the paper's cluster CSV: header ``name, die``, one face per line, faces of one cluster together
    (largest cluster first)."""
    labels = clustering.labels if isinstance(clustering, Clustering) else dict(clustering)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    order = sorted(labels, key=lambda face: (_cluster_rank(labels)[labels[face]], face))
    with path.open("w", newline="") as handle:
        handle.write("name, die\n")
        for face in order:
            handle.write(f"{face}, {labels[face]}\n")
    return path


def _cluster_rank(labels: Mapping[str, int | str]) -> dict[int | str, int]:
    sizes: dict[int | str, int] = {}
    for label in labels.values():
        sizes[label] = sizes.get(label, 0) + 1
    return {label: rank for rank, label in enumerate(sorted(sizes, key=lambda lab: (-sizes[lab], str(lab))))}


def read_clusters(path: str | Path) -> dict[str, str]:
    """Face id (canonical key) -> cluster or die label, from a CSV ``name, die`` (the paper's) or
    ``coin_id,die_id`` (coindie's labels); a ``LabelsError`` names the file and line of a bad row."""
    from coindie.io.labels import read_labels

    labels = read_labels(path)
    return {face.key: labels[face] for face in labels}


def clusters_from_labels(labels: Mapping[str, object], faces: Iterable[str] | None = None) -> dict[str, str]:
    """Canonical face keys -> label strings (restricted to ``faces`` when given)."""
    keyed = {parse_face_id(str(face)).key: str(label) for face, label in labels.items()}
    if faces is None:
        return keyed
    wanted = {parse_face_id(str(f)).key for f in faces}
    return {face: label for face, label in keyed.items() if face in wanted}


__all__ = [
    "METHODS",
    "PAPER_THRESHOLD",
    "AverageLinkage",
    "Clustering",
    "ClusteringAlgorithm",
    "ConnectedComponents",
    "Leiden",
    "algorithm_class",
    "cluster",
    "clusters_from_labels",
    "combined",
    "get_algorithm",
    "link_components",
    "list_algorithms",
    "read_clusters",
    "register_algorithm",
    "write_clusters",
]
