"""Random-search ICP (Horache et al. 2020): ICP from many random starts about the coin's axis, best kept.

Both scans are levelled (centroid to the origin, smallest principal axis to +z, signed by the normals:
:func:`coindie.preprocess.orientation.pca_transform`), so a start is a turn about z plus a small tilt. The
starts are stratified over the full turn (one random angle in each of ``n_starts`` equal sectors): no gap
wider than two sectors, where plain random draws leave wide ones. ICP (on the face only: points whose normal
is steep to the axis, the flan's edge wall, are left out) runs from every start on coarse clouds; the few
best are refined on the full clouds. Poses are ranked by the robust point-to-plane score, not by fitness,
which is near 100 % for wrong turns of a dome (see :mod:`coindie.registration.quality`).

Default of 36 starts (10° sectors): on the synthetic reliefs of the tests' ``synthetic_pairs`` ICP
converges from up to ~15° away about the axis, and libraries.md saw pairs with a single converging start of
24, so the sectors stay well inside the basin. Coarse ICP costs ~15–30 ms a start.

Known limit (measured on 40 same-die pairs of a synthetic hoard, ``coindie synth``): half the pairs fail,
because coarse ICP on whole faces follows the flans' shapes, which differ from coin to coin, more than the
die's pattern; even started at the truth it drifts to a wrong pose that scores better. More starts, other
pairing distances or finer coarse grids did not change that. The paper's table shows the same weakness.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.arrays import FloatArray
from coindie.params import Configurable, param
from coindie.preprocess.orientation import pca_transform, up_axis
from coindie.preprocess.sampling import grid_sample
from coindie.registration.base import Estimate, Timer
from coindie.registration.clouds import Cloud, content_rng
from coindie.registration.icp import MIN_CORRESPONDENCES, point_to_plane_icp
from coindie.registration.quality import robust_score
from coindie.scan import Scan
from coindie.transforms import euler_rotation, inverse, rigid


@dataclass(frozen=True, kw_only=True)
class RandomSearch(Configurable):
    """Starts, coarse ICP from each, fine ICP on the best few."""

    NAME = "search"

    n_starts: int = param(36, low=1, doc="random turns about the coin's axis (one per equal sector)")
    max_tilt_deg: float = param(3.0, unit="deg", low=0, high=90, doc="largest random tilt of a start")
    coarse_voxel: float = param(0.3, unit="mm", low=0, low_open=True, doc="grid of the coarse clouds")
    coarse_points: int = param(2000, low=MIN_CORRESPONDENCES, doc="source points used at the coarse level")
    coarse_distance: float = param(1.0, unit="mm", low=0, low_open=True, doc="pairing distance, coarse ICP")
    coarse_iterations: int = param(20, low=1, doc="coarse ICP iterations at most")
    finalists: int = param(3, low=1, doc="best coarse poses refined on the full clouds")
    fine_points: int = param(8000, low=MIN_CORRESPONDENCES, doc="source points used at the fine level")
    fine_distance: float = param(0.15, unit="mm", low=0, low_open=True, doc="pairing distance, fine ICP")
    fine_iterations: int = param(30, low=1, doc="fine ICP iterations at most")
    tolerance: float = param(1e-4, low=0, doc="ICP stops when the update (rad and mm) is smaller")
    max_normal_angle_deg: float = param(
        60.0,
        unit="deg",
        low=0,
        high=180,
        doc="ICP ignores points whose normal is farther from the coin's axis",
    )
    seed: int = param(0, low=0, doc="seed of the starts")

    def starts(self) -> list[FloatArray]:
        """Rotations (4x4) about z by one random angle per sector, each with a random small tilt."""
        rng = np.random.default_rng(self.seed)
        sector = 360.0 / self.n_starts
        turns = sector * (np.arange(self.n_starts) + rng.uniform(0, 1, self.n_starts))
        tilts = self.max_tilt_deg * np.sqrt(rng.uniform(0, 1, self.n_starts))
        directions = rng.uniform(0, 2 * np.pi, self.n_starts)
        angles = np.column_stack([tilts * np.cos(directions), tilts * np.sin(directions), turns])
        return [rigid(R, np.zeros(3)) for R in euler_rotation(angles)]


@dataclass(frozen=True)
class RandomSearchICP:
    """The ``rs-icp`` estimator."""

    search: RandomSearch

    def estimate(self, source: Cloud, target: Cloud, timer: Timer) -> Estimate:
        s = self.search
        with timer("levelling"):
            L_source = pca_transform(source.points, source.normals)
            L_target_inv = inverse(pca_transform(target.points, target.normals))
            # The edge wall of a flan is not part of the die's pattern: ICP works on the face only.
            source, target = _face(source, s.max_normal_angle_deg), _face(target, s.max_normal_angle_deg)
            coarse_source = _sample(_coarse(source, s.coarse_voxel).points, s.coarse_points, s.seed)
            coarse_target = _coarse(target, s.coarse_voxel)
        with timer("coarse"):
            coarse = [
                self._icp(coarse_source, coarse_target, L_target_inv @ R @ L_source, coarse=True)
                for R in s.starts()
            ]
        with timer("fine"):
            finalists = sorted(coarse, key=lambda c: c[0])[: s.finalists]
            fine_source = _sample(source.points, s.fine_points, s.seed)
            score, T, n_pairs = min(
                (self._icp(fine_source, target, T, coarse=False) for _, T, _ in finalists), key=lambda c: c[0]
            )
        note = f"random search: {len(coarse)} starts, best robust score {score:.4f} mm"
        if n_pairs < MIN_CORRESPONDENCES:
            failure = f"no start brought {MIN_CORRESPONDENCES} point pairs within {s.fine_distance} mm"
            return Estimate(None, n_pairs, failure=failure, notes=(note,))
        return Estimate(T, n_pairs, n_pairs, notes=(note,))

    def _icp(self, points: FloatArray, target: Cloud, T_start: FloatArray, *, coarse: bool) -> _Candidate:
        """ICP from one start, scored by the robust point-to-plane score."""
        s = self.search
        distance = s.coarse_distance if coarse else s.fine_distance
        iterations = s.coarse_iterations if coarse else s.fine_iterations
        outcome = point_to_plane_icp(
            points, target, T_start, max_iterations=iterations, max_distance=distance, tolerance=s.tolerance
        )
        T = outcome.T_target_source
        return robust_score(points, target, T, distance), T, outcome.n_correspondences


_Candidate = tuple[float, FloatArray, int]


def _face(cloud: Cloud, max_angle_deg: float) -> Cloud:
    """The points whose normal is within ``max_angle_deg`` of the face's up axis (all if too few remain)."""
    keep = cloud.normals @ up_axis(cloud.points, cloud.normals) >= np.cos(np.radians(max_angle_deg))
    return cloud.subset(np.flatnonzero(keep)) if keep.sum() >= MIN_CORRESPONDENCES else cloud


def _coarse(cloud: Cloud, voxel: float) -> Cloud:
    sampled = grid_sample(Scan(points=cloud.points, normals=cloud.normals), voxel)
    assert sampled.normals is not None
    return Cloud(sampled.points, sampled.normals)


def _sample(points: FloatArray, n: int, seed: int) -> FloatArray:
    if len(points) <= n:
        return points
    index = content_rng(points, seed).choice(len(points), n, replace=False)
    return points[np.sort(index)]
