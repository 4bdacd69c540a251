"""Die clustering of a same-die probability graph (Riedones3D, sections 3.3 and 4.3).

>>> from coindie.clustering import read_graph, get_algorithm, cluster, write_clusters, evaluate
>>> graph = read_graph("graph.json")  # doctest: +SKIP  (the paper's node-link JSON, or a pairs CSV)
>>> clusters = get_algorithm("components", threshold=0.95).fit(graph).clustering_  # doctest: +SKIP
>>> clusters = cluster(graph, "components", threshold=0.95)  # doctest: +SKIP  (the same, in one call)
>>> write_clusters(clusters, "clusters.csv")  # doctest: +SKIP  (the paper's ``name, die``)
"""

from coindie.clustering.algorithms import (
    METHODS,
    PAPER_THRESHOLD,
    AverageLinkage,
    Clustering,
    ClusteringAlgorithm,
    ConnectedComponents,
    Leiden,
    cluster,
    clusters_from_labels,
    combined,
    get_algorithm,
    list_algorithms,
    read_clusters,
    register_algorithm,
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
    "AverageLinkage",
    "Clustering",
    "ClusteringAlgorithm",
    "ConnectedComponents",
    "Evaluation",
    "GraphError",
    "Leiden",
    "Mistake",
    "ProbabilityGraph",
    "ThresholdChoice",
    "cluster",
    "clusters_from_labels",
    "combined",
    "evaluate",
    "get_algorithm",
    "list_algorithms",
    "mistakes",
    "pairwise_counts",
    "read_clusters",
    "read_graph",
    "register_algorithm",
    "select_threshold",
    "select_threshold_unsupervised",
    "threshold_grid",
    "write_clusters",
    "write_graph",
]
