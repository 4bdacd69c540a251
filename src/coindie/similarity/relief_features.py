"""Scale-free same-die features of a registered pair: how alike the two reliefs are, not how close in mm.

The paper's histogram measures cloud-to-cloud distances in millimetres, so its meaning moves with the
scanner (noise, spacing, smoothing) and with the flans (cupping, bends): a classifier fitted on one
scanner's histograms reads another scanner's same-die pairs as different dies. These features carry no
absolute scale of one scanner:

1. both faces are put in the target's canonical frame (its best-fit plane is z = 0) with the registration's
   ``T_target_source``, and rasterised on one square grid (``pixel_mm``) centred on the target's origin;
2. the low-frequency shape difference of the two aligned faces (cupping, doming, a bend, a tilt left by the
   registration) is removed: the difference of the two height maps, blurred by ``shape_sigma_mm``, is taken
   off the source;
3. both reliefs are split into bands by differences of mask-normalised Gaussian blurs — *fine* (detail
   below ``fine_sigma_mm``) and *coarse* (``fine_sigma_mm`` to ``coarse_sigma_mm``) — over the part both
   faces cover, a ``margin_mm`` band inside the outlines left out (edge wall, flan border); each band's
   values beyond ``clip_sd`` robust standard deviations are clipped, so that no single strong element
   (a pellet, a crust, a pit) carries the correlation;
4. the features are normalised cross-correlations (dimensionless, in [-1, 1]): over the whole overlap per
   band, and *local* ones in Gaussian windows of ``window_mm`` whose median and 90th percentile say how much
   of the face agrees (a weak strike, a crust or a worn half lowers the global figure, not the share that
   still matches); plus the overlap itself (a share of the smaller footprint). The coarse band's
   correlation is measured and stored, but the shipped model leaves it out
   (:data:`coindie.similarity.relief_classifier.USED_FEATURES`): dies of one type share it.

Correlations are invariant to the relief's height scale and to a height offset, and noise only lowers them
by the ratio of noise to detail, which the per-hoard calibration (:mod:`coindie.similarity.calibration`)
then reads off the hoard's own score distribution.

Written by hand: no maintained library computes masked band-pass correlations between two rasterised
point clouds; the blurs are scipy's.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import asdict, dataclass, replace
from threading import Lock
from typing import Any, ClassVar

import numpy as np
from scipy import fft, ndimage

from coindie.arrays import BoolArray, FloatArray
from coindie.errors import ParameterError
from coindie.params import Configurable, Rule, param
from coindie.preprocess.canonical import CanonicalFrame, canonical_frame
from coindie.preprocess.heightmap import HeightMap, height_map
from coindie.registration.relief_search import clipped_detail
from coindie.scan import Scan

#: The features, in the order of :func:`relief_features`' vector.
FEATURE_NAMES = ("ncc_fine", "ncc_coarse", "local_median", "local_p90", "overlap")
#: Targets' canonical frames and height maps kept ready (a 32 mm field at 0.1 mm is 320 x 320 pixels).
TARGET_CACHE_SIZE = 64
#: Points of a face used to fit its canonical frame (a regular subsample of larger clouds).
_FRAME_POINTS = 6000
#: Sources are rasterised from at most this many points (a regular subsample): a few per pixel suffice.
_MAX_SOURCE_POINTS = 40_000
#: Pixels whose local window sees less than this share of overlap are left out of the local statistics.
_MIN_WINDOW_WEIGHT = 0.5
#: Blurs at least this wide (pixels) are taken by FFT (:func:`_gaussian`).
_FFT_SIGMA_PX = 6.0
_EPS = 1e-12


@dataclass(frozen=True)
class ReliefFeatureSettings(Configurable):
    """How a registered pair becomes :data:`FEATURE_NAMES`. Lengths are in mm on the coin, not on the
    scanner: they describe the size of a die's details (strokes, pellets), which no scanner changes. The
    fine band (0.3 mm on 0.1 mm pixels) is the scale at which two dies of one type differ: the engraver's
    placing of each element, about 0.1 mm (docs/clustering.md, "Two scorers")."""

    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(
            ("pixel_mm", "fine_sigma_mm", "coarse_sigma_mm"),
            lambda s: s.pixel_mm < s.fine_sigma_mm < s.coarse_sigma_mm,
            "pixel_mm < fine_sigma_mm < coarse_sigma_mm",
        ),
        Rule(("field_mm", "pixel_mm"), lambda s: s.field_mm >= 10 * s.pixel_mm, "field_mm >= 10 pixel_mm"),
    )

    #: The lengths set by the size of a die's details, as the registration's parts declare theirs
    #: (:meth:`coindie.registration.MethodInfo.for_coins`): here every length.
    DESIGN_LENGTHS: ClassVar[tuple[str, ...]] = (
        "pixel_mm", "field_mm", "shape_sigma_mm", "fine_sigma_mm", "coarse_sigma_mm", "window_mm",
        "margin_mm",
    )  # fmt: skip

    pixel_mm: float = param(
        0.1, doc="pixel of the square grid both faces are rasterised on", unit="mm", low=0.0, low_open=True
    )
    field_mm: float = param(32.0, doc="side of that grid, centred on the target's origin", unit="mm", low=0.0)
    shape_sigma_mm: float = param(
        3.0, doc="blur of the shape difference taken off the source", unit="mm", low=0.0, low_open=True
    )
    # 0.2 mm told dies apart better at the true pose of the all-hard hoards of the two generators coindie
    # did not write (local median AUC 0.928 -> 0.976 on blind hard-33's obverses, 0.953 -> 0.996 on
    # outsider hard-33's), and as well on coarse scanners, and a model trained with it separated those
    # hoards' registered pairs better (pair AUC 0.845 -> 0.888, 0.874 -> 0.898 on the obverses); but
    # their die studies came out lower (FMI 0.800 -> 0.764, 0.961 -> 0.943), so 0.3 stays
    # (BENCHMARK.md, "One element cannot carry a correlation").
    fine_sigma_mm: float = param(0.3, doc="the fine band: detail below it", unit="mm", low=0.0)
    coarse_sigma_mm: float = param(1.0, doc="the coarse band: fine_sigma_mm to it", unit="mm", low=0.0)
    window_mm: float = param(
        1.5, doc="Gaussian window of the local correlations", unit="mm", low=0.0, low_open=True
    )
    margin_mm: float = param(
        0.6, doc="band inside the outlines left out (edge wall, flan border)", unit="mm", low=0.0
    )
    # A correlation is a sum over pixels, so one element of large relief detail (a pellet, a letter's
    # serif, a crust, a pit) can carry it alone. Two different dies registered at a wrong pose where
    # their flans share a lens of a quarter of their area scored ncc_fine 0.5-0.87 that way: one pellet
    # of each on top of the other and field around (the blind generator's flat-31 and ordinary-32,
    # BENCHMARK.md, "One element cannot carry a correlation"). Clipped at 3 robust standard deviations,
    # each band keeps the many small details a die leaves everywhere and loses the lone element's weight.
    clip_sd: float = param(
        3.0,
        doc="each band's values beyond this many robust standard deviations (1.4826 x the median absolute "
        "deviation over the overlap) are clipped before correlating; 0: no clipping",
        low=0.0,
    )

    @property
    def size_px(self) -> int:
        return int(round(self.field_mm / self.pixel_mm))

    def for_coins(self, scale: float) -> ReliefFeatureSettings:
        """These settings for coins ``scale`` times as large as those they were set for
        (:func:`coindie.preprocess.coin_size.coin_scale`): every length scaled, so that a pair and its copy
        ``scale`` times as large in every direction give the same features."""
        if scale == 1.0:
            return self
        if not (np.isfinite(scale) and scale > 0):
            raise ParameterError(f"A coin scale must be a positive number. Got {scale}.")
        return replace(self, **{name: getattr(self, name) * scale for name in self.DESIGN_LENGTHS})

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> ReliefFeatureSettings:
        """Settings as :meth:`to_dict` wrote them. A dict without ``clip_sd`` was written before the bands
        were clipped, and describes features computed without clipping (``clip_sd`` 0)."""
        values = {"clip_sd": 0.0} | {k: float(v) for k, v in data.items()}
        return cls(**values)


@dataclass(frozen=True, eq=False)
class _Target:
    frame: CanonicalFrame
    heights: FloatArray  # (size, size) heights above the target's plane; NaN outside
    mask: BoolArray
    inner: BoolArray  # the mask less the margin band inside its outline


def relief_features(
    source: Scan, target: Scan, T_target_source: FloatArray, settings: ReliefFeatureSettings | None = None
) -> FloatArray:
    """The :data:`FEATURE_NAMES` of ``source`` moved by ``T_target_source`` onto ``target`` (zeros when
    the two faces do not overlap)."""
    settings = settings or ReliefFeatureSettings()
    prepared = _prepared_target(target, settings)
    if source.n_points > _MAX_SOURCE_POINTS:
        source = source.subset(np.arange(0, source.n_points, -(-source.n_points // _MAX_SOURCE_POINTS)))
    moved = source.transformed(np.asarray(T_target_source, dtype=np.float64))
    source_heights = _grid_heights(moved, prepared.frame, settings)
    source_mask = np.isfinite(source_heights)
    both = _eroded(source_mask, settings) & prepared.inner
    smaller = min(int(source_mask.sum()), int(prepared.mask.sum()))
    if smaller == 0 or both.sum() < 25:
        return np.zeros(len(FEATURE_NAMES))
    overlap = float((source_mask & prepared.mask).sum()) / smaller
    # every blur below is of values and a mask that are zero outside ``both``: cropped to its bounding box
    # and blurred with zeros beyond the crop, they come out as on the whole field, for a fraction of the work
    window = _crop(both)
    both, source_heights, target_heights = both[window], source_heights[window], prepared.heights[window]
    weights = _MaskWeights(both)
    a = np.where(both, source_heights, 0.0).astype(np.float32)
    b = np.where(both, target_heights, 0.0).astype(np.float32)
    a = a - np.where(both, weights.blur(a - b, settings.shape_sigma_mm / settings.pixel_mm), 0.0)
    fine_a, coarse_a = _clipped(_bands(a, weights, settings), both, settings.clip_sd)
    fine_b, coarse_b = _clipped(_bands(b, weights, settings), both, settings.clip_sd)
    local = _local_ncc(fine_a, fine_b, weights, settings.window_mm / settings.pixel_mm)
    median, p90 = np.percentile(local, [50, 90]) if len(local) else (0.0, 0.0)
    return np.array(
        [_ncc(fine_a, fine_b, both), _ncc(coarse_a, coarse_b, both), median, p90, overlap], dtype=np.float64
    )


class _MaskWeights:
    """A mask and its Gaussian blurs, each computed once however many images are blurred under it."""

    def __init__(self, mask: BoolArray) -> None:
        self.mask = mask
        self._blurred: dict[float, FloatArray] = {}

    def weight(self, sigma_px: float) -> FloatArray:
        if sigma_px not in self._blurred:
            self._blurred[sigma_px] = _gaussian(self.mask.astype(np.float32), sigma_px)
        return self._blurred[sigma_px]

    def blur(self, values: FloatArray, sigma_px: float) -> FloatArray:
        """Gaussian blur of the values inside the mask, normalised by the blurred mask (no edge darkening)."""
        blurred = _gaussian(np.where(self.mask, values, 0.0).astype(np.float32), sigma_px)
        return blurred / np.maximum(self.weight(sigma_px), _EPS)


def _gaussian(values: FloatArray, sigma_px: float) -> FloatArray:
    """scipy's ``gaussian_filter`` (zeros beyond the image, the kernel cut at 4 sigma); wide kernels by FFT.

    The shape, coarse and window blurs (10-30 pixels) run scipy's direct sums over 80-240 taps a pixel,
    which is most of the features' time. Their FFT convolution with the same kernel gives the same values
    to float32 rounding (differences of about 1e-8 on heights of 0.1-1) in a third to a half of the time
    on a face's crop (measured at 280 x 280: 13.4 -> 4.9 ms at sigma 30, 5.9 -> 3.7 ms at 10, and slower
    below about 6)."""
    if sigma_px < _FFT_SIGMA_PX:
        return ndimage.gaussian_filter(values, sigma_px, mode="constant", cval=0.0)
    radius = int(4.0 * sigma_px + 0.5)  # scipy's truncate=4.0
    taps = np.exp(-0.5 * (np.arange(-radius, radius + 1, dtype=np.float64) / sigma_px) ** 2)
    taps /= taps.sum()
    blurred = np.asarray(values, dtype=np.float64)
    for axis in range(blurred.ndim):
        length = blurred.shape[axis]
        size = fft.next_fast_len(length + 2 * radius, real=True)  # no wrap: a linear convolution
        kernel = fft.rfft(taps, size).reshape([-1 if a == axis else 1 for a in range(blurred.ndim)])
        full = fft.irfft(fft.rfft(blurred, size, axis=axis) * kernel, size, axis=axis)
        blurred = full[
            tuple(slice(radius, radius + length) if a == axis else slice(None) for a in range(blurred.ndim))
        ]
    return blurred.astype(np.asarray(values).dtype)


def _crop(mask: BoolArray) -> tuple[slice, slice]:
    """The bounding box of ``mask`` and a one-pixel border, within the grid (the border keeps a row of
    background around the footprint for the distance transform; the blurs need none)."""
    rows, cols = np.flatnonzero(mask.any(axis=1)), np.flatnonzero(mask.any(axis=0))
    return slice(max(0, rows[0] - 1), rows[-1] + 2), slice(max(0, cols[0] - 1), cols[-1] + 2)


def _bands(
    heights: FloatArray, weights: _MaskWeights, settings: ReliefFeatureSettings
) -> tuple[FloatArray, ...]:
    fine_blur = weights.blur(heights, settings.fine_sigma_mm / settings.pixel_mm)
    coarse_blur = weights.blur(heights, settings.coarse_sigma_mm / settings.pixel_mm)
    mask = weights.mask
    return np.where(mask, heights - fine_blur, 0.0), np.where(mask, fine_blur - coarse_blur, 0.0)


def _clipped(bands: tuple[FloatArray, ...], mask: BoolArray, clip_sd: float) -> tuple[FloatArray, ...]:
    """Each band clipped at ``clip_sd`` robust standard deviations of its values inside ``mask`` (the
    registration's own clip of its relief images)."""
    return tuple(clipped_detail(band, mask, clip_sd) for band in bands)


def _ncc(a: FloatArray, b: FloatArray, mask: BoolArray) -> float:
    x, y = a[mask] - a[mask].mean(), b[mask] - b[mask].mean()
    x, y = x.astype(np.float64), y.astype(np.float64)
    denominator = np.sqrt(np.dot(x, x) * np.dot(y, y))
    return float(np.dot(x, y) / denominator) if denominator > _EPS else 0.0


def _local_ncc(a: FloatArray, b: FloatArray, weights: _MaskWeights, sigma_px: float) -> FloatArray:
    """Windowed correlations of two zero-mean band images at the pixels whose window is mostly overlap."""
    ab, aa, bb = (_gaussian(p, sigma_px) for p in (a * b, a * a, b * b))
    keep = weights.mask & (weights.weight(sigma_px) > _MIN_WINDOW_WEIGHT)
    return ab[keep] / np.sqrt(np.maximum(aa[keep] * bb[keep], _EPS))


def _eroded(mask: BoolArray, settings: ReliefFeatureSettings) -> BoolArray:
    margin_px = settings.margin_mm / settings.pixel_mm
    if margin_px <= 0:
        return mask
    inner = np.zeros_like(mask)
    if mask.any():
        window = _crop(mask)  # the distance transform of the footprint's box: the rest is outside
        inner[window] = ndimage.distance_transform_edt(mask[window]) > margin_px
    return inner


def _grid_heights(scan: Scan, frame: CanonicalFrame, settings: ReliefFeatureSettings) -> FloatArray:
    """Heights above ``frame``'s plane on the settings' square grid centred on the frame's origin."""
    relief = height_map(scan, resolution=settings.pixel_mm, frame=frame, detrend="plane")
    return _centred(relief, settings)


def _centred(relief: HeightMap, settings: ReliefFeatureSettings) -> FloatArray:
    size = settings.size_px
    coordinates = (np.arange(size) - (size - 1) / 2.0) * settings.pixel_mm
    y, x = np.meshgrid(coordinates[::-1], coordinates, indexing="ij")
    rows, cols = relief.mm_to_pixel(x, y)
    values = np.asarray(relief.values, dtype=np.float64)
    # nearest-pixel sampling keeps NaN (no data) from spreading into the neighbouring pixels
    return ndimage.map_coordinates(values, [rows, cols], order=0, mode="constant", cval=np.nan)


_CACHE: OrderedDict[tuple[bytes, ReliefFeatureSettings], _Target] = OrderedDict()
_LOCK = Lock()


def _prepared_target(target: Scan, settings: ReliefFeatureSettings) -> _Target:
    from coindie.registration.clouds import content_key

    normals = target.normals if target.normals is not None else np.zeros_like(target.points)
    key = (content_key(target.points, normals), settings)
    with _LOCK:
        if key in _CACHE:
            _CACHE.move_to_end(key)
            return _CACHE[key]
    stride = -(-target.n_points // _FRAME_POINTS)
    frame = canonical_frame(target.subset(np.arange(0, target.n_points, stride)))
    heights = _grid_heights(target, frame, settings)
    mask = np.isfinite(heights)
    prepared = _Target(frame, heights, mask, _eroded(mask, settings))
    with _LOCK:
        _CACHE[key] = prepared
        while len(_CACHE) > TARGET_CACHE_SIZE:
            _CACHE.popitem(last=False)
    return prepared


def clear_cache() -> None:
    """Forget the prepared targets (benchmarks timing a cold start)."""
    with _LOCK:
        _CACHE.clear()
