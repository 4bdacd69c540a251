"""Manual registration: the expert's corresponding points give a start (Kabsch), ICP refines it, the pair is
scored again with the project's classifier.

Uses the library's own pieces: :func:`coindie.transforms.fit_rigid` (Kabsch),
:func:`coindie.registration.icp.point_to_plane_icp` on the clouds sampled at the registration grid, and
:func:`coindie.similarity.histogram.c2c_histogram` with the shipped classifier.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from coindie.errors import ParameterError
from coindie.preprocess.sampling import grid_sample
from coindie.registration.clouds import Cloud
from coindie.registration.icp import MIN_CORRESPONDENCES, point_to_plane_icp
from coindie.serve.images import face_scan
from coindie.similarity.classifier import SameDieClassifier
from coindie.similarity.histogram import c2c_histogram
from coindie.transforms import fit_rigid, transform_points

#: The registration grid of the project (mm) and ICP's settings for a refined start: the paper's refinement
#: (correspondences within 0.1 mm, 10 iterations, stop below 1e-3). Wider correspondences let two flans of
#: one die slide along their domes, away from the picked alignment.
GRID_MM = 0.1
ICP_MAX_DISTANCE_MM = 0.1
ICP_ITERATIONS = 10
ICP_TOLERANCE = 1e-3


@dataclass(frozen=True)
class ManualRegistration:
    T_target_source: NDArray[np.float64]
    kabsch_rms_mm: float  # of the picked points after Kabsch
    icp_pairs: int
    icp_iterations: int
    probability: float
    histogram: NDArray[np.float64]
    reason: str


def register_by_points(
    target_path: Path,
    source_path: Path,
    target_points: NDArray,
    source_points: NDArray,
    unit: str | None = None,
) -> ManualRegistration:
    """``T_target_source`` from >= 3 corresponding points (scan frames, mm), refined and scored.

    Raises:
        ParameterError: fewer than 3 pairs of points, or points (nearly) on a line.
    """
    src, dst = np.asarray(source_points, dtype=np.float64), np.asarray(target_points, dtype=np.float64)
    if src.shape != dst.shape or src.ndim != 2 or src.shape[1] != 3 or len(src) < 3:
        raise ParameterError(
            f"manual registration needs >= 3 pairs of 3D points; got {src.shape} and {dst.shape}"
        )
    spread = np.linalg.svd(src - src.mean(axis=0), compute_uv=False)
    if spread[1] < 0.05 * max(spread[0], 1e-9):
        raise ParameterError(
            "the picked points are (nearly) on a line: pick three or more spread over the face"
        )
    T_start = fit_rigid(src, dst)
    rms = float(np.sqrt(np.mean(np.sum((transform_points(T_start, src) - dst) ** 2, axis=1))))
    target, _ = face_scan(target_path, unit)
    source, _ = face_scan(source_path, unit)
    target_cloud = Cloud.of(grid_sample(target, GRID_MM))
    source_cloud = Cloud.of(grid_sample(source, GRID_MM))
    outcome = point_to_plane_icp(
        source_cloud.points,
        target_cloud,
        T_start,
        max_iterations=ICP_ITERATIONS,
        max_distance=ICP_MAX_DISTANCE_MM,
        tolerance=ICP_TOLERANCE,
    )
    note = f"picked {len(src)} points (Kabsch RMS {rms:.3f} mm), ICP {outcome.iterations} iterations"
    classifier = SameDieClassifier.load_default()

    def scored(T: NDArray[np.float64]) -> tuple[float, NDArray[np.float64]]:
        histogram = c2c_histogram(source, target, T, classifier.settings)
        return (float(classifier.predict_proba(histogram[None, :])[0]) if histogram.any() else 0.0), histogram

    probability, histogram = scored(T_start)
    T = T_start
    if outcome.n_correspondences >= MIN_CORRESPONDENCES:
        refined, refined_histogram = scored(outcome.T_target_source)
        if refined >= probability:  # ICP keeps the expert's alignment unless it makes the pair worse
            T, probability, histogram = outcome.T_target_source, refined, refined_histogram
        else:
            note += "; ICP lowered the probability, the picked points' transform is kept"
    else:
        note += "; ICP found no overlap, the picked points' transform is kept"
    return ManualRegistration(
        T, rms, outcome.n_correspondences, outcome.iterations, probability, histogram, note
    )
