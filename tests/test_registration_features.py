"""Descriptor registration: FPFH, mutual nearest-neighbour matching, and another extractor plugged in."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from coindie.arrays import IntArray
from coindie.registration import (
    FPFH,
    Acceptance,
    FeatureRegistration,
    MutualNN,
    PatchICP,
    Pipeline,
    RansacSolver,
    Refined,
    TeaserSolver,
    get_method,
    rotation_error_deg,
    translation_error_mm,
)
from coindie.registration import base as registration_base
from coindie.registration.base import Matches
from coindie.registration.clouds import Cloud
from coindie.registration.features import nearest_rows
from coindie.transforms import euler_rigid, transform_points
from synthetic_pairs import make_coin_pair

# Linear algebra under test (FPFH under rigid motions, nearest rows by matrix products):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric


@pytest.fixture(scope="module")
def pair():
    return make_coin_pair(seed=3, radius=5.0, T_target_source=euler_rigid((10, 5, -70), (2, 1, -1)))


def test_fpfh_descriptors_do_not_change_when_the_cloud_is_moved(pair) -> None:
    fpfh = FPFH(voxel=0)
    cloud = Cloud.of(pair.target)
    moved = Cloud.of(pair.target.transformed(euler_rigid((20, -10, 135), (3, 4, 5))))
    at = np.arange(0, len(cloud.points), 97)
    np.testing.assert_allclose(fpfh.describe(moved, at), fpfh.describe(cloud, at), atol=1e-6)
    assert fpfh.describe(cloud, at).shape == (len(at), 33)


def test_mutual_matching_keeps_pairs_that_choose_each_other() -> None:
    source = np.array([[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]])
    target = np.array(
        [[0.1, 0.0], [9.0, 0.0], [9.5, 0.5]]
    )  # target 2 prefers source 1, which prefers target 2
    pairs = MutualNN().match(source, target)
    np.testing.assert_array_equal(pairs, [[0, 0], [1, 2]])


def test_nearest_rows_agrees_with_an_exhaustive_search() -> None:
    rng = np.random.default_rng(0)
    a, b = rng.normal(size=(2100, 33)), rng.normal(size=(700, 33))
    expected = np.argmin(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2), axis=1)
    np.testing.assert_array_equal(nearest_rows(a, b), expected)


def test_sampling_depends_on_the_seed_and_the_cloud_not_on_the_role(pair) -> None:
    cloud = Cloud.of(pair.target)
    matcher = MutualNN(n_points=500, seed=1)
    first = matcher.sample(cloud)
    assert len(first) == 500 and len(np.unique(first)) == 500
    np.testing.assert_array_equal(first, matcher.sample(cloud))
    assert not np.array_equal(first, MutualNN(n_points=500, seed=2).sample(cloud))
    assert len(MutualNN(n_points=10**6).sample(cloud)) == len(cloud.points)


@pytest.mark.parametrize("solver", [TeaserSolver(), RansacSolver()], ids=["teaser", "ransac"])
def test_fpfh_matches_feed_either_solver(pair, solver) -> None:
    registration = FeatureRegistration(FPFH(), MutualNN(n_points=2000), solver)
    source, target = Cloud.of(pair.source), Cloud.of(pair.target)
    timer = registration_base.Timer()
    estimate = registration.estimate(source, target, timer)
    assert estimate.T_target_source is not None, estimate.failure
    assert rotation_error_deg(pair.T_target_source, estimate.T_target_source) < 1.0
    assert estimate.n_correspondences >= estimate.n_inliers >= 3
    assert estimate.inliers is not None and len(estimate.inliers) == estimate.n_inliers
    assert {"features", "matching", "solver"} <= set(timer.seconds)


@dataclass(frozen=True)
class TruthDescriptors:
    """A stand-in for a learned extractor (FCGF, DIP): the descriptor of a point is its position in the
    target frame, so every match is right. It only shows how another extractor plugs in."""

    T_target_source: np.ndarray
    source_size: int
    NAME: str = "truth"

    def support(self, cloud: Cloud) -> Cloud:
        return cloud

    def describe(self, support: Cloud, at: IntArray) -> np.ndarray:
        is_source = len(support.points) == self.source_size
        points = support.points[at]
        return transform_points(self.T_target_source, points) if is_source else points


def test_another_descriptor_extractor_plugs_into_the_same_interface(pair, monkeypatch) -> None:
    extractor = TruthDescriptors(pair.T_target_source, pair.source.n_points)
    monkeypatch.setitem(
        registration_base._REGISTRY,
        "truth+teaser",
        registration_base.MethodInfo(
            "truth+teaser",
            "test stand-in",
            (MutualNN, TeaserSolver),
            lambda matcher, teaser: FeatureRegistration(extractor, matcher, teaser),
        ),
    )
    result = get_method("truth+teaser", n_points=800, noise_bound=0.3).register(pair.source, pair.target)
    assert result.valid, result.reason
    # Random samples of the two clouds are ~0.3 mm apart: matches are right to that, hence the tolerance.
    assert rotation_error_deg(pair.T_target_source, result.T_target_source) < 1.0
    assert translation_error_mm(pair.T_target_source, result.T_target_source) < 0.3
    assert result.params["teaser.noise_bound"] == 0.3


def test_solvers_refuse_too_few_matches_with_a_reason() -> None:
    few = Matches(np.zeros((2, 3)), np.zeros((2, 3)))
    for solver in (TeaserSolver(), RansacSolver()):
        outcome = solver.solve(few)
        assert outcome.T_target_source is None
        assert "needs at least" in outcome.failure


def test_parts_compose_into_a_registrar_without_the_registry(pair) -> None:
    registrar = Pipeline(
        "mine", Refined(FeatureRegistration(FPFH(), MutualNN(n_points=2000), TeaserSolver()), PatchICP())
    )
    result = registrar.register(pair.source, pair.target)
    assert result.valid, result.reason
    assert rotation_error_deg(pair.T_target_source, result.T_target_source) < 0.5
    assert result.params["matcher.n_points"] == 2000
    assert result.params["refine.source_radius"] == 2.0
    assert result.params["check.max_residual"] == Acceptance().max_residual
    assert result.method == "mine"
