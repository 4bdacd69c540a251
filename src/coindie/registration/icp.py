"""Point-to-plane ICP (Chen & Medioni 1992) and the ``icp`` method.

The kernel is written here rather than taken from Open3D because the methods need two things Open3D's
``registration_icp`` does not give: the paper's stopping rule (the size of the update, not the change of
fitness / RMSE), and one search tree on the target reused across the many starts of random search and
across refinement (Open3D rebuilds its tree on every call). Each iteration is one nearest-neighbour query
(scipy's cKDTree, all cores) and one 6x6 linear solve.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.arrays import FloatArray
from coindie.params import Configurable, param
from coindie.registration.base import Estimate, Timer
from coindie.registration.clouds import Cloud
from coindie.transforms import small_rotation, transform_points

#: Fewer correspondences than this leave the 6 unknowns of an ICP step under-determined.
MIN_CORRESPONDENCES = 6
#: Relative damping of the 6x6 normal equations (keeps a flat patch's free directions still).
_DAMPING = 1e-9


@dataclass(frozen=True)
class IcpOutcome:
    T_target_source: FloatArray
    n_correspondences: int  # in the last iteration
    iterations: int
    converged: bool  # the update fell below the tolerance


def point_to_plane_icp(
    source: FloatArray,
    target: Cloud,
    T_init: FloatArray,
    *,
    max_iterations: int,
    max_distance: float,
    tolerance: float,
) -> IcpOutcome:
    """Refine ``T_init`` (target <- source) by linearised point-to-plane steps.

    Source points pair with their nearest target point within ``max_distance`` (mm); iterations stop when
    the update's norm (rotation vector in rad and translation in mm, stacked) falls below ``tolerance``.
    """
    T = np.array(T_init, dtype=np.float64)
    n_pairs = 0
    for iteration in range(1, max_iterations + 1):
        update, size, n_pairs = _step(transform_points(T, source), target, max_distance)
        if update is None:
            return IcpOutcome(T, n_pairs, iteration, False)
        T = update @ T
        if size < tolerance:
            return IcpOutcome(T, n_pairs, iteration, True)
    return IcpOutcome(T, n_pairs, max_iterations, False)


def _step(moved: FloatArray, target: Cloud, max_distance: float) -> tuple[FloatArray | None, float, int]:
    """The rigid update minimising the linearised point-to-plane error, its size, the number of pairs.

    The rotation is linearised about the pairs' centroid (well conditioned wherever the clouds lie).
    """
    distances, index = target.nearest(moved, max_distance)
    near = np.isfinite(distances)
    n_pairs = int(near.sum())
    if n_pairs < MIN_CORRESPONDENCES:
        return None, np.inf, n_pairs
    p, n = moved[near], target.normals[index[near]]
    r = np.einsum("ij,ij->i", p - target.points[index[near]], n)
    centre = p.mean(axis=0)
    a = p - centre
    J = np.empty((n_pairs, 6))
    # (p - centre) x n, written out: np.cross's generic path cost a tenth of an iteration
    J[:, 0] = a[:, 1] * n[:, 2] - a[:, 2] * n[:, 1]
    J[:, 1] = a[:, 2] * n[:, 0] - a[:, 0] * n[:, 2]
    J[:, 2] = a[:, 0] * n[:, 1] - a[:, 1] * n[:, 0]
    J[:, 3:] = n
    A = J.T @ J
    A += _DAMPING * np.trace(A) * np.eye(6)
    step = np.linalg.solve(A, -J.T @ r)
    return _about(centre, step), float(np.linalg.norm(step)), n_pairs


def _about(centre: FloatArray, step: FloatArray) -> FloatArray:
    """x -> R (x - centre) + centre + t, with R from the rotation vector step[:3] and t = step[3:]."""
    T = np.eye(4)
    T[:3, :3] = small_rotation(step[:3])
    T[:3, 3] = centre - T[:3, :3] @ centre + step[3:]
    return T


@dataclass(frozen=True, kw_only=True)
class PointToPlaneICP(Configurable):
    """Point-to-plane ICP on the whole clouds from one start: a local method (it needs a start within
    ~15° and ~1 mm of the truth on coin reliefs)."""

    NAME = "icp"

    max_iterations: int = param(50, low=1, doc="iterations at most")
    max_distance: float = param(
        1.0, unit="mm", low=0, low_open=True, doc="source and target points pair within this distance"
    )
    tolerance: float = param(1e-4, low=0, doc="stop when the update (rad and mm) is smaller")
    init: str = param(
        "identity",
        choices=("identity", "centroids"),
        doc="start: the identity, or the translation that puts the source centroid on the target's",
    )

    def start(self, source: Cloud, target: Cloud) -> FloatArray:
        T = np.eye(4)
        if self.init == "centroids":
            T[:3, 3] = target.points.mean(axis=0) - source.points.mean(axis=0)
        return T

    def run(self, source: FloatArray, target: Cloud, T_init: FloatArray) -> IcpOutcome:
        return point_to_plane_icp(
            source,
            target,
            T_init,
            max_iterations=self.max_iterations,
            max_distance=self.max_distance,
            tolerance=self.tolerance,
        )


@dataclass(frozen=True)
class LocalICP:
    """The ``icp`` method: ICP from the declared start."""

    icp: PointToPlaneICP

    def estimate(self, source: Cloud, target: Cloud, timer: Timer) -> Estimate:
        with timer("icp"):
            outcome = self.icp.run(source.points, target, self.icp.start(source, target))
        if outcome.n_correspondences < MIN_CORRESPONDENCES:
            failure = (
                f"ICP found {outcome.n_correspondences} point pairs within {self.icp.max_distance} mm "
                f"(it needs {MIN_CORRESPONDENCES}): the clouds do not overlap from this start"
            )
            return Estimate(None, outcome.n_correspondences, failure=failure)
        note = f"ICP: {outcome.iterations} iterations, converged={outcome.converged}"
        return Estimate(
            outcome.T_target_source, outcome.n_correspondences, outcome.n_correspondences, notes=(note,)
        )
