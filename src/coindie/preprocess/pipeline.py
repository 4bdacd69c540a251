"""The preprocessing step of the pipeline: orient, centre, grid sample, normals if missing."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.arrays import FloatArray
from coindie.errors import InvalidScanError
from coindie.preprocess.canonical import CanonicalFrame, canonical_frame
from coindie.preprocess.config import PreprocessConfig
from coindie.preprocess.heightmap import HeightMap, height_map
from coindie.preprocess.normals import estimate_normals
from coindie.preprocess.orientation import pca_transform
from coindie.preprocess.sampling import grid_sample
from coindie.scan import Scan
from coindie.transforms import rigid

#: Local PCA needs three points for a plane.
MIN_POINTS_FOR_NORMALS = 3


@dataclass(frozen=True, eq=False)
class PreprocessResult:
    """A preprocessed scan and how it was obtained.

    Attributes:
        scan: the preprocessed scan.
        T_preprocessed_scan: 4x4 rigid transform from the input scan's frame to ``scan``'s frame.
        n_input_points: points before grid sampling.
        normals_estimated: whether the normals were estimated (the input had none).
    """

    scan: Scan
    T_preprocessed_scan: FloatArray
    n_input_points: int
    normals_estimated: bool


def preprocess(scan: Scan, config: PreprocessConfig | None = None) -> PreprocessResult:
    """Turn a scan face up and centred (paper: PCA to +z), grid sample it, estimate missing normals."""
    config = PreprocessConfig() if config is None else config
    # Orient and centre
    T_preprocessed_scan = orientation_transform(scan, config)
    out = scan.transformed(T_preprocessed_scan)
    # Grid sample
    if config.grid_size_mm is not None:
        out = grid_sample(out, config.grid_size_mm, config.grid_mode)
    # Normals if missing (face up now, so oriented toward +z)
    if out.normals is None:
        if out.n_points < MIN_POINTS_FOR_NORMALS:
            raise InvalidScanError(f"{out.n_points} points are too few to estimate normals", scan.path)
        out = out.with_normals(
            estimate_normals(out.points, k=config.normals_k, radius=config.normals_radius_mm)
        )
    return PreprocessResult(out, T_preprocessed_scan, scan.n_points, scan.normals is None)


def frame_from_config(scan: Scan, config: PreprocessConfig | None = None) -> CanonicalFrame:
    """:func:`canonical_frame` with the configuration's model, normal-angle cut and iterations."""
    config = PreprocessConfig() if config is None else config
    return canonical_frame(
        scan,
        model=config.frame_model,
        max_normal_angle_deg=config.fit_max_normal_angle_deg,
        iterations=config.fit_iterations,
    )


def height_map_from_config(
    scan: Scan, config: PreprocessConfig | None = None, frame: CanonicalFrame | None = None
) -> HeightMap:
    """:func:`height_map` with every setting taken from the configuration."""
    config = PreprocessConfig() if config is None else config
    return height_map(
        scan,
        resolution=config.heightmap_resolution_mm,
        frame=frame_from_config(scan, config) if frame is None else frame,
        detrend=config.detrend,
        max_normal_angle_deg=config.raster_max_normal_angle_deg,
        fill_max_distance=config.fill_max_distance_mm,
    )


def orientation_transform(scan: Scan, config: PreprocessConfig) -> FloatArray:
    """``T_oriented_scan`` for ``config.orientation`` ('pca', 'canonical' or 'none': only centred)."""
    if config.orientation == "pca":
        return pca_transform(scan.points, scan.normals)
    if config.orientation == "canonical":
        return frame_from_config(scan, config).T_canonical_scan
    return rigid(np.eye(3), -scan.points.mean(axis=0))
