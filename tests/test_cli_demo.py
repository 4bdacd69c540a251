"""`coindie demo` (what `make demo` runs) on a very small hoard: hoard -> project -> run -> clusters ->
evaluation, every stage on the files the previous one wrote; a second run recomputes nothing."""

from __future__ import annotations

import re

from typer.testing import CliRunner

from coindie.cli.app import app
from coindie.clustering import read_clusters
from coindie.io.labels import read_labels
from coindie.project import open_project


def test_demo_runs_the_die_study_end_to_end_and_resumes(tmp_path) -> None:
    args = ["demo", str(tmp_path), "--scale", "0.01", "--workers", "2", "--candidates", "5"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    hoard = tmp_path / "hoard"
    faces = sorted(path.stem for path in hoard.glob("*.ply"))
    project = open_project(tmp_path / "project")
    assert sorted(s.face_id for s in project.scans("ok")) == faces
    pairs = project.scored_pairs()
    assert pairs and all(p["source"][-1] == p["target"][-1] for p in pairs)  # same side only
    assert "candidate search, K = 5" in result.output
    labels = {str(k): v for k, v in read_labels(hoard / "labels.csv").items()}
    for side in "DR":
        clusters = read_clusters(tmp_path / f"clusters_{side}.csv")
        assert sorted(clusters) == [f for f in faces if f.endswith(side)]
    fmi = [float(v) for v in re.findall(r"FMI (\d\.\d+)", result.output)]
    assert len(fmi) == 2 and min(fmi) > 0.5, result.output
    assert len(labels) == len(faces)
    # the clustering command reads the project directly (both sides, no cross-side links)
    both = CliRunner().invoke(
        app, ["cluster", str(tmp_path / "project"), "--auto", "-o", str(tmp_path / "all.csv")]
    )
    assert both.exit_code == 0, both.output
    assert sorted(read_clusters(tmp_path / "all.csv")) == faces
    again = CliRunner().invoke(app, args)
    assert again.exit_code == 0, again.output
    assert "0 faces prepared, 0 pairs scored" in again.output
