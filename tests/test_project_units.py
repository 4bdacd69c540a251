"""A project's declared scan unit (``coindie init --unit``): every face of it is read in that unit, and a
project keeps the unit its faces were read in."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from coindie.io import write_ply
from coindie.project import init_project, open_project
from coindie.project.run import RunConfig, run_project
from coindie.project.store import ProjectError
from coindie.scan import Scan
from test_preprocess_synthetic import SyntheticCoin, make_scan

FACES = {f"L000{i}D": make_scan(SyntheticCoin(spacing=0.1, seed=i), name=f"L000{i}D") for i in (1, 2)}


def _hoard(folder: Path, mm_per_unit: float) -> Path:
    folder.mkdir()
    for name, face in FACES.items():
        scaled = Scan(points=face.points / mm_per_unit, normals=face.normals, id=face.id)
        write_ply(folder / f"{name}.ply", scaled, dtype=np.float64)
    return folder


def _prepared_points(project_dir: Path, scans: Path, unit: str | None) -> dict[str, int]:
    project, _ = init_project(project_dir, scans, unit=unit)
    run_project(project, RunConfig(workers=1, plan_only=True), echo=lambda _: None)
    return {scan.face_id: scan.n_points for scan in open_project(project_dir).scans("ok")}


def test_the_faces_of_a_project_in_centimetres_are_prepared_as_in_millimetres(tmp_path: Path) -> None:
    in_mm = _prepared_points(tmp_path / "mm", _hoard(tmp_path / "scans-mm", 1.0), None)
    in_cm = _hoard(tmp_path / "scans-cm", 10.0)
    declared = _prepared_points(tmp_path / "cm", in_cm, "cm")
    assert open_project(tmp_path / "cm").unit == "cm"
    assert declared.keys() == in_mm.keys() == FACES.keys()
    for face, n in in_mm.items():  # the same cells of the paper's grid, up to points on a cell's edge
        assert abs(declared[face] - n) <= 0.01 * n
    # undeclared, the faces are 2 mm coins: a hundredth of the cells
    guessed = _prepared_points(tmp_path / "guessed", in_cm, None)
    assert all(guessed[face] < 0.05 * n for face, n in in_mm.items())


def test_a_project_keeps_the_unit_its_faces_were_read_in(tmp_path: Path) -> None:
    scans = _hoard(tmp_path / "scans", 10.0)
    _prepared_points(tmp_path / "p", scans, "cm")
    init_project(tmp_path / "p", scans, unit="cm")  # the same unit again: nothing changes
    with pytest.raises(ProjectError, match="2 faces were read with unit cm.*make a new project"):
        init_project(tmp_path / "p", scans, unit="mm")
    assert open_project(tmp_path / "p").unit == "cm"
    fresh, _ = init_project(tmp_path / "q", scans)  # listed, not read: the unit can still be declared
    init_project(tmp_path / "q", scans, unit="in")
    assert fresh.unit == open_project(tmp_path / "q").unit == "in"


def test_the_review_app_shows_a_face_in_centimetres_at_its_size_in_millimetres(tmp_path: Path) -> None:
    from coindie.serve import images
    from coindie.serve.source import open_source

    scans_mm, scans_cm = _hoard(tmp_path / "scans-mm", 1.0), _hoard(tmp_path / "scans-cm", 10.0)
    _prepared_points(tmp_path / "cm", scans_cm, "cm")
    source = open_source(tmp_path / "cm")
    assert source.unit == "cm"
    grid_cm, _, _ = images.own_frame(source.scan_paths["L0001D"], 100, unit=source.unit)
    grid_mm, _, _ = images.own_frame(scans_mm / "L0001D.ply", 100)
    assert grid_cm.resolution == pytest.approx(grid_mm.resolution, rel=1e-6)  # 0.2 mm pixels on a 20 mm face
    assert grid_cm.shape == grid_mm.shape
