"""Composition: a global method followed by a local refinement (``fpfh+teaser`` + ``icp``)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from coindie.registration.base import Estimate, Estimator, Timer
from coindie.registration.clouds import Cloud


class Refinement(Protocol):
    """Improves an estimate locally (e.g. :class:`~coindie.registration.patch_icp.PatchICP`)."""

    def refine(self, source: Cloud, target: Cloud, first: Estimate) -> Estimate: ...


@dataclass(frozen=True)
class Refined:
    """Run ``global_``, then ``local`` on its estimate unless the global step failed."""

    global_: Estimator
    local: Refinement

    def estimate(self, source: Cloud, target: Cloud, timer: Timer) -> Estimate:
        first = self.global_.estimate(source, target, timer)
        if first.T_target_source is None or first.failure:
            return first
        with timer("refine"):
            return self.local.refine(source, target, first)
