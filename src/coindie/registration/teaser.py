"""TEASER's robust solver (Yang, Shi & Carlone, "TEASER: Fast and Certifiable Point Cloud Registration",
IEEE T-RO 2020), without scale, as the Riedones3D pipeline uses it.

Written by hand because TEASER++ has no installable wheel (only a C++ build with Python bindings). The
steps, from the paper:

1. Pairwise invariants. For matches i, j the translation-invariant measurements (TIMs) are dst_j - dst_i
   and src_j - src_i; a rigid map keeps their lengths, so two correct matches agree within twice the noise
   bound. Agreeing pairs are the edges of a consistency graph.
2. Maximum clique of that graph (:mod:`coindie.registration.clique`): the largest mutually consistent set
   of matches; the rest are discarded.
3. Rotation by graduated non-convexity with a truncated least-squares cost (GNC-TLS, Yang et al., "Graduated
   Non-Convexity for Robust Spatial Perception", RA-L 2020) on the clique's TIMs.
4. Translation by adaptive voting, axis by axis: the value consistent with most of the clique's
   dst_i - R src_i within the noise bound.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.arrays import BoolArray, FloatArray, IntArray
from coindie.params import Configurable, param
from coindie.registration.base import Matches, SolverOutcome
from coindie.registration.clique import consistency_graph, maximum_clique
from coindie.transforms import fit_rotation

#: A rotation needs at least this many matches (two independent TIMs).
MIN_CLIQUE = 3


@dataclass(frozen=True)
class GncResult:
    rotation: FloatArray
    weights: FloatArray  # final TLS weights of the TIMs (1: inlier, 0: outlier)
    iterations: int


def gnc_tls_rotation(
    a: FloatArray,
    b: FloatArray,
    *,
    bound: float,
    cbar2: float,
    factor: float,
    max_iterations: int,
    cost_threshold: float,
) -> GncResult:
    """R minimising sum_k min(||b_k - R a_k||^2, cbar2 bound^2) by graduated non-convexity.

    Starts from the least-squares rotation; the control parameter mu starts where the surrogate cost is
    convex over the residuals seen and grows by ``factor`` each iteration, so the surrogate approaches the
    truncated cost; weights follow the TLS update of Yang et al. (2020).
    """
    threshold = cbar2 * bound**2
    weights = np.ones(len(a))
    rotation = fit_rotation(a, b, weights)
    r2 = _squared_residuals(a, b, rotation)
    if r2.max() <= threshold:
        return GncResult(rotation, weights, 0)
    mu = 1.0 / (2.0 * r2.max() / threshold - 1.0)
    previous_cost = np.inf
    for iteration in range(1, max_iterations + 1):
        weights = _tls_weights(r2, threshold, mu)
        cost = float(weights @ r2)
        if abs(cost - previous_cost) < cost_threshold or not weights.any():
            return GncResult(rotation, weights, iteration)
        previous_cost = cost
        mu *= factor
        rotation = fit_rotation(a, b, weights)
        r2 = _squared_residuals(a, b, rotation)
    return GncResult(rotation, weights, max_iterations)


def _squared_residuals(a: FloatArray, b: FloatArray, rotation: FloatArray) -> FloatArray:
    return ((b - a @ rotation.T) ** 2).sum(axis=1)


def _tls_weights(r2: FloatArray, threshold: float, mu: float) -> FloatArray:
    """1 below mu/(mu+1) c^2, 0 above (mu+1)/mu c^2, and c sqrt(mu (mu+1) / r^2) - mu in between."""
    lower, upper = mu / (mu + 1.0) * threshold, (mu + 1.0) / mu * threshold
    between = np.sqrt(threshold * mu * (mu + 1.0) / np.maximum(r2, 1e-300)) - mu
    return np.where(r2 <= lower, 1.0, np.where(r2 >= upper, 0.0, between))


def adaptive_voting(values: FloatArray, bound: float) -> tuple[float, BoolArray]:
    """The mean of the largest set of values within a window of width 2 ``bound``, and that set."""
    order = np.argsort(values, kind="stable")
    v = values[order]
    counts = np.searchsorted(v, v + 2 * bound, side="right") - np.arange(len(v))
    start = int(np.argmax(counts))
    estimate = float(v[start : start + counts[start]].mean())
    return estimate, np.abs(values - estimate) <= bound


@dataclass(frozen=True, kw_only=True)
class TeaserSolver(Configurable):
    """TEASER without scale: max clique of pairwise-consistent matches, GNC-TLS rotation, voted translation.
    Defaults are the Riedones3D authors' (noise bound 0.5 mm, cbar2 1, GNC factor 1.4, 100 iterations,
    cost threshold 1e-12); their clique time limit of 0.5–1 s becomes a work limit of about that length,
    so that a run does not depend on the machine's speed."""

    NAME = "teaser"

    noise_bound: float = param(
        0.5, unit="mm", low=0, low_open=True, doc="largest distance of a correct match after alignment"
    )
    cbar2: float = param(1.0, low=0, low_open=True, doc="TLS truncation, in units of the squared noise bound")
    gnc_factor: float = param(
        1.4, low=1, low_open=True, doc="growth of the GNC control parameter per iteration"
    )
    max_iterations: int = param(100, low=1, doc="GNC iterations at most")
    cost_threshold: float = param(1e-12, low=0, doc="GNC stops when the cost changes less than this")
    clique_work_limit: int = param(
        500_000,
        low=0,
        doc="the maximum-clique search stops after this many vertex colourings (~0.5-1 s, reproducible)",
    )
    clique_time_limit: float = param(
        5.0, unit="s", low=0, low_open=True, doc="and in any case after this long (not reproducible)"
    )
    max_tims: int = param(
        20_000, low=10, doc="the rotation uses at most this many pairs of clique matches (drawn at random)"
    )
    seed: int = param(0, low=0, doc="seed of the draw of pairs")

    def solve(self, matches: Matches) -> SolverOutcome:
        no_inliers = np.zeros(len(matches), dtype=bool)
        if len(matches) < MIN_CLIQUE:
            return SolverOutcome(
                None, no_inliers, f"{len(matches)} matches: TEASER needs at least {MIN_CLIQUE}"
            )
        # Pairwise invariants -> maximum clique
        graph = consistency_graph(matches.source, matches.target, 2 * self.noise_bound)
        clique = maximum_clique(graph, time_limit=self.clique_time_limit, work_limit=self.clique_work_limit)
        note = f"TEASER: max clique of {len(clique.members)} of {len(matches)} matches ({clique.stop})"
        if len(clique.members) < MIN_CLIQUE:
            failure = (
                f"the largest consistent set has {len(clique.members)} matches (TEASER needs {MIN_CLIQUE})"
            )
            return SolverOutcome(None, no_inliers, failure, (note,))
        kept = matches.subset(clique.members)
        # Rotation (GNC-TLS on the clique's TIMs), then translation (adaptive voting)
        rotation = self._rotation(kept)
        translation, voted = self._translation(kept, rotation)
        inliers = no_inliers.copy()
        inliers[clique.members[voted]] = True
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = rotation, translation
        return SolverOutcome(T, inliers, notes=(note,))

    def _rotation(self, kept: Matches) -> FloatArray:
        i, j = self._pairs(len(kept))
        result = gnc_tls_rotation(
            kept.source[j] - kept.source[i],
            kept.target[j] - kept.target[i],
            bound=2 * self.noise_bound,  # a TIM carries the noise of two points
            cbar2=self.cbar2,
            factor=self.gnc_factor,
            max_iterations=self.max_iterations,
            cost_threshold=self.cost_threshold,
        )
        return result.rotation

    def _pairs(self, n: int) -> tuple[IntArray, IntArray]:
        """All pairs i < j of clique members, or ``max_tims`` random distinct pairs when there are more."""
        if n * (n - 1) // 2 <= self.max_tims:
            i, j = np.triu_indices(n, 1)
            return i, j
        rng = np.random.default_rng(self.seed)
        i = rng.integers(0, n, self.max_tims)
        j = rng.integers(0, n - 1, self.max_tims)
        return i, j + (j >= i)

    def _translation(self, kept: Matches, rotation: FloatArray) -> tuple[FloatArray, BoolArray]:
        candidates = kept.target - kept.source @ rotation.T
        translation = np.empty(3)
        agree = np.ones(len(kept), dtype=bool)
        for axis in range(3):
            translation[axis], axis_agree = adaptive_voting(candidates[:, axis], self.noise_bound)
            agree &= axis_agree
        return translation, agree
