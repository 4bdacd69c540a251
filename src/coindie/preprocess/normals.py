"""Normals by local PCA, for scans whose file has none."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike
from scipy.spatial import cKDTree

from coindie.arrays import FloatArray
from coindie.errors import ParameterError
from coindie.preprocess.defaults import NORMALS_K, NORMALS_RADIUS_MM

#: Points per batch of neighbourhoods (bounds the (batch, k, 3) temporary arrays to a few tens of MB).
_BATCH = 65_536
#: A neighbourhood needs this many points to define a plane.
_MIN_NEIGHBOURS = 3


def estimate_normals(
    points: ArrayLike,
    *,
    k: int = NORMALS_K,
    radius: float | None = NORMALS_RADIUS_MM,
    toward: ArrayLike = (0.0, 0.0, 1.0),
) -> FloatArray:
    """(N, 3) unit normals: the smallest principal axis of each point's ``k`` nearest neighbours.

    Neighbours farther than ``radius`` (mm) are ignored unless fewer than three remain. Each normal is
    flipped to the side of the direction ``toward`` (a face-up scan: +z).
    """
    points = np.asarray(points, dtype=np.float64)
    _check(points, k, radius)
    k = min(k, len(points))
    distances, neighbours = cKDTree(points).query(points, k=k, workers=-1)
    normals = np.empty_like(points)
    for start in range(0, len(points), _BATCH):
        part = slice(start, start + _BATCH)
        keep = _within(distances[part], radius)
        normals[part] = _smallest_axes(points[neighbours[part]], keep)
    flip = normals @ np.asarray(toward, dtype=np.float64) < 0
    normals[flip] *= -1.0
    return normals


def _check(points: FloatArray, k: int, radius: float | None) -> None:
    if points.ndim != 2 or points.shape[1] != 3 or len(points) < _MIN_NEIGHBOURS:
        raise ParameterError(f"Normals need an (N, 3) array with N >= 3 points. Got shape {points.shape}.")
    if k < _MIN_NEIGHBOURS:
        raise ParameterError(f"The 'k' parameter of estimate_normals must be >= 3. Got {k}.")
    if radius is not None and not radius > 0:
        raise ParameterError(
            f"The 'radius' parameter of estimate_normals must be > 0 mm or None. Got {radius}."
        )


def _within(distances: FloatArray, radius: float | None) -> np.ndarray:
    """Which neighbours count; all ``k`` for the points with fewer than three within ``radius``."""
    if radius is None:
        return np.ones(distances.shape, dtype=bool)
    keep = distances <= radius
    keep[keep.sum(axis=1) < _MIN_NEIGHBOURS] = True
    return keep


def _smallest_axes(neighbourhoods: FloatArray, keep: np.ndarray) -> FloatArray:
    """Eigenvector of the smallest eigenvalue of each (masked) neighbourhood covariance, batched."""
    weights = keep[..., None].astype(np.float64)
    mean = (neighbourhoods * weights).sum(axis=1, keepdims=True) / weights.sum(axis=1, keepdims=True)
    centred = (neighbourhoods - mean) * weights
    covariance = np.einsum("nki,nkj->nij", centred, centred)
    _, vectors = np.linalg.eigh(covariance)
    return vectors[:, :, 0]
