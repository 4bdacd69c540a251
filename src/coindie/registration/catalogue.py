"""The catalogue: every registration method coindie ships, registered by name in one place.

The CLI, the benchmarks and the contract tests enumerate it (:func:`coindie.registration.list_methods`).
Built-in methods, ours (``relief``) and the learned descriptors (FCGF, DIP, as the paper runs them in its
Table 1: descriptors on ``n`` random points per cloud, ``matcher.n_points`` 5000 by default or 250 for the
fast variant, mutual nearest neighbours, the TEASER-style solver, and optionally the paper's patch ICP).
FCGF's source is matched against every turn of the target its model searches
(:mod:`coindie.registration.learned.turns`). The learned weights are the shipped ones unless
``fcgf.weights`` / ``dip.weights`` names a model file. Importing this module does not import torch.
"""

from __future__ import annotations

from typing import Any

from coindie.registration.base import register_method
from coindie.registration.compose import Refined
from coindie.registration.features import FPFH, FeatureRegistration, MutualNN
from coindie.registration.icp import LocalICP, PointToPlaneICP
from coindie.registration.learned.dip import DIPDescriptor
from coindie.registration.learned.fcgf import SHIPPED_WEIGHTS, FCGFDescriptor
from coindie.registration.learned.turns import TurnSearchRegistration
from coindie.registration.patch_icp import PatchICP
from coindie.registration.random_search import RandomSearch, RandomSearchICP
from coindie.registration.ransac import RansacSolver
from coindie.registration.relief import ReliefBlocks, ReliefICP, ReliefRegistration, ReliefSearch
from coindie.registration.teaser import TeaserSolver

register_method(
    "icp",
    lambda icp: LocalICP(icp),
    parts=(PointToPlaneICP,),
    summary="point-to-plane ICP from one start (local: the clouds must start within ~15° and ~1 mm)",
    local=True,
)
register_method(
    "rs-icp",
    lambda search: RandomSearchICP(search),
    parts=(RandomSearch,),
    summary="random-search ICP (Horache et al. 2020): many starts about the coin's axis, best by residual",
)
for solver in (TeaserSolver, RansacSolver):
    register_method(
        f"fpfh+{solver.NAME}",
        lambda fpfh, matcher, _solver=solver, **solver_part: FeatureRegistration(
            fpfh, matcher, solver_part[_solver.NAME]
        ),
        parts=(FPFH, MutualNN, solver),
        summary=f"FPFH descriptors, mutual nearest neighbours, {solver.NAME.upper()}",
    )
    register_method(
        f"fpfh+{solver.NAME}+icp",
        lambda fpfh, matcher, refine, _solver=solver, **solver_part: Refined(
            FeatureRegistration(fpfh, matcher, solver_part[_solver.NAME]), refine
        ),
        parts=(FPFH, MutualNN, solver, PatchICP),
        summary=f"FPFH + {solver.NAME.upper()}, refined by the paper's patch ICP",
    )

_LEARNED = {
    FCGFDescriptor: "FCGF (Choy et al. 2019, sparse U-Net; the target seen at each turn its model searches)",
    DIPDescriptor: "DIP (PointNet on LRF patches)",
}


def _matching(descriptor: type, parts: dict[str, Any]) -> FeatureRegistration:
    """Descriptor matching; for FCGF, against every turn of the target its model describes (one turn
    for a model that learned the invariance, :mod:`coindie.registration.learned.turns`)."""
    kind = TurnSearchRegistration if descriptor is FCGFDescriptor else FeatureRegistration
    return kind(parts[descriptor.NAME], parts[MutualNN.NAME], parts[TeaserSolver.NAME])


for _descriptor, _label in _LEARNED.items():
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

register_method(
    "relief",
    lambda relief, icp, blocks: ReliefRegistration(relief, icp, blocks),
    parts=(ReliefSearch, ReliefICP, ReliefBlocks),
    summary="ours: canonical frames + relief images, FFT search of rotation and translation, ICP, then "
    "block matching of the reliefs in the plane",
)
