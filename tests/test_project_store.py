"""The project folder without running pairs: listing scans, changed files, labels, the append-only edits
log, the probability graph handed to the clustering, and clear errors."""

from __future__ import annotations

import json
import os
import sqlite3

import numpy as np
import pytest
from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.io import write_ply
from coindie.project import ProjectError, init_project, open_project
from coindie.project.run import candidate_face_pairs
from coindie.scan import Scan


@pytest.fixture
def scans(tmp_path):
    import numpy as np

    folder = tmp_path / "scans"
    folder.mkdir()
    rng = np.random.default_rng(0)
    for name in ("L0001D", "L0002D", "L0003D", "L0001R", "L0002R", "coin_x"):
        points = rng.normal(size=(50, 3))
        write_ply(folder / f"{name}.ply", Scan(points=points, normals=np.tile([0.0, 0.0, 1.0], (50, 1))))
    (folder / "labels.csv").write_text("coin_id,die_id\nL0001D,D1\nL0002D,D1\nL0003D,D2\n")
    return folder


def test_init_lists_faces_by_side_and_keeps_labels(scans, tmp_path) -> None:
    project, report = init_project(tmp_path / "p", scans, scans / "labels.csv")
    assert sorted(report.added) == ["L0001D", "L0001R", "L0002D", "L0002R", "L0003D", "coin_x"]
    assert {s.face_id: s.side for s in project.scans()}["coin_x"] == "?"
    assert all(s.status == "new" for s in project.scans())
    assert project.labels() == {"L0001D": "D1", "L0002D": "D1", "L0003D": "D2"}
    # init again: nothing new; a changed file is noticed and loses its pairs
    _, again = init_project(tmp_path / "p", scans)
    assert again.added == [] and again.unchanged == 6
    project.db.execute(
        "INSERT INTO pairs (source, target, params_hash, side, origin, status) "
        "VALUES ('L0001D', 'L0002D', 'h', 'D', 'exhaustive', 'done')"
    )
    path = scans / "L0001D.ply"
    os.utime(path, ns=(path.stat().st_atime_ns, path.stat().st_mtime_ns + 10**9))
    refreshed = project.refresh()
    assert refreshed.changed == ["L0001D"]
    assert project.db.execute("SELECT COUNT(*) FROM pairs").fetchone()[0] == 0


def test_edits_are_append_only(scans, tmp_path) -> None:
    project, _ = init_project(tmp_path / "p", scans)
    first = project.add_edit("expert", "cut", "L0001D", "L0002D", reason="different dies")
    project.add_edit("expert", "link", "L0001D", "L0003D")
    assert [e["action"] for e in project.edits()] == ["cut", "link"]
    assert project.edits()[0]["payload"] == {"reason": "different dies"}
    with pytest.raises(sqlite3.IntegrityError, match="append-only"):
        project.db.execute("UPDATE edits SET action = 'link' WHERE edit_id = ?", (first,))
    with pytest.raises(sqlite3.IntegrityError, match="append-only"):
        project.db.execute("DELETE FROM edits")


def test_probability_graph_has_one_side_or_both_without_cross_links(scans, tmp_path) -> None:
    project, _ = init_project(tmp_path / "p", scans)
    db = project.db
    db.execute("UPDATE scans SET status = 'ok'")
    db.execute(
        "INSERT INTO runs (started_at, status, version, params_hash, config) "
        "VALUES ('t', 'finished', 'v', 'h', '{}')"
    )
    rows = [("L0001D", "L0002D", "D", 0.9), ("L0001D", "L0003D", "D", 0.1), ("L0001R", "L0002R", "R", 0.7)]
    for a, b, side, p in rows:
        db.execute(
            "INSERT INTO pairs (source, target, params_hash, side, origin, status, valid, probability) "
            "VALUES (?, ?, 'h', ?, 'exhaustive', 'done', 1, ?)",
            (a, b, side, p),
        )
    obverses = project.probability_graph("D", calibrated=False)
    assert sorted(obverses.nodes) == ["L0001D", "L0002D", "L0003D"]
    assert sorted(obverses.probability.tolist()) == [0.1, 0.9]
    # two pairs are too few to calibrate on: the scorer's own probabilities are kept
    np.testing.assert_allclose(sorted(project.probability_graph("D").probability.tolist()), [0.1, 0.9])
    both = project.probability_graph()
    assert both.n_nodes == 6  # coin_x is a node without links
    sides = [{both.nodes[i][-1], both.nodes[j][-1]} for i, j in zip(both.i, both.j, strict=True)]
    assert all(len(s) == 1 for s in sides)


def test_candidate_pairs_are_ordered_unique_face_pairs() -> None:
    import numpy as np

    faces = [f"L{i:04d}R" for i in range(6)]
    descriptors = np.repeat(np.eye(3), 2, axis=0) + 0.01 * np.arange(6)[:, None]
    pairs = candidate_face_pairs(faces, descriptors, k=1)
    assert pairs == [("L0000R", "L0001R"), ("L0002R", "L0003R"), ("L0004R", "L0005R")]


def test_errors_name_the_folder(tmp_path) -> None:
    with pytest.raises(ProjectError, match="not a coindie project"):
        open_project(tmp_path)
    result = CliRunner().invoke(app, ["status", str(tmp_path)])
    assert result.exit_code == 2
    assert str(tmp_path) in result.output and len(result.output.strip().splitlines()) == 1
    result = CliRunner().invoke(app, ["init", str(tmp_path / "p"), str(tmp_path / "missing")])
    assert result.exit_code == 2 and "no such folder" in result.output


def test_status_json(scans, tmp_path) -> None:
    init_project(tmp_path / "p", scans)
    result = CliRunner().invoke(app, ["status", str(tmp_path / "p"), "--json"])
    assert result.exit_code == 0, result.output
    assert json.loads(result.output)["faces"] == {"new": 6}
