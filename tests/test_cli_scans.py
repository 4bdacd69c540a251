"""``coindie info`` and ``coindie render`` on PLY files the tests write."""

from __future__ import annotations

import json

import numpy as np
import pytest
from PIL import Image
from typer.testing import CliRunner

from coindie.cli import app
from coindie.io import write_ply
from test_preprocess_synthetic import SyntheticCoin, make_scan, random_pose

COIN = SyntheticCoin(spacing=0.2)


@pytest.fixture(scope="module")
def ply(tmp_path_factory):
    scan = make_scan(COIN, T_scan_coin=random_pose(0, max_tilt_deg=10), name="L0082D")
    return write_ply(tmp_path_factory.mktemp("scans") / "L0082D.ply", scan), scan


def _run(*args: str):
    return CliRunner().invoke(app, [str(a) for a in args])


def test_info_prints_the_facts(ply):
    path, scan = ply
    result = _run("info", path)
    assert result.exit_code == 0, result.output
    assert f"{scan.n_points:,}" in result.output
    assert "L0082D (obverse)" in result.output
    assert "normals   yes" in result.output
    assert "diameter  20.0" in result.output


def test_info_json_has_every_field(ply):
    path, scan = ply
    result = _run("info", path, "--json")
    assert result.exit_code == 0, result.output
    facts = json.loads(result.output)
    assert facts["points"] == scan.n_points and facts["id"] == "L0082D" and facts["face"] == "obverse"
    assert facts["has_normals"] and facts["has_colors"]
    assert facts["file_size_bytes"] == path.stat().st_size
    assert facts["diameter_mm"] == pytest.approx(2 * COIN.radius, abs=0.05)
    assert facts["spacing_mm"] == pytest.approx(COIN.spacing, rel=0.3)
    assert np.allclose(facts["extent_mm"], np.ptp(scan.points, axis=0), atol=1e-4)


def test_info_on_a_scan_without_normals(tmp_path):
    scan = make_scan(COIN, normals=False, name="coin7")
    path = write_ply(tmp_path / "coin7.ply", scan)
    facts = json.loads(_run("info", path, "--json").output)
    assert facts["has_normals"] is False and facts["face"] == "unknown" and facts["id"] == "coin7"


def test_render_writes_a_png_of_the_requested_width(ply, tmp_path):
    path, _ = ply
    out = tmp_path / "relief.png"
    result = _run("render", path, "-o", out, "--width", "200", "--tone", "grey")
    assert result.exit_code == 0, result.output
    assert str(out) in result.output
    with Image.open(out) as image:
        assert image.width == 200 and image.mode == "RGBA"


def test_render_defaults_to_the_scan_name_in_the_current_folder(ply, tmp_path, monkeypatch):
    path, _ = ply
    monkeypatch.chdir(tmp_path)
    result = _run("render", path, "--width", "50")
    assert result.exit_code == 0, result.output
    assert (tmp_path / "L0082D.png").is_file()


@pytest.mark.parametrize("command", ["info", "render"])
def test_a_bad_file_exits_2_with_a_one_line_message(command, tmp_path):
    bad = tmp_path / "broken.ply"
    bad.write_bytes(b"this is not a ply file at all")
    result = _run(command, bad)
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and "broken.ply" in lines[0] and "not a PLY file" in lines[0]


@pytest.mark.parametrize("command", ["info", "render"])
def test_a_missing_file_exits_2(command, tmp_path):
    result = _run(command, tmp_path / "nowhere.ply")
    assert result.exit_code == 2
    assert "nowhere.ply" in result.output


def test_a_bad_width_is_refused_by_the_parser(ply):
    path, _ = ply
    result = _run("render", path, "--width", "0")
    assert result.exit_code == 2
