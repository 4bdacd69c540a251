"""Rigid transforms: 4x4 homogeneous matrices (mm) named after the frames they map between.

Building and applying them (``rigid``, ``apply``, ``inverse``), fitting them to matched points (Kabsch:
``fit_rigid``, ``fit_rotation``), rotations from vectors, Euler angles and directions, and the random poses
of the paper's registration benchmark. Every module of coindie takes these helpers from here.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike
from scipy.spatial.transform import Rotation

from coindie.arrays import FloatArray

#: Below this |sin| two directions count as parallel.
_PARALLEL_EPS = 1e-12


def rigid(R: ArrayLike, t: ArrayLike) -> FloatArray:
    """The 4x4 transform ``x -> R x + t``."""
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = t
    return T


def apply(T: ArrayLike, points: ArrayLike) -> FloatArray:
    """Map (N, 3) points by a 4x4 transform."""
    T = np.asarray(T, dtype=np.float64)
    return np.asarray(points, dtype=np.float64) @ T[:3, :3].T + T[:3, 3]


def transform_points(T: FloatArray, points: FloatArray) -> FloatArray:
    """:func:`apply` for arrays already of floats (no conversion: the registration loops' form)."""
    return points @ T[:3, :3].T + T[:3, 3]


def inverse(T: ArrayLike) -> FloatArray:
    """Inverse of a rigid 4x4 transform (transpose of the rotation, no general matrix inverse)."""
    T = np.asarray(T, dtype=np.float64)
    result = np.eye(4)
    result[:3, :3] = T[:3, :3].T
    result[:3, 3] = -T[:3, :3].T @ T[:3, 3]
    return result


def fit_rigid(src: FloatArray, dst: FloatArray, weights: FloatArray | None = None) -> FloatArray:
    """``T_dst_src`` minimising the (weighted) squared distances between matched points (Kabsch)."""
    w = np.ones(len(src)) if weights is None else weights
    src_mean = np.average(src, axis=0, weights=w)
    dst_mean = np.average(dst, axis=0, weights=w)
    R = fit_rotation(src - src_mean, dst - dst_mean, w)
    return rigid(R, dst_mean - R @ src_mean)


def fit_rotation(src: FloatArray, dst: FloatArray, weights: FloatArray | None = None) -> FloatArray:
    """R minimising sum w_i ||dst_i - R src_i||^2 over rotations (vectors, no translation)."""
    if len(src) < 2:
        return np.eye(3)
    rotation, _ = Rotation.align_vectors(dst, src, weights=weights)
    return rotation.as_matrix()


def small_rotation(omega: FloatArray) -> FloatArray:
    """The rotation matrix of a rotation vector (rad)."""
    return Rotation.from_rotvec(omega).as_matrix()


def euler_rotation(angles_deg: ArrayLike) -> FloatArray:
    """The rotation (3x3, or (N, 3, 3) for (N, 3) angles) by extrinsic x, y, z angles in degrees."""
    return Rotation.from_euler("xyz", angles_deg, degrees=True).as_matrix()


def euler_rigid(rotation_deg: ArrayLike, translation: ArrayLike) -> FloatArray:
    """The 4x4 transform rotating by extrinsic x, y, z angles (degrees), then translating (mm)."""
    return rigid(euler_rotation(rotation_deg), translation)


def random_pose(
    rng: np.random.Generator,
    *,
    max_tilt_deg: float = 25.0,
    max_spin_deg: float = 180.0,
    max_shift: float = 5.0,
) -> FloatArray:
    """A random rigid transform as in the paper's benchmark: x/y within ±25°, z within ±180°."""
    tilt = rng.uniform(-max_tilt_deg, max_tilt_deg, 2)
    spin = rng.uniform(-max_spin_deg, max_spin_deg)
    return euler_rigid((tilt[0], tilt[1], spin), rng.uniform(-max_shift, max_shift, 3))


def rotation_between(a: ArrayLike, b: ArrayLike) -> FloatArray:
    """The smallest rotation (3x3, det +1) taking direction ``a`` onto direction ``b``.

    Written out (Rodrigues' formula) because scipy's ``Rotation.align_vectors`` does not pick the
    minimal rotation for a single pair in a documented way, and the minimal one keeps the scanner's
    in-plane orientation of a coin.
    """
    a = np.asarray(a, dtype=np.float64) / np.linalg.norm(a)
    b = np.asarray(b, dtype=np.float64) / np.linalg.norm(b)
    axis = np.cross(a, b)
    sin, cos = np.linalg.norm(axis), float(a @ b)
    if sin < _PARALLEL_EPS:
        return np.eye(3) if cos > 0 else _half_turn_about_normal_of(a)
    k = axis / sin
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + sin * K + (1.0 - cos) * (K @ K)


def _half_turn_about_normal_of(a: FloatArray) -> FloatArray:
    """A 180° rotation about an axis perpendicular to ``a`` (maps ``a`` to ``-a``)."""
    helper = np.eye(3)[int(np.argmin(np.abs(a)))]
    k = np.cross(a, helper)
    k /= np.linalg.norm(k)
    return 2.0 * np.outer(k, k) - np.eye(3)


def rotation_angle_deg(R: ArrayLike) -> float:
    """Angle of a rotation matrix, in degrees."""
    cos = (np.trace(np.asarray(R)[:3, :3]) - 1.0) / 2.0
    return float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def angle_between_deg(a: ArrayLike, b: ArrayLike) -> float:
    """Angle between two directions, in degrees: ``atan2(|a x b|, a . b)``, accurate for every angle,
    where ``arccos`` of the dot product cannot resolve angles below ~1e-6° (its slope is infinite at 1)."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return float(np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b)), a @ b)))
