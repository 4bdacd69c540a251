"""Synthetic coin faces with a known transform between them, for the registration tests and
``benchmarks/bench_registration_methods.py`` (a test helper, not part of the library: tests import it as
``synthetic_pairs``, found like ``real_data`` on the tests' path). Poses come from :mod:`coindie.transforms`.

A small, self-contained generator (the hoard generator in ``coindie.synth`` models dies, striking and wear;
this one only needs a surface two scans share): a shallow dome carrying a relief of Gaussian bumps and
strokes 0.1–0.5 mm high, sampled as a height field on a regular 0.1 mm grid with analytic normals. Two
scans of the same surface differ by their footprint (partial overlap), their grid offset and their noise.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from coindie.scan import Scan
from coindie.transforms import random_pose

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Relief:
    """A height field z = dome(x, y) + bumps + strokes (mm), defined on the whole plane."""

    dome_height: float
    dome_radius: float
    bump_centres: FloatArray  # (B, 2)
    bump_heights: FloatArray  # (B,)
    bump_sigmas: FloatArray  # (B,)
    stroke_starts: FloatArray  # (S, 2)
    stroke_ends: FloatArray  # (S, 2)
    stroke_heights: FloatArray  # (S,)
    stroke_widths: FloatArray  # (S,)

    def height(self, xy: FloatArray) -> FloatArray:
        r2 = (xy**2).sum(axis=1) / self.dome_radius**2
        z = self.dome_height * (1.0 - r2)
        for centre, height, sigma in zip(self.bump_centres, self.bump_heights, self.bump_sigmas, strict=True):
            z += height * np.exp(-((xy - centre) ** 2).sum(axis=1) / (2 * sigma**2))
        strokes = zip(
            self.stroke_starts, self.stroke_ends, self.stroke_heights, self.stroke_widths, strict=True
        )
        for start, end, height, width in strokes:
            z += height * np.exp(-(_distance_to_segment(xy, start, end) ** 2) / (2 * width**2))
        return z

    def normals(self, xy: FloatArray, step: float = 1e-4) -> FloatArray:
        """Unit normals (pointing up, +z side) from central differences of the height."""
        dx = (self.height(xy + [step, 0.0]) - self.height(xy - [step, 0.0])) / (2 * step)
        dy = (self.height(xy + [0.0, step]) - self.height(xy - [0.0, step])) / (2 * step)
        normals = np.stack([-dx, -dy, np.ones_like(dx)], axis=1)
        return normals / np.linalg.norm(normals, axis=1, keepdims=True)


def _distance_to_segment(xy: FloatArray, start: FloatArray, end: FloatArray) -> FloatArray:
    direction = end - start
    along = np.clip((xy - start) @ direction / (direction @ direction), 0.0, 1.0)
    return np.linalg.norm(xy - (start + along[:, None] * direction), axis=1)


def random_relief(seed: int, *, radius: float = 10.0, n_bumps: int = 40, n_strokes: int = 30) -> Relief:
    """A die-like relief over a disc of ``radius`` mm: distinct bumps and strokes 0.1–0.5 mm high."""
    rng = np.random.default_rng(seed)
    starts = _points_in_disc(rng, n_strokes, 0.85 * radius)
    angles = rng.uniform(0, 2 * np.pi, n_strokes)
    lengths = rng.uniform(1.5, 4.0, n_strokes)
    return Relief(
        dome_height=0.08 * radius,
        dome_radius=radius,
        bump_centres=_points_in_disc(rng, n_bumps, 0.9 * radius),
        bump_heights=rng.uniform(0.1, 0.5, n_bumps),
        bump_sigmas=rng.uniform(0.2, 0.6, n_bumps),
        stroke_starts=starts,
        stroke_ends=starts + lengths[:, None] * np.stack([np.cos(angles), np.sin(angles)], axis=1),
        stroke_heights=rng.uniform(0.1, 0.4, n_strokes),
        stroke_widths=rng.uniform(0.1, 0.25, n_strokes),
    )


def _points_in_disc(rng: np.random.Generator, n: int, radius: float) -> FloatArray:
    r = radius * np.sqrt(rng.uniform(0, 1, n))
    angle = rng.uniform(0, 2 * np.pi, n)
    return np.stack([r * np.cos(angle), r * np.sin(angle)], axis=1)


def scan_relief(
    relief: Relief,
    *,
    centre: tuple[float, float] = (0.0, 0.0),
    radius: float = 10.0,
    spacing: float = 0.1,
    noise: float = 0.0,
    seed: int = 0,
    face_id: str = "synthetic",
) -> Scan:
    """Sample the relief on a ``spacing`` grid (random sub-cell offset) inside a disc; Gaussian ``noise``
    (mm) along z."""
    rng = np.random.default_rng(seed)
    offset = rng.uniform(0, spacing, 2)
    ticks = np.arange(-radius, radius + spacing, spacing)
    x, y = np.meshgrid(ticks + centre[0] + offset[0], ticks + centre[1] + offset[1])
    xy = np.stack([x.ravel(), y.ravel()], axis=1)
    xy = xy[np.hypot(xy[:, 0] - centre[0], xy[:, 1] - centre[1]) <= radius]
    z = relief.height(xy) + rng.normal(0.0, noise, len(xy))
    return Scan(points=np.column_stack([xy, z]), normals=relief.normals(xy), id=face_id)


@dataclass(frozen=True)
class CoinPair:
    """Two scans of one surface; ``T_target_source`` maps source points onto the target (the truth)."""

    source: Scan
    target: Scan
    T_target_source: FloatArray


def make_coin_pair(
    *,
    seed: int = 0,
    radius: float = 10.0,
    spacing: float = 0.1,
    noise: float = 0.01,
    shift: float = 1.5,
    T_target_source: FloatArray | None = None,
    n_bumps: int = 40,
    n_strokes: int = 30,
) -> CoinPair:
    """Target: a disc of ``radius`` mm; source: a disc shifted by ``shift`` mm (partial overlap), another
    grid offset and noise, then moved by the inverse of ``T_target_source`` (default: a random pose)."""
    rng = np.random.default_rng(seed)
    relief = random_relief(seed, radius=radius, n_bumps=n_bumps, n_strokes=n_strokes)
    target = scan_relief(relief, radius=radius, spacing=spacing, noise=noise, seed=seed + 1, face_id="target")
    angle = rng.uniform(0, 2 * np.pi)
    source_in_target = scan_relief(
        relief,
        centre=(shift * np.cos(angle), shift * np.sin(angle)),
        radius=radius - 0.5 * shift,
        spacing=spacing,
        noise=noise,
        seed=seed + 2,
        face_id="source",
    )
    T = random_pose(rng) if T_target_source is None else np.asarray(T_target_source, dtype=np.float64)
    return CoinPair(source=source_in_target.transformed(np.linalg.inv(T)), target=target, T_target_source=T)
