"""The preprocessing step, its configuration, and the scan summary behind ``coindie info``."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from coindie.errors import InvalidScanError, ParameterError
from coindie.preprocess import (
    PreprocessConfig,
    frame_from_config,
    height_map_from_config,
    preprocess,
    summarize_scan,
)
from coindie.preprocess.summary import face_diameter, point_spacing
from coindie.scan import Scan
from coindie.transforms import angle_between_deg, apply
from test_preprocess_synthetic import SyntheticCoin, make_scan, random_pose

DENSE = SyntheticCoin(spacing=0.05)


def test_preprocess_orients_centres_and_samples_at_the_paper_grid():
    T_scan_coin = random_pose(0)
    scan = make_scan(DENSE, T_scan_coin=T_scan_coin)
    result = preprocess(scan)
    out = result.scan
    assert result.n_input_points == scan.n_points and not result.normals_estimated
    assert out.n_points < scan.n_points / 2.5  # 0.05 mm in, 0.1 mm cells out
    cells = np.floor(out.points / 0.1).astype(np.int64)
    assert len(np.unique(cells, axis=0)) == out.n_points
    assert angle_between_deg((result.T_preprocessed_scan @ T_scan_coin)[:3, 2], [0, 0, 1]) < 0.5
    assert np.allclose(apply(result.T_preprocessed_scan, scan.points).mean(axis=0), 0.0, atol=1e-9)


def test_missing_normals_are_estimated_face_up():
    scan = make_scan(DENSE, T_scan_coin=random_pose(1), normals=False)
    result = preprocess(scan, PreprocessConfig(grid_size_mm=0.2))
    assert result.normals_estimated and result.scan.has_normals
    face = result.scan.points[:, 2] > -0.5  # above the wall's lower part
    assert np.median(result.scan.normals[face, 2]) > 0.99


@pytest.mark.parametrize("orientation", ["pca", "canonical", "none"])
def test_every_orientation_centres_and_none_does_not_rotate(orientation):
    scan = make_scan(SyntheticCoin(spacing=0.2), T_scan_coin=random_pose(2, max_tilt_deg=20))
    result = preprocess(scan, PreprocessConfig(orientation=orientation, grid_size_mm=None))
    assert result.scan.n_points == scan.n_points
    R = result.T_preprocessed_scan[:3, :3]
    if orientation == "none":
        assert np.allclose(R, np.eye(3))
    else:
        assert angle_between_deg(R @ scan.normals.mean(axis=0), [0, 0, 1]) < 2.0


def test_last_mode_keeps_input_points():
    scan = make_scan(SyntheticCoin(spacing=0.05), wall=False)
    result = preprocess(scan, PreprocessConfig(grid_mode="last", orientation="none"))
    moved = apply(result.T_preprocessed_scan, scan.points)
    assert np.isin(result.scan.points[:, 0], moved[:, 0]).all()


def test_the_config_has_the_paper_defaults_and_documents_units():
    config = PreprocessConfig()
    assert config.grid_size_mm == 0.1 and config.orientation == "pca"
    for name, declared in PreprocessConfig.declared().items():
        assert declared.doc, name
        if name.endswith("_mm"):
            assert declared.unit == "mm", name
        if name.endswith("_deg"):
            assert declared.unit == "degrees", name


@pytest.mark.parametrize(
    ("overrides", "name"),
    [
        ({"grid_size_mm": -1.0}, "grid_size_mm"),
        ({"grid_mode": "median"}, "grid_mode"),
        ({"normals_k": 2}, "normals_k"),
        ({"fit_max_normal_angle_deg": 120}, "fit_max_normal_angle_deg"),
        ({"heightmap_resolution_mm": 0}, "heightmap_resolution_mm"),
        ({"grid_sise_mm": 0.1}, "grid_sise_mm"),
    ],
)
def test_bad_config_values_name_the_parameter(overrides, name):
    with pytest.raises(ParameterError, match=f"The '{name}' parameter of PreprocessConfig "):
        PreprocessConfig.from_overrides(**overrides)


def test_the_config_is_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        PreprocessConfig().grid_size_mm = 0.2  # type: ignore[misc]


def test_the_summary_of_a_known_disc():
    coin = SyntheticCoin(spacing=0.1)
    scan = make_scan(coin, T_scan_coin=random_pose(3), colors=True, name="L082R")
    summary = summarize_scan(scan)
    assert summary.points == scan.n_points and summary.has_normals and summary.has_colors
    assert summary.id == "L082R" and summary.face == "reverse"
    assert summary.diameter_mm == pytest.approx(2 * coin.radius, abs=0.05)
    assert summary.spacing_mm == pytest.approx(0.1, rel=0.25)
    assert np.allclose(np.subtract(summary.bbox_max_mm, summary.bbox_min_mm), summary.extent_mm)
    assert summary.file_size_bytes is None and summary.to_dict()["points"] == scan.n_points


def test_spacing_and_diameter_of_a_regular_square():
    ticks = np.arange(0.0, 3.0, 0.05)
    x, y = (a.ravel() for a in np.meshgrid(ticks, ticks))
    square = Scan(points=np.stack([x, y, np.zeros_like(x)], axis=1))
    assert point_spacing(square.points) == pytest.approx(0.05)
    assert face_diameter(square) == pytest.approx(np.hypot(2.95, 2.95))


def test_the_height_map_from_a_config_uses_its_settings():
    scan = make_scan(SyntheticCoin(spacing=0.2))
    config = PreprocessConfig(heightmap_resolution_mm=0.25, detrend="plane", frame_model="quadric")
    relief = height_map_from_config(scan, config)
    assert relief.resolution == 0.25 and relief.detrend == "plane"
    assert np.allclose(relief.T_canonical_scan, frame_from_config(scan, config).T_canonical_scan)
    assert relief.mask.any(axis=0).sum() * 0.25 == pytest.approx(20.0, abs=0.5)


def test_too_few_points_for_normals_is_an_invalid_scan():
    tiny = Scan(points=np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]), path=Path("tiny.ply"))
    with pytest.raises(InvalidScanError, match="tiny.ply.*too few"):
        preprocess(tiny)
