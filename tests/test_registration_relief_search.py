"""Planar FFT alignment of relief images: known rotations and translations are recovered."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from coindie.registration.relief_search import (
    _SWEPT,
    FixedSpectra,
    ReliefImage,
    _evidence_near_peak,
    _masked_ncc_batch,
    _peak_shift,
    _significant_peaks,
    _turn_operator,
    _window_shape,
    align_reliefs,
    correlate_turns,
    masked_ncc,
    pose_score,
    rotate_image,
    rotation_candidates,
    significance,
)

PIXEL = 0.1  # mm
DIE_PX = 400


@pytest.fixture(scope="module")
def die_field() -> np.ndarray:
    """A 40 mm die: band-limited random strokes, 0 to ~0.6 mm high."""
    rng = np.random.default_rng(0)
    field = ndimage.gaussian_filter(rng.standard_normal((DIE_PX, DIE_PX)), 3)
    return ndimage.gaussian_filter(np.clip(field / field.std() * 0.2, 0, None), 1)


def rigid_2d(angle: float, shift: np.ndarray) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, shift[0]], [s, c, shift[1]], [0.0, 0.0, 1.0]])


def strike(die: np.ndarray, T_die_coin: np.ndarray, seed: int, size: int = 256) -> np.ndarray:
    """A coin's centred height grid: the die seen through T_die_coin, an irregular flan, scanner noise."""
    rng = np.random.default_rng(seed)
    y, x = (np.mgrid[0:size, 0:size] - (size - 1) / 2) * PIXEL
    xd = T_die_coin[0, 0] * x + T_die_coin[0, 1] * y + T_die_coin[0, 2]
    yd = T_die_coin[1, 0] * x + T_die_coin[1, 1] * y + T_die_coin[1, 2]
    heights = ndimage.map_coordinates(die, [yd / PIXEL + DIE_PX / 2, xd / PIXEL + DIE_PX / 2], order=1)
    heights = heights + rng.normal(0.0, 0.008, heights.shape)
    angle = np.arctan2(y, x)
    radius = 10 + 0.6 * np.sin(3 * angle + rng.uniform(0, 6)) + 0.4 * np.sin(5 * angle + rng.uniform(0, 6))
    return np.where(np.hypot(x, y) < radius, heights, np.nan)


def angle_of(T: np.ndarray) -> float:
    return float(np.arctan2(T[1, 0], T[0, 0]))


def pose_errors(T_b_a_found: np.ndarray, T_die_a: np.ndarray, T_die_b: np.ndarray) -> tuple[float, float]:
    """(|angle error| in degrees, translation error in mm) of a found 2-D T_b_a."""
    T_b_a = np.linalg.inv(T_die_b) @ T_die_a
    angle_error = np.degrees(np.angle(np.exp(1j * (angle_of(T_b_a_found) - angle_of(T_b_a)))))
    return float(abs(angle_error)), float(np.linalg.norm(T_b_a_found[:2, 2] - T_b_a[:2, 2]))


@pytest.mark.parametrize("seed", range(6))
def test_recovers_rotation_and_translation_of_same_die_strikes(die_field: np.ndarray, seed: int) -> None:
    rng = np.random.default_rng(100 + seed)
    T_die_a = rigid_2d(rng.uniform(-np.pi, np.pi), rng.uniform(-2, 2, 2))
    T_die_b = rigid_2d(rng.uniform(-np.pi, np.pi), rng.uniform(-2, 2, 2))
    a = ReliefImage.from_grid(strike(die_field, T_die_a, seed), PIXEL)
    b = ReliefImage.from_grid(strike(die_field, T_die_b, 50 + seed), PIXEL)

    result = align_reliefs(a, b)

    angle_error, shift_error = pose_errors(result.matrix(), T_die_a, T_die_b)
    assert angle_error < 0.3
    assert shift_error < 0.05
    assert result.score > 0.8


def test_other_die_scores_low(die_field: np.ndarray) -> None:
    other = np.random.default_rng(7).permutation(die_field.ravel()).reshape(die_field.shape)
    other = ndimage.gaussian_filter(other, 2) * 3
    a = ReliefImage.from_grid(strike(die_field, rigid_2d(0.3, np.zeros(2)), 1), PIXEL)
    b = ReliefImage.from_grid(strike(other, rigid_2d(0.3, np.zeros(2)), 2), PIXEL)
    same = ReliefImage.from_grid(strike(die_field, rigid_2d(-1.0, np.ones(2)), 3), PIXEL)
    assert align_reliefs(a, b).score < 0.5 < align_reliefs(a, same).score


def test_rotation_candidates_find_a_pure_rotation(die_field: np.ndarray) -> None:
    image = strike(die_field, rigid_2d(0.0, np.zeros(2)), 0)
    turned = rotate_image(np.nan_to_num(image), np.radians(40.0))
    polar_a = ReliefImage.from_grid(np.where(np.isfinite(image), image, np.nan), PIXEL).polar
    polar_b = ReliefImage.from_grid(np.where(turned != 0, turned, np.nan), PIXEL).polar
    best = rotation_candidates(polar_a, polar_b)[0]
    assert min(abs(np.degrees(best) - 40.0), abs(np.degrees(best) - 220.0)) < 0.5


def test_masked_ncc_peak_gives_the_shift_and_ignores_outside_mask() -> None:
    rng = np.random.default_rng(3)
    fixed = rng.standard_normal((40, 50))
    moving = np.roll(fixed, (3, -5), axis=(0, 1))
    moving_mask = np.zeros_like(fixed, dtype=bool)
    moving_mask[8:32, 10:40] = True
    moving = np.where(moving_mask, moving, 1e3)  # garbage outside the mask must not matter
    ncc, overlap = masked_ncc(fixed, moving, np.ones_like(fixed, dtype=bool), moving_mask, 50)
    k = np.unravel_index(np.argmax(ncc), ncc.shape)
    d = np.array(moving.shape) - 1 - np.array(k)  # fixed[n] ~ moving[n + d]
    assert tuple(d) == (3, -5)
    assert ncc[k] == pytest.approx(1.0, abs=1e-6)
    assert overlap[k] == moving_mask.sum()


@pytest.mark.parametrize("sweep_step", [None, 3])
@pytest.mark.parametrize("seed", range(4))
def test_exhaustive_search_recovers_off_centre_strikes_with_a_weak_half(
    die_field: np.ndarray, seed: int, sweep_step: int | None
) -> None:
    """Flans struck a third of their radius off the die's centre in opposite directions (about 60 % of
    each face shared), one of them weakly struck on half its face: every turn is searched, so the
    rotation does not depend on the two footprints' spectra being alike. The peak over turns is wider
    than for whole flans (less shared relief): within 1°, which the ICP refines. The same when the sweep
    of every turn runs at a third of the resolution (``relief.sweep_step=3``) and its best turns at half."""
    rng = np.random.default_rng(300 + seed)
    direction = rng.uniform(-np.pi, np.pi)
    offset = 3.5 * np.array([np.cos(direction), np.sin(direction)])
    T_die_a = rigid_2d(rng.uniform(-np.pi, np.pi), offset)
    T_die_b = rigid_2d(rng.uniform(-np.pi, np.pi), -offset)
    grid_a = strike(die_field, T_die_a, seed)
    y, x = (np.mgrid[0 : grid_a.shape[0], 0 : grid_a.shape[1]] - (grid_a.shape[0] - 1) / 2) * PIXEL
    grid_a = np.where(x * np.cos(direction) + y * np.sin(direction) > 0, 0.25 * grid_a, grid_a)
    a = ReliefImage.from_grid(grid_a, PIXEL)
    b = ReliefImage.from_grid(strike(die_field, T_die_b, 60 + seed), PIXEL)

    found = align_reliefs(a, b, sweep_step=sweep_step)
    angle_error, shift_error = pose_errors(found.matrix(), T_die_a, T_die_b)
    assert angle_error < 1.0
    assert shift_error < 0.2


def test_batched_cropped_correlation_equals_the_full_masked_ncc(die_field: np.ndarray) -> None:
    """The search correlates squares cut to the footprints, many turns per batch of FFTs: the same peak
    scores and shifts as one full-field masked NCC per turn."""
    a = ReliefImage.from_grid(strike(die_field, rigid_2d(0.4, np.array([1.0, -0.5])), 1), PIXEL)
    b = ReliefImage.from_grid(strike(die_field, rigid_2d(-0.3, np.array([-0.8, 0.6])), 2), PIXEL)
    step, angles = 2, np.radians([0.0, 17.0, 41.0, 200.0])
    scores, shifts = correlate_turns(a, b, angles, step, min_overlap=0.3)
    detail, mask = a.reduced(step)
    fixed, fixed_mask = b.reduced(step)
    centre = (np.asarray(a.detail.shape, dtype=np.float64) - 1.0) / 2.0 / step
    min_pixels = 0.3 * min(fixed_mask.sum(), mask.sum())
    for angle, score, shift in zip(angles, scores, shifts, strict=True):
        moving = rotate_image(detail, angle, centre=centre)
        moving_mask = rotate_image(mask.astype(np.float64), angle, centre=centre) > 0.5
        ncc, overlap = masked_ncc(fixed, moving, fixed_mask, moving_mask, min_pixels)
        evidence = significance(ncc, overlap / min(fixed_mask.sum(), mask.sum()))
        k = np.unravel_index(int(np.argmax(evidence)), evidence.shape)
        d = np.asarray(moving.shape) - 1 - np.asarray(k)  # fixed[n] ~ moving[n + d]
        # float32 transforms: scores agree to ~1e-5; the peak to the parabola's sub-pixel part
        assert score == pytest.approx(float(evidence[k]), abs=1e-4)
        assert np.abs(shift - (-d[::-1]) * PIXEL * step).max() < PIXEL * step


@pytest.mark.parametrize("sweep_step", [None, 3])
@pytest.mark.parametrize("seed", range(4))
def test_strikes_far_off_centre_are_found_at_their_small_overlap(
    die_field: np.ndarray, seed: int, sweep_step: int | None
) -> None:
    """Two flans struck 5.5 mm off the die's centre in opposite directions: they share about a fifth of
    their faces. Ranked by NCC alone among overlaps of 30 % or more, the right pose was out of reach;
    ranked by significance, it is found."""
    rng = np.random.default_rng(400 + seed)
    direction = rng.uniform(-np.pi, np.pi)
    offset = 5.5 * np.array([np.cos(direction), np.sin(direction)])
    T_die_a = rigid_2d(rng.uniform(-np.pi, np.pi), offset)
    T_die_b = rigid_2d(rng.uniform(-np.pi, np.pi), -offset)
    a = ReliefImage.from_grid(strike(die_field, T_die_a, seed), PIXEL)
    b = ReliefImage.from_grid(strike(die_field, T_die_b, 70 + seed), PIXEL)

    result = align_reliefs(a, b, sweep_step=sweep_step)
    angle_error, shift_error = pose_errors(result.matrix(), T_die_a, T_die_b)
    assert angle_error < 1.0
    assert shift_error < 0.2
    assert result.score > 0.8


def test_significance_weighs_the_overlap() -> None:
    """The same correlation over four times the area is twice as far from chance; chance stays at 0; a
    turned mask a pixel larger than the smaller footprint counts as the whole of it."""
    r = np.array([0.5, 0.5, 0.0, 0.5])
    z = significance(r, np.array([0.25, 1.0, 1.0, 1.002]))
    assert z[1] == pytest.approx(2 * z[0]) and z[2] == 0.0 and z[3] == z[1]


def test_the_peak_is_found_when_the_overlap_share_exceeds_one() -> None:
    """The best correlation at an overlap share a hair above 1 (a turned mask holds a pixel more than the
    footprint it is compared with) is still the peak; it left no candidate once, and the pair failed."""
    ncc = np.zeros((5, 5))
    ncc[2, 3] = 0.9
    share = np.full((5, 5), 0.5)
    share[2, 3] = 1.001
    evidence = _evidence_near_peak(ncc, share)
    assert np.unravel_index(int(np.argmax(evidence)), evidence.shape) == (2, 3)


def test_the_turn_operator_is_rotate_image() -> None:
    """The sweep's sparse operator turns an image and its mask as :func:`rotate_image` does, at every
    angle, about an off-centre point, up to the edges (zero where the sample falls outside)."""
    rng = np.random.default_rng(5)
    image = ndimage.gaussian_filter(rng.standard_normal((31, 31)), 1.5)
    mask = ndimage.binary_erosion(np.ones((31, 31), dtype=bool), iterations=3) & (image > -0.3)
    centre = (14.7, 15.2)
    angles = tuple(float(a) for a in np.radians([0.0, 8.0, 45.0, 90.0, 173.0, 271.5]))
    turned = _turn_operator(image.shape, centre, angles) @ np.stack([image.ravel(), mask.ravel()], axis=1)
    turned = turned.reshape(len(angles), *image.shape, 2)
    for i, angle in enumerate(angles):
        expected = rotate_image(image, angle, centre=np.asarray(centre))
        assert np.abs(turned[i, ..., 0] - expected).max() < 1e-12
        expected_mask = rotate_image(mask.astype(np.float64), angle, centre=np.asarray(centre)) > 0.5
        assert np.array_equal(turned[i, ..., 1] > 0.5, expected_mask)


@pytest.mark.parametrize("seed", range(3))
def test_the_batched_peaks_are_the_single_image_peaks(seed: int) -> None:
    """:func:`_significant_peaks` over a stack gives each image's peak significance and sub-pixel place as
    the one-image path does: smooth correlations, one peak on the image's border, and one image whose
    correlations are all negative (where a neighbour outside the candidates can weigh the most)."""
    rng = np.random.default_rng(seed)
    ncc = np.stack([ndimage.gaussian_filter(rng.standard_normal((23, 27)), 2) for _ in range(6)])
    ncc = np.clip(ncc / np.abs(ncc).max() * 0.9, -1, 1).astype(np.float32)
    ncc[1, 0, 5] = 0.95  # a peak on the border: no sub-pixel part across it
    ncc[2] = -np.abs(ncc[2]) - 0.05
    overlap = rng.uniform(50.0, 400.0, ncc.shape).astype(np.float32)
    full = 300.0
    best, peaks = _significant_peaks(ncc, overlap, full)
    for i in range(len(ncc)):
        evidence = _evidence_near_peak(ncc[i], overlap[i] / full)
        assert best[i] == evidence.max()
        shift = _peak_shift(evidence, ncc.shape[1:])  # (x, y) of the peak from the far corner
        assert np.allclose(peaks[i], np.asarray(ncc.shape[1:]) - 1.0 + shift[::-1], rtol=0, atol=1e-12)


@pytest.mark.parametrize(("angle_deg", "origin"), [(0.0, 0), (33.0, 1), (250.0, -2)])
def test_shorter_transforms_give_every_shift_where_the_footprints_can_overlap(
    die_field: np.ndarray, angle_deg: float, origin: int
) -> None:
    """The correlations are taken with transforms shorter than the whole linear correlation
    (:func:`_window_shape`): every shift they leave wrapped is one where the two footprints overlap on
    fewer pixels than the floor (so it scores 0 either way), and every other shift is the full result."""
    a = ReliefImage.from_grid(strike(die_field, rigid_2d(0.4, np.array([1.0, -0.5])), 1), PIXEL)
    b = ReliefImage.from_grid(strike(die_field, rigid_2d(-0.3, np.array([-0.8, 0.6])), 2), PIXEL)
    detail, mask, _ = a.cropped(2)
    fixed, fixed_mask, _ = b.cropped(2)
    min_pixels = 0.15 * min(fixed_mask.sum(), mask.sum())
    centre = (np.asarray(detail.shape, dtype=np.float64) - 1.0) / 2.0
    moving = rotate_image(detail, np.radians(angle_deg), centre=centre)[None]
    moving_mask = rotate_image(mask.astype(np.float64), np.radians(angle_deg), centre=centre)[None] > 0.5
    shape = _window_shape(fixed.shape, detail.shape, origin, min_pixels)
    assert shape[0] < FixedSpectra.of(fixed, fixed_mask, detail.shape).shape[0]  # shorter, or no test

    full_ncc, full_overlap = _masked_ncc_batch(
        FixedSpectra.of(fixed, fixed_mask, detail.shape), moving, moving_mask, min_pixels
    )
    short = FixedSpectra.of(fixed, fixed_mask, detail.shape, shape)
    ncc, _ = _masked_ncc_batch(short, moving, moving_mask, min_pixels)
    rows, cols = ncc.shape[1:]
    # the whole correlation's shifts the short one does not hold, or holds wrapped, overlap too little
    wrapped = np.ones(full_ncc.shape[1:], dtype=bool)
    wrapped[full_ncc.shape[1] - rows : rows, full_ncc.shape[2] - cols : cols] = False
    assert full_overlap[0][wrapped].max() < min_pixels
    assert (full_ncc[0][wrapped] == 0).all()
    # and the rest is the same correlation (float32 transforms of two lengths)
    kept = ~wrapped[:rows, :cols]
    assert np.abs(ncc[0][kept] - full_ncc[0][:rows, :cols][kept]).max() < 1e-4
    assert (ncc[0][~kept] == 0).all()


def test_the_pose_score_on_the_footprints_windows_is_the_whole_images() -> None:
    """:func:`pose_score` reads both images on squares cut to their footprints: the same correlation as
    turning and shifting the whole source image and comparing it with the whole target, at any pose,
    including one that moves the source half off the target."""
    y, x = (np.mgrid[0:200, 0:200] - 99.5) * PIXEL
    images = []
    for seed, radius in ((1, 8.0), (2, 6.5)):
        heights = ndimage.gaussian_filter(np.random.default_rng(seed).standard_normal((200, 200)), 3)
        images.append(ReliefImage.from_grid(np.where(np.hypot(x - 0.7, y) < radius, heights, np.nan), PIXEL))
    source, target = images
    for angle, shift in [(0.0, (0.0, 0.0)), (0.7, (0.43, -1.21)), (-2.9, (9.0, 4.5)), (1.3, (-20.0, 0.0))]:
        offset = (shift[1] / PIXEL, shift[0] / PIXEL)
        moving = ndimage.shift(rotate_image(source.detail, angle), offset, order=1, mode="constant")
        turned_mask = rotate_image(source.mask.astype(np.float64), angle)
        both = (ndimage.shift(turned_mask, offset, order=1, mode="constant") > 0.5) & target.mask
        if both.sum() < 3:
            expected = -1.0
        else:
            f, m = target.detail[both], moving[both]
            expected = float(np.corrcoef(f, m)[0, 1])
        assert pose_score(source, target, angle, shift) == pytest.approx(expected, abs=1e-9)


def test_the_kept_turns_of_a_source_give_each_target_its_own_correlations(die_field: np.ndarray) -> None:
    """The sweep keeps each source's turned transforms (one entry per source and transform size) and
    reuses them for every target: each source against each target, in a study's order (a source's pairs
    one after another), then in the reverse order, gives exactly what it gives computed afresh; two sources
    of one size never share an entry."""
    angles = np.arange(45) * (2.0 * np.pi / 45)
    radii = {1: 0.0, 2: 0.0, 3: 2.0, 4: 3.5}  # flans of several sizes: transforms of several sizes
    images = {
        seed: ReliefImage.from_grid(
            np.where(
                np.hypot(*((np.mgrid[0:256, 0:256] - 127.5) * PIXEL)) < 12.0 - extra,
                strike(die_field, rigid_2d(0.3 * seed, np.array([0.2 * seed, -0.1])), seed),
                np.nan,
            ),
            PIXEL,
        )
        for seed, extra in radii.items()
    }
    pairs = [(s, t) for s in images for t in images if s != t]

    def fresh(source: int, target: int) -> tuple[np.ndarray, np.ndarray]:
        _SWEPT.clear()
        return correlate_turns(images[source], images[target], angles, 2, 0.15, reuse_turns=True)

    expected = {pair: fresh(*pair) for pair in pairs}
    assert len({expected[pair][0].tobytes() for pair in pairs}) == len(pairs)  # all different
    _SWEPT.clear()
    for pair in pairs + pairs[::-1]:
        scores, shifts = correlate_turns(images[pair[0]], images[pair[1]], angles, 2, 0.15, reuse_turns=True)
        assert np.array_equal(scores, expected[pair][0]) and np.array_equal(shifts, expected[pair][1])
    sizes = {images[s].cropped(2)[0].shape for s in images}
    assert len(sizes) > 1  # or no two transform sizes were tried


def _with_crusts(grid: np.ndarray, rng: np.random.Generator, n: int = 2) -> np.ndarray:
    """``grid`` with ``n`` crusts at random: smooth lumps 2 mm wide and 1 mm high, not the die's."""
    size = grid.shape[0]
    y, x = (np.mgrid[0:size, 0:size] - (size - 1) / 2) * PIXEL
    for _ in range(n):
        cx, cy = rng.uniform(-6, 6, 2)
        grid = grid + np.sqrt(np.clip(1 - (x - cx) ** 2 - (y - cy) ** 2, 0, None))
    return grid


def test_clipped_detail_keeps_a_crust_from_carrying_the_search() -> None:
    """Two strikes of one die, each with two crusts of its own (lumps whose relief detail is tenfold the
    die's): with the detail clipped at 3 robust standard deviations (``relief.clip=3``), all twelve poses
    are found; unclipped, the crusts of one pair laid on each other outscore the die. Clipping leaves nine
    pixels in ten of the detail as they were (those it changes: the crusts and the die's tallest strokes)."""
    rng0 = np.random.default_rng(0)
    field = ndimage.gaussian_filter(rng0.standard_normal((DIE_PX, DIE_PX)), 3)
    die = ndimage.gaussian_filter(np.clip(field / field.std() * 0.2, 0, None), 1)
    right = {0.0: 0, 3.0: 0}
    for seed in range(12):
        rng = np.random.default_rng(500 + seed)
        T_die_a = rigid_2d(rng.uniform(-np.pi, np.pi), rng.normal(0, 1, 2))
        T_die_b = rigid_2d(rng.uniform(-np.pi, np.pi), rng.normal(0, 1, 2))
        grid_a = _with_crusts(strike(die, T_die_a, seed), rng)
        grid_b = _with_crusts(strike(die, T_die_b, 60 + seed), rng)
        for clip_sd in right:
            a = ReliefImage.from_grid(grid_a, PIXEL, clip_sd=clip_sd)
            b = ReliefImage.from_grid(grid_b, PIXEL, clip_sd=clip_sd)
            angle_error, shift_error = pose_errors(align_reliefs(a, b).matrix(), T_die_a, T_die_b)
            right[clip_sd] += angle_error < 1.0 and shift_error < 0.2
        if seed == 0:
            plain = ReliefImage.from_grid(grid_a, PIXEL).detail
            limit = np.abs(a.detail).max()
            assert limit < 0.5 * np.abs(plain).max()
            kept = np.abs(plain) < limit
            np.testing.assert_array_equal(a.detail[kept], plain[kept])
            assert kept[a.mask].mean() > 0.85  # 0.91 here: the crusts and the die's tallest strokes
    assert right[3.0] == 12
    assert right[0.0] < 12
