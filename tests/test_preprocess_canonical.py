"""Canonical frame (robust plane / quadric, edge wall ignored) and the height map."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.preprocess import canonical_frame, height_map
from coindie.transforms import angle_between_deg, apply
from test_preprocess_synthetic import SyntheticCoin, make_scan, random_pose

# Linear algebra under test (plane and quadric fits (least squares)):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric

COIN = SyntheticCoin(spacing=0.1, noise=0.002)


def _up_of(T_scan_coin: np.ndarray) -> np.ndarray:
    return T_scan_coin[:3, 2]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_the_tilted_plane_is_recovered_with_normals(seed):
    T_scan_coin = random_pose(seed, max_tilt_deg=20)
    frame = canonical_frame(make_scan(COIN, T_scan_coin=T_scan_coin))
    assert angle_between_deg(frame.up, _up_of(T_scan_coin)) < 0.1
    T = frame.T_canonical_scan
    assert np.isclose(np.linalg.det(T[:3, :3]), 1.0) and np.allclose(T[3], [0, 0, 0, 1])


@pytest.mark.parametrize("seed", [0, 1])
def test_the_tilted_plane_is_recovered_without_normals_despite_the_wall(seed):
    T_scan_coin = random_pose(seed, max_tilt_deg=20)
    frame = canonical_frame(make_scan(COIN, T_scan_coin=T_scan_coin, normals=False))
    assert angle_between_deg(frame.up, _up_of(T_scan_coin)) < 0.3


def test_the_wall_would_tilt_a_plain_fit_of_a_one_sided_wall():
    # A wall on one side only: ignoring it (normals) keeps the plane; a least-squares plane would tilt.
    coin = SyntheticCoin(spacing=0.1, wall_height=3.0)
    scan = make_scan(coin)
    one_side = (scan.points[:, 0] > 0) | (scan.normals[:, 2] > 0.5)
    frame = canonical_frame(scan.subset(one_side))
    assert angle_between_deg(frame.up, [0, 0, 1]) < 0.1
    points = scan.points[one_side]
    plain = np.linalg.lstsq(np.c_[points[:, :2], np.ones(len(points))], points[:, 2], rcond=None)[0]
    assert angle_between_deg([-plain[0], -plain[1], 1.0], [0, 0, 1]) > 0.5


def test_the_field_is_at_z_zero_and_the_quadric_is_the_dome():
    T_scan_coin = random_pose(4, max_tilt_deg=10)
    scan = make_scan(COIN, T_scan_coin=T_scan_coin)
    frame = canonical_frame(scan, model="quadric")
    assert frame.quadric[3] == pytest.approx(-COIN.dome, rel=0.05)
    assert frame.quadric[5] == pytest.approx(-COIN.dome, rel=0.05)
    assert abs(frame.quadric[4]) < 0.1 * COIN.dome
    # The quadric frame's z = 0 is the dome's apex height (the tangent plane at the centre).
    apex = apply(frame.T_canonical_scan @ T_scan_coin, [[0.0, 0.0, 0.0]])[0]
    assert abs(apex[2]) < 0.02
    assert frame.residual_mm < 0.01


def test_the_plane_frame_puts_the_best_plane_at_zero():
    scan = make_scan(COIN, T_scan_coin=random_pose(6, max_tilt_deg=15))
    frame = canonical_frame(scan, model="plane")
    face = apply(frame.T_canonical_scan, scan.points[scan.normals @ frame.up > 0.9])
    slope = np.linalg.lstsq(np.c_[face[:, :2], np.ones(len(face))], face[:, 2], rcond=None)[0]
    assert np.abs(slope[:2]).max() < 1e-3


def _index(relief, x: float, y: float) -> tuple[int, int]:
    rows, cols = relief.mm_to_pixel(x, y)
    return int(np.rint(rows)), int(np.rint(cols))


def _relief_at(coin: SyntheticCoin, T_scan_coin: np.ndarray, relief, xy: np.ndarray) -> np.ndarray:
    """Height-map values at coin-frame (x, y) points of the face."""
    on_face = np.c_[xy, coin.height(xy[:, 0], xy[:, 1])]
    canonical = apply(relief.T_canonical_scan @ T_scan_coin, on_face)
    rows, cols = relief.mm_to_pixel(canonical[:, 0], canonical[:, 1])
    return relief.values[np.rint(rows).astype(int), np.rint(cols).astype(int)]


def test_the_height_map_shows_the_bumps_at_their_heights():
    T_scan_coin = random_pose(7, max_tilt_deg=15)
    scan = make_scan(COIN, T_scan_coin=T_scan_coin)
    relief = height_map(scan, resolution=0.05)
    centres = np.array([b[:2] for b in COIN.bumps])
    measured = _relief_at(COIN, T_scan_coin, relief, centres)
    assert np.allclose(measured, [b[2] for b in COIN.bumps], atol=0.015)
    rng = np.random.default_rng(0)
    field = rng.uniform(-7, 7, (400, 2))
    field = field[COIN.relief(field[:, 0], field[:, 1]) < 1e-4]
    assert np.percentile(np.abs(_relief_at(COIN, T_scan_coin, relief, field)), 95) < 0.01


def test_plane_detrending_keeps_the_dome():
    scan = make_scan(COIN)
    relief = height_map(scan, resolution=0.1, detrend="plane")
    centre, edge = relief.values[_index(relief, 0.0, 0.0)], relief.values[_index(relief, 9.0, 0.0)]
    assert centre - edge == pytest.approx(COIN.dome * 81.0, abs=0.02)


def test_height_map_geometry_and_pixel_conversions():
    scan = make_scan(COIN, T_scan_coin=random_pose(8, max_tilt_deg=5))
    relief = height_map(scan, resolution=0.1)
    assert relief.values.dtype == np.float32 and relief.values.shape == relief.mask.shape
    assert relief.shape[0] * 0.1 == pytest.approx(2 * COIN.radius, abs=2.0)
    rows, cols = np.array([0.0, 3.0, 17.5]), np.array([0.0, 11.0, 2.25])
    x, y = relief.pixel_to_mm(rows, cols)
    assert np.allclose(relief.mm_to_pixel(x, y), (rows, cols))
    assert relief.pixel_to_mm(0, 0) == pytest.approx(relief.origin)
    x1, y1 = relief.pixel_to_mm(1, 1)
    assert x1 > relief.origin[0] and y1 < relief.origin[1]  # columns go +x, rows go -y


def test_small_holes_are_filled_inside_the_coin_and_large_ones_and_the_outside_are_not():
    coin = SyntheticCoin(spacing=0.1)
    small = height_map(make_scan(coin, hole=(2.0, -5.0, 0.2)), resolution=0.1, fill_max_distance=0.3)
    large = height_map(make_scan(coin, hole=(2.0, -5.0, 1.5)), resolution=0.1, fill_max_distance=0.3)
    for relief in (small, large):
        assert not relief.mask[0, 0] and not relief.mask[-1, -1]
    assert small.mask[_index(small, 2.0, -5.0)]
    assert not small.observed[_index(small, 2.0, -5.0)]
    assert small.values[_index(small, 2.0, -5.0)] == pytest.approx(0.0, abs=0.01)
    assert not large.mask[_index(large, 2.0, -5.0)]
    assert large.mask[_index(large, 0.0, 0.0)]


def test_the_edge_wall_stays_out_of_the_height_map():
    relief = height_map(make_scan(COIN), resolution=0.1)
    assert np.nanmin(relief.values) > -0.02  # the wall goes 1.5 mm down


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"resolution": 0.0}, "resolution"),
        ({"resolution": 1e-5}, "too large"),
        ({"detrend": "cubic"}, "detrend"),
        ({"fill_max_distance": -1.0}, "fill_max_distance"),
    ],
)
def test_bad_height_map_parameters_are_refused(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        height_map(make_scan(SyntheticCoin(spacing=0.5)), **kwargs)


@pytest.mark.parametrize(
    "kwargs",
    [{"model": "cubic"}, {"max_normal_angle_deg": 0.0}, {"max_normal_angle_deg": 95}, {"iterations": 0}],
)
def test_bad_frame_parameters_are_refused(kwargs):
    with pytest.raises(ParameterError):
        canonical_frame(make_scan(SyntheticCoin(spacing=0.5)), **kwargs)
