"""The three designs of the Riedones hoard, built from relief primitives.

Obverse: a head to the right with large S-shaped locks ending in pellets, a beaded cord across the hair,
a big eye, nose, lips, ear and neck; the beard family adds beard curls and a moustache. Reverse: a
human-headed horse to the left with a mane and an S-shaped tail, a wheel with spokes below it, a
charioteer's arc with pellets above. Both have a pellet border at ~11.8 mm, larger than the flan: it shows
only on off-centre strikes. Sizes: strokes 0.2-0.5 mm half-width, relief 0.2-0.4 mm per layer (up to
~0.8 mm where details lie on masses). The type ``rng`` moves every element a little (0.3 mm) and varies
counts, so that two types of one family differ clearly while staying recognisable.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from coindie.synth._primitives import Dome, Primitive, Stroke, pellet

#: A half-width or height (mm): one value, or values along the stroke.
Widths = float | tuple[float, ...]
#: Per-type jitter of element positions (mm).
_TYPE_JITTER = 0.3
#: The motifs below are drawn for a ~19 mm field; this scale makes them fill a 21 mm flan.
_SCALE = 1.12


class _Builder:
    """Collects primitives drawn at ``scale`` (positions and masses; detail strokes keep their width),
    jittering each element by a type-level shift."""

    def __init__(self, rng: np.random.Generator, scale: float) -> None:
        self.rng = rng
        self.scale = scale
        self.items: list[Primitive] = []

    def shift(self) -> np.ndarray:
        return self.rng.normal(0.0, _TYPE_JITTER, 2)

    def stroke(
        self, control: list[tuple[float, float]], hw: Widths, h: Widths, layer: int = 1, **kw: Any
    ) -> None:
        d, k = self.shift(), self.scale
        pts = tuple((float(k * x + d[0]), float(k * y + d[1])) for x, y in control)
        hw = tuple(np.atleast_1d(hw).astype(float) * (k if layer == 0 else 1.0))
        h = tuple(np.atleast_1d(h).astype(float))
        self.items.append(Stroke(pts, hw, h, layer=layer, **kw))

    def dome(self, x: float, y: float, a: float, b: float, h: float, **kw: Any) -> None:
        d, k = self.shift(), self.scale
        self.items.append(Dome((float(k * x + d[0]), float(k * y + d[1])), (k * a, k * b), h, **kw))

    def pellet(self, x: float, y: float, r: float, h: float, minor: bool = False) -> None:
        d, k = self.rng.normal(0.0, _TYPE_JITTER / 2, 2), self.scale
        self.items.append(pellet(float(k * x + d[0]), float(k * y + d[1]), r, h, minor))


def obverse(rng: np.random.Generator, beard: bool) -> tuple[Primitive, ...]:
    """A head to the right with locks of hair (and a beard when ``beard``)."""
    b = _Builder(rng, _SCALE)
    _head_masses(b)
    _face_details(b)
    _locks(b)
    _cord(b)
    if beard:
        _beard(b)
    _border(b)
    return tuple(b.items)


def reverse(rng: np.random.Generator) -> tuple[Primitive, ...]:
    """A human-headed horse to the left above a wheel, a charioteer's arc above."""
    b = _Builder(rng, _SCALE)
    _horse_masses(b)
    _legs(b)
    _tail_and_mane(b)
    _wheel(b, centre=(1.3, -4.3), radius=1.8)
    _charioteer(b)
    _border(b)
    return tuple(b.items)


# --- obverse ---------------------------------------------------------------------------------------------


def _head_masses(b: _Builder) -> None:
    b.dome(3.0, -0.2, 2.7, 3.7, 0.32, angle=0.15, sharpness=0.35, layer=0)  # face
    b.dome(-0.9, 1.1, 4.3, 4.0, 0.22, angle=-0.2, sharpness=0.35, layer=0)  # skull under the hair
    b.stroke(
        [(2.0, -3.0), (1.4, -5.6), (1.1, -8.3)], (1.9, 2.1, 2.3), (0.3, 0.26, 0.2), sharpness=0.4, layer=0
    )


def _face_details(b: _Builder) -> None:
    b.stroke([(4.8, 2.3), (5.8, 0.7), (6.6, -0.5), (5.9, -0.95)], (0.32, 0.42, 0.48, 0.32), 0.26)  # nose
    b.stroke([(2.5, 2.4), (3.8, 3.0), (4.9, 2.4)], (0.24,), (0.22,))  # brow
    b.stroke([(2.9, 1.4), (3.8, 1.95), (4.7, 1.4), (3.8, 0.9)], (0.13,), (0.2,), closed=True)  # eye
    b.pellet(3.8, 1.42, 0.32, 0.3)
    b.stroke([(5.4, -1.8), (6.2, -1.95)], (0.22,), (0.24,))  # upper lip
    b.stroke([(5.3, -2.5), (6.0, -2.65)], (0.2,), (0.22,))  # lower lip
    b.stroke([(5.6, -3.2), (5.0, -3.95), (3.9, -3.9)], (0.3,), (0.2,))  # chin
    b.stroke([(1.6, -1.0), (2.8, -2.4), (4.2, -3.2)], (0.18,), (0.14,))  # jaw
    b.stroke([(1.6, 0.9), (0.8, 0.35), (0.9, -0.6), (1.6, -0.95)], (0.2,), (0.22,))  # ear
    b.pellet(1.25, -0.05, 0.24, 0.24)


def _locks(b: _Builder) -> None:
    """S-shaped locks from the skull, flowing back (to the left) and ending in pellets."""
    n = int(b.rng.integers(8, 12))
    root_centre = np.array([-0.6, 1.0])
    for angle in np.linspace(np.radians(70), np.radians(245), n) + b.rng.normal(0, 0.05, n):
        out = np.array([np.cos(angle), np.sin(angle)])
        back = out * 0.7 + np.array([-0.55, -0.15])
        back /= np.linalg.norm(back)
        side = np.array([-back[1], back[0]])
        start = root_centre + 2.9 * out
        length = b.rng.uniform(4.5, 6.5)
        amp = b.rng.uniform(0.5, 0.95) * b.rng.choice([-1.0, 1.0])
        t = np.linspace(0.0, 1.0, 5)
        pts = start + np.outer(t * length, back) + np.outer(amp * np.sin(2 * np.pi * t), side)
        b.stroke([tuple(p) for p in pts], (0.55, 0.48, 0.4, 0.34), (0.4, 0.4, 0.36, 0.34))
        end = pts[-1] + 0.45 * back
        b.pellet(end[0], end[1], b.rng.uniform(0.5, 0.65), 0.42)


def _cord(b: _Builder) -> None:
    """A beaded cord across the hair: pellets along an arc over the skull."""
    n = int(b.rng.integers(9, 13))
    for a in np.linspace(np.radians(25), np.radians(190), n):
        b.pellet(-0.6 + 3.5 * np.cos(a), 1.0 + 3.5 * np.sin(a), 0.3, 0.3)


def _beard(b: _Builder) -> None:
    """Curls along the jaw and chin, and a moustache."""
    n = int(b.rng.integers(7, 11))
    for t in np.linspace(0.0, 1.0, n):
        x, y = 1.9 + 3.3 * t, -2.1 - 2.2 * t
        tip = (x - 0.3 + 0.4 * t, y - b.rng.uniform(0.9, 1.4))
        b.stroke(
            [(x, y), ((x + tip[0]) / 2 + 0.25, (y + tip[1]) / 2), tip], (0.22, 0.18, 0.14), (0.24, 0.22, 0.18)
        )
    b.stroke([(4.9, -1.35), (5.7, -1.55), (6.4, -1.3), (6.8, -0.9)], (0.2,), (0.22,))


def _border(b: _Builder) -> None:
    """A pellet border (mostly outside the flan)."""
    b.scale = 1.0
    n = int(b.rng.integers(40, 49))
    phase = b.rng.uniform(0, 2 * np.pi)
    for a in phase + np.linspace(0, 2 * np.pi, n, endpoint=False):
        b.pellet(11.8 * np.cos(a), 11.8 * np.sin(a), 0.32, 0.24, minor=True)


# --- reverse ---------------------------------------------------------------------------------------------


def _horse_masses(b: _Builder) -> None:
    b.dome(0.8, 0.8, 4.3, 2.1, 0.34, angle=-0.08, sharpness=0.4, layer=0)  # body
    b.dome(3.9, 0.9, 1.8, 1.8, 0.36, sharpness=0.45, layer=0)  # croup
    b.dome(-2.6, 0.6, 1.7, 1.9, 0.35, sharpness=0.45, layer=0)  # chest
    b.stroke(
        [(-2.6, 1.2), (-4.0, 3.0), (-4.9, 4.6)], (1.3, 1.0, 0.8), (0.33,), sharpness=0.5, layer=0
    )  # neck
    b.dome(-5.7, 5.2, 1.25, 0.8, 0.33, angle=0.5, sharpness=0.5, layer=0)  # human head
    b.pellet(-5.8, 5.45, 0.22, 0.2)  # eye
    b.stroke([(-5.0, 5.9), (-4.6, 6.6), (-4.0, 6.9)], (0.16,), (0.2,))  # hair of the head


def _legs(b: _Builder) -> None:
    legs = (
        [(-2.6, -0.8), (-3.3, -3.2), (-3.0, -5.6), (-3.6, -6.6)],
        [(-1.6, -0.9), (-1.6, -3.4), (-0.9, -5.2), (-1.2, -6.4)],
        [(3.5, -0.6), (4.4, -2.8), (3.6, -4.8), (4.0, -6.5)],
        [(4.6, -0.2), (5.7, -2.4), (5.2, -4.4), (5.8, -6.0)],
    )
    for leg in legs:
        b.stroke(leg, (0.55, 0.38, 0.3, 0.3), (0.34, 0.32, 0.3, 0.3))
        b.pellet(leg[-1][0] - 0.3, leg[-1][1] - 0.2, 0.36, 0.32)  # hoof


def _tail_and_mane(b: _Builder) -> None:
    b.stroke([(5.2, 1.6), (6.6, 2.6), (7.2, 1.4), (8.2, 0.8), (8.8, 2.2)], (0.34, 0.3, 0.26, 0.22), (0.3,))
    b.pellet(9.0, 2.7, 0.38, 0.32)
    n = int(b.rng.integers(4, 7))
    for t in np.linspace(0.0, 1.0, n):
        x, y = -2.3 - 2.2 * t, 2.3 + 2.6 * t
        b.stroke([(x, y), (x + 0.6, y + 0.55), (x + 1.0, y + 0.5)], (0.18, 0.15, 0.12), (0.22,))


def _wheel(b: _Builder, centre: tuple[float, float], radius: float) -> None:
    a = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    ring = [(centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)) for t in a]
    b.stroke(ring, (0.2,), (0.3,), closed=True)
    b.pellet(centre[0], centre[1], 0.45, 0.36)
    n = int(b.rng.integers(5, 9))
    for t in b.rng.uniform(0, 2 * np.pi) + np.linspace(0, 2 * np.pi, n, endpoint=False):
        tip = (centre[0] + 0.95 * radius * np.cos(t), centre[1] + 0.95 * radius * np.sin(t))
        b.stroke([centre, tip], (0.14,), (0.24,))


def _charioteer(b: _Builder) -> None:
    """An arc over the horse's back with pellets, and a small figure (the charioteer's body and arm)."""
    arc = [(-3.6, 6.3), (-1.2, 7.7), (1.8, 7.7), (4.6, 6.1)]
    b.stroke(arc, (0.3, 0.26, 0.26, 0.22), (0.3,))
    for x, y in ((-2.4, 8.6), (0.3, 9.1), (3.0, 8.5), (5.4, 6.9)):
        b.pellet(x, y, 0.34, 0.3)
    b.stroke([(1.0, 2.4), (1.4, 4.0), (1.1, 5.6)], (0.35, 0.28, 0.22), (0.3,))  # body
    b.stroke([(1.2, 4.6), (2.4, 5.0), (3.4, 4.4)], (0.18,), (0.24,))  # arm
    b.pellet(1.0, 6.2, 0.45, 0.34)  # head
