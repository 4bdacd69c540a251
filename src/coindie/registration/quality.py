"""How well an estimated transform aligns two clouds, and whether to accept it.

Fitness (the share of source points with a target point nearby) cannot tell a right pose from a wrong one
on coins: a wrongly turned shallow dome still lies within 0.2–0.3 mm of the other coin almost everywhere
(93–99 % fitness on synthetic pairs). The median point-to-plane residual of those points does
separate them (right poses ≤ 0.011 mm, wrong ones ≥ 0.027 mm on synthetic reliefs), so it is the score that
ranks candidate poses. It no longer decides ``valid`` by default: a fixed residual in millimetres refused
75 % of the right same-die poses of another generator's hoards (noisier scanners, cupped flans: residuals
of 0.03-0.07 mm), so a registration is refused only where there is no coin pose at all (too little
overlap, a degenerate fit), and the same-die scorer judges the rest (:mod:`coindie.similarity`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.arrays import FloatArray
from coindie.params import Configurable, param
from coindie.registration.clouds import Cloud
from coindie.transforms import transform_points


@dataclass(frozen=True)
class Alignment:
    """Figures of one transform on one pair."""

    fitness: float  # share of source points with a target point within ``distance``
    inlier_rmse: float  # RMS distance (mm) of those points to their nearest target point
    residual: float  # median |point-to-plane distance| (mm) of those points; inf without any
    n_inliers: int  # number of those points
    overlap: float = float("nan")  # share of source points over the target's footprint (when measured)
    tilt_deg: float = 0.0  # angle between the two faces' up directions once aligned (when measured)


def alignment(
    source: FloatArray,
    target: Cloud,
    T_target_source: FloatArray,
    distance: float,
    *,
    source_up: FloatArray | None = None,
) -> Alignment:
    """Fitness, RMSE and median point-to-plane residual of ``source`` points moved onto ``target``; with
    ``source_up`` (the source face's up direction, its frame) also the share of them over the target's
    footprint and the tilt between the two faces."""
    moved = transform_points(T_target_source, source)
    overlap, tilt = float("nan"), 0.0
    if source_up is not None:
        footprint = target.footprint
        overlap = float(footprint.covers(moved).mean())
        up = np.asarray(T_target_source)[:3, :3] @ np.asarray(source_up, dtype=np.float64)
        tilt = float(np.degrees(np.arctan2(np.linalg.norm(np.cross(up, footprint.up)), up @ footprint.up)))
    distances, index = target.nearest(moved, distance)
    near = np.isfinite(distances)
    if not near.any():
        return Alignment(0.0, float("inf"), float("inf"), 0, overlap, tilt)
    offsets = moved[near] - target.points[index[near]]
    plane = np.abs(np.einsum("ij,ij->i", offsets, target.normals[index[near]]))
    rmse = float(np.sqrt(np.mean(distances[near] ** 2)))
    return Alignment(float(near.mean()), rmse, float(np.median(plane)), int(near.sum()), overlap, tilt)


def robust_score(source: FloatArray, target: Cloud, T_target_source: FloatArray, distance: float) -> float:
    """Median over all source points of the point-to-plane residual, clipped at ``distance`` (points with
    no target neighbour count as ``distance``): one number that is low only when most points lie on the
    target's surface. Ranks candidate poses when the overlap is over half of the source."""
    moved = transform_points(T_target_source, source)
    distances, index = target.nearest(moved, distance)
    residual = np.full(len(moved), distance)
    near = np.isfinite(distances)
    offsets = moved[near] - target.points[index[near]]
    residual[near] = np.abs(np.einsum("ij,ij->i", offsets, target.normals[index[near]]))
    return float(np.median(np.minimum(residual, distance)))


@dataclass(frozen=True, kw_only=True)
class Acceptance(Configurable):
    """When a registration counts as valid: the two faces overlap and face the same way.

    ``overlap="footprint"`` (the default) measures the overlap as an area: the share of the source's points
    that land over the target face's outline in its best-fit plane, whatever the scanner's noise or
    spacing, the flans' cupping or a bend; a pose that tilts one face by more than ``max_tilt`` against
    the other is degenerate. ``overlap="distance"`` is the earlier test, the share of source points
    within ``overlap_distance`` of the target in 3-D: a bend or a cupping difference of a few tenths of a
    millimetre puts right poses under it (``overlap_distance`` still sets the reach of the reported
    fitness, RMSE and residual).
    """

    NAME = "check"

    overlap: str = param(
        "footprint",
        choices=("footprint", "distance"),
        doc="how the overlap is measured: area over the target's outline (footprint), or source points "
        "within overlap_distance of the target (distance)",
    )
    overlap_distance: float = param(
        0.3, unit="mm", low=0, low_open=True, doc="a source point overlaps the target within this distance"
    )
    min_fitness: float = param(
        0.15,
        low=0,
        high=1,
        doc="smallest share of overlapping source points for a valid result (two strikes a third of the "
        "diameter off centre leave about a fifth of the faces in common)",
    )
    max_tilt: float = param(
        45.0, unit="deg", low=0, high=180, doc="largest angle between the two faces once aligned (footprint)"
    )
    max_points: int = param(
        10_000, low=100, doc="source points scored at most (a regular subsample of larger clouds)"
    )
    max_residual: float = param(
        0.0,
        unit="mm",
        low=0,
        doc="largest median point-to-plane residual of overlapping points for a valid result (0: not "
        "tested; a residual in mm measures the scanner's noise and the flans' shapes as much as the pose)",
    )

    def judge(self, figures: Alignment) -> str:
        """Why the figures are not acceptable ("" when they are)."""
        if self.overlap == "footprint" and np.isfinite(figures.overlap):
            if figures.tilt_deg > self.max_tilt:
                tilt = figures.tilt_deg
                return f"the aligned faces are tilted {tilt:.0f}° apart (max_tilt {self.max_tilt:g})"
            if figures.overlap < self.min_fitness:
                return (
                    f"only {figures.overlap:.1%} of the source lies over the target's outline "
                    f"(min_fitness {self.min_fitness})"
                )
        elif figures.fitness < self.min_fitness:
            return (
                f"only {figures.fitness:.1%} of the source points lie within {self.overlap_distance} mm "
                f"of the target (min_fitness {self.min_fitness})"
            )
        if self.max_residual > 0 and figures.residual > self.max_residual:
            return (
                f"median point-to-plane residual {figures.residual:.4f} mm exceeds max_residual "
                f"{self.max_residual} mm"
            )
        return ""
