"""The hand-written TEASER solver and its maximum-clique search, against known transforms and brute force."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from coindie.registration import Matches, TeaserSolver, rotation_error_deg, translation_error_mm
from coindie.registration.clique import consistency_graph, core_numbers, maximum_clique
from coindie.registration.teaser import adaptive_voting, gnc_tls_rotation
from coindie.transforms import inverse, random_pose

# Linear algebra under test (TEASER's rotation (GNC-TLS, SVD) and translation):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric


def outlier_matches(
    n: int, inlier_share: float, seed: int, noise: float = 0.01
) -> tuple[Matches, np.ndarray, int]:
    """Matches in a 20 mm box: the first ``inlier_share`` follow a known transform (with noise), the rest
    point to random places."""
    rng = np.random.default_rng(seed)
    T = random_pose(rng)
    src = rng.uniform(-10, 10, (n, 3))
    dst = src @ T[:3, :3].T + T[:3, 3] + rng.normal(0, noise, (n, 3))
    k = int(round(n * inlier_share))
    dst[k:] = rng.uniform(-10, 10, (n - k, 3)) + T[:3, 3]
    return Matches(src, dst), T, k


@pytest.mark.parametrize("noise_bound", [0.5, 0.05])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_recovers_a_known_transform_from_95_percent_outliers(noise_bound: float, seed: int) -> None:
    matches, T, k = outlier_matches(1000, 0.05, seed)
    outcome = TeaserSolver(noise_bound=noise_bound).solve(matches)
    assert outcome.T_target_source is not None, outcome.failure
    assert rotation_error_deg(T, outcome.T_target_source) < 1.0
    assert translation_error_mm(T, outcome.T_target_source) < 0.1
    assert outcome.inliers[:k].mean() > 0.9  # the true matches are kept...
    assert outcome.inliers[k:].sum() <= 2  # ...and hardly any of the 950 wrong ones


def test_is_deterministic_and_swapping_the_sides_inverts_the_transform() -> None:
    matches, T, _ = outlier_matches(800, 0.05, seed=3)
    solver = TeaserSolver()
    first, again = solver.solve(matches), solver.solve(matches)
    np.testing.assert_array_equal(first.T_target_source, again.T_target_source)
    swapped = solver.solve(Matches(matches.target, matches.source))
    assert rotation_error_deg(inverse(T), swapped.T_target_source) < 1.0
    assert translation_error_mm(inverse(T), swapped.T_target_source) < 0.1


def test_too_few_matches_is_a_failure_not_an_identity() -> None:
    outcome = TeaserSolver().solve(Matches(np.zeros((2, 3)), np.ones((2, 3))))
    assert outcome.T_target_source is None
    assert "at least 3" in outcome.failure
    assert not outcome.inliers.any()


def test_gnc_tls_rotation_ignores_a_third_of_wrong_vectors() -> None:
    rng = np.random.default_rng(4)
    R = random_pose(rng)[:3, :3]
    a = rng.normal(size=(300, 3)) * 5
    b = a @ R.T + rng.normal(0, 0.01, a.shape)
    b[:100] = rng.normal(size=(100, 3)) * 5
    result = gnc_tls_rotation(
        a, b, bound=0.1, cbar2=1.0, factor=1.4, max_iterations=100, cost_threshold=1e-12
    )
    assert np.degrees(np.arccos((np.trace(R.T @ result.rotation) - 1) / 2)) < 0.2
    assert (result.weights[100:] > 0.5).all()
    assert (result.weights[:100] < 0.5).mean() > 0.95


def test_adaptive_voting_finds_the_densest_window() -> None:
    values = np.array([-3.0, 1.0, 1.02, 0.98, 1.01, 5.0, 7.0, 0.99])
    estimate, agree = adaptive_voting(values, bound=0.05)
    assert estimate == pytest.approx(1.0, abs=0.01)
    np.testing.assert_array_equal(agree, [False, True, True, True, True, False, False, True])


def test_consistency_graph_links_matches_whose_distances_agree() -> None:
    src = np.array([[0.0, 0, 0], [1, 0, 0], [0, 2, 0]])
    dst = np.array([[5.0, 0, 0], [5, 1.05, 0], [5, 0, 3]])  # |d01| 1 vs 1.05; |d02| 2 vs 3; |d12| √5 vs ~3.16
    adjacency = consistency_graph(src, dst, bound=0.1)
    np.testing.assert_array_equal(
        adjacency, [[False, True, False], [True, False, False], [False, False, False]]
    )


def brute_force_clique_size(adjacency: np.ndarray) -> int:
    n = len(adjacency)
    for size in range(n, 0, -1):
        for subset in itertools.combinations(range(n), size):
            if all(adjacency[i, j] for i, j in itertools.combinations(subset, 2)):
                return size
    return 0


def random_graph(rng: np.random.Generator, n: int, density: float) -> np.ndarray:
    upper = np.triu(rng.uniform(size=(n, n)) < density, 1)
    return upper | upper.T


def test_maximum_clique_matches_brute_force_on_small_graphs() -> None:
    rng = np.random.default_rng(5)
    for _ in range(60):
        adjacency = random_graph(rng, int(rng.integers(1, 12)), rng.uniform(0.2, 0.9))
        result = maximum_clique(adjacency, time_limit=10.0, work_limit=10**7)
        members = result.members
        assert all(adjacency[i, j] for i, j in itertools.combinations(members, 2))
        assert len(members) == brute_force_clique_size(adjacency)
        assert result.exact


def test_maximum_clique_finds_a_planted_clique() -> None:
    rng = np.random.default_rng(6)
    adjacency = random_graph(rng, 400, 0.1)
    planted = rng.choice(400, 25, replace=False)
    adjacency[np.ix_(planted, planted)] = True
    np.fill_diagonal(adjacency, False)
    result = maximum_clique(adjacency, time_limit=10.0, work_limit=10**7)
    np.testing.assert_array_equal(result.members, np.sort(planted))
    assert result.exact


def test_work_limit_stops_the_search_with_a_valid_clique() -> None:
    adjacency = random_graph(np.random.default_rng(7), 300, 0.5)
    result = maximum_clique(adjacency, time_limit=10.0, work_limit=1)
    assert result.stop == "work limit"
    assert len(result.members) >= 2
    assert all(adjacency[i, j] for i, j in itertools.combinations(result.members, 2))


def test_core_numbers_of_a_known_graph() -> None:
    # A triangle (core 2) with a pendant vertex (core 1) and an isolated vertex (core 0).
    adjacency = np.zeros((5, 5), dtype=bool)
    for i, j in [(0, 1), (1, 2), (0, 2), (2, 3)]:
        adjacency[i, j] = adjacency[j, i] = True
    np.testing.assert_array_equal(core_numbers(adjacency), [2, 2, 2, 1, 0])
