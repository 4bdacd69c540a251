"""The canonical frame of a coin face: its best-fit plane is z = 0, face up, centred.

Every later stage (height maps, levelled registration, renders) works in this frame. The fit is robust
to the two things that are not the face's field: the coin's edge wall (left out by its normals, which
are far from up) and the relief (down-weighted by a Tukey biweight on the residuals).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike

from coindie.arrays import FloatArray
from coindie.errors import ParameterError
from coindie.preprocess.defaults import FIT_ITERATIONS, FIT_MAX_NORMAL_ANGLE_DEG, FIT_MAX_POINTS
from coindie.preprocess.orientation import pca_transform
from coindie.scan import Scan
from coindie.transforms import apply, rigid, rotation_between

SurfaceModel = Literal["plane", "quadric"]

#: Tukey biweight tuning constant (95 % efficiency under Gaussian noise), in robust standard deviations.
TUKEY_C = 4.685
#: MAD to standard deviation for Gaussian noise.
_MAD_TO_SIGMA = 1.4826
#: Residual scale floor (mm), so that noise-free synthetic data do not divide by zero.
_MIN_SCALE_MM = 1e-6
_Z = np.array([0.0, 0.0, 1.0])


@dataclass(frozen=True, eq=False)
class CanonicalFrame:
    """Where a coin face lies.

    Attributes:
        T_canonical_scan: 4x4 rigid transform from the scan's frame to the canonical frame.
        quadric: (6,) coefficients of the best-fit quadric in the canonical frame (mm):
            ``z = q0 + q1 x + q2 y + q3 x² + q4 x y + q5 y²``.
        model: the surface whose (tangent) plane defines the frame.
        n_support: points (of the fitted subsample) with non-zero weight in the final fit.
        residual_mm: robust standard deviation of the relief about the quadric (mm).
    """

    T_canonical_scan: FloatArray
    quadric: FloatArray
    model: SurfaceModel
    n_support: int
    residual_mm: float

    @property
    def up(self) -> FloatArray:
        """The face's up direction in the scan's frame."""
        return self.T_canonical_scan[2, :3].copy()

    def surface_height(self, x: ArrayLike, y: ArrayLike) -> FloatArray:
        """Height of the best-fit quadric (mm) at canonical (x, y)."""
        return design_matrix(np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)) @ self.quadric


def canonical_frame(
    scan: Scan,
    *,
    model: SurfaceModel = "plane",
    max_normal_angle_deg: float = FIT_MAX_NORMAL_ANGLE_DEG,
    iterations: int = FIT_ITERATIONS,
) -> CanonicalFrame:
    """Fit the face's plane (or quadric) robustly and return the frame in which it is z = 0, face up.

    Steps: PCA orientation (a first guess of up); a reweighted fit of ``model`` on the points whose
    normal is within ``max_normal_angle_deg`` of up; the smallest rotation that levels the plane (for a
    quadric, its tangent plane at the centre); then the quadric is refitted in the levelled frame.
    """
    _check(model, max_normal_angle_deg, iterations)
    T_pca_scan = pca_transform(scan.points, scan.normals)
    fitted = scan.subset(_regular_sample(scan.n_points)).transformed(T_pca_scan)
    prior = _support(fitted, max_normal_angle_deg)
    xy, z = fitted.points[:, :2], fitted.points[:, 2]
    coefficients, _, _ = robust_fit(xy, z, prior, model=model, iterations=iterations)
    T_canonical_pca = _levelling(coefficients)
    levelled = apply(T_canonical_pca, fitted.points)
    quadric, weights, scale = robust_fit(levelled[:, :2], levelled[:, 2], prior, "quadric", iterations)
    return CanonicalFrame(
        T_canonical_scan=T_canonical_pca @ T_pca_scan,
        quadric=quadric,
        model=model,
        n_support=int(np.count_nonzero(weights)),
        residual_mm=scale,
    )


def _check(model: str, max_normal_angle_deg: float, iterations: int) -> None:
    if model not in ("plane", "quadric"):
        raise ParameterError(
            f"The 'model' parameter of canonical_frame must be 'plane' or 'quadric'. Got {model!r}."
        )
    if not 0 < max_normal_angle_deg <= 90:
        raise ParameterError(
            f"The 'max_normal_angle_deg' parameter must be in (0, 90] degrees. Got {max_normal_angle_deg}."
        )
    if iterations < 1:
        raise ParameterError(f"The 'iterations' parameter of canonical_frame must be >= 1. Got {iterations}.")


def _regular_sample(n_points: int) -> np.ndarray:
    """Every k-th point, at most ``FIT_MAX_POINTS`` (deterministic; six coefficients need few points)."""
    return np.arange(0, n_points, max(1, -(-n_points // FIT_MAX_POINTS)))


def _support(scan: Scan, max_normal_angle_deg: float) -> FloatArray:
    """Prior weights: 1 for points facing up (the face), 0 for the edge wall; all 1 without normals."""
    if scan.normals is None:
        return np.ones(scan.n_points)
    facing_up = scan.normals[:, 2] >= np.cos(np.radians(max_normal_angle_deg))
    if np.count_nonzero(facing_up) < 6:  # normals that say nothing useful: trust the reweighting alone
        return np.ones(scan.n_points)
    return facing_up.astype(np.float64)


def _levelling(coefficients: FloatArray) -> FloatArray:
    """``T_canonical_pca``: the fitted surface's tangent plane at (0, 0) becomes z = 0."""
    height, slope_x, slope_y = coefficients[:3]
    R = rotation_between(np.array([-slope_x, -slope_y, 1.0]), _Z)
    return rigid(R, -R @ np.array([0.0, 0.0, height]))


def design_matrix(x: FloatArray, y: FloatArray, model: SurfaceModel = "quadric") -> FloatArray:
    """Columns ``1, x, y`` (plane) or ``1, x, y, x², x y, y²`` (quadric)."""
    columns = [np.ones_like(x), x, y]
    if model == "quadric":
        columns += [x * x, x * y, y * y]
    return np.stack(columns, axis=-1)


def robust_fit(
    xy: FloatArray, z: FloatArray, prior: FloatArray, model: SurfaceModel, iterations: int
) -> tuple[FloatArray, FloatArray, float]:
    """Iteratively reweighted least squares of ``z ≈ f(x, y)`` with Tukey's biweight.

    Returns (coefficients padded to the quadric's six, final weights, robust residual scale in mm).
    """
    A = design_matrix(xy[:, 0], xy[:, 1], model)
    weights, support = prior, prior > 0
    for _ in range(iterations):
        coefficients = _weighted_least_squares(A, z, weights)
        residuals = z - A @ coefficients
        scale = max(_MAD_TO_SIGMA * float(np.median(np.abs(residuals[support]))), _MIN_SCALE_MM)
        u = residuals / (TUKEY_C * scale)
        weights = prior * np.where(np.abs(u) < 1.0, (1.0 - u * u) ** 2, 0.0)
        if np.count_nonzero(weights) < A.shape[1]:  # degenerate: keep the previous weights' solution
            weights = prior
            break
    return np.pad(coefficients, (0, 6 - len(coefficients))), weights, scale


def _weighted_least_squares(A: FloatArray, z: FloatArray, weights: FloatArray) -> FloatArray:
    """argmin_c sum w (A c - z)^2 through the (at most 6x6) normal equations: ~20x faster than an SVD of
    the tall weighted matrix, and well conditioned for coordinates of a few tens of mm."""
    normal = A.T @ (A * weights[:, None])
    rhs = A.T @ (z * weights)
    try:
        return np.linalg.solve(normal, rhs)
    except np.linalg.LinAlgError:
        return np.linalg.lstsq(normal, rhs, rcond=None)[0]
