"""coindie cluster and coindie eval on the real beard graph and on hand-made files."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.clustering import read_clusters
from real_data import real_file


def _beard() -> str:
    """The real beard graph of the paper (the test skips without ../shared beside the clone)."""
    return str(real_file("beard_probability_graph.json"))


def _invoke(*args: str):  # noqa: ANN202
    return CliRunner().invoke(app, list(args))


def test_cluster_the_real_beard_graph_at_the_papers_threshold(tmp_path: Path) -> None:
    out = tmp_path / "clusters.csv"
    result = _invoke("cluster", _beard(), "-o", str(out), "--json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.output)
    assert report["threshold"] == 0.95 and report["n_faces"] == 81 and report["n_clusters"] == 10
    assert len(read_clusters(out)) == 81 and sum(report["sizes"]) == 81


def test_auto_threshold_and_eval_against_labels(tmp_path: Path) -> None:
    auto = tmp_path / "auto.csv"
    result = _invoke("cluster", _beard(), "-o", str(auto), "--auto", "--json")
    assert result.exit_code == 0, result.output
    assert 7 <= json.loads(result.output)["n_clusters"] <= 9
    paper = tmp_path / "paper.csv"
    assert _invoke("cluster", _beard(), "-o", str(paper), "--threshold", "0.95").exit_code == 0
    # The two clusterings against each other: the 0.95 clusters only split the automatic ones.
    result = _invoke("eval", str(paper), str(auto), "--json")
    scores = json.loads(result.output)
    assert set(scores) >= {"fmi", "ari", "ami", "n_clusters", "n_dies"}
    assert scores["n_clusters"] == 10 and scores["precision"] == 1.0 and scores["recall"] < 1.0


def test_eval_lists_mistakes(tmp_path: Path) -> None:
    clusters = tmp_path / "c.csv"
    clusters.write_text("name, die\nL001D, 0\nL002D, 0\nL003D, 1\n")
    labels = tmp_path / "labels.csv"
    labels.write_text("coin_id,die_id\nL0001D,A\nL0002D,B\nL0003D,B\n")
    result = _invoke("eval", str(clusters), str(labels), "--mistakes")
    assert result.exit_code == 0, result.output
    assert (
        "split B" in result.output
        and "merged 0" in result.output
        and "clusters 2 for 2 dies" in result.output
    )


def test_pairs_csv_input_and_clean_errors(tmp_path: Path) -> None:
    pairs = tmp_path / "pairs.csv"
    pairs.write_text("source,target,probability\nL0001R,L0002R,0.99\nL0002R,L0003R,0.2\n")
    out = tmp_path / "c.csv"
    result = _invoke("cluster", str(pairs), "-o", str(out), "--threshold", "0.5", "--method", "average")
    assert result.exit_code == 0, result.output
    labels = read_clusters(out)
    assert labels["L0001R"] == labels["L0002R"] != labels["L0003R"]
    bad = _invoke("cluster", str(tmp_path / "missing.csv"), "-o", str(out))
    assert bad.exit_code == 2 and "missing.csv" in bad.output and "no such file" in bad.output
    both = _invoke("cluster", str(pairs), "-o", str(out), "--threshold", "0.5", "--auto")
    assert both.exit_code == 2 and "not both" in both.output
    method = _invoke("cluster", str(pairs), "-o", str(out), "--method", "kmeans")
    assert method.exit_code == 2 and "components" in method.output
    project = _invoke("cluster", str(tmp_path), "-o", str(out))
    assert project.exit_code == 2 and "not a coindie project" in project.output
