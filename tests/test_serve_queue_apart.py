"""The review queue offers first the pairs that stand apart above the rest of their side though the scorer
judges them different-die: on scans that lower every score, a two-design hoard's few same-die pairs."""

from __future__ import annotations

from pathlib import Path

from fastapi.testclient import TestClient

from coindie.clustering.corrections import pair
from coindie.serve import create_app, open_source
from scored_projects import two_designs

TOKEN = "t0ken-for-tests"
HEADERS = {"X-Coindie-Token": TOKEN}


def test_pairs_apart_come_first_in_the_review_queue_until_decided(tmp_path: Path) -> None:
    """A two-design hoard on scans that lower every score: its 4 same-die pairs score below 0 but stand
    apart above the pairs of one design. ``/api/queue`` offers them first, and only them as such; a pair
    the expert cuts leaves the queue."""
    project, i, j, same_die = two_designs(tmp_path, 4, (-5.0, 0.8), seed=6)
    folder = project.folder
    names = [f"L{k + 1:04d}D" for k in range(40)]
    truth = {pair(names[a], names[b]) for a, b in zip(i[same_die], j[same_die], strict=True)}
    project.close()
    source = open_source(folder)
    assert set(source.apart) == truth
    client = TestClient(create_app(source, TOKEN), base_url="http://127.0.0.1:8765")
    items = client.get("/api/queue", headers=HEADERS).json()["items"]
    first = items[: len(truth)]
    assert {pair(item["a"], item["b"]) for item in first} == truth
    assert all(item["kind"] == "apart" and "perhaps one die" in item["why"] for item in first)
    assert all(item["kind"] != "apart" for item in items[len(truth) :])
    a, b = first[0]["a"], first[0]["b"]
    edit = {"action": "cut", "a": a, "b": b, "base_seq": 0, "client": "test"}
    assert client.post("/api/edits", json=edit, headers=HEADERS).status_code == 200
    left = client.get("/api/queue", headers=HEADERS).json()["items"]
    assert {pair(item["a"], item["b"]) for item in left if item["kind"] == "apart"} == truth - {pair(a, b)}


def test_no_pair_apart_where_the_scorer_sees_the_die_links(tmp_path: Path) -> None:
    """The same hoard on scans the scorer knows: its same-die pairs score far above 0, its own probabilities
    link them, and the queue has no pair apart."""
    project, _, _, _ = two_designs(tmp_path, 4, (12.0, 4.0), seed=6)
    folder = project.folder
    project.close()
    assert open_source(folder).apart == {}
