"""The contract every registered registration method keeps, checked on synthetic coin pairs with known truth.

The pair: a 12 mm die-like relief (dome, bumps and strokes 0.1–0.5 mm high, 0.1 mm grid, analytic normals);
the source is another, smaller disc of it (partial overlap), on another grid offset, with 0.01 mm noise,
moved by a known rigid transform. Global methods get a large transform (120° about the axis, tilted);
local methods (``icp``) only refine a start near the truth, so they get a mild one (8° and 0.4 mm).

Learned methods (``dip``, ``fcgf``) run with their shipped weights (trained on synthetic coins, not on
this relief). Tolerances: methods that end with ICP must land within 0.5° and 0.1 mm. Methods that end
with a robust solver on FPFH matches (``fpfh+teaser``, ``fpfh+ransac``) estimate from matches between
points of a 0.2 mm support grid, so they get 1° and 0.3 mm. (The relief is bolder than real coins' so
that FPFH has a chance: the paper reports FPFH + TEASER failing on most real dies.)
"""

from __future__ import annotations

import numpy as np
import pytest

from coindie.errors import InvalidScanError
from coindie.registration import (
    RegistrationResult,
    get_method,
    list_methods,
    method_info,
    rotation_error_deg,
    translation_error_mm,
)
from coindie.scan import Scan
from coindie.transforms import euler_rigid, inverse
from synthetic_pairs import CoinPair, make_coin_pair, random_relief, scan_relief

RADIUS = 6.0
#: (degrees, mm) a method's estimate must be within; methods not listed get DEFAULT_TOLERANCE.
COARSE_TOLERANCE = (1.0, 0.3)
TOLERANCE = {"fpfh+teaser": COARSE_TOLERANCE, "fpfh+ransac": COARSE_TOLERANCE}
DEFAULT_TOLERANCE = (0.5, 0.1)

METHODS = list_methods()


def tolerance(method: str) -> tuple[float, float]:
    return TOLERANCE.get(method, DEFAULT_TOLERANCE)


@pytest.fixture(scope="module")
def pairs() -> dict[str, CoinPair]:
    hard = euler_rigid((15.0, -10.0, 120.0), (5.0, -3.0, 2.0))
    mild = euler_rigid((2.0, -1.0, 8.0), (0.3, -0.2, 0.1))
    return {
        "global": make_coin_pair(seed=5, radius=RADIUS, T_target_source=hard),
        "local": make_coin_pair(seed=5, radius=RADIUS, T_target_source=mild),
    }


def pair_for(method: str, pairs: dict[str, CoinPair]) -> CoinPair:
    return pairs["local" if method_info(method).local else "global"]


@pytest.fixture(scope="module")
def forward(pairs: dict[str, CoinPair]) -> dict[str, RegistrationResult]:
    """Each method's result on its pair, computed once for the tests that compare with it."""
    results = {}
    for method in METHODS:
        pair = pair_for(method, pairs)
        results[method] = get_method(method).register(pair.source, pair.target)
    return results


def assert_close(T_true: np.ndarray, T: np.ndarray, method: str) -> None:
    max_deg, max_mm = tolerance(method)
    assert rotation_error_deg(T_true, T) < max_deg, (
        f"{method}: rotation off by {rotation_error_deg(T_true, T):.3f}°"
    )
    assert translation_error_mm(T_true, T) < max_mm, (
        f"{method}: translation off by {translation_error_mm(T_true, T):.3f} mm"
    )


@pytest.mark.parametrize("method", METHODS)
def test_recovers_the_known_transform(method: str, pairs, forward) -> None:
    result = forward[method]
    assert result.valid, result.reason
    assert_close(pair_for(method, pairs).T_target_source, result.T_target_source, method)
    assert result.T_target_source.shape == (4, 4)
    assert np.allclose(result.T_target_source[3], [0, 0, 0, 1])
    assert np.isclose(np.linalg.det(result.T_target_source[:3, :3]), 1.0)


@pytest.mark.parametrize("method", METHODS)
def test_result_carries_its_figures_and_parameters(method: str, forward) -> None:
    result = forward[method]
    assert result.method == method
    assert result.params == get_method(method).params  # every declared parameter, with its value
    assert set(result.params) == set(method_info(method).params())
    assert 0.5 < result.fitness <= 1.0
    assert 0.0 <= result.residual < 0.02  # mm: the 0.01 mm noise, not a misalignment
    assert result.n_correspondences >= result.n_inliers > 0
    assert result.timings["total"] >= max(v for k, v in result.timings.items() if k != "total")
    assert result.to_dict()["T_target_source"] == result.T_target_source.tolist()


@pytest.mark.parametrize("method", METHODS)
def test_swapping_source_and_target_gives_the_inverse(method: str, pairs, forward) -> None:
    pair = pair_for(method, pairs)
    backward = get_method(method).register(pair.target, pair.source)
    assert backward.valid, backward.reason
    assert_close(inverse(pair.T_target_source), backward.T_target_source, method)
    assert_close(inverse(forward[method].T_target_source), backward.T_target_source, method)


@pytest.mark.parametrize("method", METHODS)
def test_point_order_does_not_matter(method: str, pairs, forward) -> None:
    pair = pair_for(method, pairs)
    rng = np.random.default_rng(1)
    source = pair.source.subset(rng.permutation(pair.source.n_points))
    target = pair.target.subset(rng.permutation(pair.target.n_points))
    result = get_method(method).register(source, target)
    # Inputs are put in a canonical order: the same pair in any order gives the same result, exactly.
    np.testing.assert_allclose(result.T_target_source, forward[method].T_target_source, atol=1e-9)


@pytest.mark.parametrize("method", METHODS)
def test_surfaces_without_a_common_part_fit_worse_than_the_true_pair(method: str, pairs, forward) -> None:
    """Two different reliefs: there is no right answer. A registration is refused only where there is no
    pose at all (no overlap, a degenerate fit); otherwise the pose it returns is judged by the same-die
    scorer, and its residual must say it fits far worse than the true pair's."""
    target = pair_for(method, pairs).target
    other = scan_relief(random_relief(99, radius=RADIUS), radius=RADIUS - 0.75, noise=0.01, seed=3)
    result = get_method(method).register(other, target)
    if not result.valid:
        assert result.reason
    else:
        assert result.residual > 2.0 * forward[method].residual


@pytest.mark.parametrize("method", [m for m in METHODS if method_info(m).local])
def test_local_methods_report_clouds_a_metre_apart_as_not_valid(method: str, pairs) -> None:
    pair = pair_for(method, pairs)
    far = pair.source.transformed(euler_rigid((0.0, 0.0, 0.0), (1000.0, 0.0, 0.0)))
    result = get_method(method).register(far, pair.target)
    assert not result.valid
    assert "overlap" in result.reason or "pairs" in result.reason


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize(
    ("points", "problem"),
    [
        (np.empty((0, 3)), "zero points"),
        (np.array([[0.0, 0.0, 0.0], [np.nan, 1.0, 2.0]] * 10), "NaN"),
        (np.zeros((5, 3)), "at least"),
        (np.zeros((10, 2)), "(N, 3)"),
    ],
    ids=["empty", "nan", "too-few", "not-3d"],
)
def test_bad_input_is_a_clear_error(method: str, points: np.ndarray, problem: str, pairs) -> None:
    registrar = get_method(method)
    target = pair_for(method, pairs).target
    with pytest.raises(InvalidScanError, match="source") as error:
        registrar.register(points, target)
    assert problem in str(error.value)
    with pytest.raises(InvalidScanError, match="target"):
        registrar.register(target, points)


def test_a_scan_without_normals_gets_estimated_ones(pairs) -> None:
    pair = pairs["local"]
    bare = Scan(points=pair.source.points)
    result = get_method("icp").register(bare, pair.target)
    assert result.valid, result.reason
    assert_close(pair.T_target_source, result.T_target_source, "icp")
