"""Rigid registration of two coin faces: one interface, methods registered by name.

>>> from coindie.registration import get_method
>>> result = get_method("rs-icp").register(source_scan, target_scan)  # doctest: +SKIP
>>> result.T_target_source, result.valid, result.residual  # doctest: +SKIP
"""

from coindie.params import Configurable, Param, param
from coindie.registration import catalogue as _catalogue  # noqa: F401  (registers every method)
from coindie.registration.base import (
    CorrespondenceSolver,
    Estimate,
    Matches,
    MethodInfo,
    Pipeline,
    Registrar,
    RegistrationResult,
    SolverOutcome,
    get_method,
    list_methods,
    method_info,
    register_method,
)
from coindie.registration.compose import Refined
from coindie.registration.features import FPFH, FeatureExtractor, FeatureRegistration, MutualNN
from coindie.registration.icp import PointToPlaneICP, point_to_plane_icp
from coindie.registration.metrics import (
    planar_errors,
    rotation_error_deg,
    scaled_registration_error,
    translation_error_mm,
)
from coindie.registration.patch_icp import PatchICP
from coindie.registration.quality import Acceptance
from coindie.registration.random_search import RandomSearch
from coindie.registration.ransac import RansacSolver
from coindie.registration.teaser import TeaserSolver

__all__ = [
    "FPFH",
    "Acceptance",
    "Configurable",
    "CorrespondenceSolver",
    "Estimate",
    "FeatureExtractor",
    "FeatureRegistration",
    "Matches",
    "MethodInfo",
    "MutualNN",
    "Param",
    "PatchICP",
    "Pipeline",
    "PointToPlaneICP",
    "RandomSearch",
    "RansacSolver",
    "Refined",
    "Registrar",
    "RegistrationResult",
    "SolverOutcome",
    "TeaserSolver",
    "get_method",
    "list_methods",
    "method_info",
    "param",
    "planar_errors",
    "point_to_plane_icp",
    "register_method",
    "rotation_error_deg",
    "scaled_registration_error",
    "translation_error_mm",
]
