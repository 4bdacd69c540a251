"""RANSAC on putative matches, from Open3D (``registration_ransac_based_on_correspondence``).

The Riedones3D authors' alternative to TEASER: distance threshold 0.5 mm, 4 matches per hypothesis. Open3D
draws its samples from the generator seeded by ``open3d.utility.random.seed``, but its parallel loop may stop
early at a thread-dependent iteration, so its own output can differ between runs (measured: 1 run in 6 moved
0.1 mm on an easy pair). A least-squares refit on the inliers, iterated until the inlier set stops changing,
follows: hypotheses near the same pose converge to the same inlier set, and with it 8 repeated runs on each
of 3 synthetic pairs gave identical transforms.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.arrays import FloatArray
from coindie.params import Configurable, param
from coindie.registration.base import Matches, SolverOutcome
from coindie.transforms import fit_rigid, transform_points

#: Least-squares refits on the inliers at most (they stop as soon as the inlier set no longer changes).
_REFITS = 10


@dataclass(frozen=True, kw_only=True)
class RansacSolver(Configurable):
    """Open3D's RANSAC on matches, with an edge-length pre-check of each sample, then a refit on inliers."""

    NAME = "ransac"

    distance: float = param(
        0.5, unit="mm", low=0, low_open=True, doc="a match is an inlier within this distance"
    )
    sample_size: int = param(4, low=3, doc="matches per hypothesis")
    max_iterations: int = param(100_000, low=1, doc="hypotheses at most")
    confidence: float = param(0.999, low=0, high=1, high_open=True, doc="stop once this sure of the best")
    edge_similarity: float = param(
        0.9, low=0, high=1, high_open=True, doc="reject samples whose edge lengths differ by more (0: off)"
    )
    seed: int = param(0, low=0, doc="seed of Open3D's random generator")

    def solve(self, matches: Matches) -> SolverOutcome:
        no_inliers = np.zeros(len(matches), dtype=bool)
        if len(matches) < self.sample_size:
            failure = f"{len(matches)} matches: RANSAC needs at least {self.sample_size}"
            return SolverOutcome(None, no_inliers, failure)
        T = self._open3d_ransac(matches)
        inliers = self._inliers(matches, T)
        if inliers.sum() < 3:
            return SolverOutcome(None, inliers, f"RANSAC kept {int(inliers.sum())} inlier matches (needs 3)")
        T, inliers = self._refit(matches, T, inliers)
        note = f"RANSAC: {int(inliers.sum())} of {len(matches)} matches within {self.distance} mm"
        return SolverOutcome(T, inliers, notes=(note,))

    def _open3d_ransac(self, matches: Matches) -> FloatArray:
        import open3d as o3d

        reg = o3d.pipelines.registration
        o3d.utility.random.seed(self.seed)
        pairs = np.repeat(np.arange(len(matches), dtype=np.int32)[:, None], 2, axis=1)
        checkers = [reg.CorrespondenceCheckerBasedOnDistance(self.distance)]
        if self.edge_similarity > 0:
            checkers.insert(0, reg.CorrespondenceCheckerBasedOnEdgeLength(self.edge_similarity))
        result = reg.registration_ransac_based_on_correspondence(
            _cloud(matches.source),
            _cloud(matches.target),
            o3d.utility.Vector2iVector(pairs),
            self.distance,
            reg.TransformationEstimationPointToPoint(False),
            self.sample_size,
            checkers,
            reg.RANSACConvergenceCriteria(self.max_iterations, self.confidence),
        )
        return np.array(result.transformation, dtype=np.float64)

    def _inliers(self, matches: Matches, T: FloatArray) -> np.ndarray:
        residual = np.linalg.norm(transform_points(T, matches.source) - matches.target, axis=1)
        return residual <= self.distance

    def _refit(self, matches: Matches, T: FloatArray, inliers: np.ndarray) -> tuple[FloatArray, np.ndarray]:
        for _ in range(_REFITS):
            T = fit_rigid(matches.source[inliers], matches.target[inliers])
            updated = self._inliers(matches, T)
            if np.array_equal(updated, inliers) or updated.sum() < 3:
                break
            inliers = updated
        return T, inliers


def _cloud(points: FloatArray):  # -> open3d.geometry.PointCloud (Open3D is imported lazily)
    import open3d as o3d

    return o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
