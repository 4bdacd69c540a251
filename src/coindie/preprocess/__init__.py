"""Preprocessing of coin-face scans: orientation, grid sampling, normals, canonical frame, height maps.

The pipeline step is :func:`preprocess` (orient face up, centre, grid sample 0.1 mm as in the paper,
normals if missing), configured by :class:`PreprocessConfig`. Later stages build on
:func:`canonical_frame` (best-fit plane at z = 0, face up) and :func:`height_map` (the relief as an image).

Names are imported on first use (PEP 562) so that a command needing only the height map does not pay
for the k-d tree at start-up.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from coindie.preprocess.canonical import CanonicalFrame, canonical_frame
    from coindie.preprocess.config import PreprocessConfig
    from coindie.preprocess.heightmap import HeightMap, height_map
    from coindie.preprocess.normals import estimate_normals
    from coindie.preprocess.orientation import orient_to_z, up_axis
    from coindie.preprocess.pipeline import (
        PreprocessResult,
        frame_from_config,
        height_map_from_config,
        preprocess,
    )
    from coindie.preprocess.sampling import grid_sample
    from coindie.preprocess.summary import ScanSummary, summarize_scan

_MODULE_OF = {
    "CanonicalFrame": "canonical",
    "canonical_frame": "canonical",
    "PreprocessConfig": "config",
    "HeightMap": "heightmap",
    "height_map": "heightmap",
    "estimate_normals": "normals",
    "orient_to_z": "orientation",
    "up_axis": "orientation",
    "PreprocessResult": "pipeline",
    "preprocess": "pipeline",
    "frame_from_config": "pipeline",
    "height_map_from_config": "pipeline",
    "grid_sample": "sampling",
    "ScanSummary": "summary",
    "summarize_scan": "summary",
}

__all__ = [
    "CanonicalFrame",
    "HeightMap",
    "PreprocessConfig",
    "PreprocessResult",
    "ScanSummary",
    "canonical_frame",
    "estimate_normals",
    "frame_from_config",
    "grid_sample",
    "height_map",
    "height_map_from_config",
    "orient_to_z",
    "preprocess",
    "summarize_scan",
    "up_axis",
]


def __getattr__(name: str) -> Any:
    module = _MODULE_OF.get(name)
    if module is None:
        raise AttributeError(f"module 'coindie.preprocess' has no attribute {name!r}")
    return getattr(importlib.import_module(f"coindie.preprocess.{module}"), name)


def __dir__() -> list[str]:
    return __all__
