"""Block matching of two reliefs in the plane: a pose a degree and a few tenths of a millimetre off is
brought to the truth, crusts and worn areas do not pull it, and other dies do not look consistent."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from coindie.registration.relief_blocks import (
    FineRelief,
    _shifted_tile_products,
    _shifted_window_sums,
    _weighted_rigid,
    refine_planar,
)

PIXEL = 0.1  # mm
DIE_PX = 400
SIZE = 240  # pixels of a face's grid (24 mm)
SETTINGS = {"window_mm": 2.4, "reach_px": 2}


def die(seed: int) -> np.ndarray:
    """A 40 mm die: band-limited random strokes, 0 to ~0.6 mm high."""
    rng = np.random.default_rng(seed)
    field = ndimage.gaussian_filter(rng.standard_normal((DIE_PX, DIE_PX)), 3)
    return ndimage.gaussian_filter(np.clip(field / field.std() * 0.2, 0, None), 1)


def strike(
    die_heights: np.ndarray, angle: float, shift: tuple[float, float], seed: int, crust: float = 0.0
) -> np.ndarray:
    """A face's centred grid (rows along +y): the die's point at R(angle) p + shift seen at p, a cupped
    flan, noise, and crusts (random lumps 0.1 mm high) over a ``crust`` share of the face."""
    rng = np.random.default_rng(seed)
    y, x = (np.mgrid[0:SIZE, 0:SIZE] - (SIZE - 1) / 2) * PIXEL
    c, s = np.cos(angle), np.sin(angle)
    xd, yd = c * x - s * y + shift[0], s * x + c * y + shift[1]
    heights = ndimage.map_coordinates(
        die_heights, [yd / PIXEL + DIE_PX / 2, xd / PIXEL + DIE_PX / 2], order=1
    )
    heights += 0.002 * (x**2 + y**2) * rng.uniform(-1, 1) + rng.normal(0.0, 0.006, heights.shape)
    if crust:
        blobs = ndimage.gaussian_filter(rng.standard_normal((SIZE, SIZE)), 12)
        covered = blobs > np.quantile(blobs, 1.0 - crust)
        heights += np.where(covered, 0.1 * ndimage.gaussian_filter(rng.random((SIZE, SIZE)), 1.5), 0.0)
    return np.where(np.hypot(x, y) < 10.0, heights, np.nan)


def fine(values: np.ndarray) -> FineRelief:
    return FineRelief.from_grid(values, PIXEL, high_pass_mm=1.0, margin_mm=0.6, steps=(4, 2, 1))


def planar(angle: float, shift: tuple[float, float]) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, shift[0]], [s, c, shift[1]], [0.0, 0.0, 1.0]])


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize("crust", [0.0, 0.3])
def test_a_pose_off_by_a_degree_and_tenths_of_a_millimetre_is_brought_to_the_truth(
    seed: int, crust: float
) -> None:
    """Two strikes of one die, the target crusted over a ``crust`` share: from a start 1.5° and 0.35 mm
    off, the pose comes within 0.05° and 0.02 mm of the truth (a fifth of the finest pixel)."""
    die_heights = die(seed)
    T_die_source = planar(np.radians(40.0 * seed), (0.4, -0.3))
    T_die_target = planar(np.radians(-25.0), (-0.5, 0.2))
    source = fine(
        strike(
            die_heights, np.arctan2(T_die_source[1, 0], T_die_source[0, 0]), tuple(T_die_source[:2, 2]), seed
        )
    )
    target = fine(strike(die_heights, np.radians(-25.0), (-0.5, 0.2), seed + 10, crust=crust))
    T_true = np.linalg.inv(T_die_target) @ T_die_source  # p_target = T_true p_source
    angle_true = float(np.arctan2(T_true[1, 0], T_true[0, 0]))
    start_angle = angle_true + np.radians(1.5)
    start_shift = (float(T_true[0, 2]) + 0.25, float(T_true[1, 2]) - 0.25)
    refined = refine_planar(source, target, start_angle, start_shift, **SETTINGS)
    assert abs(np.degrees(refined.angle_rad - angle_true)) < 0.05
    assert np.hypot(refined.shift_mm[0] - T_true[0, 2], refined.shift_mm[1] - T_true[1, 2]) < 0.02
    assert refined.improved
    assert refined.agreement_after > refined.agreement_before + 0.2
    assert refined.consistent > 0.7


def test_other_dies_do_not_look_consistent() -> None:
    """Strikes of two dies: few windows' shifts agree on one motion, and the agreement stays low."""
    for seed in range(3):
        source = fine(strike(die(seed), 0.3, (0.2, 0.1), seed))
        target = fine(strike(die(seed + 50), 0.0, (0.0, 0.0), seed + 1))
        refined = refine_planar(source, target, 0.3, (0.1, 0.0), **SETTINGS)
        assert refined.consistent < 0.5
        assert refined.agreement_after < 0.3


def test_the_identity_stays_where_it_is() -> None:
    """A face against itself from the true pose: the refinement moves it by under a hundredth of a pixel."""
    face = fine(strike(die(3), 0.2, (0.1, 0.3), 3))
    refined = refine_planar(face, face, 0.0, (0.0, 0.0), **SETTINGS)
    assert abs(refined.angle_rad) < 1e-4
    assert np.hypot(*refined.shift_mm) < 1e-3
    assert refined.agreement_after == pytest.approx(1.0, abs=1e-4)  # float32 images


@pytest.mark.parametrize("seed", range(3))
def test_relief_moves_a_pose_off_in_the_plane_back_to_the_truth_and_keeps_a_right_one(seed: int) -> None:
    """Through both canonical frames: the ``relief`` method's last step, given a pair's true pose turned by
    1.5° about the target's axis and moved 0.3 mm, returns a pose within 0.1° and half a pixel (0.05 mm)
    of the truth (the windows' optimum on rasterised scans lies 0.01-0.04 mm from it); given the true
    pose, returns it as it is (within a pixel the ICP's pose stands)."""
    from coindie.registration import get_method
    from coindie.registration.metrics import rotation_error_deg, translation_error_mm
    from synthetic_pairs import make_coin_pair

    pair = make_coin_pair(seed=seed, radius=9.0, spacing=0.05, noise=0.005)
    method = get_method("relief")
    estimator = method.estimator
    source, target = (
        estimator.prepare(method._cloud(pair.source)),
        estimator.prepare(method._cloud(pair.target)),
    )
    off = np.eye(4)
    off[:2, :2] = planar(np.radians(1.5), (0.0, 0.0))[:2, :2]
    off[:2, 3] = (0.2, -0.22)
    T_frame = target.frame.T_canonical_scan
    T_off = np.linalg.inv(T_frame) @ off @ T_frame @ pair.T_target_source
    assert rotation_error_deg(pair.T_target_source, T_off) > 1.4
    T_back, note = estimator._block_matched(T_off, source, target)
    assert rotation_error_deg(pair.T_target_source, T_back) < 0.1, note
    assert translation_error_mm(pair.T_target_source, T_back) < 0.05, note
    T_kept, note = estimator._block_matched(pair.T_target_source, source, target)
    np.testing.assert_array_equal(T_kept, pair.T_target_source)
    assert "refused" in note or "within a pixel" in note


def test_window_sums_are_the_sums_over_each_window_at_each_shift() -> None:
    rng = np.random.default_rng(3)
    tile, side = 4, 5
    fixed = rng.standard_normal((6 * tile, 5 * tile)).astype(np.float32)
    moving = rng.standard_normal((fixed.shape[0] + side - 1, fixed.shape[1] + side - 1)).astype(np.float32)
    sums = _shifted_window_sums(moving, tile, side)
    products = _shifted_tile_products(moving, fixed, tile, side)
    assert sums.shape == (side, side, 5, 4) and products.shape == (side, side, 6, 5)
    for i, j, k, n in [(0, 0, 0, 0), (4, 2, 3, 1), (1, 3, 4, 3), (2, 4, 2, 2)]:
        box = moving[k * tile + i : k * tile + i + 2 * tile, n * tile + j : n * tile + j + 2 * tile]
        assert sums[i, j, k, n] == pytest.approx(box.astype(np.float64).sum(), abs=1e-9)
        shifted = moving[i : i + fixed.shape[0], j : j + fixed.shape[1]]
        product = (shifted.astype(np.float64) * fixed)[k * tile : (k + 1) * tile, n * tile : (n + 1) * tile]
        assert products[i, j, k, n] == pytest.approx(product.sum(), abs=1e-5)


def test_the_weighted_rigid_fit_recovers_a_turn_and_a_shift_and_never_reflects() -> None:
    rng = np.random.default_rng(4)
    source = rng.uniform(-10, 10, (30, 2))
    for angle in (0.3, -2.9, 3.1):
        c, s = np.cos(angle), np.sin(angle)
        R_true = np.array([[c, -s], [s, c]])
        target = source @ R_true.T + [0.4, -1.2]
        weight = rng.uniform(0.1, 1.0, len(source))
        R, t = _weighted_rigid(source, target, weight)
        assert np.allclose(R, R_true, atol=1e-12) and np.allclose(t, [0.4, -1.2], atol=1e-12)
    # points mirrored: the best proper rotation, never a reflection
    R, _ = _weighted_rigid(source, source * [1.0, -1.0], np.ones(len(source)))
    assert np.linalg.det(R) == pytest.approx(1.0)
