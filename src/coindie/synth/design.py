"""Coin types and dies: the relief a die strikes, as a height field in the die frame.

A *type* is a shared design (a head with locks of hair, the same head with a beard, a horse above a
wheel), made of relief primitives (``_primitives``: ridges along curves, domes). A *die* is one
hand-engraved copy of a type: the engraver places every element again, so each stroke of a die is
shifted (0.05-0.3 mm), slightly turned and bent, made a little wider or narrower, higher or lower
(10-20 %), a minor element may be left out, and a few die-specific ornaments are added (an extra pellet,
a small crescent, one lock drawn differently). Dies of one type therefore differ only in details, which
makes die clustering fine-grained.

Frames: the die frame has the die's working face in the plane z = 0 and the design centred at (0, 0);
heights are those of the struck coin (the mirror of the engraving): relief(x, y) >= 0 plus the die face's
curvature (``Die.dish``: obverse dies domed, reverse dies hollow, as the scyphate Armorican staters).
The engraved area (``DieParams.extent_mm``, 30 mm) is larger than the 20-22 mm coins.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np
from scipy import ndimage

from coindie.arrays import FloatArray
from coindie.errors import ParameterError
from coindie.params import Configurable
from coindie.synth import _motifs
from coindie.synth._params import param
from coindie.synth._primitives import Primitive, Stroke, n_control, pellet, rasterise_relief
from coindie.synth._raster import Grid, Placement, resample
from coindie.synth.life import DEFAULT_LIFE, Crack, LifeParams, draw_cracks

#: Radius (mm) at which ``DieParams.sagitta_mm`` is measured.
DISH_RADIUS_MM = 10.0
#: Die relief fields kept per process (each ~6 MB at the default 0.025 mm pitch over 30 mm).
DIE_CACHE_SIZE = 24


class Family(StrEnum):
    """The three designs of the hoard."""

    OBVERSE = "obverse"
    BEARD = "beard"
    REVERSE = "reverse"


@dataclass(frozen=True)
class TypeDesign:
    """The shared design of a coin type: relief primitives in the die frame (mm)."""

    family: Family
    seed: int
    primitives: tuple[Primitive, ...] = field(repr=False)


def make_type(family: Family | str, seed: int) -> TypeDesign:
    """The design of one coin type of ``family``; ``seed`` varies positions (~0.3 mm) and counts."""
    try:
        family = Family(family)
    except ValueError:
        raise ParameterError(f"unknown coin family {family!r}; known: {', '.join(Family)}") from None
    rng = np.random.default_rng([seed, list(Family).index(family), 7103])
    if family is Family.REVERSE:
        primitives = _motifs.reverse(rng)
    else:
        primitives = _motifs.obverse(rng, beard=family is Family.BEARD)
    return TypeDesign(family, seed, primitives)


@dataclass(frozen=True)
class DieParams(Configurable):
    """How a die engraver's copy departs from the type, and the die's surface. Every field is checked
    against its range at construction (``ParameterError``)."""

    element_shift_mm: float = param(
        0.12, unit="mm", lo=0.0, hi=1.0, doc="sd of the shift of each element (stroke, pellet, mass)"
    )
    element_rotation_deg: float = param(
        2.5, unit="deg", lo=0.0, hi=20.0, doc="sd of the rotation of each element about its centre"
    )
    control_jitter_mm: float = param(
        0.06, unit="mm", lo=0.0, hi=0.5, doc="sd of the displacement of each control point (bends strokes)"
    )
    width_jitter: float = param(
        0.12, unit="fraction", lo=0.0, hi=0.5, doc="sd of log width scale per element"
    )
    height_jitter: float = param(
        0.12, unit="fraction", lo=0.0, hi=0.5, doc="sd of log height scale per element"
    )
    scale_jitter: float = param(
        0.008,
        unit="fraction",
        lo=0.0,
        hi=0.1,
        doc="sd of the whole design's scale (copy drawn larger/smaller)",
    )
    omit_probability: float = param(
        0.03,
        unit="probability",
        lo=0.0,
        hi=0.5,
        doc="chance that a minor element (border pellet) is left out",
    )
    ornaments_mean: float = param(
        1.5, unit="count", lo=0.0, hi=10.0, doc="Poisson mean of die-specific ornaments (pellets, crescents)"
    )
    variant_mean: float = param(
        0.7, unit="count", lo=0.0, hi=10.0, doc="Poisson mean of strokes drawn differently (0.35 mm bends)"
    )
    relief_scale: float = param(1.0, unit="factor", lo=0.2, hi=3.0, doc="multiplies every relief height")
    sagitta_mm: float = param(
        0.25,
        unit="mm",
        lo=0.0,
        hi=1.5,
        doc="die face curvature: height change at 10 mm from the centre (obverse domed, reverse hollow)",
    )
    sagitta_jitter: float = param(
        0.2, unit="fraction", lo=0.0, hi=1.0, doc="relative sd of the sagitta per die"
    )
    texture_mm: float = param(
        0.004, unit="mm", lo=0.0, hi=0.05, doc="rms of the die face's own fine texture (shared by its coins)"
    )
    texture_length_mm: float = param(
        0.25, unit="mm", lo=0.1, hi=2.0, doc="correlation length (Gaussian sigma) of that texture"
    )
    smoothing_mm: float = param(
        0.03, unit="mm", lo=0.0, hi=0.2, doc="Gaussian sigma of the metal's rounding of every edge"
    )
    pitch_mm: float = param(0.025, unit="mm", lo=0.005, hi=0.1, doc="pixel of the die's height field")
    extent_mm: float = param(30.0, unit="mm", lo=16.0, hi=60.0, doc="side of the die's engraved square area")


@dataclass(frozen=True)
class Die:
    """One die: an engraved copy of ``type`` plus its life (cracks appear at given ages).

    ``primitives`` are the die's own elements; ``dish_mm`` the signed face curvature at 10 mm (negative:
    domed). Relief fields are derived on demand and cached per process (``relief``).
    """

    type: TypeDesign
    die_id: str
    seed: int
    params: DieParams
    life: LifeParams
    primitives: tuple[Primitive, ...] = field(repr=False)
    dish_mm: float
    cracks: tuple[Crack, ...]

    @property
    def family(self) -> Family:
        return self.type.family

    def dish(self, xy: FloatArray) -> FloatArray:
        """Height of the die face's curvature at die-frame points (N, 2): dish_mm * (r / 10 mm)^2."""
        xy = np.asarray(xy)
        return self.dish_mm * (xy[..., 0] ** 2 + xy[..., 1] ** 2) / DISH_RADIUS_MM**2

    def relief(self) -> tuple[Grid, np.ndarray]:
        """The fresh die's relief (without dish and cracks): its grid and float32 heights (cached)."""
        return _relief_field(self)


def make_die(
    design: TypeDesign,
    die_id: str,
    seed: int,
    params: DieParams = DieParams(),
    life: LifeParams = DEFAULT_LIFE,
) -> Die:
    """One hand-engraved copy of ``design``: pure function of its arguments (``seed`` drives the copy)."""
    rng = np.random.default_rng([seed, 9157])
    scale = 1.0 + rng.normal(0.0, params.scale_jitter)
    kept = [p for p in design.primitives if not (p.minor and rng.random() < params.omit_probability)]
    primitives = [_engraved(p, rng, params).scaled_about_origin(scale) for p in kept]
    _draw_variants(primitives, rng, params)
    primitives += _ornaments(rng, params, primitives)
    sign = 1.0 if design.family is Family.REVERSE else -1.0
    dish = sign * params.sagitta_mm * max(0.0, 1.0 + rng.normal(0.0, params.sagitta_jitter))
    cracks = draw_cracks(np.random.default_rng([seed, 4421]), life)
    return Die(design, die_id, seed, params, life, tuple(primitives), dish, cracks)


def _engraved(p: Primitive, rng: np.random.Generator, params: DieParams) -> Primitive:
    shift = rng.normal(0.0, params.element_shift_mm, 2)
    rotation = np.radians(rng.normal(0.0, params.element_rotation_deg))
    jitter = rng.normal(0.0, params.control_jitter_mm, (n_control(p), 2))
    width, height = np.exp(rng.normal(0.0, [params.width_jitter, params.height_jitter]))
    return p.moved(shift, rotation, jitter).resized(float(width), float(height))


def _draw_variants(primitives: list[Primitive], rng: np.random.Generator, params: DieParams) -> None:
    """Redraw a few detail strokes with a larger bend (the engraver's own version of a lock)."""
    strokes = [i for i, p in enumerate(primitives) if isinstance(p, Stroke) and p.layer == 1 and not p.closed]
    for i in rng.choice(strokes, size=min(rng.poisson(params.variant_mean), len(strokes)), replace=False):
        p = primitives[i]
        primitives[i] = p.moved(np.zeros(2), 0.0, rng.normal(0.0, 0.35, (n_control(p), 2)))


def _ornaments(rng: np.random.Generator, params: DieParams, primitives: list[Primitive]) -> list[Primitive]:
    """Die-specific extras near the design: a pellet or a small crescent, 0.6-1.2 mm off an element."""
    extras: list[Primitive] = []
    for _ in range(rng.poisson(params.ornaments_mean)):
        anchor = primitives[int(rng.integers(len(primitives)))].centroid()
        anchor = anchor * min(1.0, 9.0 / max(np.linalg.norm(anchor), 1e-9))
        a = rng.uniform(0, 2 * np.pi)
        at = anchor + rng.uniform(0.6, 1.2) * np.array([np.cos(a), np.sin(a)])
        if rng.random() < 0.6:
            extras.append(
                pellet(float(at[0]), float(at[1]), rng.uniform(0.22, 0.38), rng.uniform(0.22, 0.32))
            )
        else:
            extras.append(_crescent(at, a, rng))
    return extras


def _crescent(at: FloatArray, angle: float, rng: np.random.Generator) -> Stroke:
    t = angle + np.linspace(-1.0, 1.0, 4)
    r = rng.uniform(0.4, 0.7)
    control = tuple((float(at[0] + r * np.cos(u)), float(at[1] + r * np.sin(u))) for u in t)
    return Stroke(control, (0.16,), (rng.uniform(0.18, 0.28),))


@functools.lru_cache(maxsize=DIE_CACHE_SIZE)
def _relief_field(die: Die) -> tuple[Grid, np.ndarray]:
    params = die.params
    grid = Grid.square((0.0, 0.0), params.extent_mm, params.pitch_mm)
    relief = rasterise_relief(die.primitives, grid, params.relief_scale)
    if params.smoothing_mm > 0:
        relief = ndimage.gaussian_filter(relief, params.smoothing_mm / params.pitch_mm)
    field32 = (relief + _texture(die, grid)).astype(np.float32)
    field32.setflags(write=False)
    return grid, field32


def _texture(die: Die, grid: Grid) -> FloatArray:
    """Smooth random texture of the die face (tool marks, pitting of the die): shared by all its coins."""
    if die.params.texture_mm == 0:
        return np.zeros(grid.shape)
    rng = np.random.default_rng([die.seed, 2208])
    # Filtered on a grid 4x coarser, then interpolated: the texture is smooth at that scale, and this is
    # ~10x faster than filtering at full resolution.
    coarse = Grid.square((0.0, 0.0), die.params.extent_mm + 1.0, 4 * grid.pitch)
    sigma = die.params.texture_length_mm / coarse.pitch
    noise = ndimage.gaussian_filter(rng.standard_normal(coarse.shape), sigma, mode="wrap")
    noise = resample(noise, coarse, grid, Placement())
    return noise * (die.params.texture_mm / max(float(noise.std()), 1e-12))
