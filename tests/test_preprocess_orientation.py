"""Orientation: PCA to +z, flipped to the normals' side, and the rigid-transform helpers."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coindie.preprocess import PreprocessConfig, orient_to_z, preprocess, up_axis
from coindie.transforms import angle_between_deg, apply, rigid, rotation_angle_deg, rotation_between
from test_preprocess_synthetic import SyntheticCoin, make_scan, random_pose

# Linear algebra under test (PCA axes (eigh) and rotations between directions):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric

Z = np.array([0.0, 0.0, 1.0])
COIN = SyntheticCoin(spacing=0.2)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_a_randomly_rotated_relief_comes_back_face_up(seed):
    T_scan_coin = random_pose(seed)
    oriented, T_oriented_scan = orient_to_z(make_scan(COIN, T_scan_coin=T_scan_coin))
    coin_up_now = (T_oriented_scan @ T_scan_coin)[:3, :3] @ Z
    assert angle_between_deg(coin_up_now, Z) < 0.5
    assert np.allclose(oriented.points.mean(axis=0), 0.0, atol=1e-9)


def test_the_transform_is_rigid_and_maps_the_input_to_the_output():
    scan = make_scan(COIN, T_scan_coin=random_pose(5))
    oriented, T = orient_to_z(scan)
    assert T.shape == (4, 4)
    assert np.isclose(np.linalg.det(T[:3, :3]), 1.0)
    assert np.allclose(T[:3, :3] @ T[:3, :3].T, np.eye(3), atol=1e-12)
    assert np.allclose(T[3], [0, 0, 0, 1])
    assert np.allclose(oriented.points, apply(T, scan.points))
    assert np.allclose(oriented.normals, scan.normals @ T[:3, :3].T)


def test_a_face_down_scan_with_normals_is_turned_over():
    upside_down = rigid(Rotation.from_euler("x", 180, degrees=True).as_matrix(), [1.0, 2.0, 3.0])
    oriented, _ = orient_to_z(make_scan(COIN, T_scan_coin=upside_down))
    assert oriented.normals.mean(axis=0)[2] > 0.5


@pytest.mark.parametrize("wall", [True, False])
def test_without_normals_the_axis_points_to_the_side_the_geometry_says_is_up(wall):
    """A scan without normals, tilted face up or face down: the axis points to the coin's up side (its
    wall below the face; without the wall, its raised relief), not to the scanner's +z."""
    points = make_scan(COIN, normals=False, wall=wall).points
    for degrees in (30.0, 95.0, 150.0, 180.0):
        R = Rotation.from_euler("y", degrees, degrees=True).as_matrix()
        assert angle_between_deg(up_axis(points @ R.T), R @ Z) < 0.5


def test_a_face_down_scan_without_normals_is_preprocessed_face_up():
    """The paper's preprocessing (PCA to +z, normals estimated afterwards) of a scan without normals
    written face down: the coin comes out face up, its normals out of the coin."""
    T_scan_coin = rigid(Rotation.from_euler("xy", [170, 20], degrees=True).as_matrix(), [4.0, -3.0, 2.0])
    result = preprocess(make_scan(COIN, T_scan_coin=T_scan_coin, normals=False), PreprocessConfig())
    coin_up_now = (result.T_preprocessed_scan @ T_scan_coin)[:3, :3] @ Z
    assert angle_between_deg(coin_up_now, Z) < 0.5
    assert result.normals_estimated
    assert result.scan.normals is not None and result.scan.normals.mean(axis=0)[2] > 0.5


def test_orientation_keeps_the_in_plane_direction_of_a_slightly_tilted_scan():
    tilt = rigid(Rotation.from_euler("x", 3, degrees=True).as_matrix(), [0.0, 0.0, 0.0])
    _, T = orient_to_z(make_scan(COIN, T_scan_coin=tilt))
    assert rotation_angle_deg(T[:3, :3]) == pytest.approx(3.0, abs=0.3)


@pytest.mark.parametrize("seed", range(5))
def test_rotation_between_is_the_smallest_rotation(seed):
    rng = np.random.default_rng(seed)
    a, b = rng.normal(size=3), rng.normal(size=3)
    R = rotation_between(a, b)
    assert np.isclose(np.linalg.det(R), 1.0)
    assert angle_between_deg(R @ a, b) < 1e-6
    assert rotation_angle_deg(R) == pytest.approx(angle_between_deg(a, b), abs=1e-6)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_rotation_between_parallel_and_opposite_directions(sign):
    a = np.array([0.3, -0.2, 0.9])
    R = rotation_between(a, sign * a)
    assert np.isclose(np.linalg.det(R), 1.0)
    assert angle_between_deg(R @ a, sign * a) < 1e-6
