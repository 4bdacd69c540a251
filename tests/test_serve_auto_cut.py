"""The review app opens a project on the clusters of ``coindie cluster --auto`` (coindie.serve.cuts)."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient
from typer.testing import CliRunner

from coindie.clustering import ProbabilityGraph, cluster, read_clusters
from coindie.serve import create_app, open_source
from coindie.serve.cuts import START, SideCut, auto_links, components_at

TOKEN = "t0ken-for-tests"
HEADERS = {"X-Coindie-Token": TOKEN}


def _groups(groups) -> list[list[str]]:  # noqa: ANN001
    return sorted(sorted(g) for g in groups)


def _components(n: int, links: list[tuple[int, int]]) -> int:
    """The number of connected components of ``n`` nodes and ``links`` (union-find, as the browser)."""
    parent = list(range(n))

    def find(x: int) -> int:
        while parent[x] != x:
            x = parent[x]
        return x

    for i, j in links:
        parent[find(i)] = find(j)
    return len({find(k) for k in range(n)})


def _cli_auto(project, tmp_path) -> list[list[str]]:  # noqa: ANN001
    from coindie.cli import app

    out = tmp_path / "auto.csv"
    result = CliRunner().invoke(app, ["cluster", str(project), "--auto", "-o", str(out)])
    assert result.exit_code == 0, result.output
    labels = read_clusters(out)
    return _groups([f for f in labels if labels[f] == die] for die in set(labels.values()))


def _weak_face_graph() -> tuple[ProbabilityGraph, dict[str, int]]:
    """Three dies of six faces; L0001D is weak: every probability it has is low (0.1-0.2 with its
    die-mates, 1e-4 with the others), as on a hoard whose scorer does not know its scanner."""
    rng = np.random.default_rng(5)
    names = [f"L{k + 1:04d}D" for k in range(18)]
    die = {name: k // 6 for k, name in enumerate(names)}
    edges = []
    for a in range(18):
        for b in range(a + 1, 18):
            same = die[names[a]] == die[names[b]]
            if a == 0:
                p = rng.uniform(0.1, 0.2) if same else 1e-4
            else:
                p = rng.uniform(0.6, 0.99) if same else rng.uniform(0.0, 0.02)
            edges.append((names[a], names[b], float(p)))
    return ProbabilityGraph.from_edges(edges, names), die


def test_auto_links_at_the_start_are_the_sides_cut_weak_face_included():
    graph, die = _weak_face_graph()
    tau = 0.3
    # the second pass of --auto compares faces by the direction of their rows alone
    links = auto_links([SideCut("D", graph, "consensus", tau, {"measure": "cosine"})], graph.nodes, [])
    start = components_at(links, START, "consensus")
    expected = cluster(graph, "consensus", tau, measure="cosine")
    assert _groups(start.clusters()) == _groups(expected.clusters())
    truth = [[f for f in graph.nodes if die[f] == d] for d in range(3)]
    assert _groups(start.clusters()) == _groups(truth)  # the weak face is with its die
    # the paper's components at 0.95 leave it alone: what the app showed before
    assert ["L0001D"] in cluster(graph, "components", 0.95).clusters()
    # the slider: stricter to the right, looser to the left, every face merged at 0 and apart at 1
    counts = [components_at(links, t, "consensus").n_clusters for t in np.linspace(0.0, 1.0, 21)]
    assert counts == sorted(counts) and counts[0] == 1 and counts[-1] == graph.n_nodes


@pytest.fixture
def auto_served(fresh_project):
    source = open_source(fresh_project)  # no threshold: the sides' own cuts
    return source, TestClient(create_app(source, TOKEN), base_url="http://127.0.0.1:8765")


def test_review_of_a_project_starts_on_cluster_auto(auto_served, fresh_project, tmp_path):
    source, client = auto_served
    assert {cut.side for cut in source.cuts} == {"D", "R"}
    state = client.get("/api/state", headers=HEADERS).json()
    assert state["threshold"] == START and state["method"] == "consensus" and state["links"]
    shown = client.get("/api/clusters", headers=HEADERS).json()
    assert _groups(c["members"] for c in shown["clusters"]) == _cli_auto(fresh_project, tmp_path)
    # the browser's rule on the state it is sent: components of the links above t
    for t in (0.2, START, 0.8):
        n = _components(len(state["nodes"]), [(i, j) for i, j, v in state["links"] if v > t])
        assert n == client.get(f"/api/clusters?threshold={t}", headers=HEADERS).json()["n_clusters"], t


def test_review_edits_on_the_auto_cut_agree_with_the_command_line(auto_served, fresh_project, tmp_path):
    _, client = auto_served
    shown = client.get("/api/clusters", headers=HEADERS).json()
    big = max((c["members"] for c in shown["clusters"]), key=len)
    assert len(big) >= 2
    group, rest = big[:1], big[1:]
    edit = {"action": "split", "a": group[0], "payload": {"group": group, "rest": rest}, "base_seq": 0}
    assert client.post("/api/edits", json=edit, headers=HEADERS).status_code == 200
    after = client.get("/api/clusters", headers=HEADERS).json()
    groups = _groups(c["members"] for c in after["clusters"])
    assert [group[0]] in groups and sorted(rest) in groups
    assert groups == _cli_auto(fresh_project, tmp_path)  # coindie cluster --auto replays the same edit
    face = client.get(f"/api/faces/{group[0]}", headers=HEADERS).json()
    assert face["cluster"] == [group[0]]
    exported = client.get("/api/export/clusters.csv", headers=HEADERS).text.splitlines()[1:]
    assert len(exported) == sum(len(g) for g in groups)
    queue = client.get("/api/queue", headers=HEADERS).json()["items"]
    assert all(0.0 <= it["uncertainty"] <= 1.0 for it in queue)


def test_review_queue_offers_a_weak_singleton_its_die_mates_one_after_another():
    from coindie.clustering.corrections import Edit, replay
    from coindie.serve.queue import review_queue

    graph, die = _weak_face_graph()
    cut = SideCut("D", graph, "consensus", 0.3)  # the first pass's measure: the weak face stays alone
    offered: list[str] = []
    edits: list[Edit] = []
    for k in range(3):
        links = auto_links([cut], graph.nodes, edits)
        assert components_at(links, START, "consensus").labels  # every face has a cluster
        queue = review_queue(graph, links, replay(graph, edits), START)
        items = [it for it in queue if "L0001D" in (it.a, it.b)]
        assert items  # the face alone is offered (a merge near the cut, or its best partner left)
        other = items[0].b if items[0].a == "L0001D" else items[0].a
        offered.append(other)
        edits.append(Edit(k + 1, "cut", "L0001D", other))  # the expert says no: the next partner comes
    assert len(set(offered)) == 3 and all(die[f] == die["L0001D"] for f in offered)
    # with the slider far right, every face alone is still offered with its most probable partner
    links = auto_links([cut], graph.nodes, [])
    strict = components_at(links, 0.95, "consensus")
    alone = {f for f in graph.nodes if list(strict.labels.values()).count(strict.labels[f]) == 1}
    queue = review_queue(graph, links, replay(graph, []), 0.95, limit=1000)
    assert "L0001D" in alone and alone <= {f for it in queue if it.kind == "runner-up" for f in (it.a, it.b)}
