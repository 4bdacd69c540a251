"""The clustering benchmark on a tiny synthetic hoard whose dies are known."""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coindie.bench.clustering import BenchOptions, benchmark_clustering, chosen_faces
from coindie.cli.app import app
from coindie.clustering import evaluate, read_clusters, read_graph
from coindie.io.truth import load_truth

DEFAULT_MODEL = Path(str(resources.files("coindie") / "data" / "same_die_classifier.json"))


@pytest.fixture(scope="module")
def hoard(tmp_path_factory) -> Path:
    from coindie.synth.hoard import synthesize

    # The default scanner (0.05 mm, like the riedones hoard the shipped model was trained on): distances
    # between coarser scans are larger, and the model would not apply.
    out = tmp_path_factory.mktemp("tiny_hoard")
    synthesize(out, preset="tiny", seed=3, workers=1)
    return out


@pytest.fixture(scope="module")
def run(hoard: Path, tmp_path_factory) -> tuple[Path, dict]:
    out = tmp_path_factory.mktemp("bench")
    # The tiny hoard's training split has one die per side (no different-die pair to learn from): the
    # shipped model is used; training is tested in test_similarity_score.
    return out, benchmark_clustering(hoard, out, BenchOptions(model=DEFAULT_MODEL))


def test_outputs_and_table(run: tuple[Path, dict], hoard: Path) -> None:
    out, summary = run
    for name in ("pairs.csv", "summary.json", "summary.md", "fmi_vs_threshold.png"):
        assert (out / name).is_file(), name
    truth = load_truth(hoard)
    for group, entry in summary["groups"].items():
        test_faces = [f for f in truth.faces_in("cluster_test") if f.family == group]
        assert entry["n_faces"] == len(test_faces) and entry["n_dies"] == len({f.die for f in test_faces})
        pairs = entry["pairs"]
        assert pairs["n_pairs"] == len(test_faces) * (len(test_faces) - 1) // 2
        n_same = sum(a.die == b.die for a in test_faces for b in test_faces if a.face_id < b.face_id)
        assert pairs["n_same_die"] == n_same
        for method, rows in entry["methods"].items():
            assert {"silhouette", "paper", "best_possible"} <= set(rows), (group, method)
            for r in rows.values():
                assert 0.0 <= r["fmi"] <= 1.0 and r["n_dies"] == entry["n_dies"]
            assert rows["best_possible"]["fmi"] >= max(r["fmi"] for r in rows.values()) - 1e-12
    saved = json.loads((out / "summary.json").read_text())
    assert set(saved["groups"]) == set(summary["groups"])
    assert "| group | method |" in (out / "summary.md").read_text()


def test_cluster_files_agree_with_the_summary(run: tuple[Path, dict], hoard: Path) -> None:
    out, summary = run
    labels = read_clusters(hoard / "labels.csv")
    for group, entry in summary["groups"].items():
        rows = entry["methods"]["components"]
        chosen = rows.get("validation", rows["paper"])
        result = evaluate(read_clusters(out / f"clusters_{group}.csv"), labels)
        assert result.fmi == pytest.approx(chosen["fmi"]) and result.n_clusters == chosen["n_clusters"]
        graph = read_graph(out / f"graph_cluster_test_{group}.json")
        assert (
            graph.n_nodes == entry["n_faces"]
            and graph.n_edges == entry["n_faces"] * (entry["n_faces"] - 1) // 2
        )


def test_a_second_run_resumes_without_measuring_again(run: tuple[Path, dict], hoard: Path) -> None:
    out, summary = run
    seen: list[tuple[int, int]] = []
    again = benchmark_clustering(
        hoard, out, BenchOptions(model=DEFAULT_MODEL), progress=lambda a, t: seen.append((a, t))
    )
    assert len(seen) == 1 and seen[0][0] == seen[0][1]  # every pair already done
    assert again["groups"] == summary["groups"]


def test_max_faces_takes_a_sample_of_dies(hoard: Path) -> None:
    truth = load_truth(hoard)
    faces = chosen_faces(truth, "cluster_test", "R", max_faces=2)
    assert len(faces) == 2 and all(f.family == "R" for f in faces)


def test_cli_refuses_an_unknown_method(hoard: Path, tmp_path: Path) -> None:
    result = CliRunner().invoke(
        app, ["bench", "clustering", str(hoard), "--out", str(tmp_path), "--method", "x"]
    )
    assert result.exit_code == 2 and "unknown method" in result.output


def test_one_group_takes_its_threshold_from_the_obverses(run: tuple[Path, dict], hoard: Path) -> None:
    out, summary = run
    only = benchmark_clustering(hoard, out, BenchOptions(model=DEFAULT_MODEL, groups=("DB",)))
    assert set(only["groups"]) == {"DB"}
    assert only["groups"]["DB"] == summary["groups"]["DB"]  # DB's τ comes from D's validation split
