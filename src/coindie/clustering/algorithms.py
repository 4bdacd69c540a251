"""Die clusters from a probability graph, by one of three methods behind one call.

- ``components`` (the paper's, section 3.3): keep the links whose probability is above ``threshold`` (the
  authors' viewer keeps ``weight > threshold``); clusters are the connected components. One wrong link
  merges two whole dies, so errors chain.
- ``average``: average-linkage agglomerative clustering on the distance ``1 - p`` (unscored pairs at
  distance 1), cut at ``1 - threshold``: two clusters merge only when their faces are, on average, linked
  above the threshold, so one wrong link cannot merge two dies.
- ``leiden``: community detection (Leiden, modularity with a resolution) on the thresholded graph weighted
  by the probabilities: a component made of two dense groups joined by a few links is cut in two.

Faces without any kept link are clusters of their own. Cluster labels are 0, 1, ... in order of the first
face (in the graph's node order) of each cluster.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import IntArray
from coindie.clustering.graph import ProbabilityGraph
from coindie.errors import ParameterError
from coindie.ids import parse_face_id

METHODS = ("components", "average", "leiden")
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


def cluster(
    graph: ProbabilityGraph,
    method: str = "components",
    threshold: float = PAPER_THRESHOLD,
    *,
    resolution: float = 1.0,
    seed: int = 0,
) -> Clustering:
    """Cluster the faces of ``graph`` into dies.

    Args:
        method: ``components``, ``average`` or ``leiden`` (see the module's docstring).
        threshold: links with a probability above it count (for ``average``: the cut at distance
            ``1 - threshold``).
        resolution: Leiden's modularity resolution (higher: more, smaller clusters).
        seed: Leiden's random seed.
    """
    if method not in METHODS:
        raise ParameterError(f"The clustering method must be one of {', '.join(METHODS)}. Got {method!r}.")
    if not (isinstance(threshold, int | float) and 0.0 <= threshold <= 1.0):
        raise ParameterError(f"The clustering threshold must be in [0, 1]. Got {threshold!r}.")
    if graph.n_nodes == 0:
        return Clustering({}, method, float(threshold))
    if method == "components":
        raw = _components(graph, threshold)
    elif method == "average":
        raw = _average_linkage(graph, threshold)
    else:
        raw = _leiden(graph, threshold, resolution, seed)
    return Clustering(dict(zip(graph.nodes, _relabelled(raw), strict=True)), method, float(threshold))


def _components(graph: ProbabilityGraph, threshold: float) -> IntArray:
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    kept = graph.probability > threshold
    n = graph.n_nodes
    adjacency = coo_matrix((np.ones(int(kept.sum())), (graph.i[kept], graph.j[kept])), shape=(n, n))
    return connected_components(adjacency, directed=False)[1]


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
    "Clustering",
    "cluster",
    "clusters_from_labels",
    "read_clusters",
    "write_clusters",
]
