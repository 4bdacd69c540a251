"""Circulation: what happens to a coin between its strike and its scan.

- wear: the high points rub first. The relief r becomes r (1 - w r / top): the design's top loses a
  share ``w`` of its height, lower relief proportionally less, the field nothing;
- scratches: thin V-shaped grooves along slightly bowed lines;
- nicks: small dents with sharp edges (knocks against other coins);
- corrosion pits: many tiny pits, gathered around a few corrosion spots.

The Riedones hoard barely circulated (the paper), so the defaults keep wear low.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from coindie.synth import _raster
from coindie.synth._params import check_ranges, param
from coindie.synth.strike import Surface


@dataclass(frozen=True)
class CirculationParams:
    """Ranges from which each coin's circulation damage is drawn (``sample_circulation``)."""

    wear_max: float = param(
        0.25,
        unit="fraction",
        lo=0.0,
        hi=0.9,
        doc="most height lost at the design's top; a coin draws wear_max * U^2",
    )
    scratches_mean: float = param(1.5, unit="count", lo=0.0, hi=50.0, doc="Poisson mean of scratches")
    scratch_length_mm: tuple[float, float] = param(
        (1.0, 8.0), unit="mm", lo=0.05, hi=40.0, pair=True, doc="range of a scratch's length"
    )
    scratch_half_width_mm: tuple[float, float] = param(
        (0.02, 0.05), unit="mm", lo=0.005, hi=1.0, pair=True, doc="range of a scratch's half-width"
    )
    scratch_depth_mm: tuple[float, float] = param(
        (0.01, 0.04), unit="mm", lo=0.0, hi=1.0, pair=True, doc="range of a scratch's depth"
    )
    nicks_mean: float = param(0.8, unit="count", lo=0.0, hi=50.0, doc="Poisson mean of nicks")
    nick_radius_mm: tuple[float, float] = param(
        (0.1, 0.4), unit="mm", lo=0.01, hi=5.0, pair=True, doc="range of a nick's radius"
    )
    nick_depth_mm: tuple[float, float] = param(
        (0.04, 0.15), unit="mm", lo=0.0, hi=2.0, pair=True, doc="range of a nick's depth"
    )
    pits_mean: float = param(25.0, unit="count", lo=0.0, hi=5000.0, doc="Poisson mean of corrosion pits")
    pit_radius_mm: tuple[float, float] = param(
        (0.02, 0.08), unit="mm", lo=0.005, hi=2.0, pair=True, doc="range of a pit's radius"
    )
    pit_depth_mm: tuple[float, float] = param(
        (0.01, 0.05), unit="mm", lo=0.0, hi=1.0, pair=True, doc="range of a pit's depth"
    )
    pit_clusters: int = param(3, unit="count", lo=1, hi=50, doc="corrosion spots the pits gather around")
    pit_spread_mm: float = param(2.0, unit="mm", lo=0.05, hi=30.0, doc="sd of a pit's distance to its spot")

    def __post_init__(self) -> None:
        check_ranges(self)


@dataclass(frozen=True)
class Scratch:
    """A groove from ``start`` to ``end`` (coin frame, mm), bowed sideways by ``bow_mm`` at its middle."""

    start: tuple[float, float]
    end: tuple[float, float]
    bow_mm: float
    half_width_mm: float
    depth_mm: float


@dataclass(frozen=True)
class Dent:
    """A spherical dent (nick or pit) at ``centre`` (coin frame)."""

    centre: tuple[float, float]
    radius_mm: float
    depth_mm: float


@dataclass(frozen=True)
class CirculationSpec:
    """One coin's circulation damage."""

    wear: float = 0.0
    scratches: tuple[Scratch, ...] = ()
    nicks: tuple[Dent, ...] = ()
    pits: tuple[Dent, ...] = ()


def sample_circulation(rng: np.random.Generator, params: CirculationParams, radius: float) -> CirculationSpec:
    """Draw one coin's damage; ``radius`` (mm) is the flan's."""
    return CirculationSpec(
        wear=float(params.wear_max * rng.random() ** 2),
        scratches=tuple(_scratch(rng, params, radius) for _ in range(rng.poisson(params.scratches_mean))),
        nicks=tuple(
            _dent(rng, _in_disc(rng, radius), params.nick_radius_mm, params.nick_depth_mm)
            for _ in range(rng.poisson(params.nicks_mean))
        ),
        pits=_pits(rng, params, radius),
    )


def _in_disc(rng: np.random.Generator, radius: float) -> np.ndarray:
    r, a = radius * np.sqrt(rng.random()), rng.uniform(0, 2 * np.pi)
    return np.array([r * np.cos(a), r * np.sin(a)])


def _scratch(rng: np.random.Generator, params: CirculationParams, radius: float) -> Scratch:
    start = _in_disc(rng, radius)
    length, a = rng.uniform(*params.scratch_length_mm), rng.uniform(0, 2 * np.pi)
    end = start + length * np.array([np.cos(a), np.sin(a)])
    return Scratch(
        (float(start[0]), float(start[1])),
        (float(end[0]), float(end[1])),
        float(rng.normal(0.0, 0.08 * length)),
        float(rng.uniform(*params.scratch_half_width_mm)),
        float(rng.uniform(*params.scratch_depth_mm)),
    )


def _dent(
    rng: np.random.Generator, at: np.ndarray, radius: tuple[float, float], depth: tuple[float, float]
) -> Dent:
    return Dent((float(at[0]), float(at[1])), float(rng.uniform(*radius)), float(rng.uniform(*depth)))


def _pits(rng: np.random.Generator, params: CirculationParams, radius: float) -> tuple[Dent, ...]:
    n = rng.poisson(params.pits_mean)
    spots = np.array([_in_disc(rng, radius) for _ in range(params.pit_clusters)])
    which = rng.integers(params.pit_clusters, size=n)
    at = spots[which] + rng.normal(0.0, params.pit_spread_mm, (n, 2))
    return tuple(_dent(rng, p, params.pit_radius_mm, params.pit_depth_mm) for p in at)


def circulate(surface: Surface, spec: CirculationSpec) -> None:
    """Apply the damage to ``surface`` in place."""
    if spec.wear > 0:
        top = max(surface.design_top(), 1e-6)
        r = surface.relief
        surface.relief = r * (1.0 - spec.wear * np.clip(r, 0.0, None) / top)
    grid = surface.grid
    for scratch in spec.scratches:
        _raster.paste_add(surface.relief, _groove(grid, scratch), sign=-1.0)
    for dent in spec.nicks + spec.pits:
        patch = _raster.ellipse(grid, dent.centre, (dent.radius_mm,) * 2, 0.0, dent.depth_mm, 0.5)
        _raster.paste_add(surface.relief, patch, sign=-1.0)


def _groove(grid: _raster.Grid, scratch: Scratch) -> _raster.Patch | None:
    a, b = np.asarray(scratch.start), np.asarray(scratch.end)
    d = b - a
    normal = np.array([-d[1], d[0]]) / max(float(np.linalg.norm(d)), 1e-9)
    t = np.linspace(0.0, 1.0, 9)
    control = a + np.outer(t, d) + np.outer(4 * t * (1 - t) * scratch.bow_mm, normal)
    samples, _ = _raster.sample_curve(control, False, 0.4 * grid.pitch)
    n = len(samples)
    return _raster.ridge(grid, samples, np.full(n, scratch.half_width_mm), np.full(n, scratch.depth_mm), 1.0)
