"""Matching descriptors that are not invariant to turns about the coin's axis: search the turns.

A model trained on pairs turned alike within ±180°/n (:class:`~coindie.registration.learned.fcgf.FCGFConfig`
``spins = n``) describes the source once and the target at n turns about its axis (``describe_views``). The
source's descriptors are matched to all n views at once, by mutual nearest neighbours: a source point's
partner is its nearest descriptor over every view, and the views within the model's tolerance of the true
turn are the ones whose descriptors agree. The matches (to the target's points, whichever view they came
from) go to the robust solver, which keeps the consistent ones. With n = 1 this is
:class:`~coindie.registration.features.FeatureRegistration`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from coindie.arrays import FloatArray, IntArray
from coindie.registration.clouds import Cloud
from coindie.registration.features import FeatureExtractor, FeatureRegistration


class ViewDescriptor(FeatureExtractor, Protocol):
    def describe_views(self, support: Cloud, at: IntArray) -> FloatArray:
        """(views, len(at), D): the descriptors of the points ``at`` in each view of the cloud."""
        ...


@dataclass(frozen=True)
class TurnSearchRegistration(FeatureRegistration):
    """Source descriptors -> mutual matches against every view of the target -> robust solver."""

    features: ViewDescriptor

    def _describe_target(self, cloud: Cloud) -> tuple[Cloud, IntArray, FloatArray]:
        """Every view's descriptors of the sampled points, one row per point and view."""
        support = self.features.support(cloud)
        at = self.matcher.sample(support)
        views = self.features.describe_views(support, at)
        return support, np.tile(at, len(views)), views.reshape(-1, views.shape[2])
