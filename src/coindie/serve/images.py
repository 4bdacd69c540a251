"""Images of faces and pairs for the review app, rendered on the server as PNG.

- a face's thumbnail: :func:`coindie.render.render_relief`;
- a pair in the aligned frame: both height maps on one pixel grid of the target's canonical frame (the
  source moved by ``T_target_source``), hill-shaded; their height difference; the c2c-distance heat map
  (distance of each source point to the target, the scorer's own :func:`c2c_distances`);
- a face in its own frame with its grid (for picking corresponding points).
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from PIL import Image
from scipy import ndimage

from coindie.io import read_scan
from coindie.preprocess.canonical import CanonicalFrame, canonical_frame
from coindie.preprocess.heightmap import HeightMap, height_map
from coindie.render import TONES, hillshade, render_relief
from coindie.scan import Scan
from coindie.similarity.histogram import HistogramSettings, c2c_distances, density_histogram, sampled_face
from coindie.transforms import apply

#: Height difference (mm) shown at full colour in the difference view.
DIFFERENCE_RANGE_MM = 0.2
#: Points per cloud sent to the 3D view.
CLOUD_POINTS = 30000


@lru_cache(maxsize=64)
def face_scan(path: Path, unit: str | None = None) -> tuple[Scan, CanonicalFrame]:
    """A face read in millimetres (``unit``: the project's declared scan unit) and its canonical frame."""
    scan = read_scan(path, unit=unit)
    return scan, canonical_frame(scan)


def png(image: Image.Image) -> bytes:
    buffer = io.BytesIO()
    image.save(buffer, format="PNG", compress_level=1)
    return buffer.getvalue()


@lru_cache(maxsize=4096)
def thumbnail(path: Path, width_px: int = 160, unit: str | None = None) -> bytes:
    scan, frame = face_scan(path, unit)
    return png(render_relief(scan, width_px=width_px, frame=frame))


@dataclass(frozen=True)
class Grid:
    """A pixel grid of a canonical frame: pixel (row, col) centre at (x0 + col*res, y0 - row*res) mm."""

    x0: float
    y0: float
    resolution: float
    shape: tuple[int, int]

    @property
    def size(self) -> int:
        return self.shape[0] * self.shape[1]

    def to_dict(self) -> dict[str, float | int]:
        return {
            "x0": self.x0,
            "y0": self.y0,
            "resolution": self.resolution,
            "height": self.shape[0],
            "width": self.shape[1],
        }


def _resolution(frame: CanonicalFrame, scan: Scan, width_px: int) -> float:
    xy = apply(frame.T_canonical_scan, scan.points)[:, :2]
    return float(max(np.ptp(xy, axis=0).max() / width_px, 0.02))


def _placed(relief: HeightMap, grid: Grid) -> NDArray[np.float64]:
    """The height map's values on ``grid`` (NaN elsewhere); offsets rounded to the nearest pixel."""
    out = np.full(grid.shape, np.nan)
    dr = round((grid.y0 - relief.origin[1]) / grid.resolution)
    dc = round((relief.origin[0] - grid.x0) / grid.resolution)
    h, w = relief.shape
    r0, c0 = max(dr, 0), max(dc, 0)
    r1, c1 = min(dr + h, grid.shape[0]), min(dc + w, grid.shape[1])
    if r1 > r0 and c1 > c0:
        out[r0:r1, c0:c1] = relief.values[r0 - dr : r1 - dr, c0 - dc : c1 - dc]
    return out


def _union_grid(reliefs: list[HeightMap], resolution: float) -> Grid:
    x0 = min(r.origin[0] for r in reliefs)
    y0 = max(r.origin[1] for r in reliefs)
    x1 = max(r.origin[0] + r.shape[1] * resolution for r in reliefs)
    y1 = min(r.origin[1] - r.shape[0] * resolution for r in reliefs)
    return Grid(
        x0, y0, resolution, (int(np.ceil((y0 - y1) / resolution)), int(np.ceil((x1 - x0) / resolution)))
    )


def _shade_rgba(values: NDArray[np.float64], resolution: float, tone: str = "bronze") -> Image.Image:
    mask = np.isfinite(values)
    relief = HeightMap(values.astype(np.float32), resolution, (0.0, 0.0), np.eye(4), "quadric", mask)
    shade = hillshade(relief, 315.0, 45.0, 2.0)
    stops = np.array(TONES[tone], dtype=np.float64)
    positions = np.linspace(0.0, 1.0, len(stops))
    rgb = np.stack([np.interp(shade, positions, stops[:, c]) for c in range(3)], axis=-1)
    rgba = np.concatenate([rgb, np.where(mask, 255.0, 0.0)[..., None]], axis=-1)
    return Image.fromarray(np.clip(np.rint(rgba), 0, 255).astype(np.uint8), "RGBA")


def _ramp(values: NDArray[np.float64], low: float, high: float, colormap: str) -> Image.Image:
    from matplotlib import colormaps

    mask = np.isfinite(values)
    scaled = np.clip((np.nan_to_num(values) - low) / (high - low), 0.0, 1.0)
    rgba = (colormaps[colormap](scaled) * 255).astype(np.uint8)
    rgba[..., 3] = np.where(mask, 255, 0)
    return Image.fromarray(rgba, "RGBA")


@dataclass(frozen=True)
class AlignedPair:
    """Both faces on one grid of the target's canonical frame."""

    grid: Grid
    target: NDArray[np.float64]
    source: NDArray[np.float64]
    heat: NDArray[np.float64]  # mean c2c distance (mm) of the source points in each pixel; NaN: none


@lru_cache(maxsize=16)
def aligned_pair(
    target_path: Path, source_path: Path, T_key: tuple[float, ...], width_px: int, unit: str | None = None
) -> AlignedPair:
    T_target_source = np.asarray(T_key, dtype=np.float64).reshape(4, 4)
    target, frame = face_scan(target_path, unit)
    source, _ = face_scan(source_path, unit)
    moved = source.transformed(T_target_source)
    resolution = _resolution(frame, target, width_px)
    reliefs = [
        height_map(s, frame=frame, resolution=resolution, fill_max_distance=3 * resolution)
        for s in (target, moved)
    ]
    grid = _union_grid(reliefs, resolution)
    settings = HistogramSettings()
    distances = _pair_distances(target_path, source_path, T_key, unit)
    points = sampled_face(source, settings.source_grid_mm, settings.max_normal_angle_rad).points
    canonical = apply(frame.T_canonical_scan @ T_target_source, points)
    rows = np.rint((grid.y0 - canonical[:, 1]) / resolution).astype(np.int64)
    cols = np.rint((canonical[:, 0] - grid.x0) / resolution).astype(np.int64)
    inside = (
        (rows >= 0) & (rows < grid.shape[0]) & (cols >= 0) & (cols < grid.shape[1]) & np.isfinite(distances)
    )
    flat = rows[inside] * grid.shape[1] + cols[inside]
    sums = np.bincount(
        flat, weights=np.minimum(distances[inside], settings.max_distance_mm), minlength=grid.size
    )
    counts = np.bincount(flat, minlength=grid.size).astype(np.float64)
    # The source is sampled coarser than the pixels: average over 3x3 pixels so the map has no holes.
    sums = ndimage.uniform_filter(sums.reshape(grid.shape), 3).ravel()
    counts = ndimage.uniform_filter(counts.reshape(grid.shape), 3).ravel()
    with np.errstate(invalid="ignore", divide="ignore"):
        heat = np.where(counts > 0, sums / counts, np.nan).reshape(grid.shape)
    target_values = _placed(reliefs[0], grid)
    heat[~np.isfinite(target_values)] = np.nan  # a distance to the target means something only over it
    return AlignedPair(grid, target_values, _placed(reliefs[1], grid), heat)


@lru_cache(maxsize=16)
def _pair_distances(
    target_path: Path, source_path: Path, T_key: tuple[float, ...], unit: str | None = None
) -> NDArray[np.float64]:
    """The c2c distances of a pair at its pose (``T_key``: T_target_source, row by row), default histogram
    settings: what the heat map and the histogram of an opened pair both read, searched once."""
    T_target_source = np.asarray(T_key, dtype=np.float64).reshape(4, 4)
    target, _ = face_scan(target_path, unit)
    source, _ = face_scan(source_path, unit)
    distances = c2c_distances(source, target, T_target_source, HistogramSettings())
    distances.setflags(write=False)  # shared by every caller of the cache
    return distances


@lru_cache(maxsize=256)
def pair_histogram(
    target_path: Path, source_path: Path, T_key: tuple[float, ...], unit: str | None = None
) -> tuple[float, ...]:
    """The paper's distance histogram of a pair at its pose (``T_key``: T_target_source, row by row), for
    a pair whose run did not measure it (``coindie run`` measures it only with ``--histograms`` or for the
    paper scorer): :func:`~coindie.similarity.histogram.c2c_histogram` with the default (one-way)
    settings, from the distances the pair's heat map reads."""
    settings = HistogramSettings()
    distances = _pair_distances(target_path, source_path, T_key, unit)
    return tuple(float(v) for v in density_histogram(distances, settings))


def pair_image(aligned: AlignedPair, kind: str) -> bytes:
    """``target``, ``source`` (hill-shaded, aligned), ``difference`` (source - target height, mm) or ``heat``
    (c2c distance of the source to the target, mm)."""
    if kind == "target":
        return png(_shade_rgba(aligned.target, aligned.grid.resolution))
    if kind == "source":
        return png(_shade_rgba(aligned.source, aligned.grid.resolution))
    if kind == "difference":
        d = aligned.source - aligned.target
        d -= np.nanmedian(d) if np.isfinite(d).any() else 0.0  # the pair's height offset is not a difference
        return png(_ramp(d, -DIFFERENCE_RANGE_MM, DIFFERENCE_RANGE_MM, "RdBu_r"))
    if kind == "heat":
        return png(_ramp(aligned.heat, 0.0, HistogramSettings().max_distance_mm / 3, "inferno"))
    raise KeyError(f"no pair image {kind!r}: one of target, source, difference, heat")


def own_frame(
    path: Path, width_px: int = 480, unit: str | None = None
) -> tuple[Grid, NDArray[np.float64], CanonicalFrame]:
    """A face in its canonical frame: grid, heights on it, frame (for picking points)."""
    scan, frame = face_scan(path, unit)
    resolution = _resolution(frame, scan, width_px)
    relief = height_map(scan, frame=frame, resolution=resolution, fill_max_distance=3 * resolution)
    grid = Grid(relief.origin[0], relief.origin[1], resolution, relief.shape)
    return grid, relief.values.astype(np.float64), frame


def picked_points(
    path: Path, pixels: list[tuple[float, float]], width_px: int = 480, unit: str | None = None
) -> NDArray[np.float64]:
    """Scan-frame 3D points (mm) under picked pixels (col, row) of :func:`own_frame`'s image.

    The height is the median of the relief within 2 pixels (a click lands between points); the quadric
    the heights were measured from is added back.
    """
    grid, values, frame = own_frame(path, width_px, unit)
    out = []
    for col, row in pixels:
        r, c = int(round(row)), int(round(col))
        window = values[max(r - 2, 0) : r + 3, max(c - 2, 0) : c + 3]
        if not np.isfinite(window).any():
            raise ValueError(f"pixel ({col:.0f}, {row:.0f}) is off the coin")
        x, y = grid.x0 + col * grid.resolution, grid.y0 - row * grid.resolution
        z = float(np.nanmedian(window)) + float(frame.surface_height(np.array([x]), np.array([y]))[0])
        out.append((x, y, z))
    canonical = np.asarray(out, dtype=np.float64)
    return apply(np.linalg.inv(frame.T_canonical_scan), canonical)


def own_image(path: Path, width_px: int = 480, unit: str | None = None) -> bytes:
    grid, values, _ = own_frame(path, width_px, unit)
    return png(_shade_rgba(values, grid.resolution))


def clouds(
    target_path: Path, source_path: Path, T_target_source: NDArray[np.float64], unit: str | None = None
) -> dict[str, list]:
    """Both clouds in the target's canonical frame (subsampled, centred), for the 3D view."""
    target, frame = face_scan(target_path, unit)
    source, _ = face_scan(source_path, unit)
    rng = np.random.default_rng(0)

    def pick(points: NDArray[np.float64]) -> NDArray[np.float64]:
        index = rng.choice(len(points), size=min(CLOUD_POINTS, len(points)), replace=False)
        return points[np.sort(index)]

    t = apply(frame.T_canonical_scan, pick(target.points))
    s = apply(frame.T_canonical_scan @ T_target_source, pick(source.points))
    centre = t.mean(axis=0)
    return {
        "target": np.round(t - centre, 4).ravel().tolist(),
        "source": np.round(s - centre, 4).ravel().tolist(),
    }
