"""Point-to-plane ICP, the paper's patch refinement, random-search starts, scores and error metrics."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.registration import (
    Matches,
    PatchICP,
    RandomSearch,
    point_to_plane_icp,
    rotation_error_deg,
    scaled_registration_error,
    translation_error_mm,
)
from coindie.registration.base import Estimate
from coindie.registration.clouds import Cloud
from coindie.registration.patch_icp import _patch
from coindie.registration.quality import alignment, robust_score
from coindie.transforms import euler_rigid, inverse, transform_points
from synthetic_pairs import CoinPair, make_coin_pair

# Linear algebra under test (ICP (Kabsch SVD per iteration) and the error metrics):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric


@pytest.fixture(scope="module")
def level_pair() -> CoinPair:
    """A 5 mm coin pair whose truth is the identity (both scans in the same frame)."""
    return make_coin_pair(seed=2, radius=5.0, T_target_source=np.eye(4))


def icp(pair: CoinPair, T_init: np.ndarray, **options):
    settings = {"max_iterations": 50, "max_distance": 1.0, "tolerance": 1e-5} | options
    return point_to_plane_icp(pair.source.points, Cloud.of(pair.target), T_init, **settings)


@pytest.mark.parametrize("start", [((0, 0, 8), (0.3, -0.2, 0.1)), ((2, -1, -5), (-0.4, 0.2, 0.0))])
def test_icp_converges_from_a_nearby_start(level_pair: CoinPair, start) -> None:
    outcome = icp(level_pair, euler_rigid(*start))
    assert outcome.converged
    assert rotation_error_deg(np.eye(4), outcome.T_target_source) < 0.2
    assert translation_error_mm(np.eye(4), outcome.T_target_source) < 0.02


def test_icp_works_far_from_the_origin(level_pair: CoinPair) -> None:
    """The step is linearised about the pairs' centroid, not the origin: a coin 1 m away converges too."""
    away = euler_rigid((0, 0, 0), (1000.0, -500.0, 200.0))
    pair = CoinPair(level_pair.source.transformed(away), level_pair.target.transformed(away), np.eye(4))
    start = away @ euler_rigid((1, 0, 6), (0.2, 0.1, 0.0)) @ inverse(away)  # 6° about the coin itself
    outcome = icp(pair, start)
    assert outcome.converged
    points = pair.source.points
    moved = transform_points(outcome.T_target_source, points)
    assert np.linalg.norm(moved - points, axis=1).max() < 0.02  # mm, on the coin (1 m from the origin)


def test_icp_stops_after_max_iterations_and_says_it_did_not_converge(level_pair: CoinPair) -> None:
    outcome = icp(level_pair, euler_rigid((0, 0, 8), (0.3, 0, 0)), max_iterations=2, tolerance=0.0)
    assert outcome.iterations == 2
    assert not outcome.converged


def test_icp_without_pairs_stops_at_once(level_pair: CoinPair) -> None:
    outcome = icp(level_pair, euler_rigid((0, 0, 0), (50.0, 0, 0)))
    assert outcome.n_correspondences == 0
    assert not outcome.converged


def test_patch_refinement_improves_a_coarse_estimate(level_pair: CoinPair) -> None:
    source, target = Cloud.of(level_pair.source), Cloud.of(level_pair.target)
    coarse = euler_rigid((0.3, -0.2, 0.5), (0.04, -0.03, 0.02))
    rng = np.random.default_rng(0)
    centres = source.points[rng.choice(len(source.points), 150, replace=False)]
    inliers = Matches(centres, centres)  # the truth is the identity
    refined = PatchICP().refine(source, target, Estimate(coarse, 150, 150, inliers))
    assert rotation_error_deg(np.eye(4), refined.T_target_source) < 0.5 * rotation_error_deg(
        np.eye(4), coarse
    )
    assert translation_error_mm(np.eye(4), refined.T_target_source) < 0.02
    assert any("patch ICP" in note for note in refined.notes)


def test_patch_refinement_without_inliers_keeps_the_estimate_with_a_note(level_pair: CoinPair) -> None:
    source, target = Cloud.of(level_pair.source), Cloud.of(level_pair.target)
    first = Estimate(np.eye(4), 0, 0, None)
    refined = PatchICP().refine(source, target, first)
    assert refined.T_target_source is first.T_target_source
    assert "skipped" in refined.notes[-1]


def test_patches_keep_the_nearest_points_within_the_radius(level_pair: CoinPair) -> None:
    cloud = Cloud.of(level_pair.target)
    centre = cloud.points[[np.argmin(np.linalg.norm(cloud.points[:, :2], axis=1))]]  # the point at the middle
    capped = _patch(cloud, centre, radius=4.0, max_points=1000)
    assert len(capped) == 1000  # a 4 mm disc holds ~5000 points at 0.1 mm: the cap decides
    small = _patch(cloud, centre, radius=0.5, max_points=1000)
    assert 0 < len(small) < 1000
    assert np.linalg.norm(cloud.points[small] - centre, axis=1).max() <= 0.5


def test_random_search_starts_cover_the_turn_in_equal_sectors() -> None:
    search = RandomSearch(n_starts=12, max_tilt_deg=3.0, seed=4)
    starts = search.starts()
    turns = np.sort([np.degrees(np.arctan2(T[1, 0], T[0, 0])) % 360 for T in starts])
    assert np.all(np.diff(turns) < 2 * 360 / 12)
    tilts = [np.degrees(np.arccos(np.clip(T[2, 2], -1, 1))) for T in starts]
    assert max(tilts) <= 3.0 + 1e-9
    assert all(np.array_equal(a, b) for a, b in zip(starts, search.starts(), strict=True))


def test_the_residual_tells_a_wrong_turn_from_the_right_pose_when_fitness_cannot(
    level_pair: CoinPair,
) -> None:
    """The scoring trap: a dome turned the wrong way still overlaps almost everywhere."""
    source, target = level_pair.source.points, Cloud.of(level_pair.target)
    wrong = euler_rigid((0, 0, 40), (0, 0, 0))
    right_fit, wrong_fit = alignment(source, target, np.eye(4), 0.3), alignment(source, target, wrong, 0.3)
    assert wrong_fit.fitness > 0.8 * right_fit.fitness
    assert wrong_fit.residual > 3 * right_fit.residual
    assert robust_score(source, target, wrong, 0.3) > 3 * robust_score(source, target, np.eye(4), 0.3)


def test_alignment_figures_of_a_cloud_on_itself() -> None:
    pair = make_coin_pair(seed=1, radius=3.0, noise=0.0, T_target_source=np.eye(4))
    figures = alignment(pair.target.points, Cloud.of(pair.target), np.eye(4), 0.3)
    assert figures.fitness == 1.0
    assert figures.residual == 0.0
    assert figures.inlier_rmse == 0.0
    assert figures.n_inliers == pair.target.n_points


def test_sre_of_a_pure_translation_follows_the_paper_formula() -> None:
    rng = np.random.default_rng(0)
    x = rng.normal(size=(500, 3)) * 5
    T_true = euler_rigid((10, 20, 30), (1, 2, 3))
    shift = np.array([0.1, 0.0, 0.0])
    T_est = T_true.copy()
    T_est[:3, 3] += shift
    expected = np.mean(0.1 / np.linalg.norm(x - x.mean(axis=0), axis=1))
    assert scaled_registration_error(x, T_true, T_est) == pytest.approx(expected)
    assert scaled_registration_error(x, T_true, T_true) == 0.0


def test_rotation_and_translation_errors() -> None:
    T = euler_rigid((0, 0, 30), (1, 2, 3))
    U = euler_rigid((0, 0, 37), (1, 2, 3.5))
    assert rotation_error_deg(T, U) == pytest.approx(7.0)
    assert translation_error_mm(T, U) == pytest.approx(0.5)
    np.testing.assert_allclose(inverse(T) @ T, np.eye(4), atol=1e-12)
    np.testing.assert_allclose(
        transform_points(inverse(T), transform_points(T, np.ones((1, 3)))), np.ones((1, 3))
    )
