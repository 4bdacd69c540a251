"""Scans written in metres or micrometres are read in millimetres; scans in millimetres, and clouds that are
no coin in any unit, are read as written."""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import pytest

from coindie.io import read_scan, write_ply
from coindie.io.units import COIN_SIZE_MM, face_size, file_unit
from coindie.preprocess import grid_sample
from coindie.scan import Scan
from test_preprocess_synthetic import SyntheticCoin, make_scan

#: A 20 mm face with its wall, 0.2 mm apart.
FACE = make_scan(SyntheticCoin(spacing=0.2))


def _written(tmp_path: Path, scale: float, name: str = "L0001D") -> Path:
    """FACE written with its coordinates multiplied by ``scale`` (1e-3: metres; 1e3: micrometres)."""
    scaled = Scan(points=FACE.points * scale, normals=FACE.normals, id=FACE.id)
    return write_ply(tmp_path / f"{name}.ply", scaled, dtype=np.float64)


@pytest.mark.parametrize(("scale", "unit"), [(1e-3, "metres"), (1e3, "micrometres")])
def test_a_face_in_metres_or_micrometres_is_read_in_millimetres(
    tmp_path: Path, scale: float, unit: str, caplog: pytest.LogCaptureFixture
) -> None:
    path = _written(tmp_path, scale)
    with caplog.at_level(logging.WARNING, logger="coindie.io.units"):
        scan = read_scan(path)
    np.testing.assert_allclose(scan.points, FACE.points, rtol=1e-12, atol=1e-9)
    assert scan.normals is not None
    np.testing.assert_allclose(scan.normals, FACE.normals, atol=1e-12)
    # the grid of the paper's preprocessing sees the same face: the same cells
    assert grid_sample(scan, 0.1).n_points == grid_sample(FACE, 0.1).n_points
    assert str(path) in caplog.text and unit in caplog.text


def test_a_face_in_millimetres_is_read_exactly_as_written(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    path = _written(tmp_path, 1.0)
    with caplog.at_level(logging.WARNING, logger="coindie.io.units"):
        scan = read_scan(path)
    np.testing.assert_array_equal(scan.points, FACE.points)
    assert caplog.text == ""


@pytest.mark.parametrize("size_mm", [0.5, 1.0, 500.0, 1000.0])
def test_a_cloud_that_is_no_coin_in_any_unit_is_read_as_written(tmp_path: Path, size_mm: float) -> None:
    """Between the units' bounds (a fragment of 1 mm, a 0.5 m object) no unit makes a coin of the cloud:
    it is left in the file's numbers, for the later steps to judge."""
    scale = size_mm / face_size(FACE.points)
    assert file_unit(FACE.points * scale) == "mm"
    np.testing.assert_array_equal(read_scan(_written(tmp_path, scale)).points, FACE.points * scale)


def test_each_unit_reads_only_its_own_sizes() -> None:
    """The bounds of a coin's size keep the units apart: a face 2-200 mm across is millimetres, 1,000
    times smaller metres, 1,000 times larger micrometres, and nothing else is rescaled."""
    size = face_size(FACE.points)
    low, high = COIN_SIZE_MM
    for across_mm in (low * 1.01, 20.0, high * 0.99):
        points = FACE.points * (across_mm / size)
        assert file_unit(points) == "mm"
        assert file_unit(points / 1000.0) == "m"
        assert file_unit(points * 1000.0) == "um"
    for across_mm in (low * 0.99, high * 1.01):
        assert file_unit(FACE.points * (across_mm / size)) == "mm"


@pytest.mark.parametrize(("unit", "mm_per_unit"), [("cm", 10.0), ("in", 25.4), ("m", 1000.0), ("um", 0.001)])
def test_a_declared_unit_is_read_as_declared(tmp_path: Path, unit: str, mm_per_unit: float) -> None:
    """Centimetres and inches cannot be told from a face's size (a 20 mm face is 2 cm across: a coin in
    millimetres too); declared, every unit reads the face back in millimetres."""
    path = _written(tmp_path, 1.0 / mm_per_unit)
    scan = read_scan(path, unit=unit)
    np.testing.assert_allclose(scan.points, FACE.points, rtol=1e-12, atol=1e-9)
    assert grid_sample(scan, 0.1).n_points == grid_sample(FACE, 0.1).n_points
    if unit == "cm":  # undeclared, a face in centimetres is a 2 mm coin, read as written
        np.testing.assert_allclose(read_scan(path).points, FACE.points / 10.0, rtol=1e-12, atol=1e-12)


def test_a_declared_unit_overrides_the_size_and_an_unknown_one_is_refused(tmp_path: Path) -> None:
    from coindie.errors import ParameterError

    path = _written(tmp_path, 1e-3)  # a face in metres by its size
    np.testing.assert_array_equal(read_scan(path, unit="mm").points, FACE.points * 1e-3)
    with pytest.raises(ParameterError, match="unknown unit 'mile'.*cm"):
        read_scan(path, unit="mile")
