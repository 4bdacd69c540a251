"""The physics of a hoard by name: today's ``default``, the ``wide`` world, and the generalisation axes.

The world a user's scans come from (issue 13) is cut into axes, each with a documented range (``AXES``):
scanner (spacing, noise, smoothing, normals, holes, scanners mixed in one hoard), flan (cupping, bend,
broken), strike (weak, offcentre, double), wear and corrosion. An axis is set by a position x in [0, 1]
along its range: ``low`` (x = 0, the range's gentle end), ``middle`` (0.5), ``high`` (1, its hard end).

- ``axis_physics(axis, level)``: today's physics with one axis set (the benchmark's rows);
- ``hard``: every axis at ``high`` at once (the all-hard mix);
- ``wide``: a per-hoard draw (seeded by the hoard seed, stream ``("physics", "wide")``) of every axis
  over its whole range, and of 1-3 scanners that each face picks from; the per-coin and per-face values
  are then drawn from the resulting ranges as always (``face.sample_face_spec``);
- names: ``physics_by_name("default" | "wide" | "hard" | "AXIS:LEVEL")``, followed by ``,AXIS:LEVEL``
  overrides (``wide,noise:middle`` is the wide world with the noise held at its middle, the
  leave-one-out training world; ``noise:high,spacing:high`` two axes at once).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace

import numpy as np

from coindie.errors import ParameterError
from coindie.synth._params import new_field
from coindie.synth.circulation import CirculationParams
from coindie.synth.design import DieParams
from coindie.synth.life import LifeParams
from coindie.synth.plan import derived_seed
from coindie.synth.scanner import ScanParams
from coindie.synth.strike import StrikeParams


@dataclass(frozen=True)
class PhysicsParams:
    """The physics' parameters used for every face of a hoard (the per-face values are drawn from them).

    ``scanners``: other scanners of the hoard; when given, each face is scanned by one of
    ``(scan, *scanners)``, drawn uniformly per face (stream ``("scanner", face id)``), so that the two
    faces of a pair may come from different scanners.
    """

    die: DieParams = field(default_factory=DieParams)
    life: LifeParams = field(default_factory=LifeParams)
    strike: StrikeParams = field(default_factory=StrikeParams)
    circulation: CirculationParams = field(default_factory=CirculationParams)
    scan: ScanParams = field(default_factory=ScanParams)
    scanners: tuple[ScanParams, ...] = new_field(())

    def all_scanners(self) -> tuple[ScanParams, ...]:
        return (self.scan, *self.scanners)


LOW, MIDDLE, HIGH = "low", "middle", "high"
#: Levels of an axis and their position along its range.
LEVELS: dict[str, float] = {LOW: 0.0, MIDDLE: 0.5, HIGH: 1.0}

# The ranges (mm unless said).
SPACING_MM = (0.02, 0.15)
NOISE_MM = (0.003, 0.03)
SMOOTHING_MM = (0.0, 0.15)
HOLE_SHARE = (0.0, 0.15)
CUP_SD_MM = (0.0, 0.15)
WEAR = (0.0, 0.7)
CORROSION_SHARE = (0.0, 0.3)


@dataclass(frozen=True)
class Axis:
    """One axis of the wide world: its range in words, where it is drawn, and how x in [0, 1] sets it."""

    name: str
    range: str
    drawn: str
    apply: Callable[[PhysicsParams, float], PhysicsParams] = field(repr=False, compare=False)


def _lerp(bounds: tuple[float, float], x: float) -> float:
    return bounds[0] + x * (bounds[1] - bounds[0])


def _scans(physics: PhysicsParams, **changes: object) -> PhysicsParams:
    """Change every scanner of the hoard alike."""
    return replace(
        physics,
        scan=replace(physics.scan, **changes),
        scanners=tuple(replace(s, **changes) for s in physics.scanners),
    )


def _spacing(p: PhysicsParams, x: float) -> PhysicsParams:
    return _scans(p, spacing_mm=_lerp(SPACING_MM, x))


def _noise(p: PhysicsParams, x: float) -> PhysicsParams:
    v = _lerp(NOISE_MM, x)
    return _scans(p, noise_mm=(v, v))


def _smoothing(p: PhysicsParams, x: float) -> PhysicsParams:
    return _scans(p, smoothing_mm=_lerp(SMOOTHING_MM, x))


def _normals(p: PhysicsParams, x: float) -> PhysicsParams:
    return _scans(p, estimated_normals=x)


def _holes(p: PhysicsParams, x: float) -> PhysicsParams:
    v = _lerp(HOLE_SHARE, x)
    return _scans(p, hole_share=(v / 2, v))


def _mirror(value: float, bounds: tuple[float, float], x: float) -> float:
    """``value`` moved by x towards its mirror image in ``bounds`` (x = 1: the other end of the range)."""
    return value + x * (bounds[0] + bounds[1] - 2 * value)


def contrasting_scanner(scan: ScanParams, x: float) -> ScanParams:
    """Another scanner, x of the way to the mirror image of ``scan`` in the ranges of spacing, noise,
    smoothing and normals (x = 1 and today's 0.05 mm scanner: 0.12 mm, 0.023-0.028 mm noise, smoothed,
    estimated normals)."""
    lo, hi = scan.noise_mm
    noise = sorted(float(np.clip(_mirror(v, NOISE_MM, x), *NOISE_MM)) for v in (lo, hi))
    return replace(
        scan,
        spacing_mm=float(np.clip(_mirror(scan.spacing_mm, SPACING_MM, x), *SPACING_MM)),
        noise_mm=(noise[0], noise[1]),
        smoothing_mm=float(np.clip(_mirror(scan.smoothing_mm, SMOOTHING_MM, x), *SMOOTHING_MM)),
        estimated_normals=float(_mirror(scan.estimated_normals, (0.0, 1.0), x)),
    )


def _scanners(p: PhysicsParams, x: float) -> PhysicsParams:
    if x <= 0:
        return replace(p, scanners=())
    return replace(p, scanners=(contrasting_scanner(p.scan, x),))


def _cupping(p: PhysicsParams, x: float) -> PhysicsParams:
    return replace(p, strike=replace(p.strike, cup_mm=_lerp(CUP_SD_MM, x)))


def _bend(p: PhysicsParams, x: float) -> PhysicsParams:
    return replace(p, strike=replace(p.strike, bend_probability=0.5 * x, bend_angle_deg=(3.0, 6.0 + 9.0 * x)))


def _broken(p: PhysicsParams, x: float) -> PhysicsParams:
    strike = replace(p.strike, chunk_probability=0.5 * x, chunk_depth_mm=(0.8, 3.5 + 1.5 * x))
    return replace(p, strike=strike)


def _weak(p: PhysicsParams, x: float) -> PhysicsParams:
    strike = replace(
        p.strike,
        weak_probability=x,
        weak_zones_max=2,
        weak_radius_mm=(2.0 + 2.0 * x, 5.0 + 3.0 * x),
        weak_depth=(0.2 + 0.2 * x, 0.7 + 0.2 * x),
    )
    return replace(p, strike=strike)


def _offcentre(p: PhysicsParams, x: float) -> PhysicsParams:
    # Rayleigh scale of a sixth of a 21 mm diameter at x = 1, clipped at a third of the diameter.
    return replace(p, strike=replace(p.strike, off_centre_mm=3.5 * x, off_centre_max_share=x / 3))


def _double(p: PhysicsParams, x: float) -> PhysicsParams:
    strike = replace(p.strike, double_probability=0.5 * x, double_shift_mm=(0.2, 1.0 + 0.5 * x))
    return replace(p, strike=strike)


def _wear(p: PhysicsParams, x: float) -> PhysicsParams:
    top = _lerp(WEAR, x)
    return replace(p, circulation=replace(p.circulation, wear_min=top / 2, wear_max=top))


def _corrosion(p: PhysicsParams, x: float) -> PhysicsParams:
    v = _lerp(CORROSION_SHARE, x)
    circulation = replace(
        p.circulation,
        # Pits over ~v of the face (measured by circulation.dent_share: 0.30-0.34 at x = 1).
        pits_mean=25.0 + 3975.0 * x,
        pit_radius_mm=(0.02 + 0.03 * x, 0.08 + 0.12 * x),
        pit_clusters=int(round(3 + 9 * x)),
        pit_spread_mm=2.0 + 3.0 * x,
        crust_share=(v / 2, v),
    )
    return replace(p, circulation=circulation)


#: The axes in the order they are applied (scanner axes first: ``scanners`` mirrors the scanner they set).
AXES: dict[str, Axis] = {
    a.name: a
    for a in (
        Axis("spacing", "vertex spacing 0.02-0.15 mm", "scanner", _spacing),
        Axis("noise", "noise sd along the normal 0.003-0.03 mm", "scanner; face within its range", _noise),
        Axis("smoothing", "mesh smoothing sd 0-0.15 mm (raw to smoothed)", "scanner", _smoothing),
        Axis("normals", "share of faces with estimated (PCA) normals 0-1", "face", _normals),
        Axis("holes", "share of the face missing 0-0.15, in 1-3 blobs", "face (v/2-v)", _holes),
        Axis("scanners", "a second scanner, up to the mirror image of the first", "face", _scanners),
        Axis("cupping", "cupping sd at 10 mm 0-0.15 mm (differences up to ~±0.3)", "coin", _cupping),
        Axis("bend", "share of bent coins 0-0.5, fold 3-15 deg", "coin", _bend),
        Axis("broken", "share of broken flans 0-0.5, break 0.8-5 mm deep", "coin", _broken),
        Axis("weak", "weak zones on 0-100 % of coins, up to ~half the face", "coin", _weak),
        Axis("offcentre", "off-centre up to a third of the diameter", "coin", _offcentre),
        Axis("double", "share of double strikes 0-0.5", "coin", _double),
        Axis("wear", "relief lost on the high points up to 0.7 (coins v/2-v)", "coin", _wear),
        Axis("corrosion", "pits and crusts each over up to 0.3 of the face", "coin", _corrosion),
    )
}
SCANNER_AXES = ("spacing", "noise", "smoothing", "normals", "holes", "scanners")
#: The generalisation benchmark's rows: every (axis, level), then the all-hard mix.
BENCHMARK_ROWS: tuple[str, ...] = (*(f"{a}:{lvl}" for a in AXES for lvl in (LOW, HIGH)), "hard")


def _level(axis: str, level: str) -> float:
    if axis not in AXES:
        raise ParameterError(f"unknown physics axis {axis!r}; known: {', '.join(AXES)}")
    if level not in LEVELS:
        raise ParameterError(f"unknown level {level!r} of axis {axis!r}; known: {', '.join(LEVELS)}")
    return LEVELS[level]


def with_axes(physics: PhysicsParams, levels: Mapping[str, str]) -> PhysicsParams:
    """``physics`` with each named axis set to its level (applied in ``AXES`` order)."""
    positions = {axis: _level(axis, level) for axis, level in levels.items()}
    for axis in AXES:
        if axis in positions:
            physics = AXES[axis].apply(physics, positions[axis])
    return physics


def axis_physics(axis: str, level: str) -> PhysicsParams:
    """Today's physics with one axis at ``level`` (``low``, ``middle``, ``high``)."""
    return with_axes(PhysicsParams(), {axis: level})


def hard_physics() -> PhysicsParams:
    """Every axis at its hard extreme at once (the all-hard mix)."""
    return with_axes(PhysicsParams(), dict.fromkeys(AXES, HIGH))


def wide_physics(seed: int, held: Mapping[str, str] | None = None) -> PhysicsParams:
    """The wide world for the hoard of ``seed``: every axis drawn over its range for this hoard, and 1-3
    scanners (each face picks one); the axes in ``held`` are set to their level instead."""
    held = dict(held or {})
    for axis, level in held.items():
        _level(axis, level)
    rng = np.random.default_rng(derived_seed(seed, "physics", "wide"))
    n_scanners = int(rng.integers(1, 4))
    scanners = tuple(_wide_scanner(rng) for _ in range(n_scanners))
    physics = PhysicsParams(scan=scanners[0], scanners=scanners[1:])
    for axis in AXES:
        x = float(rng.random())  # drawn for every axis, held or not, so holding one leaves the others
        if axis in SCANNER_AXES:
            continue
        physics = AXES[axis].apply(physics, LEVELS[held[axis]] if axis in held else x)
    held_scanner = {a: lvl for a, lvl in held.items() if a in SCANNER_AXES}
    if "scanners" in held_scanner:
        physics = replace(physics, scanners=())
    return with_axes(physics, held_scanner)


def _wide_scanner(rng: np.random.Generator) -> ScanParams:
    """One scanner of the wide world: spacing, noise range, smoothing, normals and holes of its own."""
    spacing = float(rng.uniform(*SPACING_MM))
    noise = np.sort(rng.uniform(*NOISE_MM, 2))
    smoothing = float(rng.uniform(*SMOOTHING_MM)) if rng.random() < 0.5 else 0.0
    estimated = float(rng.random() < 0.5)
    holes = float(rng.uniform(*HOLE_SHARE))
    return ScanParams(
        spacing_mm=spacing,
        noise_mm=(float(noise[0]), float(noise[1])),
        smoothing_mm=smoothing,
        estimated_normals=estimated,
        hole_share=(0.0, holes),
    )


def rescanned(
    physics: PhysicsParams,
    *,
    noise_factor: float = 1.0,
    spacing_factor: float = 1.0,
    added_cup_mm: float = 0.0,
) -> PhysicsParams:
    """The same hoard's coins rescanned: every scanner's noise and spacing multiplied, and each coin's
    cupping changed by U(-added_cup_mm, +added_cup_mm) (0.15: differences up to ±0.3 mm at 10 mm).

    Made with the same preset and seed, the hoard has the same dies, coins, strikes and damage (those are
    drawn before the scan, and the added cupping after everything); only the scans differ.
    """

    def scaled(scan: ScanParams) -> ScanParams:
        lo, hi = scan.noise_mm
        return replace(
            scan,
            spacing_mm=scan.spacing_mm * spacing_factor,
            noise_mm=(lo * noise_factor, hi * noise_factor),
        )

    strike = replace(physics.strike, cup_added_mm=physics.strike.cup_added_mm + added_cup_mm)
    return replace(
        physics,
        scan=scaled(physics.scan),
        scanners=tuple(scaled(s) for s in physics.scanners),
        strike=strike,
    )


@dataclass(frozen=True)
class NamedPhysics:
    """A physics given by name; ``resolve(seed)`` gives the hoard's parameters (``wide`` draws them)."""

    name: str
    base: str
    levels: tuple[tuple[str, str], ...] = ()

    def resolve(self, seed: int) -> PhysicsParams:
        levels = dict(self.levels)
        if self.base == "wide":
            return wide_physics(seed, levels)
        start = hard_physics() if self.base == "hard" else PhysicsParams()
        return with_axes(start, levels)


#: Physics names besides ``AXIS:LEVEL``.
PHYSICS_NAMES = ("default", "wide", "hard")


def physics_by_name(name: str) -> NamedPhysics:
    """``default``, ``wide``, ``hard`` or ``AXIS:LEVEL``, then any ``,AXIS:LEVEL`` (see the module doc)."""
    tokens = [t.strip() for t in name.split(",") if t.strip()]
    if not tokens:
        raise ParameterError("empty physics name; use default, wide, hard or AXIS:LEVEL")
    base, canonical = "default", list(tokens)
    if ":" not in tokens[0]:
        base = tokens.pop(0)
        if base not in PHYSICS_NAMES:
            raise ParameterError(
                f"unknown physics {base!r}; known: {', '.join(PHYSICS_NAMES)}, or AXIS:LEVEL with an axis "
                f"of {', '.join(AXES)} and a level of {', '.join(LEVELS)}"
            )
    levels = []
    for token in tokens:
        axis, _, level = token.partition(":")
        _level(axis, level)
        levels.append((axis, level))
    return NamedPhysics(",".join(canonical), base, tuple(levels))
