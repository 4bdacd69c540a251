"""Turn a scan face up: centre it and rotate its smallest principal axis onto +z (the paper's step)."""

from __future__ import annotations

import numpy as np

from coindie.arrays import FloatArray
from coindie.io.orientation import GEOMETRY_SAMPLE, face_up
from coindie.preprocess.normals import estimate_normals
from coindie.scan import Scan
from coindie.transforms import rigid, rotation_between

_Z = np.array([0.0, 0.0, 1.0])
#: A mean normal shorter than this is no guide to which side is up (normals cancel out).
_MIN_MEAN_NORMAL = 1e-3
#: Fewer points than this carry no geometry worth reading: the scanner's +z side is kept.
_MIN_GEOMETRY_POINTS = 100


def up_axis(points: FloatArray, normals: FloatArray | None = None) -> FloatArray:
    """The unit direction of the smallest principal axis, pointing to the face's up side.

    Up is the side of the mean normal when there are normals. Without normals (or when they cancel
    out) it is the side the face's geometry says (:func:`coindie.io.orientation.face_up`: the edge wall
    below the face, the relief raised), not the scanner's +z: a scan written in any pose does not keep
    it. The scanner's +z side is kept only where the geometry says nothing (too few points, no wall
    and a symmetric relief).
    """
    centred = points - points.mean(axis=0)
    _, vectors = np.linalg.eigh(centred.T @ centred)
    axis = vectors[:, 0]
    reference = None if normals is None else normals.mean(axis=0)
    if reference is None or np.linalg.norm(reference) < _MIN_MEAN_NORMAL:
        reference = _geometric_up(points)
    return axis if axis @ reference >= 0 else -axis


def _geometric_up(points: FloatArray) -> FloatArray:
    """The face's up direction from its geometry alone (normals estimated by local PCA on a regular
    subsample of at most ``GEOMETRY_SAMPLE`` points, the one the reader's orientation check reads, their
    signs unused); the scanner's +z for clouds too small to read."""
    if len(points) < _MIN_GEOMETRY_POINTS:
        return _Z
    sample = points[:: max(1, -(-len(points) // GEOMETRY_SAMPLE))]
    return face_up(sample, estimate_normals(sample))


def pca_transform(points: FloatArray, normals: FloatArray | None = None) -> FloatArray:
    """``T_oriented_scan``: the centroid to the origin, :func:`up_axis` to +z by the smallest rotation.

    The smallest rotation keeps the scanner's in-plane orientation (PCA's in-plane axes of a round coin
    are arbitrary and would spin the image from scan to scan).
    """
    R = rotation_between(up_axis(points, normals), _Z)
    return rigid(R, -R @ points.mean(axis=0))


def orient_to_z(scan: Scan) -> tuple[Scan, FloatArray]:
    """The scan centred on its centroid and turned face up (+z), with ``T_oriented_scan`` (4x4, det +1)."""
    T_oriented_scan = pca_transform(scan.points, scan.normals)
    return scan.transformed(T_oriented_scan), T_oriented_scan
