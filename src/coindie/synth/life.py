"""Die life: a die wears and cracks while it strikes.

``age`` is the fraction (0-1) of the die's working life already spent when a coin is struck. Two effects:

- softening: the engraving's edges round off and its depth decreases; the relief at ``age`` is the fresh
  relief mixed with a worn one (Gaussian-rounded by ``softening_blur_mm`` and lowered by
  ``relief_loss``) in proportion to the age;
- cracks: a die cracks part-way through its life (``crack_start_age``); metal flows into the crack, so it
  shows on the coin as a thin raised, jagged line that lengthens (to its full length
  ``crack_growth`` of the life later) and opens (its height and width grow) with age.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from scipy import ndimage

from coindie.arrays import FloatArray
from coindie.params import Configurable
from coindie.synth import _raster
from coindie.synth._params import param
from coindie.synth._raster import Grid, Placement

if TYPE_CHECKING:
    from coindie.synth.design import Die

#: Step (mm) of a crack's random walk.
CRACK_STEP_MM = 0.1
#: Worn relief fields kept per process.
WORN_CACHE_SIZE = 24


@dataclass(frozen=True)
class LifeParams(Configurable):
    """How a die softens and cracks over its life (ages 0-1). Checked at construction."""

    softening_blur_mm: float = param(
        0.03, unit="mm", lo=0.0, hi=0.3, doc="Gaussian sigma of the rounding of the relief at the end of life"
    )
    relief_loss: float = param(
        0.1, unit="fraction", lo=0.0, hi=0.6, doc="share of the relief height lost at the end of life"
    )
    cracks_mean: float = param(
        1.0, unit="count", lo=0.0, hi=10.0, doc="Poisson mean of cracks over a die's life"
    )
    crack_start_age: tuple[float, float] = param(
        (0.15, 0.9), unit="age", lo=0.0, hi=1.0, pair=True, doc="range of the age at which a crack appears"
    )
    crack_growth: float = param(
        0.3, unit="age", lo=0.01, hi=1.0, doc="share of the life a crack takes to reach its full length"
    )
    crack_length_mm: tuple[float, float] = param(
        (2.0, 9.0), unit="mm", lo=0.1, hi=30.0, pair=True, doc="range of a crack's full length"
    )
    crack_half_width_mm: tuple[float, float] = param(
        (0.03, 0.07),
        unit="mm",
        lo=0.005,
        hi=0.5,
        pair=True,
        doc="range of a crack's half-width when fully open",
    )
    crack_height_mm: tuple[float, float] = param(
        (0.03, 0.09), unit="mm", lo=0.0, hi=0.5, pair=True, doc="range of a crack's height when fully open"
    )
    crack_wiggle_deg: float = param(
        12.0, unit="deg", lo=0.0, hi=60.0, doc="sd of a crack's change of direction per 0.1 mm step"
    )


#: The default die life.
DEFAULT_LIFE = LifeParams()


@dataclass(frozen=True)
class Crack:
    """A die crack: a jagged path in the die frame from where it starts, and when and how it grows."""

    path: tuple[tuple[float, float], ...]
    start_age: float
    full_age: float
    half_width: float
    height: float

    def opening(self, age: float) -> float:
        """0 before ``start_age``, rising to 1 at ``full_age``: the share of the path visible at ``age``."""
        return float(np.clip((age - self.start_age) / max(self.full_age - self.start_age, 1e-9), 0.0, 1.0))

    def visible(self, age: float, step: float) -> tuple[FloatArray, float, float] | None:
        """Samples (every ``step`` mm) of the part of the path open at ``age``, its half-width and height."""
        f = self.opening(age)
        if f <= 0.0:
            return None
        samples, s = _raster.sample_polyline(np.asarray(self.path), step)
        grow = 0.5 + 0.5 * f
        return samples[s <= f], self.half_width * grow, self.height * grow


def draw_cracks(rng: np.random.Generator, life: LifeParams) -> tuple[Crack, ...]:
    """The cracks a die will develop: random walks starting 4-11 mm from the centre, heading inwards."""
    return tuple(_draw_crack(rng, life) for _ in range(rng.poisson(life.cracks_mean)))


def _draw_crack(rng: np.random.Generator, life: LifeParams) -> Crack:
    r, a = rng.uniform(4.0, 11.0), rng.uniform(0.0, 2 * np.pi)
    heading = a + np.pi + rng.uniform(-1.2, 1.2)
    n = max(int(rng.uniform(*life.crack_length_mm) / CRACK_STEP_MM), 2)
    turns = np.cumsum(rng.normal(0.0, np.radians(life.crack_wiggle_deg), n))
    steps = CRACK_STEP_MM * np.column_stack([np.cos(heading + turns), np.sin(heading + turns)])
    path = np.vstack(
        [[r * np.cos(a), r * np.sin(a)], r * np.array([np.cos(a), np.sin(a)]) + np.cumsum(steps, 0)]
    )
    start = rng.uniform(*life.crack_start_age)
    return Crack(
        path=tuple((float(x), float(y)) for x, y in path),
        start_age=float(start),
        full_age=float(start + life.crack_growth),
        half_width=float(rng.uniform(*life.crack_half_width_mm)),
        height=float(rng.uniform(*life.crack_height_mm)),
    )


def relief_at(die: Die, age: float, target: Grid, placement: Placement, cracks: bool = True) -> FloatArray:
    """The die's relief (no dish) at ``age`` on the pixels of ``target``, a grid in another frame (a coin's)
    whose points map into the die frame by ``placement``."""
    grid, fresh = die.relief()
    relief = _raster.resample(fresh, grid, target, placement)
    if age > 0 and (die.life.softening_blur_mm > 0 or die.life.relief_loss > 0):
        worn = _raster.resample(_worn_field(die), grid, target, placement)
        relief += age * (worn - relief)
    if cracks:
        relief += crack_relief(die, age, target, placement)
    return relief


def crack_relief(die: Die, age: float, target: Grid, placement: Placement) -> FloatArray:
    """Raised lines of the die's cracks open at ``age``, on ``target`` (mapped by ``placement``)."""
    out = np.zeros(target.shape)
    for crack in die.cracks:
        seen = crack.visible(age, 0.4 * target.pitch)
        if seen is None or len(seen[0]) < 2:
            continue
        samples, half_width, height = seen
        local = placement.inverse_apply(samples)
        n = len(local)
        _raster.paste_max(out, _raster.ridge(target, local, np.full(n, half_width), np.full(n, height), 1.0))
    return out


def die_height(die: Die, age: float, xy: FloatArray) -> FloatArray:
    """Height of the struck relief (dish + relief + cracks) at die-frame points (N, 2), at ``age``."""
    xy = np.asarray(xy, dtype=np.float64)
    grid, fresh = die.relief()
    index = grid.fractional_index(xy)
    relief = ndimage.map_coordinates(fresh, index, order=1, mode="nearest").astype(np.float64)
    worn = ndimage.map_coordinates(_worn_field(die), index, order=1, mode="nearest")
    relief += age * (worn - relief)
    crack_grid = Grid.square((0.0, 0.0), die.params.extent_mm, die.params.pitch_mm)
    cracks = crack_relief(die, age, crack_grid, Placement())
    relief += ndimage.map_coordinates(cracks, crack_grid.fractional_index(xy), order=1, mode="nearest")
    return relief + die.dish(xy)


@functools.lru_cache(maxsize=WORN_CACHE_SIZE)
def _worn_field(die: Die) -> np.ndarray:
    """The relief at the end of the die's life: rounded and lowered (float32, cached)."""
    grid, fresh = die.relief()
    sigma = die.life.softening_blur_mm / grid.pitch
    worn = ndimage.gaussian_filter(fresh.astype(np.float64), sigma) if sigma > 0 else fresh.astype(np.float64)
    worn = (worn * (1.0 - die.life.relief_loss)).astype(np.float32)
    worn.setflags(write=False)
    return worn
