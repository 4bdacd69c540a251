"""What ``coindie info`` says about a scan: size, extent, diameter, spacing."""

from __future__ import annotations

from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np
from scipy.spatial import ConvexHull, QhullError, cKDTree

from coindie.arrays import FloatArray
from coindie.preprocess.orientation import pca_transform
from coindie.scan import Scan
from coindie.transforms import apply

#: The point spacing is the median nearest-neighbour distance over this many random points (enough for
#: a median to about 1 %, and much faster than all 200k).
SPACING_SAMPLE = 10_000
#: Directions (over 180°) across which the face's width is measured for its diameter.
DIAMETER_DIRECTIONS = 360


@dataclass(frozen=True)
class ScanSummary:
    """Facts about one scan. Lengths in mm; ``extent_mm`` is the bounding box (x, y, z) in the scan frame."""

    id: str
    face: str
    path: str | None
    file_size_bytes: int | None
    points: int
    has_normals: bool
    has_colors: bool
    bbox_min_mm: tuple[float, float, float]
    bbox_max_mm: tuple[float, float, float]
    extent_mm: tuple[float, float, float]
    diameter_mm: float
    spacing_mm: float

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def summarize_scan(scan: Scan, *, seed: int = 0) -> ScanSummary:
    """Summarise ``scan`` (its file size too when it has a path that exists)."""
    low, high = scan.points.min(axis=0), scan.points.max(axis=0)
    path = scan.path
    return ScanSummary(
        id=scan.id.name,
        face={"D": "obverse", "R": "reverse"}.get(scan.face.value, "unknown"),
        path=None if path is None else str(path),
        file_size_bytes=path.stat().st_size if path is not None and Path(path).is_file() else None,
        points=scan.n_points,
        has_normals=scan.has_normals,
        has_colors=scan.colors is not None,
        bbox_min_mm=_triple(low),
        bbox_max_mm=_triple(high),
        extent_mm=_triple(high - low),
        diameter_mm=face_diameter(scan),
        spacing_mm=point_spacing(scan.points, seed=seed),
    )


def face_diameter(scan: Scan) -> float:
    """Largest width (mm) of the face seen from above (after PCA orientation).

    The width is measured across ``DIAMETER_DIRECTIONS`` directions on the convex hull's vertices: at
    0.5° steps it is short of the true diameter by at most 1 - cos(0.25°) = 1e-5 of it (0.2 µm on a
    20 mm coin), and costs a few ms where all pairs of a dense rim's hull vertices cost 0.5 s.
    """
    xy = apply(pca_transform(scan.points, scan.normals), scan.points)[:, :2]
    try:
        corners = xy[ConvexHull(xy).vertices]
    except QhullError:  # collinear or too few points: the hull is the points themselves
        corners = xy
    angles = np.linspace(0.0, np.pi, DIAMETER_DIRECTIONS, endpoint=False)
    along = corners @ np.stack([np.cos(angles), np.sin(angles)])
    return float(np.ptp(along, axis=0).max())


def point_spacing(points: FloatArray, *, seed: int = 0) -> float:
    """Median distance (mm) from a point to its nearest neighbour, over a random sample of points."""
    if len(points) < 2:
        return 0.0
    rng = np.random.default_rng(seed)
    sample = points[rng.choice(len(points), min(SPACING_SAMPLE, len(points)), replace=False)]
    # An unbalanced tree with larger leaves builds ~2x faster and answers these few queries as fast.
    distances, _ = cKDTree(points, leafsize=32, balanced_tree=False).query(sample, k=2)
    return float(np.median(distances[:, 1]))


def _triple(values: FloatArray) -> tuple[float, float, float]:
    return (float(values[0]), float(values[1]), float(values[2]))
