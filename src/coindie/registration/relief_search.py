"""Planar alignment of two relief images: the rotation and translation that bring one coin's relief onto
another's, found by FFT correlation rather than by local search.

A struck coin is a nearly flat relief. Once two scans are put in their canonical frames (the face's best-fit
surface is z = 0, relief up), the transform between them is, to first order, a rotation about z and a
translation in the plane. That 2-D problem is solved globally in a few FFTs:

1. **Rotation**, by default by exhaustive search: the source is turned by every multiple of a few degrees and
   each turn is correlated with the target at reduced resolution (below, in one batch of FFTs); the best
   few turns go on. The alternative (``search="spectrum"``) is Fourier–Mellin without scale: the
   magnitude of a 2-D Fourier transform does not change when the image is translated and turns with it
   when it is rotated; resampled in polar coordinates, a rotation becomes a circular shift along the
   angle axis, found by one 1-D circular correlation summed over radii (a magnitude spectrum is centrally
   symmetric, so each peak θ leaves θ + 180° open). It costs a third as much but reads the whole
   footprint's spectrum: where two flans overlap on half their surface, or crusts, a double strike or
   holes fill the spectrum, the right angle is often not among its peaks (measured on the all-hard
   synthetic mix, 450 same-die pairs of nine hoards: the planar pose within 5° and 1 mm of the truth for
   63 % by the spectrum, 78 % by the search at 8° steps, its 4 best turns tried again 2.7° to either
   side; 78 % at 6°, 10° or 12°, 77 % at 15°: ``benchmarks/bench_planar_search.py``).
2. **Translation and the choice among angles**: for each candidate angle the source image is rotated and
   correlated with the target by *masked* normalised cross-correlation (Padfield, "Masked object registration
   in the Fourier domain", IEEE TIP 2012), which ignores everything outside each coin's footprint (the flan
   outline and the edge wall differ from coin to coin, the die pattern does not). Peaks are ranked by
   their significance (:func:`significance`: the NCC's Fisher z weighted by the square root of the overlap),
   so that two coins struck far off centre, which share a fifth of their faces, are found at their small
   overlap. The best peak gives the angle, the translation, and its NCC in [-1, 1], itself a measure of
   how alike the two reliefs are.

Written by hand because no maintained library offers it with a score: scikit-image's masked
``phase_cross_correlation`` returns the shift alone, and one score per candidate angle is what decides.
Images here are (rows = y, columns = x) arrays on a common pixel size, with pixel (i, j) at
x = x0 + j * pixel, y = y0 + i * pixel.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import numpy as np
from numpy.typing import NDArray
from scipy import fft, ndimage, sparse, stats

from coindie.caches import LRUCache

FloatImage = NDArray[np.float64]
BoolImage = NDArray[np.bool_]


@dataclass(frozen=True)
class PlanarAlignment:
    """Result of aligning a source relief image onto a target one.

    ``angle_rad`` and ``shift_mm`` define the 2-D rigid map p -> R(angle) p + shift that takes source
    image coordinates (mm, about the source image's origin) to target image coordinates.
    """

    angle_rad: float
    shift_mm: tuple[float, float]
    score: float
    candidates: tuple[tuple[float, float], ...]  # (angle_rad, score) of every angle tried

    def matrix(self) -> NDArray[np.float64]:
        """3x3 homogeneous 2-D transform T_target_source."""
        c, s = np.cos(self.angle_rad), np.sin(self.angle_rad)
        return np.array([[c, -s, self.shift_mm[0]], [s, c, self.shift_mm[1]], [0.0, 0.0, 1.0]])


def high_pass(values: FloatImage, mask: BoolImage, sigma_px: float) -> FloatImage:
    """Relief detail: values minus their mask-normalised Gaussian blur; zero outside the mask."""
    inside = mask.astype(np.float64)
    filled = np.where(mask, values, 0.0)
    weight = ndimage.gaussian_filter(inside, sigma_px)
    low = ndimage.gaussian_filter(filled, sigma_px) / np.maximum(weight, 1e-6)
    return np.where(mask, values - low, 0.0)


def footprint_detail(
    values: FloatImage, pixel_mm: float, high_pass_mm: float, margin_mm: float, clip_sd: float = 0.0
) -> tuple[FloatImage, BoolImage, NDArray[np.int32]]:
    """A centred height grid's (NaN where there is no surface) relief detail, high-passed inside its
    footprint less ``margin_mm`` and clipped at ``clip_sd`` robust standard deviations (0: not clipped,
    :func:`clipped_detail`); that footprint; and each pixel's taxicab distance to the outside (pixels).

    One distance transform gives the footprint less the margin and any core less more (the planar search's
    window) at once; as binary erosions they cost ten times more."""
    footprint = np.isfinite(values)
    margin_px = max(int(round(margin_mm / pixel_mm)), 0)
    inside = ndimage.distance_transform_cdt(np.pad(footprint, 1), metric="taxicab")[1:-1, 1:-1]
    mask = inside > margin_px
    detail = high_pass(np.nan_to_num(values), mask, high_pass_mm / pixel_mm)
    return clipped_detail(detail, mask, clip_sd), mask, inside


def clipped_detail(detail: FloatImage, mask: BoolImage, clip_sd: float) -> FloatImage:
    """``detail`` clipped at ``clip_sd`` robust standard deviations (1.4826 x its median absolute deviation
    inside ``mask``); as it is where ``clip_sd`` is 0 or the detail is flat.

    A correlation is a sum over pixels: one element of large detail (a pellet, a crust, a pit, a cud)
    can outweigh the many small ones a die leaves everywhere, and a wrong pose that lays one such element
    on another can outscore the right one."""
    if clip_sd <= 0 or not mask.any():
        return detail
    limit = clip_sd * float(stats.median_abs_deviation(detail[mask], axis=None, scale="normal"))
    return np.clip(detail, -limit, limit) if limit > 0 else detail


def polar_log_spectrum(image: FloatImage, n_angles: int = 360, r_min_px: int = 3) -> FloatImage:
    """log(1 + |FFT|) of a square image resampled on (radius, angle in [0, pi)), each radius centred.

    The image is zero-padded to a square power of two, so radii are comparable between images of
    different sizes padded to the same ``size``.
    """
    size = image.shape[0]
    spectrum = np.abs(fft.fftshift(fft.fft2(image)))
    radii = np.arange(r_min_px, size // 2 - 1, dtype=np.float64)
    angles = np.linspace(0.0, np.pi, n_angles, endpoint=False)
    rows = size / 2 + radii[:, None] * np.sin(angles)[None, :]
    cols = size / 2 + radii[:, None] * np.cos(angles)[None, :]
    polar = np.log1p(ndimage.map_coordinates(spectrum, [rows, cols], order=1))
    return polar - polar.mean(axis=1, keepdims=True)


def rotation_candidates(
    polar_source: FloatImage, polar_target: FloatImage, n_peaks: int = 2, min_separation_deg: float = 10.0
) -> list[float]:
    """Angles (rad, in [0, pi)) that best turn the source spectrum onto the target one, best first."""
    n_angles = polar_source.shape[1]
    product = fft.rfft(polar_target, axis=1) * np.conj(fft.rfft(polar_source, axis=1))
    correlation = fft.irfft(product.sum(axis=0), n=n_angles)
    separation = max(1, int(round(min_separation_deg / 180.0 * n_angles)))
    peaks: list[float] = []
    for index in np.argsort(correlation)[::-1]:
        if all(min(abs(index - p), n_angles - abs(index - p)) >= separation for p in map(round, peaks)):
            peaks.append(index + _parabolic_offset(correlation, int(index)))
        if len(peaks) == n_peaks:
            break
    return [float(p) * np.pi / n_angles for p in peaks]


@dataclass(frozen=True, eq=False)
class FixedSpectra:
    """The Fourier transforms of the fixed image that masked NCC needs, for moving images of one shape:
    computed once per target face and reused by every source (half of the transforms of a correlation)."""

    shape: tuple[int, int]
    fixed_shape: tuple[int, int]
    moving_shape: tuple[int, int]
    F_f: NDArray[np.complex128]
    F_fm: NDArray[np.complex128]
    F_ff: NDArray[np.complex128]

    @classmethod
    def of(
        cls,
        fixed: FloatImage,
        fixed_mask: BoolImage,
        moving_shape: tuple[int, ...],
        shape: tuple[int, int] | None = None,
    ) -> FixedSpectra:
        """``shape``: the transforms' size, by default the whole linear correlation's (see
        :func:`_window_shape` for a smaller one)."""
        if shape is None:
            full = [
                fft.next_fast_len(a + b - 1, real=True)
                for a, b in zip(fixed.shape, moving_shape, strict=True)
            ]
            shape = (full[0], full[1])
        return cls(
            (shape[0], shape[1]),
            (fixed.shape[0], fixed.shape[1]),
            (moving_shape[0], moving_shape[1]),
            *_masked_transforms(fixed, fixed_mask, shape),
        )


@dataclass(frozen=True, eq=False)
class MovingSpectra:
    """The Fourier transforms of a stack of moving images (axis 0) that masked NCC needs: the other half
    of a correlation's transforms. A source's turns at the sweep's angles are the same against every
    target of a study, so they are kept (:func:`_swept_spectra`) and reused."""

    shape: tuple[int, int]
    moving_shape: tuple[int, int]
    F_m: NDArray[np.complex128]
    F_mm: NDArray[np.complex128]
    F_m_squared: NDArray[np.complex128]

    @classmethod
    def of(cls, moving: FloatImage, moving_mask: BoolImage, shape: tuple[int, int]) -> MovingSpectra:
        """Each image reversed in both axes: the products with the fixed side's transforms are then
        correlations."""
        flipped = _masked_transforms(moving[:, ::-1, ::-1], moving_mask[:, ::-1, ::-1], shape)
        return cls(shape, (moving.shape[1], moving.shape[2]), *flipped)


def _masked_transforms(
    values: FloatImage, mask: BoolImage, shape: tuple[int, int]
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128]]:
    """The float32 transforms at ``shape`` (of the last two axes) of the values inside the mask, of the
    mask and of the squared values inside it: one side's half of a masked correlation."""
    inside = mask.astype(np.float32)
    masked = values.astype(np.float32) * inside
    return fft.rfft2(masked, shape), fft.rfft2(inside, shape), fft.rfft2(masked * masked, shape)


def masked_ncc(
    fixed: FloatImage | FixedSpectra,
    moving: FloatImage,
    fixed_mask: BoolImage | None,
    moving_mask: BoolImage,
    min_overlap: float,
) -> tuple[FloatImage, FloatImage]:
    """Masked normalised cross-correlation for every integer shift (Padfield 2012), and the overlaps.

    Entry [k] of the full correlation (shape fixed + moving - 1) compares fixed[n] with
    moving[n + (moving.shape - 1 - k)]. Shifts whose overlap is below ``min_overlap`` pixels score 0.
    ``fixed`` may be given as its precomputed :class:`FixedSpectra` (``fixed_mask`` is then unused).
    """
    if not isinstance(fixed, FixedSpectra):
        assert fixed_mask is not None
        fixed = FixedSpectra.of(fixed, fixed_mask, moving.shape)
    if fixed.moving_shape != moving.shape:
        raise ValueError(f"moving image {moving.shape} does not match the spectra's {fixed.moving_shape}")
    ncc, overlap = _masked_ncc_batch(fixed, moving[None], moving_mask[None], min_overlap)
    return ncc[0], overlap[0]


def rotate_image(
    image: FloatImage, angle_rad: float, order: int = 1, centre: NDArray[np.float64] | None = None
) -> FloatImage:
    """Rotate an image by ``angle_rad`` (counter-clockwise in x-right, y-up coordinates) about ``centre``
    (row, col; default: the image's centre)."""
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    # output pixel q (row, col) samples input at R^-1 (q - centre) + centre; in (row=y, col=x) order.
    inverse = np.array([[c, -s], [s, c]])  # R^-1 written for (y, x) vectors
    if centre is None:
        centre = (np.asarray(image.shape, dtype=np.float64) - 1.0) / 2.0
    offset = centre - inverse @ centre
    return ndimage.affine_transform(image, inverse, offset=offset, order=order, mode="constant", cval=0.0)


@lru_cache(maxsize=8)
def _turn_operator(
    shape: tuple[int, ...], centre: tuple[float, float], angles: tuple[float, ...]
) -> sparse.csr_array:
    """The bilinear turns of :func:`rotate_image` (``mode="constant"``: zero wherever the sample falls
    outside the image) about ``centre`` by each of ``angles``, as one sparse matrix from a flattened image
    to the flattened turned images, stacked by angle.

    Written by hand because scipy's interpolation takes one image and one transform per call: on the
    sweep's small images (about 60 pixels square) its 90 calls (the detail and its mask at 45 turns)
    took 15 ms, the sparse product of all of them 1.5 ms (building the operator: 12 ms). Built once per
    image size and kept, eight sizes at most (a hoard's crops come in a handful of sizes), 6-9 MB each
    at the default settings."""
    height, width = shape[0], shape[1]
    rows, cols = np.mgrid[0:height, 0:width].astype(np.float64)
    dy, dx = (rows - centre[0]).ravel(), (cols - centre[1]).ravel()
    c, s = np.cos(angles)[:, None], np.sin(angles)[:, None]
    y, x = c * dy - s * dx + centre[0], s * dy + c * dx + centre[1]  # the input sampled (rotate_image)
    inside = (y >= 0) & (y <= height - 1) & (x >= 0) & (x <= width - 1)
    y, x = y[inside], x[inside]
    y0, x0 = np.floor(y), np.floor(x)
    fy, fx = y - y0, x - x0
    r0, c0 = y0.astype(np.intp), x0.astype(np.intp)
    r1, c1 = np.minimum(r0 + 1, height - 1), np.minimum(c0 + 1, width - 1)
    corners = np.stack([r0 * width + c0, r0 * width + c1, r1 * width + c0, r1 * width + c1], axis=1)
    weights = np.stack([(1 - fy) * (1 - fx), (1 - fy) * fx, fy * (1 - fx), fy * fx], axis=1)
    # CSR written directly (four entries a row inside the image, none outside), 32-bit indices
    starts = np.concatenate([[0], np.cumsum(4 * inside.ravel(), dtype=np.int64)]).astype(np.int32)
    return sparse.csr_array(
        (weights.ravel(), corners.ravel().astype(np.int32), starts),
        shape=(len(angles) * height * width, height * width),
    )


def _parabolic_offset(values: NDArray[np.float64], index: int) -> float:
    """Sub-sample offset of a peak from a parabola through it and its two (circular) neighbours."""
    left, centre, right = values[index - 1], values[index], values[(index + 1) % len(values)]
    curvature = left - 2.0 * centre + right
    return 0.0 if curvature >= 0 else float(0.5 * (left - right) / curvature)


@dataclass(frozen=True, eq=False)
class ReliefImage:
    """What one face contributes to planar alignment, computed once per face and cached.

    ``detail`` is the high-passed relief (mm) on a square grid whose centre pixel is the origin of the
    face's canonical frame; ``mask`` its footprint less a margin (no edge wall, no flan outline);
    ``polar`` its polar log-spectrum for the rotation search.
    """

    detail: FloatImage
    mask: BoolImage
    pixel_mm: float
    polar: FloatImage
    _spectra: dict[tuple[int, tuple[int, ...], tuple[int, int]], FixedSpectra] = field(
        default_factory=dict, repr=False
    )
    _cropped: dict[int, tuple[FloatImage, BoolImage, int]] = field(default_factory=dict, repr=False)

    @classmethod
    def from_grid(
        cls,
        values: FloatImage,
        pixel_mm: float,
        *,
        high_pass_mm: float = 0.8,
        margin_mm: float = 0.5,
        clip_sd: float = 0.0,
        n_angles: int = 360,
    ) -> ReliefImage:
        """From a centred square height grid (NaN where there is no surface)."""
        detail, mask, inside = footprint_detail(values, pixel_mm, high_pass_mm, margin_mm, clip_sd)
        margin_px = max(int(round(margin_mm / pixel_mm)), 0)
        window = ndimage.gaussian_filter((inside > 2 * margin_px).astype(np.float64), max(margin_px, 1))
        return cls(detail, mask, pixel_mm, polar_log_spectrum(detail * window, n_angles=n_angles))

    def reduced(self, step: int) -> tuple[FloatImage, BoolImage]:
        """Detail and mask at 1/step resolution (plain subsampling: the detail is already smooth)."""
        return self.detail[::step, ::step], self.mask[::step, ::step]

    def cropped(self, step: int) -> tuple[FloatImage, BoolImage, int]:
        """Detail and mask at 1/step resolution cut to the square about the image's centre that holds
        the footprint at every turn, and the index where the square starts (rows and columns alike).

        The field is wider than a coin so that any face fits; correlating the square alone costs half
        as much, and pixels outside both footprints change no masked correlation. Cached per step: every
        correlation of the face asks for it."""
        if step not in self._cropped:
            self._cropped[step] = self._crop(step)
        return self._cropped[step]

    @cached_property
    def window(self) -> tuple[FloatImage, BoolImage, int]:
        """Detail and mask at full resolution cut to a square about the image's centre that holds the
        footprint at every turn with two pixels to spare, and the index where it starts (rows and columns
        alike). Outside it the detail and the mask are zero at any turn, before and after a bilinear turn
        or shift, so masked correlations on it equal those on the whole image (whose corners are empty
        field) at about half the cost (the pose check: 5.6 -> 3.2 ms a pair)."""
        _, _, start = self.cropped(1)
        start = max(start - 2, 0)
        stop = self.detail.shape[0] - start
        return self.detail[start:stop, start:stop], self.mask[start:stop, start:stop], start

    def turned_window(self, angle_rad: float) -> tuple[FloatImage, FloatImage, int]:
        """The :attr:`window`'s detail and mask (as weights in [0, 1]) turned by ``angle_rad`` about the
        image's centre, as :func:`rotate_image` turns the whole image, and the window's start."""
        detail, mask, start = self.window
        centre = (np.asarray(self.detail.shape, dtype=np.float64) - 1.0) / 2.0 - start
        turned = rotate_image(detail, angle_rad, centre=centre)
        return turned, rotate_image(mask.astype(np.float64), angle_rad, centre=centre), start

    def _crop(self, step: int) -> tuple[FloatImage, BoolImage, int]:
        detail, mask = self.reduced(step)
        size = detail.shape[0]
        centre = (self.detail.shape[0] - 1.0) / 2.0 / step
        rows, cols = np.nonzero(mask)
        if len(rows) == 0:
            return detail, mask, 0
        reach = float(np.sqrt(((rows - centre) ** 2 + (cols - centre) ** 2).max()))
        start = max(int(np.floor(centre - reach)) - 1, 0)
        stop = min(int(np.ceil(centre + reach)) + 2, size)
        start = min(start, size - stop)  # the same margin on both sides keeps the centre where it was
        stop = size - start
        return detail[start:stop, start:stop], mask[start:stop, start:stop], start


def align_reliefs(
    source: ReliefImage,
    target: ReliefImage,
    *,
    n_angle_peaks: int = 4,
    coarse_step: int = 2,
    min_overlap: float = 0.15,
    search: str = "exhaustive",
    angle_step_deg: float = 8.0,
    sweep_step: int | None = None,
) -> PlanarAlignment:
    """Rotation + translation taking the source relief onto the target (see the module docstring).

    Turns and translations are ranked by the :func:`significance` of their correlation, among those whose
    footprints overlap on at least ``min_overlap`` of the smaller one; the returned ``score`` is the NCC of
    the chosen pose.

    ``search="exhaustive"``: every turn by ``angle_step_deg`` is scored at 1/``sweep_step`` resolution
    (default: ``coarse_step``), and the ``n_angle_peaks`` best, and a third of a step to either side of
    each, at 1/``coarse_step``. ``"spectrum"``: the ``n_angle_peaks`` peaks of the spectra's
    correlation, each with its 180° twin, are scored. The best angle is then correlated at full
    resolution for its translation and final score.
    """
    if source.detail.shape != target.detail.shape or source.pixel_mm != target.pixel_mm:
        raise ValueError("relief images must share their grid (shape and pixel size)")
    if search == "exhaustive":
        sweep = coarse_step if sweep_step is None else sweep_step
        tried = _search_turns(source, target, angle_step_deg, n_angle_peaks, coarse_step, min_overlap, sweep)
    elif search == "spectrum":
        angles = rotation_candidates(source.polar, target.polar, n_peaks=n_angle_peaks)
        candidates = [a + half for a in angles for half in (0.0, np.pi)]
        tried = [(a, *_correlate(source, target, a, coarse_step, min_overlap)) for a in candidates]
    else:
        raise ValueError(f"search must be 'exhaustive' or 'spectrum', not {search!r}")
    angle, _, coarse_shift = max(tried, key=lambda t: t[1])
    score, shift = _refine_shift(source, target, angle, coarse_shift, max(coarse_step, 1))
    return PlanarAlignment(
        angle_rad=float(np.arctan2(np.sin(angle), np.cos(angle))),
        shift_mm=shift,
        score=score,
        candidates=tuple((a, s) for a, s, _ in tried),
    )


def pose_score(
    source: ReliefImage, target: ReliefImage, angle_rad: float, shift_mm: tuple[float, float]
) -> float:
    """Masked NCC of the source relief moved by (``angle_rad``, ``shift_mm``) against the target, over
    both footprints: the score :func:`align_reliefs` maximises, at any pose (sub-pixel shifts by linear
    interpolation). -1 without overlap. A dimensionless judge of a refined pose."""
    offset = np.array([shift_mm[1], shift_mm[0]]) / source.pixel_mm  # (rows, cols)
    turned, turned_mask, source_start = source.turned_window(angle_rad)
    fixed, fixed_mask, target_start = target.window
    # the turned source, moved by the offset, read on the target's window: (rows, cols) q of the window
    # sample the turned window at q - offset + (target_start - source_start)
    behind = np.full(2, float(source_start - target_start)) + offset
    moving = _moved(turned, behind, fixed.shape)
    moving_mask = _moved(turned_mask, behind, fixed.shape) > 0.5
    both = moving_mask & fixed_mask
    if int(both.sum()) < 3:
        return -1.0
    f, m = fixed[both], moving[both]
    f, m = f - f.mean(), m - m.mean()
    denominator = float(np.sqrt((f @ f) * (m @ m)))
    return float(f @ m) / denominator if denominator > 0 else -1.0


def _correlate(
    source: ReliefImage, target: ReliefImage, angle: float, step: int, min_overlap: float
) -> tuple[float, tuple[float, float]]:
    """Masked NCC of the source turned by ``angle`` against the target at 1/step resolution: the peak
    score and the translation (mm)."""
    scores, shifts = correlate_turns(source, target, np.array([angle]), step, min_overlap)
    return float(scores[0]), (float(shifts[0, 0]), float(shifts[0, 1]))


def _search_turns(
    source: ReliefImage,
    target: ReliefImage,
    step_deg: float,
    n_best: int,
    step: int,
    min_overlap: float,
    sweep_step: int,
) -> list[tuple[float, float, tuple[float, float]]]:
    """(angle, score, shift) of the turns tried by the exhaustive search: every ``step_deg`` at
    1/``sweep_step`` resolution, then the ``n_best`` best, and a third of a step to either side of each,
    at 1/``step`` (the turns of a coarser sweep are scored again: significances at two resolutions do
    not compare).

    The sweep is most of the search's cost; the choice among its best turns is where resolution tells.
    Of 550 same-die pairs of eleven hoards (four all-hard, six single-axis extremes, riedones), a sweep at
    1/3 and its best turns at 1/2 put 491 in the ICP's reach, against 492 with everything at 1/2
    (bench_planar_search.py), for a third less time; but the die study of the all-hard hoards moved with
    the 77 of 1,560 poses that changed (seed 4500: FMI 0.946 -> 0.900, a die merged; 6500: 0.909 ->
    0.895), so relief keeps the sweep at 1/2 (BENCHMARK.md)."""
    n_turns = max(int(round(360.0 / step_deg)), 1)
    turns = np.arange(n_turns) * (2.0 * np.pi / n_turns)
    scores, shifts = correlate_turns(source, target, turns, sweep_step, min_overlap, reuse_turns=True)
    best = np.argsort(scores)[::-1][:n_best]
    third = np.pi / n_turns / 1.5
    nearby = np.concatenate([turns[best] - third, turns[best] + third])
    angles = np.concatenate([turns[best], nearby])
    if sweep_step == step:  # the best turns' scores at this resolution are the sweep's
        near_scores, near_shifts = correlate_turns(source, target, nearby, step, min_overlap)
        all_scores = np.concatenate([scores[best], near_scores])
        all_shifts = np.concatenate([shifts[best], near_shifts])
    else:
        all_scores, all_shifts = correlate_turns(source, target, angles, step, min_overlap)
    tried = [
        (float(a), float(s), (float(d[0]), float(d[1])))
        for a, s, d in zip(angles, all_scores, all_shifts, strict=True)
    ]
    # The best angle to below the step, by halving: try half the last step to either side, keep the best.
    best_angle = max(tried, key=lambda entry: entry[1])[0]
    delta = third / 2.0
    while delta > np.radians(0.2):
        either_side = np.array([best_angle - delta, best_angle + delta])
        side_scores, side_shifts = correlate_turns(source, target, either_side, step, min_overlap)
        for candidate, score, shift in zip(either_side, side_scores, side_shifts, strict=True):
            tried.append((float(candidate), float(score), (float(shift[0]), float(shift[1]))))
        best_angle = max(tried, key=lambda entry: entry[1])[0]
        delta /= 2.0
    return tried


def correlate_turns(
    source: ReliefImage,
    target: ReliefImage,
    angles: NDArray[np.float64],
    step: int,
    min_overlap: float,
    batch: int = 32,
    *,
    reuse_turns: bool = False,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Peak masked NCC and its (x, y) translation (mm) of the source turned by each angle against the
    target, at 1/``step`` resolution: :func:`_correlate` for many angles, the FFTs of a batch of turned
    images taken in one call (the Python per angle is what a loop of single correlations spends most on).

    ``reuse_turns``: the same ``angles`` come back for every face of a study (the exhaustive sweep), so
    the images are turned by a sparse operator kept per image size (:func:`_turn_operator`) instead of
    one interpolation per angle; the same bilinear values."""
    detail, mask, source_start = source.cropped(step)
    fixed_detail, fixed_mask, target_start = target.cropped(step)
    min_pixels = min_overlap * min(fixed_mask.sum(), mask.sum())
    shape = _window_shape(fixed_detail.shape, detail.shape, source_start - target_start, min_pixels)
    fixed = _cropped_spectra(target, step, detail.shape, shape)
    # Rotating the reduced image about the full image's centre (in reduced pixels) is the reduced
    # rotated image, at 1/step^2 of the cost.
    centre = (np.asarray(source.detail.shape, dtype=np.float64) - 1.0) / 2.0 / step - source_start
    # A crop that starts later moves the correlation's origin: back to the full images' shifts.
    origin = float(source_start - target_start)
    full = max(float(min(fixed_mask.sum(), mask.sum())), 1.0)
    scores = np.empty(len(angles))
    shifts = np.empty((len(angles), 2))
    if reuse_turns:
        spectra = _swept_spectra(
            source, step, (detail, mask, centre), tuple(map(float, angles)), shape, batch
        )
    for first in range(0, len(angles), batch):
        chunk = angles[first : first + batch]
        if reuse_turns:
            moving = spectra[first // batch]
        else:
            turned = np.stack([rotate_image(detail, a, centre=centre) for a in chunk])
            turned_masks = [rotate_image(mask.astype(np.float64), a, centre=centre) for a in chunk]
            moving = MovingSpectra.of(turned, np.stack(turned_masks) > 0.5, shape)
        ncc, overlap = _masked_ncc_spectra(fixed, moving, min_pixels)
        best, peaks = _significant_peaks(ncc, overlap, full)
        scores[first : first + len(chunk)] = best
        # target(q) ~ turned_source(q + d), d = moving.shape - 1 - peak: the translation is -d, in (x, y)
        d = np.asarray(moving.moving_shape, dtype=np.float64) - 1.0 - peaks
        shifts[first : first + len(chunk)] = (-d[:, ::-1] - origin) * source.pixel_mm * step
    return scores, shifts


#: The sweep's turned transforms of the last few sources (with each source, so that its id stays its own):
#: an all-pairs study registers each source against every target in turn (the project's batches run a
#: source's pairs one after another), and the turned source's transforms are a third of a correlation's.
#: Each entry holds 45 turns x 3 transforms, about 6 MB at the defaults; a source meets two or three
#: transform sizes (they depend on the target's crop).
_SWEPT: LRUCache[tuple[object, ...], tuple[ReliefImage, list[MovingSpectra]]] = LRUCache(6)


def _swept_spectra(
    source: ReliefImage,
    step: int,
    cropped: tuple[FloatImage, BoolImage, NDArray[np.float64]],
    angles: tuple[float, ...],
    shape: tuple[int, int],
    batch: int,
) -> list[MovingSpectra]:
    """The transforms of ``source``'s cropped square at 1/``step`` (``cropped``: its detail, its mask and
    the image's centre in it) turned by each of ``angles`` (by the sparse :func:`_turn_operator`), in
    batches of ``batch`` turns, at transform size ``shape``; kept in :data:`_SWEPT`."""
    detail, mask, centre = cropped

    def compute() -> tuple[ReliefImage, list[MovingSpectra]]:
        operator = _turn_operator(detail.shape, (float(centre[0]), float(centre[1])), angles)
        both = operator @ np.stack([detail.ravel(), mask.ravel().astype(np.float64)], axis=1)
        turned = both.reshape(len(angles), *detail.shape, 2)
        moving, masks = turned[..., 0], turned[..., 1] > 0.5
        return source, [
            MovingSpectra.of(moving[first : first + batch], masks[first : first + batch], shape)
            for first in range(0, len(angles), batch)
        ]

    return _SWEPT.get((id(source), step, angles, shape, batch), compute)[1]


def _significant_peaks(
    ncc: FloatImage, overlap: FloatImage, full: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """For a stack of correlations (axis 0) and their overlaps (pixels): the largest :func:`significance`
    of each (overlap shares of ``full`` pixels) and where it lies, (row, col) to below a pixel from a
    parabola through its neighbours; what :func:`_evidence_near_peak` and :func:`_peak_shift` give, one
    image at a time, taken for the whole stack in a few array operations (one image at a time cost
    about 10 ms a pair, mostly Python)."""
    count, height, width = ncc.shape
    flat, overlap_flat = ncc.reshape(count, -1), overlap.reshape(count, -1)
    images = np.arange(count)
    first = flat.argmax(axis=1)
    bound = significance(flat[images, first], overlap_flat[images, first] / full).astype(np.float64)
    weighed = flat >= np.tanh(np.maximum(bound, 0.0))[:, None]
    weighed[images, first] = True
    image, index = np.nonzero(weighed)
    values = significance(flat[image, index], overlap_flat[image, index] / full)
    # the first largest of each image's values (np.nonzero lists them by image, then by index)
    best = np.maximum.reduceat(values, np.searchsorted(image, images))
    at_best = np.flatnonzero(values == best[image])
    peak = index[at_best[np.unique(image[at_best], return_index=True)[1]]]
    row, col = np.divmod(peak, width)
    # the 3 x 3 neighbourhood of each peak, weighed exactly (-inf beyond the image)
    rows, cols = row[:, None, None] + np.arange(-1, 2)[:, None], col[:, None, None] + np.arange(-1, 2)
    inside = (rows >= 0) & (rows < height) & (cols >= 0) & (cols < width)
    rows, cols = np.clip(rows, 0, height - 1), np.clip(cols, 0, width - 1)
    stack = images[:, None, None]
    near = significance(ncc[stack, rows, cols], overlap[stack, rows, cols] / full)
    near = np.where(inside, near.astype(np.float64), -np.inf)
    peaks = np.stack([row, col], axis=1).astype(np.float64)
    for i in range(count):
        if np.count_nonzero(near[i] >= near[i, 1, 1]) > 1:
            # a neighbour weighs as much as the peak (an exact tie, or one outside the candidates where
            # every correlation is negative): the single-image path settles it as it always did
            evidence = _evidence_near_peak(ncc[i], overlap[i] / full)
            shape = np.asarray(ncc.shape[1:], dtype=np.float64)
            peaks[i] = shape - 1.0 + _peak_shift(evidence, ncc.shape[1:])[::-1]
            best[i] = evidence.max()
            continue
        peaks[i, 0] += _parabola(near[i, 0, 1], near[i, 1, 1], near[i, 2, 1], row[i], height)
        peaks[i, 1] += _parabola(near[i, 1, 0], near[i, 1, 1], near[i, 1, 2], col[i], width)
    return best.astype(np.float64), peaks


def _parabola(left: float, centre: float, right: float, index: int, size: int) -> float:
    """Sub-pixel offset of a peak at ``index`` of an axis of ``size`` from a parabola through it and its
    neighbours (:func:`_parabolic_offset_2d` on three values)."""
    if index == 0 or index == size - 1 or not np.isfinite(left) or not np.isfinite(right):
        return 0.0
    curvature = left - 2.0 * centre + right
    return 0.0 if curvature >= 0 else float(0.5 * (left - right) / curvature)


def _evidence_near_peak(ncc: FloatImage, overlap_share: FloatImage) -> FloatImage:
    """:func:`significance` where it can be the largest, and around that peak; -inf elsewhere.

    Written for speed: the significance of every shift of every turn cost as much as the correlations.
    A shift can beat the best correlation's significance only if its own Fisher z alone beats it (the
    overlap share is at most 1), so only shifts whose NCC exceeds tanh of that bound are weighed; the
    peak and its 3 x 3 neighbourhood (for the sub-pixel parabola) are then exact."""
    first = int(np.argmax(ncc))
    bound = float(significance(ncc.flat[first], overlap_share.flat[first]))
    candidates = np.union1d(np.flatnonzero(ncc.ravel() >= np.tanh(max(bound, 0.0))), [first])
    weighed = significance(ncc.ravel()[candidates], overlap_share.ravel()[candidates])
    peak = np.unravel_index(int(candidates[int(np.argmax(weighed))]), ncc.shape)
    evidence = np.full(ncc.shape, -np.inf)
    evidence.flat[candidates] = weighed
    rows = slice(max(peak[0] - 1, 0), peak[0] + 2)
    cols = slice(max(peak[1] - 1, 0), peak[1] + 2)
    evidence[rows, cols] = significance(ncc[rows, cols], overlap_share[rows, cols])
    return evidence


def significance(ncc: FloatImage, overlap_share: FloatImage) -> FloatImage:
    """How far a correlation is from chance given the area it was measured on: Fisher's z of the NCC
    times the square root of the overlap (a share of the smaller footprint). Its sampling spread is about
    1 / sqrt(pixels), so a high correlation over a small overlap (a strike a third of the diameter off
    centre on both coins leaves a fifth of the face in common) and a moderate one over the whole face
    (two dies of one design) are weighed alike; the NCC alone lets small overlaps win by chance, an
    overlap floor refuses the off-centre pairs."""
    z = np.arctanh(np.clip(ncc, -0.999, 0.999))
    # a turned mask can hold a pixel more than the smaller footprint: a share is at most 1
    return z * np.sqrt(np.clip(overlap_share, 0.0, 1.0))


def _cropped_spectra(
    image: ReliefImage, step: int, moving_shape: tuple[int, ...], shape: tuple[int, int]
) -> FixedSpectra:
    """The fixed-side spectra of ``image``'s cropped square for moving images of ``moving_shape``,
    transformed at ``shape`` (cached with the image's other spectra)."""
    key = (step, tuple(moving_shape), shape)
    if key not in image._spectra:
        detail, mask, _ = image.cropped(step)
        image._spectra[key] = FixedSpectra.of(detail, mask, moving_shape, shape)
    return image._spectra[key]


def _window_shape(
    fixed_shape: tuple[int, ...], moving_shape: tuple[int, ...], origin: int, min_pixels: float
) -> tuple[int, int]:
    """The size of the transforms that give a masked correlation exactly at every shift where the two
    footprints can overlap on ``min_pixels``, and nowhere else needed.

    Both crops are squares about their images' centres (the canonical origins), each holding its
    footprint at every turn, so no two footprints overlap more than two discs of the squares' half-sides
    (and a pixel): beyond the shift where those discs' lens falls below ``min_pixels``, every shift
    scores 0 whatever the images. A transform of length N < L (the linear correlation's) wraps the
    correlation's first L - N entries onto its last; those outside the needed shifts are left wrapped
    and marked invalid. About a fifth less work than the whole linear correlation at the default
    min_overlap. ``origin``: the source crop's start less the target's (the zero shift's offset)."""
    radius_fixed, radius_moving = fixed_shape[0] / 2.0 + 1.0, moving_shape[0] / 2.0 + 1.0
    distances = np.arange(int(np.ceil(radius_fixed + radius_moving)) + 2, dtype=np.float64)
    outside = np.flatnonzero(_lens_area(radius_fixed, radius_moving, distances) < min_pixels)
    reach = int(distances[outside[0]]) if len(outside) else len(distances)
    shape = []
    for fixed_size, moving_size in zip(fixed_shape, moving_shape, strict=True):
        linear = fixed_size + moving_size - 1
        zero = moving_size - 1 + origin  # the index of the zero shift
        needed = max(linear - zero + reach, zero + reach + 1, fixed_size, moving_size)
        shape.append(fft.next_fast_len(min(needed, linear), real=True))
    return shape[0], shape[1]


def _lens_area(radius_a: float, radius_b: float, distance: NDArray[np.float64]) -> NDArray[np.float64]:
    """Area shared by two discs of these radii whose centres are ``distance`` apart."""
    d = np.maximum(distance, 1e-12)
    cos_a = np.clip((d**2 + radius_a**2 - radius_b**2) / (2 * d * radius_a), -1.0, 1.0)
    cos_b = np.clip((d**2 + radius_b**2 - radius_a**2) / (2 * d * radius_b), -1.0, 1.0)
    kite = (-d + radius_a + radius_b) * (d + radius_a - radius_b) * (d - radius_a + radius_b)
    kite = np.sqrt(np.maximum(kite * (d + radius_a + radius_b), 0.0))
    lens = radius_a**2 * np.arccos(cos_a) + radius_b**2 * np.arccos(cos_b) - 0.5 * kite
    inside = d <= abs(radius_a - radius_b)
    return np.where(
        d >= radius_a + radius_b, 0.0, np.where(inside, np.pi * min(radius_a, radius_b) ** 2, lens)
    )


def _masked_ncc_batch(
    fixed: FixedSpectra, moving: FloatImage, moving_mask: BoolImage, min_overlap: float
) -> tuple[FloatImage, FloatImage]:
    """:func:`masked_ncc` for a stack of moving images (axis 0) against one fixed image, the FFTs of the
    whole stack taken in one call each."""
    return _masked_ncc_spectra(fixed, MovingSpectra.of(moving, moving_mask, fixed.shape), min_overlap)


def _masked_ncc_spectra(
    fixed: FixedSpectra, moving: MovingSpectra, min_overlap: float
) -> tuple[FloatImage, FloatImage]:
    """:func:`_masked_ncc_batch` from both sides' transforms."""
    shape = fixed.shape
    if moving.shape != shape:
        raise ValueError(f"moving spectra of transforms {moving.shape} do not match the fixed ones' {shape}")
    linear = (
        fixed.fixed_shape[0] + moving.moving_shape[0] - 1,
        fixed.fixed_shape[1] + moving.moving_shape[1] - 1,
    )
    out = (min(linear[0], shape[0]), min(linear[1], shape[1]))
    # entries below these hold wrapped sums when the transforms are shorter than the correlation
    wrapped = (linear[0] - out[0], linear[1] - out[1])

    def backward(a: NDArray[np.complex128]) -> FloatImage:
        return fft.irfft2(a, shape, axes=(-2, -1))

    # The moments over the whole transforms (contiguous, in place where an array is not needed again:
    # a third less time than on the cut views), cut to the linear correlation's shifts at the end.
    overlap = backward(fixed.F_fm * moving.F_mm)
    np.maximum(np.rint(overlap, out=overlap), 1.0, out=overlap)
    sum_f, sum_m = backward(fixed.F_f * moving.F_mm), backward(fixed.F_fm * moving.F_m)
    numerator = backward(fixed.F_f * moving.F_m)
    numerator -= sum_f * sum_m / overlap
    var_f = backward(fixed.F_ff * moving.F_mm)
    var_f -= np.divide(np.square(sum_f, out=sum_f), overlap, out=sum_f)
    var_m = backward(fixed.F_fm * moving.F_m_squared)
    var_m -= np.divide(np.square(sum_m, out=sum_m), overlap, out=sum_m)
    var_f *= var_m
    denominator = np.sqrt(np.maximum(var_f, 0.0, out=var_f), out=var_f)[:, : out[0], : out[1]]
    numerator, overlap = numerator[:, : out[0], : out[1]], overlap[:, : out[0], : out[1]]
    top = denominator[:, wrapped[0] :, wrapped[1] :].max(axis=(1, 2), keepdims=True)
    valid = denominator > 1e-9 * np.maximum(top, 1e-300)
    valid &= overlap >= min_overlap
    valid[:, : wrapped[0]] = False
    valid[:, :, : wrapped[1]] = False
    ncc = np.divide(numerator, denominator, out=np.zeros(numerator.shape, numerator.dtype), where=valid)
    return np.clip(ncc, -1.0, 1.0, out=ncc), overlap


def _refine_shift(
    source: ReliefImage, target: ReliefImage, angle: float, shift_mm: tuple[float, float], radius_px: int
) -> tuple[float, tuple[float, float]]:
    """Masked NCC at full resolution for the integer shifts within ``radius_px`` of ``shift_mm`` (the
    coarse estimate), and the sub-pixel peak: a few direct sums instead of full-size FFTs."""
    moving, turned_mask, source_start = source.turned_window(angle)
    moving_mask = turned_mask > 0.5
    fixed, fixed_mask, target_start = target.window
    centre = np.rint(np.asarray(shift_mm) / source.pixel_mm).astype(int)  # (x, y) pixels
    behind = source_start - target_start  # the windows' shifts are the whole images' less this
    offsets = range(-radius_px, radius_px + 1)
    scores = np.full((len(offsets), len(offsets)), -1.0)
    for a, dy in enumerate(offsets):
        for b, dx in enumerate(offsets):
            rows, cols = centre[1] + dy + behind, centre[0] + dx + behind
            scores[a, b] = _ncc_at(fixed, fixed_mask, moving, moving_mask, rows, cols)
    k = np.unravel_index(int(np.argmax(scores)), scores.shape)
    sub = [_parabolic_offset_2d(scores, k, axis) for axis in (0, 1)]
    rows = centre[1] + offsets[k[0]] + sub[0]
    cols = centre[0] + offsets[k[1]] + sub[1]
    return float(scores[k]), (float(cols * source.pixel_mm), float(rows * source.pixel_mm))


def _moved(image: FloatImage, offset: NDArray[np.float64], shape: tuple[int, ...]) -> FloatImage:
    """``image`` moved by ``offset`` (rows, cols; bilinear, zero beyond its edges) on a grid of ``shape``
    (as :func:`scipy.ndimage.shift` does where the two grids are one)."""
    return ndimage.affine_transform(
        image, np.ones(2), offset=-offset, output_shape=tuple(shape), order=1, mode="constant", cval=0.0
    )


def _ncc_at(
    fixed: FloatImage, fixed_mask: BoolImage, moving: FloatImage, moving_mask: BoolImage, rows: int, cols: int
) -> float:
    """Masked NCC of fixed[i, j] against moving[i - rows, j - cols] over both footprints (the two images
    may differ in size)."""
    (height, width), (moving_height, moving_width) = fixed.shape, moving.shape
    f_rows = slice(max(0, rows), min(height, moving_height + rows))
    f_cols = slice(max(0, cols), min(width, moving_width + cols))
    m_rows = slice(f_rows.start - rows, f_rows.stop - rows)
    m_cols = slice(f_cols.start - cols, f_cols.stop - cols)
    if f_rows.stop <= f_rows.start or f_cols.stop <= f_cols.start:
        return -1.0
    both = fixed_mask[f_rows, f_cols] & moving_mask[m_rows, m_cols]
    n = int(both.sum())
    if n < 3:
        return -1.0
    f, m = fixed[f_rows, f_cols][both], moving[m_rows, m_cols][both]
    f, m = f - f.mean(), m - m.mean()
    denominator = float(np.sqrt((f @ f) * (m @ m)))
    return float(f @ m) / denominator if denominator > 0 else -1.0


def _peak_shift(ncc: FloatImage, moving_shape: tuple[int, ...]) -> NDArray[np.float64]:
    """(x, y) translation, in pixels, of the rotated source onto the target at the correlation peak."""
    k = np.unravel_index(int(np.argmax(ncc)), ncc.shape)
    sub = np.array([_parabolic_offset_2d(ncc, k, axis) for axis in (0, 1)])
    d = np.asarray(moving_shape, dtype=np.float64) - 1.0 - (np.asarray(k, dtype=np.float64) + sub)
    # target(q) ~ rotated_source(q + d)  =>  translation = -d ; returned in (x, y) order
    return -d[::-1]


def _parabolic_offset_2d(values: FloatImage, index: tuple[int, ...], axis: int) -> float:
    i = list(index)
    if i[axis] == 0 or i[axis] == values.shape[axis] - 1:
        return 0.0
    lo, hi = list(i), list(i)
    lo[axis] -= 1
    hi[axis] += 1
    left, centre, right = values[tuple(lo)], values[tuple(i)], values[tuple(hi)]
    if not np.isfinite(left) or not np.isfinite(right):  # a neighbour left unweighed: no sub-pixel part
        return 0.0
    curvature = left - 2.0 * centre + right
    return 0.0 if curvature >= 0 else float(0.5 * (left - right) / curvature)
