"""Errors of an estimated transform against the truth: the paper's SRE, rotation and translation errors,
and the errors in the face's own plane.

The paper's errors mix what a die study needs with what it does not. A bent or cupped flan has no single
true tilt: two coins of one die, one bent by a few degrees, are best laid on each other a degree or two
off the die's axis, and the rotation error counts that tilt. The translation error is taken at the scan's
origin, which a scanner may leave tens of mm off the coin, so any rotation error adds to it in proportion.
What the relief features read is the other part: how far the die's elements land from each other in the
face's plane. :func:`planar_errors` gives it (the turn about the face's normal, and the median in-plane
displacement of the face's points), measured on the source's own points like the SRE."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from coindie.registration.clouds import Plane
from coindie.transforms import (
    apply,
    inverse,  # noqa: F401  (registration/speed.py imports it from here)
)


def scaled_registration_error(points_source: ArrayLike, T_true: ArrayLike, T_estimated: ArrayLike) -> float:
    """The Scaled Registration Error (Fontana et al. 2020), as written in the Riedones3D paper:

    SRE = 1/n sum_i ||T_true x_i - T_est x_i|| / ||T_true x_i - T_true x_mean||

    with x_i the source points and x_mean their centroid. The denominator is the distance of x_i to the
    centroid (a rigid map keeps it), so the error is relative to the cloud's size; the paper reports it
    x1000. Points at the centroid itself (zero denominator) are left out.
    """
    x = np.asarray(points_source, dtype=np.float64)
    A, B = np.asarray(T_true, dtype=np.float64), np.asarray(T_estimated, dtype=np.float64)
    true = x @ A[:3, :3].T + A[:3, 3]
    estimated = x @ B[:3, :3].T + B[:3, 3]
    centre = x.mean(axis=0) @ A[:3, :3].T + A[:3, 3]
    scale = np.linalg.norm(true - centre, axis=1)
    keep = scale > 0
    return float(np.mean(np.linalg.norm(true - estimated, axis=1)[keep] / scale[keep]))


def rotation_error_deg(T_true: ArrayLike, T_estimated: ArrayLike) -> float:
    """Angle (degrees) of the rotation R_true^T R_estimated."""
    A, B = np.asarray(T_true, dtype=np.float64), np.asarray(T_estimated, dtype=np.float64)
    cos = (np.trace(A[:3, :3].T @ B[:3, :3]) - 1.0) / 2.0
    return float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def translation_error_mm(T_true: ArrayLike, T_estimated: ArrayLike) -> float:
    """Distance (mm) between the two translations."""
    A, B = np.asarray(T_true, dtype=np.float64), np.asarray(T_estimated, dtype=np.float64)
    return float(np.linalg.norm(A[:3, 3] - B[:3, 3]))


def planar_errors(points_source: ArrayLike, T_true: ArrayLike, T_estimated: ArrayLike) -> tuple[float, float]:
    """The error of ``T_estimated`` in the face's own plane: (turn about the face's normal in degrees,
    median in-plane displacement of the source points in mm).

    The plane is the best-fit plane of the source points placed by ``T_true`` (:meth:`coindie.registration.
    clouds.Plane.fit`: its normal the direction of least spread); the turn is the twist of the rotation
    ``R_estimated R_true^T`` about that normal (its swing, the tilt, is left out); the displacement is each
    point's ``T_estimated x - T_true x`` with its component along the normal taken off."""
    from scipy.spatial.transform import Rotation

    A, B = np.asarray(T_true, dtype=np.float64), np.asarray(T_estimated, dtype=np.float64)
    true, estimated = apply(A, points_source), apply(B, points_source)
    normal = Plane.fit(true).up
    moved = estimated - true
    in_plane = moved - np.outer(moved @ normal, normal)
    # swing-twist decomposition: the twist about n keeps the quaternion's vector part along n
    *vector, w = Rotation.from_matrix(B[:3, :3] @ A[:3, :3].T).as_quat()
    twist = 2.0 * np.degrees(np.arctan2(abs(float(np.dot(vector, normal))), abs(w)))
    return float(twist), float(np.median(np.linalg.norm(in_plane, axis=1)))
