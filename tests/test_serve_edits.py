"""The edit log: append-only, replayed into corrections, conflicts refused, one result on the command line."""

from __future__ import annotations

import sqlite3

import pytest
from typer.testing import CliRunner

from coindie.cli import app
from coindie.clustering import ProbabilityGraph, cluster, read_clusters
from coindie.clustering.corrections import EditError, corrected_clusters
from coindie.project.edits import EditConflict, EditLog, sidecar_path


def _graph() -> ProbabilityGraph:
    # Two dies {A1..A3}, {B1, B2} joined by one wrong link A3-B1; C alone, its best partner B2.
    edges = [
        ("A1", "A2", 0.99),
        ("A2", "A3", 0.97),
        ("A1", "A3", 0.98),
        ("B1", "B2", 0.99),
        ("A3", "B1", 0.96),
        ("C", "B2", 0.90),
    ]
    return ProbabilityGraph.from_edges(edges)


def _groups(clustering) -> set[frozenset[str]]:
    return {frozenset(c) for c in clustering.clusters()}


def test_edits_replay_cut_link_move_split_undo_redo(tmp_path):
    graph, log = _graph(), EditLog(tmp_path / "log.sqlite")
    assert _groups(log.clusters(graph, 0.95)) == {frozenset({"A1", "A2", "A3", "B1", "B2"}), frozenset({"C"})}
    cut = log.append(graph, "cut", "A3", "B1", base_seq=0, threshold=0.95)
    assert _groups(log.clusters(graph, 0.95)) == {
        frozenset({"A1", "A2", "A3"}),
        frozenset({"B1", "B2"}),
        frozenset({"C"}),
    }
    # The cut holds whatever the threshold: at 0.5 C joins B's cluster, A stays apart.
    assert frozenset({"B1", "B2", "C"}) in _groups(log.clusters(graph, 0.5))
    log.append(graph, "link", "C", "B2", base_seq=1)
    assert frozenset({"B1", "B2", "C"}) in _groups(log.clusters(graph, 0.95))
    log.append(graph, "undo", payload={"target": 2}, base_seq=2)
    assert frozenset({"C"}) in _groups(log.clusters(graph, 0.95))
    log.append(graph, "redo", payload={"target": 2}, base_seq=3)
    assert frozenset({"B1", "B2", "C"}) in _groups(log.clusters(graph, 0.95))
    log.append(graph, "move", "A1", "C", base_seq=4)
    assert frozenset({"A1", "B1", "B2", "C"}) in _groups(log.clusters(graph, 0.95))
    log.append(graph, "split", "A1", payload={"group": ["A1", "C"], "rest": ["B1", "B2"]}, base_seq=5)
    assert {frozenset({"A1", "C"}), frozenset({"B1", "B2"}), frozenset({"A2", "A3"})} <= _groups(
        log.clusters(graph, 0.95)
    )
    assert [e.action for e in log.edits()] == ["cut", "link", "undo", "redo", "move", "split"]
    assert log.edits()[0].payload["before"] == [["A1", "A2", "A3", "B1", "B2"]]
    assert cut.payload["after"] == [["A1", "A2", "A3"], ["B1", "B2"]]


def test_edits_log_is_append_only(tmp_path):
    graph, log = _graph(), EditLog(tmp_path / "log.sqlite")
    log.append(graph, "cut", "A3", "B1", base_seq=0)
    db = sqlite3.connect(tmp_path / "log.sqlite")
    with pytest.raises(sqlite3.DatabaseError, match="append-only"):
        db.execute("DELETE FROM edits")
    with pytest.raises(sqlite3.DatabaseError, match="append-only"):
        db.execute("UPDATE edits SET action = 'link'")


def test_edits_stale_conflicting_edit_is_refused_and_other_kept(tmp_path):
    graph, log = _graph(), EditLog(tmp_path / "log.sqlite")
    log.append(graph, "cut", "A3", "B1", base_seq=0, client="tab1")
    with pytest.raises(EditConflict, match="edit 1 .*A3"):
        log.append(graph, "link", "A3", "B1", base_seq=0, client="tab2")
    log.append(graph, "link", "C", "B2", base_seq=0, client="tab2")  # stale but about other faces
    assert [(e.action, e.payload["client"]) for e in log.edits()] == [("cut", "tab1"), ("link", "tab2")]


@pytest.mark.parametrize(
    ("action", "a", "b", "payload", "message"),
    [
        ("cut", "A1", "NOPE", {}, "no face NOPE"),
        ("cut", "A1", "A1", {}, "two different faces"),
        ("shred", "A1", "A2", {}, "unknown edit action"),
        ("undo", None, None, {"target": 7}, "not an edit of this log"),
        ("register", "A1", "A2", {"probability": 3}, "probability in"),
    ],
)
def test_edits_bad_edit_is_refused_with_its_reason(tmp_path, action, a, b, payload, message):
    log = EditLog(tmp_path / "log.sqlite")
    with pytest.raises(EditError, match=message):
        log.append(_graph(), action, a, b, payload, base_seq=0)
    assert log.last_seq() == 0


def test_edits_undo_twice_is_refused(tmp_path):
    graph, log = _graph(), EditLog(tmp_path / "log.sqlite")
    log.append(graph, "cut", "A3", "B1", base_seq=0)
    log.append(graph, "undo", payload={"target": 1}, base_seq=1)
    with pytest.raises(EditError, match="already undone"):
        log.append(graph, "undo", payload={"target": 1}, base_seq=2)


def test_edits_without_edits_replay_is_the_automatic_clustering(tmp_path):
    graph = _graph()
    log = EditLog(tmp_path / "log.sqlite")
    for tau in (0.0, 0.5, 0.95, 0.985):
        assert (
            corrected_clusters(graph, log.corrections(graph), tau).labels
            == cluster(graph, "components", tau).labels
        )


def test_edits_cli_cluster_applies_the_sidecar_log(tmp_path):
    from coindie.clustering import write_graph

    graph_path = write_graph(_graph(), tmp_path / "graph.json")
    log = EditLog(sidecar_path(graph_path))
    log.append(read_graph_of(graph_path), "cut", "A3", "B1", base_seq=0)
    log.close()
    out = tmp_path / "clusters.csv"
    result = CliRunner().invoke(app, ["cluster", str(graph_path), "-o", str(out), "--threshold", "0.95"])
    assert result.exit_code == 0, result.output
    assert "1 expert edits" in result.output
    labels = read_clusters(out)
    assert labels["A3"] != labels["B1"] and labels["A1"] == labels["A3"]


def read_graph_of(path):
    from coindie.clustering import read_graph

    return read_graph(path)


def test_edits_cli_cluster_of_a_project_agrees_with_the_server(fresh_project, tmp_path):
    from coindie.serve import open_source

    source = open_source(fresh_project, threshold=0.5)
    first, second = source.graph.nodes[0], source.graph.nodes[1]
    source.log.append(source.graph, "move", first, None, base_seq=0)
    source.log.append(source.graph, "link", first, source.graph.nodes[-1], base_seq=1)
    expected = source.log.clusters(source.graph, 0.5)
    out = tmp_path / "clusters.csv"
    result = CliRunner().invoke(app, ["cluster", str(fresh_project), "-o", str(out), "--threshold", "0.5"])
    assert result.exit_code == 0, result.output
    got = read_clusters(out)
    assert {frozenset(f for f in got if got[f] == got[x]) for x in got} == _groups(expected)
    assert got[first] == got[source.graph.nodes[-1]]
    assert expected.labels[first] != expected.labels[second] or second == source.graph.nodes[-1]
