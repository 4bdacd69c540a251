"""Grid sampling: one point per occupied cell, 'mean' and 'last' modes."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from coindie.errors import ParameterError
from coindie.preprocess import grid_sample
from coindie.scan import Scan


def _cells(points: np.ndarray, size: float) -> np.ndarray:
    return np.floor(points / size).astype(np.int64)


def _random_scan(n: int = 5000, seed: int = 0) -> Scan:
    rng = np.random.default_rng(seed)
    points = rng.uniform(-1.0, 1.0, (n, 3)) * [2.0, 2.0, 0.3]
    normals = rng.normal(size=(n, 3)) + [0, 0, 3]
    colors = rng.integers(0, 256, (n, 3), dtype=np.uint8)
    return Scan(points=points, normals=normals, colors=colors)


@pytest.mark.parametrize("mode", ["mean", "last"])
def test_no_two_output_points_share_a_cell_and_every_occupied_cell_is_kept(mode):
    scan, size = _random_scan(), 0.25
    out = grid_sample(scan, size, mode)
    out_cells = {tuple(c) for c in _cells(out.points, size)}
    assert len(out_cells) == out.n_points
    assert out_cells == {tuple(c) for c in _cells(scan.points, size)}


def test_a_dense_regular_plane_comes_out_at_the_grid_spacing():
    ticks = np.arange(0.0, 5.0, 0.01) + 0.003
    x, y = np.meshgrid(ticks, ticks)
    plane = Scan(points=np.stack([x.ravel(), y.ravel(), np.full(x.size, 0.05)], axis=1))
    out = grid_sample(plane, 0.1, "mean")
    spacing, _ = cKDTree(out.points).query(out.points, k=2)
    assert np.median(spacing[:, 1]) == pytest.approx(0.1, rel=0.02)
    assert out.n_points == 50 * 50


def test_last_mode_returns_input_points_exactly_the_last_of_each_cell():
    scan, size = _random_scan(800, seed=3), 0.5
    out = grid_sample(scan, size, "last")
    last_of_cell = {tuple(c): i for i, c in enumerate(_cells(scan.points, size))}  # later overwrite earlier
    expected = sorted(last_of_cell.values())
    kept = sorted(int(np.flatnonzero((scan.points == p).all(axis=1))[0]) for p in out.points)
    assert kept == expected
    row = {tuple(p): i for i, p in enumerate(map(tuple, scan.points))}
    for p, n, c in zip(out.points, out.normals, out.colors, strict=True):
        i = row[tuple(p)]
        # Scan re-normalises normals on construction: equal to the last bit or so.
        assert np.allclose(n, scan.normals[i], rtol=0, atol=1e-15) and np.array_equal(c, scan.colors[i])


def test_mean_mode_averages_points_normals_and_colours():
    points = np.array([[0.01, 0.01, 0.01], [0.03, 0.05, 0.07], [0.55, 0.5, 0.5]])
    normals = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    colors = np.array([[0, 0, 0], [100, 201, 50], [7, 7, 7]], dtype=np.uint8)
    out = grid_sample(Scan(points=points, normals=normals, colors=colors), 0.1, "mean")
    first = np.argmin(out.points[:, 0])
    assert np.allclose(out.points[first], [0.02, 0.03, 0.04])
    assert np.allclose(out.normals[first], np.array([1.0, 1.0, 0.0]) / np.sqrt(2.0))
    assert np.array_equal(out.colors[first], [50, 100, 25])  # 100.5 rounds to even
    assert np.allclose(np.linalg.norm(out.normals, axis=1), 1.0)


def test_opposite_normals_in_one_cell_do_not_give_a_zero_normal():
    points = np.array([[0.01, 0.01, 0.01], [0.02, 0.02, 0.02]])
    normals = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    out = grid_sample(Scan(points=points, normals=normals), 0.1, "mean")
    assert np.allclose(np.linalg.norm(out.normals, axis=1), 1.0)


@pytest.mark.parametrize("size", [0.0, -0.1, float("nan")])
def test_a_bad_size_is_refused(size):
    with pytest.raises(ParameterError, match="grid size"):
        grid_sample(_random_scan(10), size)


def test_a_bad_mode_is_refused():
    with pytest.raises(ParameterError, match="'mean' or 'last'"):
        grid_sample(_random_scan(10), 0.1, "median")  # type: ignore[arg-type]
