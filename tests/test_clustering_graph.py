"""The probability graph and the paper's formats, on the real beard graph of Riedones3D."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from coindie.clustering import (
    GraphError,
    ProbabilityGraph,
    cluster,
    read_clusters,
    read_graph,
    write_clusters,
    write_graph,
)
from real_data import real_file


@pytest.fixture(scope="module")
def beard() -> ProbabilityGraph:
    return read_graph(real_file("beard_probability_graph.json"))


def _edge_map(graph: ProbabilityGraph) -> dict[frozenset, float]:
    return {frozenset((a, b)): p for a, b, p in graph.edges()}


def test_reads_the_real_beard_graph(beard: ProbabilityGraph) -> None:
    raw = json.loads(real_file("beard_probability_graph.json").read_text())
    assert beard.n_nodes == 81 and beard.n_edges == 3240 == len(raw["links"])
    assert beard.nodes[0] == "L0001D" and beard.nodes[-1] == "L0081D"
    edges = _edge_map(beard)
    for link in raw["links"][:50]:
        assert edges[frozenset((link["source"], link["target"]))] == link["weight"]


@pytest.mark.parametrize("name", ["graph.json", "pairs.csv"])
def test_writing_and_reading_round_trips_the_beard_graph(
    beard: ProbabilityGraph, tmp_path: Path, name
) -> None:
    again = read_graph(write_graph(beard, tmp_path / name))
    assert again.nodes == beard.nodes
    assert _edge_map(again) == _edge_map(beard)


def test_node_link_output_is_what_networkx_reads(beard: ProbabilityGraph, tmp_path: Path) -> None:
    import networkx as nx

    document = json.loads(write_graph(beard, tmp_path / "graph.json").read_text())
    g = nx.node_link_graph(document, edges="links")
    assert g.number_of_nodes() == 81 and g.number_of_edges() == 3240
    a, b, p = next(beard.edges())
    assert g[a][b]["weight"] == p


def test_cluster_csv_round_trips_in_the_papers_format(beard: ProbabilityGraph, tmp_path: Path) -> None:
    clusters = cluster(beard, "components", 0.95)
    path = write_clusters(clusters, tmp_path / "clusters.csv")
    assert path.read_text().splitlines()[0] == "name, die"
    back = read_clusters(path)
    assert set(back) == set(beard.nodes)
    assert {f: str(c) for f, c in clusters.labels.items()} == back


def test_ids_are_canonical_and_both_directions_average(tmp_path: Path) -> None:
    graph = ProbabilityGraph.from_edges([("L082D", "L0083D", 0.2), ("L083D", "L0082D", 0.6)], ["L0084D"])
    assert graph.nodes == ("L0084D", "L0082D", "L0083D")
    assert list(graph.edges()) == [("L0082D", "L0083D", pytest.approx(0.4))]
    P = graph.matrix()
    assert P.shape == (3, 3) and np.allclose(np.diag(P), 1.0) and P[1, 2] == P[2, 1] == pytest.approx(0.4)
    sub = graph.subgraph(["L0083D", "L0084D"])
    assert sub.nodes == ("L0084D", "L0083D") and sub.n_edges == 0


def test_bad_files_name_the_file_and_problem(tmp_path: Path) -> None:
    csv_path = tmp_path / "pairs.csv"
    csv_path.write_text("source,target,probability\nL0001D,L0002D,1.5\n")
    with pytest.raises(GraphError, match=r"pairs.csv.*not in \[0, 1\]"):
        read_graph(csv_path)
    csv_path.write_text("a,b\n1,2\n")
    with pytest.raises(GraphError, match="columns source, target, probability"):
        read_graph(csv_path)
    csv_path.write_text("source,target,probability\nL0001D,L0002D,high\n")
    with pytest.raises(GraphError, match="line 2"):
        read_graph(csv_path)
    json_path = tmp_path / "graph.json"
    json_path.write_text('{"nodes": []')
    with pytest.raises(GraphError, match="graph.json"):
        read_graph(json_path)
    with pytest.raises(GraphError, match="no such file"):
        read_graph(tmp_path / "missing.json")
