"""Circulation: what happens to a coin between its strike and its scan.

- wear: the high points rub first. The relief r becomes r (1 - w r / top): the design's top loses a
  share ``w`` of its height, lower relief proportionally less, the field nothing; above w = 0.5 (where
  that curve would fold over) the w = 0.5 curve is planed off at (1 - w) top;
- scratches: thin V-shaped grooves along slightly bowed lines;
- nicks: small dents with sharp edges (knocks against other coins);
- corrosion pits: many tiny pits, gathered around a few corrosion spots;
- corrosion crusts (off by default): raised, irregular patches of corrosion products over a share of the
  face, a smooth random field thresholded so that exactly that share of the flan is covered.

The Riedones hoard barely circulated (the paper), so the defaults keep wear low.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np
from scipy import ndimage

from coindie.params import Configurable, Rule
from coindie.synth import _raster
from coindie.synth._params import new_field, param
from coindie.synth.strike import Surface

#: Softness (mm) of the plane that heavy wear (over half the top's height) cuts the relief with.
_WEAR_SOFTNESS_MM = 0.01


@dataclass(frozen=True)
class CirculationParams(Configurable):
    """Ranges from which each coin's circulation damage is drawn (``sample_circulation``)."""

    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(("wear_min", "wear_max"), lambda p: p.wear_min <= p.wear_max, "wear_min <= wear_max"),
    )

    wear_max: float = param(
        0.25,
        unit="fraction",
        lo=0.0,
        hi=0.9,
        doc="most height lost at the design's top; a coin draws wear_max * U^2",
    )
    wear_min: float = param(
        0.0,
        unit="fraction",
        lo=0.0,
        hi=0.9,
        new=True,
        doc="least height lost at the design's top; a coin draws wear_min + (wear_max - wear_min) * U^2",
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
    crust_share: tuple[float, float] = param(
        (0.0, 0.0),
        unit="fraction",
        lo=0.0,
        hi=0.6,
        pair=True,
        new=True,
        doc="range of the share of the face under corrosion crusts",
    )
    crust_height_mm: tuple[float, float] = param(
        (0.02, 0.15), unit="mm", lo=0.0, hi=0.5, pair=True, new=True, doc="range of the crusts' height"
    )
    crust_patch_mm: float = param(
        1.0, unit="mm", lo=0.1, hi=10.0, new=True, doc="size (Gaussian sigma) of the crusts' patches"
    )


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
    crust_share: float = new_field(0.0)
    crust_height_mm: float = new_field(0.0)
    crust_patch_mm: float = new_field(1.0)
    crust_seed: int = new_field(0)


def sample_circulation(rng: np.random.Generator, params: CirculationParams, radius: float) -> CirculationSpec:
    """Draw one coin's damage; ``radius`` (mm) is the flan's. Crusts are drawn last and only where they
    are switched on, so that the damage of the default parameters is the same as before they existed."""
    spec = CirculationSpec(
        wear=float(params.wear_min + (params.wear_max - params.wear_min) * rng.random() ** 2),
        scratches=tuple(_scratch(rng, params, radius) for _ in range(rng.poisson(params.scratches_mean))),
        nicks=tuple(
            _dent(rng, _in_disc(rng, radius), params.nick_radius_mm, params.nick_depth_mm)
            for _ in range(rng.poisson(params.nicks_mean))
        ),
        pits=_pits(rng, params, radius),
    )
    if params.crust_share[1] <= 0:
        return spec
    return replace(
        spec,
        crust_share=float(rng.uniform(*params.crust_share)),
        crust_height_mm=float(rng.uniform(*params.crust_height_mm)),
        crust_patch_mm=params.crust_patch_mm,
        crust_seed=int(rng.integers(2**31)),
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
        if spec.wear <= 0.5:
            surface.relief = r * (1.0 - spec.wear * np.clip(r, 0.0, None) / top)
        else:
            # r (1 - w r / top) stops rising at r = top / 2w: above w = 0.5 it would turn the high points
            # into hollows. Heavier wear keeps the w = 0.5 curve (flat at the top) and planes it off at the
            # height (1 - w) top, softly (a soft minimum over _WEAR_SOFTNESS_MM), as a worn coin's plateaus.
            worn = r * (1.0 - 0.5 * np.clip(r, 0.0, None) / top)
            cap = (1.0 - spec.wear) * top
            surface.relief = cap - _WEAR_SOFTNESS_MM * np.logaddexp(0.0, (cap - worn) / _WEAR_SOFTNESS_MM)
    grid = surface.grid
    for scratch in spec.scratches:
        _raster.paste_add(surface.relief, _groove(grid, scratch), sign=-1.0)
    for dent in spec.nicks + spec.pits:
        patch = _raster.ellipse(grid, dent.centre, (dent.radius_mm,) * 2, 0.0, dent.depth_mm, 0.5)
        _raster.paste_add(surface.relief, patch, sign=-1.0)
    if spec.crust_share > 0 and spec.crust_height_mm > 0:
        surface.relief = surface.relief + crust_heights(surface, spec)


def crust_heights(surface: Surface, spec: CirculationSpec) -> np.ndarray:
    """Heights (mm) of the coin's crusts on its grid: zero outside the crusts, exactly ``crust_share`` of the
    flan's pixels covered.

    The patches are a Gaussian random field drawn on a lattice fixed in the coin frame (pitch: a third of
    the patch size) and interpolated, so the same coin gets the same crusts whatever the scanner's spacing;
    their surface is rough (a finer field) and their edges rise over a short ramp.
    """
    grid = surface.grid
    rng = np.random.default_rng([spec.crust_seed, 1913])
    patches = _coin_field(rng, grid, spec.crust_patch_mm / 3, 3.0)
    rough = _coin_field(rng, grid, 0.05, 2.0)
    on_flan = surface.inside_depth > 0
    if not on_flan.any():
        return np.zeros(grid.shape)
    threshold = np.quantile(patches[on_flan], 1.0 - spec.crust_share)
    ramp = np.clip((patches - threshold) / 0.3, 0.0, 1.0)
    texture = 0.6 + 0.4 * (0.5 + 0.5 * np.tanh(rough))
    return spec.crust_height_mm * np.sqrt(ramp) * texture * on_flan


def _coin_field(rng: np.random.Generator, grid: _raster.Grid, pitch: float, sigma_px: float) -> np.ndarray:
    """A unit-sd smooth Gaussian field drawn on a coin-frame lattice of ``pitch`` mm centred on the coin,
    read on ``grid``."""
    X, Y = grid.coords()
    # A fixed extent (50 mm, or the grid's if larger): the lattice, so the field, does not depend on the grid.
    half = max(25.0, float(np.abs(X).max()), float(np.abs(Y).max()))
    n = int(np.ceil(2 * half / pitch)) + 1
    field = ndimage.gaussian_filter(rng.standard_normal((n, n)), sigma_px, mode="wrap")
    field /= max(float(field.std()), 1e-12)
    index = np.stack([(Y + half) / pitch, (X + half) / pitch])
    return ndimage.map_coordinates(field, index, order=1, mode="nearest")


def _groove(grid: _raster.Grid, scratch: Scratch) -> _raster.Patch | None:
    a, b = np.asarray(scratch.start), np.asarray(scratch.end)
    d = b - a
    normal = np.array([-d[1], d[0]]) / max(float(np.linalg.norm(d)), 1e-9)
    t = np.linspace(0.0, 1.0, 9)
    control = a + np.outer(t, d) + np.outer(4 * t * (1 - t) * scratch.bow_mm, normal)
    samples, _ = _raster.sample_curve(control, False, 0.4 * grid.pitch)
    n = len(samples)
    return _raster.ridge(grid, samples, np.full(n, scratch.half_width_mm), np.full(n, scratch.depth_mm), 1.0)


def dent_share(dents: tuple[Dent, ...], radius: float, pitch: float = 0.05) -> float:
    """Share of a flan disc of ``radius`` (mm, centred) covered by the dents (pits, nicks): a measure of a
    drawn coin's corrosion, for the documented ranges."""
    axis = np.arange(-radius, radius, pitch) + pitch / 2
    X, Y = np.meshgrid(axis, axis)
    on_flan = X * X + Y * Y < radius * radius
    hit = np.zeros(X.shape, dtype=bool)
    for dent in dents:
        (cx, cy), r = dent.centre, dent.radius_mm
        i0, i1 = np.searchsorted(axis, [cy - r, cy + r])
        j0, j1 = np.searchsorted(axis, [cx - r, cx + r])
        window = (slice(i0, i1), slice(j0, j1))
        hit[window] |= (X[window] - cx) ** 2 + (Y[window] - cy) ** 2 < r * r
    return float((hit & on_flan).sum() / max(int(on_flan.sum()), 1))
