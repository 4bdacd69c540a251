"""The errors of a pose in the face's own plane: a turn about the face's normal and an in-plane shift
count, a tilt and a lift along the normal do not (a bent flan has no single true tilt)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coindie.registration import planar_errors, rotation_error_deg


@pytest.fixture(scope="module")
def face() -> tuple[np.ndarray, np.ndarray]:
    """A 20 mm disc of points with 0.05 mm of relief, and a true pose that lays it far from the origin
    and tilted, as a scanner leaves a face."""
    rng = np.random.default_rng(7)
    xy = rng.uniform(-10.0, 10.0, (6000, 2))
    xy = xy[np.hypot(*xy.T) < 10.0]
    points = np.c_[xy, rng.normal(0.0, 0.05, len(xy))]
    T_true = np.eye(4)
    T_true[:3, :3] = Rotation.from_euler("xyz", [25.0, -15.0, 70.0], degrees=True).as_matrix()
    T_true[:3, 3] = [40.0, -35.0, 12.0]
    return points, T_true


def _off(T_true: np.ndarray, points: np.ndarray, *, twist: float, tilt: float, shift) -> np.ndarray:
    """T_true followed by an error about the placed face's centre: a turn about its normal by ``twist``
    degrees, a tilt about one of its in-plane axes by ``tilt`` degrees, then a move by ``shift`` (mm, in
    the placed face's own axes: x, y in its plane, z along its normal)."""
    axes = T_true[:3, :3]
    centre = (points @ axes.T + T_true[:3, 3]).mean(axis=0)
    turn = Rotation.from_rotvec(np.radians(tilt) * axes[:, 0]) * Rotation.from_rotvec(
        np.radians(twist) * axes[:, 2]
    )
    error = np.eye(4)
    error[:3, :3] = turn.as_matrix()
    error[:3, 3] = centre - turn.as_matrix() @ centre + axes @ np.asarray(shift, dtype=np.float64)
    return error @ T_true


def test_a_turn_about_the_normal_is_the_twist_and_moves_points_by_their_radius(face) -> None:
    points, T_true = face
    twist, planar = planar_errors(points, T_true, _off(T_true, points, twist=3.0, tilt=0.0, shift=[0, 0, 0]))
    assert twist == pytest.approx(3.0, abs=1e-6)
    median_radius = np.median(np.hypot(points[:, 0], points[:, 1]))
    assert planar == pytest.approx(median_radius * 2 * np.sin(np.radians(1.5)), rel=0.02)


def test_a_tilt_and_a_lift_along_the_normal_are_not_planar_errors(face) -> None:
    points, T_true = face
    T = _off(T_true, points, twist=0.0, tilt=4.0, shift=[0.0, 0.0, 0.5])
    assert rotation_error_deg(T_true, T) == pytest.approx(4.0, abs=1e-6)  # the paper's error counts it
    twist, planar = planar_errors(points, T_true, T)
    assert twist < 0.01  # the plane is fitted to 0.05 mm of relief: its normal is known to ~0.01°
    # a 4° tilt shortens the face's radius by 1 - cos 4° (at most 0.024 mm at 10 mm) in the plane
    assert planar < 10.0 * (1 - np.cos(np.radians(4.0)))


def test_an_in_plane_shift_is_measured_whole_and_a_turn_and_shift_add_up(face) -> None:
    points, T_true = face
    _, shifted = planar_errors(
        points, T_true, _off(T_true, points, twist=0.0, tilt=0.0, shift=[0.12, 0.16, 0])
    )
    assert shifted == pytest.approx(0.2, abs=1e-9)
    twist, both = planar_errors(points, T_true, _off(T_true, points, twist=-1.0, tilt=2.0, shift=[0.2, 0, 0]))
    assert twist == pytest.approx(1.0, abs=1e-3)
    assert both > 0.2


def test_a_half_turn_is_a_half_turn(face) -> None:
    points, T_true = face
    twist, planar = planar_errors(
        points, T_true, _off(T_true, points, twist=179.0, tilt=0.0, shift=[0, 0, 0])
    )
    assert twist == pytest.approx(179.0, abs=1e-6)
    assert planar > 5.0
