"""The learned registration methods, as the paper runs them (Table 1): FCGF or DIP descriptors on ``n``
random points per cloud (``matcher.n_points``: 5000 by default, 250 for the paper's fast variant), mutual
nearest neighbours, the TEASER-style solver, and optionally the paper's patch ICP (``+icp``). FCGF's
source is matched against every turn of the target its model searches (:mod:`coindie.learned.turns`).

``fcgf``, ``fcgf+icp``, ``dip``, ``dip+icp``; the weights are the shipped ones unless ``fcgf.weights`` /
``dip.weights`` names a model file. Importing this module does not import torch.
"""

from __future__ import annotations

from typing import Any

from coindie.learned.dip import DIPDescriptor
from coindie.learned.fcgf import SHIPPED_WEIGHTS, FCGFDescriptor
from coindie.learned.turns import TurnSearchRegistration
from coindie.registration.base import register_method
from coindie.registration.compose import Refined
from coindie.registration.features import FeatureRegistration, MutualNN
from coindie.registration.refine import PatchICP
from coindie.registration.teaser import TeaserSolver

_LABELS = {
    FCGFDescriptor: "FCGF (Choy et al. 2019, sparse U-Net; the target seen at each turn its model searches)",
    DIPDescriptor: "DIP (PointNet on LRF patches)",
}


def _matching(descriptor: type, parts: dict[str, Any]) -> FeatureRegistration:
    """Descriptor matching; for FCGF, against every turn of the target its model describes (one turn
    for a model that learned the invariance, :mod:`coindie.learned.turns`)."""
    kind = TurnSearchRegistration if descriptor is FCGFDescriptor else FeatureRegistration
    return kind(parts[descriptor.NAME], parts[MutualNN.NAME], parts[TeaserSolver.NAME])


for _descriptor, _label in _LABELS.items():
    _note = ""
    if _descriptor is FCGFDescriptor and not SHIPPED_WEIGHTS.is_file():
        _note = " (no shipped weights: train them with coindie train fcgf, pass fcgf.weights)"
    register_method(
        _descriptor.NAME,
        lambda _d=_descriptor, **parts: _matching(_d, parts),
        parts=(_descriptor, MutualNN, TeaserSolver),
        summary=f"{_label} descriptors, mutual nearest neighbours, TEASER{_note}",
    )
    register_method(
        f"{_descriptor.NAME}+icp",
        lambda _d=_descriptor, **parts: Refined(_matching(_d, parts), parts[PatchICP.NAME]),
        parts=(_descriptor, MutualNN, TeaserSolver, PatchICP),
        summary=f"{_label} + TEASER, refined by the paper's patch ICP{_note}",
    )
