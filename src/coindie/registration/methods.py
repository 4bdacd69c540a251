"""The built-in methods, registered by name (the CLI, the benchmark and the contract tests list them)."""

from __future__ import annotations

from coindie.registration.base import register_method
from coindie.registration.compose import Refined
from coindie.registration.features import FPFH, FeatureRegistration, MutualNN
from coindie.registration.icp import LocalICP, PointToPlaneICP
from coindie.registration.random_search import RandomSearch, RandomSearchICP
from coindie.registration.ransac import RansacSolver
from coindie.registration.refine import PatchICP
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

# Ours, registered by its own module (it lives beside the planar alignment it builds on).
# The learned descriptors (FCGF, DIP), registered by their package (torch is imported only when used).
from coindie.learned import methods as _learned  # noqa: E402, F401
from coindie.registration import relief as _relief  # noqa: E402, F401
