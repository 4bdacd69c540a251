"""Rasterising relief primitives on regular grids: ridges along curves, domes, ellipses.

Heights are evaluated in small windows around each primitive, so the cost scales with the primitive's
area, not with the grid's.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy import interpolate, ndimage

from coindie.arrays import FloatArray

#: Neighbouring curve samples examined around the distance transform's nearest one (see ``ridge``).
_REFINE = 2


@dataclass(frozen=True)
class Grid:
    """Square pixels: pixel (row i, column j) has its centre at (x0 + j * pitch, y0 + i * pitch), in mm."""

    x0: float
    y0: float
    pitch: float
    ny: int
    nx: int

    @classmethod
    def square(cls, centre: tuple[float, float], side: float, pitch: float) -> Grid:
        """A grid of about ``side`` x ``side`` mm centred on ``centre``."""
        n = int(np.ceil(side / pitch)) + 1
        half = (n - 1) * pitch / 2
        return cls(centre[0] - half, centre[1] - half, pitch, n, n)

    @property
    def shape(self) -> tuple[int, int]:
        return (self.ny, self.nx)

    def axes(self) -> tuple[FloatArray, FloatArray]:
        """Pixel-centre coordinates along x (columns) and y (rows)."""
        return self.x0 + self.pitch * np.arange(self.nx), self.y0 + self.pitch * np.arange(self.ny)

    def coords(self) -> tuple[FloatArray, FloatArray]:
        """X, Y arrays of shape (ny, nx)."""
        x, y = self.axes()
        return np.meshgrid(x, y)

    def fractional_index(self, xy: FloatArray) -> FloatArray:
        """(2, N) fractional (row, column) indices of points (N, 2), for ``ndimage.map_coordinates``."""
        xy = np.asarray(xy, dtype=np.float64)
        return np.stack([(xy[:, 1] - self.y0) / self.pitch, (xy[:, 0] - self.x0) / self.pitch])

    def window(self, lo: FloatArray, hi: FloatArray) -> tuple[slice, slice, Grid] | None:
        """The sub-grid covering the box [lo, hi] (clipped to this grid), or None when they do not meet."""
        c0 = max(int(np.floor((lo[0] - self.x0) / self.pitch)), 0)
        c1 = min(int(np.ceil((hi[0] - self.x0) / self.pitch)) + 1, self.nx)
        r0 = max(int(np.floor((lo[1] - self.y0) / self.pitch)), 0)
        r1 = min(int(np.ceil((hi[1] - self.y0) / self.pitch)) + 1, self.ny)
        if c1 <= c0 or r1 <= r0:
            return None
        sub = Grid(self.x0 + c0 * self.pitch, self.y0 + r0 * self.pitch, self.pitch, r1 - r0, c1 - c0)
        return slice(r0, r1), slice(c0, c1), sub


Patch = tuple[slice, slice, FloatArray]


def profile(u: FloatArray, sharpness: float) -> FloatArray:
    """Cross-section of a ridge or dome: (1 - u^2)^sharpness for |u| < 1, else 0 (u = distance / half-width).

    sharpness < 1 gives flat-topped masses, > 1 pointed ridges.
    """
    return np.clip(1.0 - u * u, 0.0, None) ** sharpness


def sample_curve(control: FloatArray, closed: bool, step: float) -> tuple[FloatArray, FloatArray]:
    """Points every ``step`` mm along a smooth cubic spline through ``control`` (K, 2) and their arc-length
    fraction in [0, 1]."""
    control = np.asarray(control, dtype=np.float64)
    if closed:
        control = np.vstack([control, control[:1]])
    chord = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(control, axis=0), axis=1))]
    spline = interpolate.CubicSpline(chord, control, bc_type="periodic" if closed else "not-a-knot")
    fine_t = np.linspace(0.0, chord[-1], 16 * len(control) + 16)
    fine = spline(fine_t)
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(fine, axis=0), axis=1))]
    n = max(int(np.ceil(arc[-1] / step)) + 1, 2)
    s = np.linspace(0.0, arc[-1], n)
    return spline(np.interp(s, arc, fine_t)), s / max(arc[-1], 1e-12)


def ridge(
    grid: Grid, samples: FloatArray, half_width: FloatArray, height: FloatArray, sharpness: float
) -> Patch | None:
    """Heights of a ridge along densely sampled curve points (spacing below half a pixel).

    A Euclidean distance transform finds each pixel's nearest sample in C (fast, but only to the pixel);
    the exact distance is then taken to that sample and its neighbours along the curve.
    """
    reach = float(half_width.max()) + grid.pitch
    sub = grid.window(samples.min(axis=0) - reach, samples.max(axis=0) + reach)
    if sub is None:
        return None
    rows, cols, win = sub
    nearest = _nearest_sample(win, samples)
    if nearest is None:
        return None
    X, Y = win.coords()
    best_d2 = np.full(win.shape, np.inf)
    best = nearest
    for offset in range(-_REFINE, _REFINE + 1):
        k = np.clip(nearest + offset, 0, len(samples) - 1)
        d2 = (X - samples[k, 0]) ** 2 + (Y - samples[k, 1]) ** 2
        closer = d2 < best_d2
        best_d2 = np.where(closer, d2, best_d2)
        best = np.where(closer, k, best)
    u = np.sqrt(best_d2) / half_width[best]
    return rows, cols, height[best] * profile(u, sharpness)


def _nearest_sample(win: Grid, samples: FloatArray) -> NDArray[np.int64] | None:
    idx = np.rint(win.fractional_index(samples)).astype(np.int64)
    inside = (idx[0] >= 0) & (idx[0] < win.ny) & (idx[1] >= 0) & (idx[1] < win.nx)
    if not inside.any():
        return None
    label = np.full(win.shape, -1, dtype=np.int64)
    label[idx[0, inside], idx[1, inside]] = np.flatnonzero(inside)
    _, (ri, ci) = ndimage.distance_transform_edt(label < 0, return_indices=True)
    return label[ri, ci]


def ellipse(
    grid: Grid,
    centre: tuple[float, float],
    axes: tuple[float, float],
    angle: float,
    height: float,
    sharpness: float,
) -> Patch | None:
    """An elliptic dome (semi-axes ``axes`` mm, turned by ``angle`` rad); a circle when the axes are equal."""
    reach = max(axes) + grid.pitch
    c = np.asarray(centre, dtype=np.float64)
    sub = grid.window(c - reach, c + reach)
    if sub is None:
        return None
    rows, cols, win = sub
    X, Y = win.coords()
    cos, sin = np.cos(angle), np.sin(angle)
    u = ((X - c[0]) * cos + (Y - c[1]) * sin) / axes[0]
    v = (-(X - c[0]) * sin + (Y - c[1]) * cos) / axes[1]
    return rows, cols, height * profile(np.sqrt(u * u + v * v), sharpness)


def paste_max(target: FloatArray, patch: Patch | None) -> None:
    """Combine a patch into ``target`` by maximum (overlapping engravings: the deepest cut wins)."""
    if patch is not None:
        rows, cols, values = patch
        np.maximum(target[rows, cols], values, out=target[rows, cols])


def paste_add(target: FloatArray, patch: Patch | None, sign: float = 1.0) -> None:
    """Add (or, with sign -1, subtract) a patch into ``target``."""
    if patch is not None:
        rows, cols, values = patch
        target[rows, cols] += sign * values


def sample_polyline(points: FloatArray, step: float) -> tuple[FloatArray, FloatArray]:
    """Points every ``step`` mm along a polyline (kept jagged, unlike ``sample_curve``) and their arc-length
    fraction in [0, 1]."""
    points = np.asarray(points, dtype=np.float64)
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))]
    n = max(int(np.ceil(arc[-1] / step)) + 1, 2)
    s = np.linspace(0.0, arc[-1], n)
    xy = np.column_stack([np.interp(s, arc, points[:, 0]), np.interp(s, arc, points[:, 1])])
    return xy, s / max(arc[-1], 1e-12)


@dataclass(frozen=True)
class Placement:
    """A rigid map of the plane: p_out = R(rotation) p_in + shift (rotation in rad, shift in mm)."""

    rotation: float = 0.0
    shift: tuple[float, float] = (0.0, 0.0)

    def apply(self, xy: FloatArray) -> FloatArray:
        c, s = np.cos(self.rotation), np.sin(self.rotation)
        return np.asarray(xy) @ np.array([[c, s], [-s, c]]) + np.asarray(self.shift)

    def inverse_apply(self, xy: FloatArray) -> FloatArray:
        c, s = np.cos(self.rotation), np.sin(self.rotation)
        return (np.asarray(xy) - np.asarray(self.shift)) @ np.array([[c, -s], [s, c]])


def resample(field: NDArray, field_grid: Grid, target: Grid, placement: Placement) -> FloatArray:
    """``field`` (on ``field_grid``) seen at the pixels of ``target``, whose points map into the field's frame
    by ``placement``: bilinear, one C pass (``ndimage.affine_transform``), edges clamped."""
    c, s = np.cos(placement.rotation), np.sin(placement.rotation)
    k = target.pitch / field_grid.pitch
    matrix = k * np.array([[c, s], [-s, c]])
    tx, ty = placement.shift
    offset = [
        (s * target.x0 + c * target.y0 + ty - field_grid.y0) / field_grid.pitch,
        (c * target.x0 - s * target.y0 + tx - field_grid.x0) / field_grid.pitch,
    ]
    out = ndimage.affine_transform(field, matrix, offset, output_shape=target.shape, order=1, mode="nearest")
    return out.astype(np.float64, copy=False)
