"""Striking: a flan pressed between the dies takes the relief of the part of the die it covers.

The COIN frame has its origin at the flan's centre and z along the face's outward normal; a coin point p
lies over the die point p + offset (an off-centre strike shows another part of the die; the die's
engraved area is larger than the flan). Effects, each drawn per coin from ``StrikeParams``:

- irregular flan outline (low harmonics), rounded edge (the flan's rim never touches the die);
- off-centre strike; extra cupping or doming of the flan on top of the die face's own curvature;
- incomplete strike: in weak zones the metal did not fill the die's deepest hollows, so the highest
  relief is flattened (relief above a cap is removed, smoothly) - the field is untouched;
- double strike: a second, shifted and turned, fainter impression (a ghost of the design);
- bend: the coin folded along a line (applied to the scanned points: an isometric fold);
- chunks: pieces broken off the flan along straight breaks (the points are gone);
- flaws: deep voids of the flan (a fissure or crater, like the failure case L0059R of the paper).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from coindie.arrays import FloatArray
from coindie.params import Configurable
from coindie.synth import _raster
from coindie.synth._params import param
from coindie.synth._raster import Grid, Placement
from coindie.synth.life import relief_at

if TYPE_CHECKING:
    from coindie.synth.design import Die

#: Highest harmonic of the flan outline.
OUTLINE_HARMONICS = 6
#: Directions in the table the outline radius is interpolated from.
_OUTLINE_TABLE = 8192
#: Softness (mm) of the cap that flattens unfilled relief.
_FILL_SOFTNESS_MM = 0.015


@dataclass(frozen=True)
class StrikeParams(Configurable):
    """Ranges from which each coin's strike is drawn (``sample_strike``). Checked at construction."""

    flan_diameter_mm: tuple[float, float] = param(
        (20.0, 22.0), unit="mm", lo=4.0, hi=40.0, pair=True, doc="range of the flan's mean diameter"
    )
    outline_irregularity: float = param(
        0.03,
        unit="fraction",
        lo=0.0,
        hi=0.15,
        doc="sd of the relative amplitude of outline harmonic 2 (harmonic k: x (2/k)^1.5, k <= 6)",
    )
    off_centre_mm: float = param(
        0.8, unit="mm", lo=0.0, hi=8.0, doc="Rayleigh scale of the distance between flan and design centres"
    )
    off_centre_max_share: float = param(
        1.0,
        unit="fraction",
        lo=0.0,
        hi=1.0,
        new=True,
        doc="the distance between flan and design centres is clipped to this share of the flan's diameter",
    )
    cup_mm: float = param(
        0.02, unit="mm", lo=0.0, hi=1.0, doc="sd of the flan's extra cupping (+) or doming (-) at 10 mm"
    )
    cup_added_mm: float = param(
        0.0,
        unit="mm",
        lo=0.0,
        hi=1.0,
        new=True,
        doc="each coin's cupping at 10 mm changed by U(-a, a), drawn after all else (same coins, recupped)",
    )
    weak_probability: float = param(0.4, unit="probability", lo=0.0, hi=1.0, doc="chance of weak zones")
    weak_zones_max: int = param(2, unit="count", lo=1, hi=8, doc="at most this many weak zones")
    weak_radius_mm: tuple[float, float] = param(
        (2.0, 5.0), unit="mm", lo=0.2, hi=20.0, pair=True, doc="range of a weak zone's radius"
    )
    weak_depth: tuple[float, float] = param(
        (0.2, 0.7),
        unit="fraction",
        lo=0.0,
        hi=1.0,
        pair=True,
        doc="share of the relief left unfilled at its centre",
    )
    double_probability: float = param(
        0.02, unit="probability", lo=0.0, hi=1.0, doc="chance of a double strike"
    )
    double_shift_mm: tuple[float, float] = param(
        (0.2, 1.0), unit="mm", lo=0.0, hi=5.0, pair=True, doc="range of the second strike's shift"
    )
    double_rotation_deg: float = param(3.0, unit="deg", lo=0.0, hi=45.0, doc="sd of the second strike's turn")
    double_strength: tuple[float, float] = param(
        (0.2, 0.5), unit="fraction", lo=0.0, hi=1.0, pair=True, doc="ghost height relative to the design"
    )
    bend_probability: float = param(0.02, unit="probability", lo=0.0, hi=1.0, doc="chance of a bent coin")
    bend_angle_deg: tuple[float, float] = param(
        (3.0, 12.0), unit="deg", lo=0.0, hi=60.0, pair=True, doc="range of the fold angle"
    )
    chunk_probability: float = param(0.03, unit="probability", lo=0.0, hi=1.0, doc="chance of a broken flan")
    chunk_depth_mm: tuple[float, float] = param(
        (0.8, 3.5), unit="mm", lo=0.0, hi=10.0, pair=True, doc="how far a straight break cuts into the flan"
    )
    flaw_probability: float = param(0.03, unit="probability", lo=0.0, hi=1.0, doc="chance of a flan flaw")
    flaw_length_mm: tuple[float, float] = param(
        (1.0, 5.0), unit="mm", lo=0.05, hi=20.0, pair=True, doc="range of a flaw's length"
    )
    flaw_width_mm: tuple[float, float] = param(
        (0.3, 1.2), unit="mm", lo=0.05, hi=10.0, pair=True, doc="range of a flaw's width"
    )
    flaw_depth_mm: tuple[float, float] = param(
        (0.15, 0.6), unit="mm", lo=0.0, hi=3.0, pair=True, doc="range of a flaw's depth"
    )
    edge_roll_mm: tuple[float, float] = param(
        (0.3, 0.6), unit="mm", lo=0.0, hi=3.0, pair=True, doc="range of the width of the flan's rounded rim"
    )
    edge_drop_mm: tuple[float, float] = param(
        (0.1, 0.3), unit="mm", lo=0.0, hi=2.0, pair=True, doc="range of how far the rim falls off"
    )


@dataclass(frozen=True)
class WeakZone:
    """A weakly struck zone: a compact bump of ``radius_mm`` around ``centre`` (coin frame) where the relief
    is capped at (1 - depth) of the design's top height."""

    centre: tuple[float, float]
    radius_mm: float
    depth: float


@dataclass(frozen=True)
class DoubleStrike:
    """The second impression: its placement relative to the first (coin frame) and its relative height."""

    shift_mm: tuple[float, float]
    rotation_deg: float
    strength: float


@dataclass(frozen=True)
class Bend:
    """A fold along the line {p : p . u(axis) = distance_mm}; the side beyond it turns by ``angle_deg``
    (positive: up) over a ``width_mm`` wide band."""

    axis_deg: float
    distance_mm: float
    angle_deg: float
    width_mm: float


@dataclass(frozen=True)
class Chunk:
    """A straight break: the flan is cut off ``depth_mm`` inside its rim, in direction ``angle_deg``."""

    angle_deg: float
    depth_mm: float


@dataclass(frozen=True)
class Flaw:
    """A void in the flan: an elongated, flat-bottomed depression (coin frame)."""

    centre: tuple[float, float]
    length_mm: float
    width_mm: float
    angle_deg: float
    depth_mm: float


@dataclass(frozen=True)
class StrikeSpec:
    """One coin's strike (all lengths in mm, coin frame unless said)."""

    flan_radius_mm: float
    outline: tuple[tuple[float, float], ...]  # (relative amplitude, phase rad) of harmonics 2, 3, ...
    offset_mm: tuple[float, float]  # the die-frame point under the flan's centre
    cup_mm: float
    edge_roll_mm: float
    edge_drop_mm: float
    weak: tuple[WeakZone, ...] = ()
    double: DoubleStrike | None = None
    bend: Bend | None = None
    chunks: tuple[Chunk, ...] = ()
    flaws: tuple[Flaw, ...] = field(default=())

    @property
    def placement(self) -> Placement:
        """Coin frame -> die frame."""
        return Placement(0.0, self.offset_mm)


def sample_strike(rng: np.random.Generator, params: StrikeParams) -> StrikeSpec:
    """Draw one coin's strike from ``params``."""
    radius = rng.uniform(*params.flan_diameter_mm) / 2
    # Amplitudes fall as (2/k)^1.5 with the harmonic k: a flan is irregular at large scales, smooth at small.
    outline = tuple(
        (
            float(abs(rng.normal(0.0, params.outline_irregularity * (2 / k) ** 1.5))),
            float(rng.uniform(0, 2 * np.pi)),
        )
        for k in range(2, OUTLINE_HARMONICS + 1)
    )
    a = rng.uniform(0, 2 * np.pi)
    distance = rng.rayleigh(params.off_centre_mm) if params.off_centre_mm else 0.0
    if params.off_centre_max_share < 1.0:
        distance = min(distance, params.off_centre_max_share * 2 * radius)
    offset = distance * np.array([np.cos(a), np.sin(a)]) if params.off_centre_mm else (0, 0)
    return StrikeSpec(
        flan_radius_mm=float(radius),
        outline=outline,
        offset_mm=(float(offset[0]), float(offset[1])),
        cup_mm=float(rng.normal(0.0, params.cup_mm)),
        edge_roll_mm=float(rng.uniform(*params.edge_roll_mm)),
        edge_drop_mm=float(rng.uniform(*params.edge_drop_mm)),
        weak=_weak_zones(rng, params, radius),
        double=_double(rng, params),
        bend=_bend(rng, params, radius),
        chunks=_chunks(rng, params),
        flaws=_flaws(rng, params, radius),
    )


def _in_disc(rng: np.random.Generator, radius: float) -> tuple[float, float]:
    r, a = radius * np.sqrt(rng.random()), rng.uniform(0, 2 * np.pi)
    return (float(r * np.cos(a)), float(r * np.sin(a)))


def _weak_zones(rng: np.random.Generator, params: StrikeParams, radius: float) -> tuple[WeakZone, ...]:
    if rng.random() >= params.weak_probability:
        return ()
    n = int(rng.integers(1, params.weak_zones_max + 1))
    # Weakly struck areas are most often towards the rim, where the flan was thinner.
    zones = []
    for _ in range(n):
        r, a = radius * rng.uniform(0.4, 1.0), rng.uniform(0, 2 * np.pi)
        zones.append(
            WeakZone(
                (float(r * np.cos(a)), float(r * np.sin(a))),
                float(rng.uniform(*params.weak_radius_mm)),
                float(rng.uniform(*params.weak_depth)),
            )
        )
    return tuple(zones)


def _double(rng: np.random.Generator, params: StrikeParams) -> DoubleStrike | None:
    if rng.random() >= params.double_probability:
        return None
    a = rng.uniform(0, 2 * np.pi)
    d = rng.uniform(*params.double_shift_mm)
    return DoubleStrike(
        (float(d * np.cos(a)), float(d * np.sin(a))),
        float(rng.normal(0.0, params.double_rotation_deg)),
        float(rng.uniform(*params.double_strength)),
    )


def _bend(rng: np.random.Generator, params: StrikeParams, radius: float) -> Bend | None:
    if rng.random() >= params.bend_probability:
        return None
    sign = rng.choice([-1.0, 1.0])
    # The fold line lies off the centre and the smaller side turns (an edge bent up or down), so the
    # die-frame truth of the coin holds for most of its face.
    return Bend(
        float(rng.uniform(0, 360)),
        float(rng.uniform(0.2, 0.6) * radius),
        float(sign * rng.uniform(*params.bend_angle_deg)),
        float(rng.uniform(1.0, 3.0)),
    )


def _chunks(rng: np.random.Generator, params: StrikeParams) -> tuple[Chunk, ...]:
    if rng.random() >= params.chunk_probability:
        return ()
    return (Chunk(float(rng.uniform(0, 360)), float(rng.uniform(*params.chunk_depth_mm))),)


def _flaws(rng: np.random.Generator, params: StrikeParams, radius: float) -> tuple[Flaw, ...]:
    if rng.random() >= params.flaw_probability:
        return ()
    return (
        Flaw(
            _in_disc(rng, 0.8 * radius),
            float(rng.uniform(*params.flaw_length_mm)),
            float(rng.uniform(*params.flaw_width_mm)),
            float(rng.uniform(0, 180)),
            float(rng.uniform(*params.flaw_depth_mm)),
        ),
    )


# --- the flan's outline ----------------------------------------------------------------------------------


def outline_radius(spec: StrikeSpec, phi: FloatArray) -> FloatArray:
    """Radius (mm) of the flan's outline in direction ``phi`` (rad, coin frame), breaks included.

    Interpolated in a table of 8192 directions (1e-5 mm off the exact curve; ten times faster on a grid).
    """
    table_phi = np.linspace(-np.pi, np.pi, _OUTLINE_TABLE, endpoint=False)
    table = _exact_outline_radius(spec, table_phi)
    return np.interp(np.asarray(phi, dtype=np.float64), table_phi, table, period=2 * np.pi)


def _exact_outline_radius(spec: StrikeSpec, phi: FloatArray) -> FloatArray:
    wave = sum(a * np.cos(k * phi + p) for k, (a, p) in enumerate(spec.outline, start=2))
    r = spec.flan_radius_mm * (1.0 + wave)
    for chunk in spec.chunks:
        # A straight break: the chord at distance (radius - depth) from the centre, normal to angle_deg.
        at = np.radians(chunk.angle_deg)
        d = spec.flan_radius_mm - chunk.depth_mm
        cos = np.cos(phi - at)
        r = np.where(cos > 1e-6, np.minimum(r, d / np.maximum(cos, 1e-6)), r)
    return r


def max_radius(spec: StrikeSpec) -> float:
    return spec.flan_radius_mm * (1.0 + sum(a for a, _ in spec.outline))


# --- the struck surface ----------------------------------------------------------------------------------


@dataclass
class Surface:
    """A struck face on a coin-frame grid: height = base (the flan's shape) + relief (the design)."""

    grid: Grid
    base: FloatArray
    relief: FloatArray
    inside_depth: FloatArray  # distance (mm) inside the outline (negative outside)

    @property
    def height(self) -> FloatArray:
        return self.base + self.relief

    def design_top(self) -> float:
        """A robust top height of the relief on the flan (99.5th percentile)."""
        on_flan = self.relief[self.inside_depth > 0]
        return float(np.percentile(on_flan, 99.5)) if on_flan.size else 0.0


def coin_grid(spec: StrikeSpec, pitch: float) -> Grid:
    """A square coin-frame grid covering the flan with a small margin."""
    return Grid.square((0.0, 0.0), 2 * max_radius(spec) + 0.4, pitch)


def strike(die: Die, age: float, spec: StrikeSpec, grid: Grid) -> Surface:
    """The face struck by ``die`` at ``age`` with the strike ``spec``, on ``grid`` (coin frame)."""
    X, Y = grid.coords()
    placement = spec.placement
    relief = relief_at(die, age, grid, placement)
    if spec.double is not None:
        relief = _double_strike(die, age, spec, grid, relief)
    depth = _inside_depth(spec, X, Y)
    surface = Surface(grid, _flan_base(die, spec, X, Y, depth), relief, depth)
    top = surface.design_top()
    for zone in spec.weak:
        _weaken(surface, zone, top)
    for flaw in spec.flaws:
        _raster.paste_add(surface.base, _flaw_patch(grid, flaw), sign=-1.0)
    return surface


def _flan_base(die: Die, spec: StrikeSpec, X: FloatArray, Y: FloatArray, depth: FloatArray) -> FloatArray:
    """Die face curvature seen through the offset, the flan's own cupping, and its rounded rim."""
    die_xy = np.stack([X + spec.offset_mm[0], Y + spec.offset_mm[1]], axis=-1)
    base = die.dish(die_xy) + spec.cup_mm * (X * X + Y * Y) / 100.0
    if spec.edge_roll_mm > 0:
        fall = np.clip(1.0 - depth / spec.edge_roll_mm, 0.0, 1.0)
        base -= spec.edge_drop_mm * fall * fall
    return base


def _inside_depth(spec: StrikeSpec, X: FloatArray, Y: FloatArray) -> FloatArray:
    """Radial distance inside the outline (a close stand-in for the distance to it: the outline is nearly
    circular)."""
    return outline_radius(spec, np.arctan2(Y, X)) - np.hypot(X, Y)


def _double_strike(die: Die, age: float, spec: StrikeSpec, grid: Grid, relief: FloatArray) -> FloatArray:
    second = spec.double
    assert second is not None
    shifted = Placement(
        np.radians(second.rotation_deg),
        (spec.offset_mm[0] + second.shift_mm[0], spec.offset_mm[1] + second.shift_mm[1]),
    )
    ghost = relief_at(die, age, grid, shifted, cracks=False)
    return np.maximum(relief, second.strength * ghost)


def _weaken(surface: Surface, zone: WeakZone, top: float) -> None:
    """Flatten the relief above (1 - depth) x top inside the zone, smoothly fading to nothing at its edge."""
    c = np.asarray(zone.centre)
    sub = surface.grid.window(c - zone.radius_mm, c + zone.radius_mm)
    if sub is None:
        return
    rows, cols, win = sub
    X, Y = win.coords()
    d2 = ((X - c[0]) ** 2 + (Y - c[1]) ** 2) / zone.radius_mm**2
    bump = np.clip(1.0 - d2, 0.0, None) ** 2
    cap = (1.0 - zone.depth) * top
    relief = surface.relief[rows, cols]
    excess = _FILL_SOFTNESS_MM * np.logaddexp(0.0, (relief - cap) / _FILL_SOFTNESS_MM)
    surface.relief[rows, cols] = relief - bump * excess


def _flaw_patch(grid: Grid, flaw: Flaw) -> _raster.Patch | None:
    return _raster.ellipse(
        grid,
        flaw.centre,
        (flaw.length_mm / 2, flaw.width_mm / 2),
        np.radians(flaw.angle_deg),
        flaw.depth_mm,
        0.25,
    )


# --- bending (applied to points: an isometric fold) -------------------------------------------------------


def bend_points(bend: Bend, points: FloatArray, normals: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Fold coin-frame points and normals (N, 3) along the bend's line.

    Along s = p . u - distance the sheet turns by theta(s), rising smoothly from 0 (s <= 0) to the fold
    angle (s >= width); the fold keeps lengths: the mid-surface point at s goes to (S(s), Z(s)) with
    S' = cos(theta), Z' = sin(theta), and the height above it goes along the turned normal.
    """
    u = np.array([np.cos(np.radians(bend.axis_deg)), np.sin(np.radians(bend.axis_deg)), 0.0])
    s = points @ u - bend.distance_mm
    table = np.linspace(0.0, max(float(s.max()), 0.0) + 1e-6, 4096)
    theta = np.radians(bend.angle_deg) * _smoothstep(table / bend.width_mm)
    step = np.diff(table, prepend=0.0)
    S, Z = np.cumsum(np.cos(theta) * step), np.cumsum(np.sin(theta) * step)
    t = np.clip(s, 0.0, None)
    th = np.interp(t, table, theta)
    along = np.where(s > 0, np.interp(t, table, S), s)
    lift = np.where(s > 0, np.interp(t, table, Z), 0.0)
    z = points[:, 2]
    new_s = along - z * np.sin(th)
    new_z = lift + z * np.cos(th)
    out = points + np.outer(new_s - s, u)
    out[:, 2] = new_z
    n_s = normals @ u
    turned_s = n_s * np.cos(th) - normals[:, 2] * np.sin(th)
    turned_z = n_s * np.sin(th) + normals[:, 2] * np.cos(th)
    new_normals = normals + np.outer(turned_s - n_s, u)
    new_normals[:, 2] = turned_z
    return out, new_normals


def _smoothstep(x: FloatArray) -> FloatArray:
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3.0 - 2.0 * x)


# --- measures of a drawn strike (for the wide world's documented ranges) -----------------------------------


def weak_share(spec: StrikeSpec, pitch: float = 0.1) -> float:
    """Share of the flan (inside its outline) that lies in some weak zone (within a zone's radius)."""
    grid = coin_grid(spec, pitch)
    X, Y = grid.coords()
    on_flan = _inside_depth(spec, X, Y) > 0
    weak = np.zeros(X.shape, dtype=bool)
    for zone in spec.weak:
        weak |= (X - zone.centre[0]) ** 2 + (Y - zone.centre[1]) ** 2 < zone.radius_mm**2
    return float((weak & on_flan).sum() / max(int(on_flan.sum()), 1))
