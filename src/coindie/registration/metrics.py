"""Errors of an estimated transform against the truth: the paper's SRE, rotation and translation errors."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from coindie.transforms import inverse  # noqa: F401  (registration/speed.py imports it from here)


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
