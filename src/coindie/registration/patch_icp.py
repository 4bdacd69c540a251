"""The Riedones3D refinement: point-to-plane ICP on patches around the inlier matches of a global method.

From the authors' code: at most 100 inlier matches; around each, the source points within 2 mm and the
target points within 4 mm, at most 1000 each (the nearest ones: a 4 mm disc holds ~5000 points at 0.1 mm, so
the cap, not the radius, bounds the target patches); 10 iterations, correspondences within 0.1 mm, stop when
the update is below 1e-3. Working on patches keeps ICP on the die pattern the matches agree on and away from
the edges and cracks that pull whole-cloud ICP off.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from coindie.arrays import IntArray
from coindie.params import Configurable, param
from coindie.registration.base import Estimate, Matches
from coindie.registration.clouds import Cloud, content_rng
from coindie.registration.icp import MIN_CORRESPONDENCES, point_to_plane_icp


@dataclass(frozen=True, kw_only=True)
class PatchICP(Configurable):
    """Point-to-plane ICP restricted to patches around the inlier matches (the paper's ``+ ICP``)."""

    NAME = "refine"

    max_matches: int = param(100, low=1, doc="patches are centred on at most this many inlier matches")
    source_radius: float = param(2.0, unit="mm", low=0, low_open=True, doc="radius of a source patch")
    target_radius: float = param(4.0, unit="mm", low=0, low_open=True, doc="radius of a target patch")
    max_patch_points: int = param(1000, low=1, doc="a patch keeps at most this many (nearest) points")
    max_iterations: int = param(10, low=1, doc="ICP iterations at most")
    max_distance: float = param(
        0.1, unit="mm", low=0, low_open=True, doc="source and target points pair within this distance"
    )
    tolerance: float = param(1e-3, low=0, doc="stop when the update (rad and mm) is smaller")
    seed: int = param(0, low=0, doc="seed of the draw of matches when there are more than max_matches")

    def refine(self, source: Cloud, target: Cloud, first: Estimate) -> Estimate:
        """The estimate with its transform refined; unchanged (with a note) when refinement cannot run."""
        if first.T_target_source is None or first.inliers is None or len(first.inliers) == 0:
            return _noted(first, "refinement skipped: no inlier matches to centre patches on")
        centres = self._centres(first.inliers)
        source_patch = source.subset(
            _patch(source, centres.source, self.source_radius, self.max_patch_points)
        )
        target_patch = target.subset(
            _patch(target, centres.target, self.target_radius, self.max_patch_points)
        )
        outcome = point_to_plane_icp(
            source_patch.points,
            target_patch,
            first.T_target_source,
            max_iterations=self.max_iterations,
            max_distance=self.max_distance,
            tolerance=self.tolerance,
        )
        if outcome.n_correspondences < MIN_CORRESPONDENCES:
            pairs = f"{outcome.n_correspondences} point pairs within {self.max_distance} mm"
            return _noted(first, f"refinement skipped: {pairs}")
        note = (
            f"patch ICP: {len(source_patch.points)} source / {len(target_patch.points)} target points, "
            f"{outcome.iterations} iterations, converged={outcome.converged}"
        )
        return replace(_noted(first, note), T_target_source=outcome.T_target_source)

    def _centres(self, inliers: Matches) -> Matches:
        if len(inliers) <= self.max_matches:
            return inliers
        chosen = content_rng(inliers.source, self.seed).choice(len(inliers), self.max_matches, replace=False)
        return inliers.subset(np.sort(chosen))


def _patch(cloud: Cloud, centres: np.ndarray, radius: float, max_points: int) -> IntArray:
    """Indices of the union of each centre's nearest ``max_points`` cloud points within ``radius``."""
    k = min(max_points, len(cloud.points))
    distances, index = cloud.tree.query(centres, k=k, distance_upper_bound=radius, workers=-1)
    index = np.asarray(index).reshape(len(centres), -1)
    found = np.isfinite(np.asarray(distances).reshape(len(centres), -1))
    return np.unique(index[found])


def _noted(estimate: Estimate, note: str) -> Estimate:
    return replace(estimate, notes=(*estimate.notes, note))
