"""Small rigid-transform helpers (4x4 homogeneous matrices, mm)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

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
