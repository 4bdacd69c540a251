"""Die clustering of a same-die probability graph (Riedones3D, sections 3.3 and 4.3).

>>> from coindie.clustering import read_graph, cluster, write_clusters, evaluate
>>> graph = read_graph("graph.json")  # doctest: +SKIP  (the paper's node-link JSON, or a pairs CSV)
>>> clusters = cluster(graph, "components", threshold=0.95)  # doctest: +SKIP
>>> write_clusters(clusters, "clusters.csv")  # doctest: +SKIP  (the paper's ``name, die``)
"""

from coindie.clustering.algorithms import (
    METHODS,
    PAPER_THRESHOLD,
    Clustering,
    cluster,
    clusters_from_labels,
    read_clusters,
    write_clusters,
)
from coindie.clustering.evaluation import Evaluation, Mistake, evaluate, mistakes, pairwise_counts
from coindie.clustering.graph import GraphError, ProbabilityGraph, read_graph, write_graph
from coindie.clustering.threshold import (
    ThresholdChoice,
    select_threshold,
    select_threshold_unsupervised,
    threshold_grid,
)

__all__ = [
    "METHODS",
    "PAPER_THRESHOLD",
    "Clustering",
    "Evaluation",
    "GraphError",
    "Mistake",
    "ProbabilityGraph",
    "ThresholdChoice",
    "cluster",
    "clusters_from_labels",
    "evaluate",
    "mistakes",
    "pairwise_counts",
    "read_clusters",
    "read_graph",
    "select_threshold",
    "select_threshold_unsupervised",
    "threshold_grid",
    "write_clusters",
    "write_graph",
]
