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


def alignment(source: FloatArray, target: Cloud, T_target_source: FloatArray, distance: float) -> Alignment:
    """Fitness, RMSE and median point-to-plane residual of ``source`` points moved onto ``target``."""
    moved = transform_points(T_target_source, source)
    distances, index = target.nearest(moved, distance)
    near = np.isfinite(distances)
    if not near.any():
        return Alignment(0.0, float("inf"), float("inf"), 0)
    offsets = moved[near] - target.points[index[near]]
    plane = np.abs(np.einsum("ij,ij->i", offsets, target.normals[index[near]]))
    rmse = float(np.sqrt(np.mean(distances[near] ** 2)))
    return Alignment(float(near.mean()), rmse, float(np.median(plane)), int(near.sum()))


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
    """When a registration counts as valid: enough overlap, and a small median point-to-plane residual."""

    NAME = "check"

    overlap_distance: float = param(
        0.3, unit="mm", low=0, low_open=True, doc="a source point overlaps the target within this distance"
    )
    min_fitness: float = param(
        0.3, low=0, high=1, doc="smallest share of overlapping source points for a valid result"
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
        if figures.fitness < self.min_fitness:
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
