"""Relief primitives of a coin design: strokes (ridges along curves) and domes (pellets, elliptic masses).

Coordinates in mm in the die frame (design centred at (0, 0)), heights in mm as they stand on the coin.
Layer 0 holds the broad masses (the cheek, the horse's body), combined by maximum; layer 1 the details
(locks, eye, legs, pellets), combined by maximum among themselves and added on top of the masses, as an
engraver cuts the details deeper into a hollowed mass.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from coindie.arrays import FloatArray
from coindie.synth import _raster
from coindie.synth._raster import Grid, Patch

#: Spacing of the samples along a stroke, as a fraction of the grid pitch (the ridge needs < 0.5).
_SAMPLE_STEP = 0.4


@dataclass(frozen=True)
class Stroke:
    """A ridge along a smooth curve through ``control`` points.

    ``half_width`` and ``height`` (mm) are given at evenly spaced positions along the curve (one value:
    constant) and interpolated in between; the ends are rounded.
    """

    control: tuple[tuple[float, float], ...]
    half_width: tuple[float, ...]
    height: tuple[float, ...]
    sharpness: float = 0.8
    closed: bool = False
    layer: int = 1
    minor: bool = False

    def centroid(self) -> FloatArray:
        return np.mean(np.asarray(self.control), axis=0)

    def rasterise(self, grid: Grid) -> Patch | None:
        samples, s = _raster.sample_curve(np.asarray(self.control), self.closed, _SAMPLE_STEP * grid.pitch)
        half_width = _along(self.half_width, s)
        height = _along(self.height, s)
        return _raster.ridge(grid, samples, half_width, height, self.sharpness)

    def moved(self, shift: FloatArray, rotation: float, jitter: FloatArray) -> Stroke:
        """Rotated by ``rotation`` rad about its centroid, shifted, control points jittered by (K, 2)."""
        c = self.centroid()
        moved = _rotate(np.asarray(self.control) - c, rotation) + c + shift + jitter
        return replace(self, control=_tuple2(moved))

    def resized(self, width: float, height: float) -> Stroke:
        return replace(
            self,
            half_width=tuple(w * width for w in self.half_width),
            height=tuple(h * height for h in self.height),
        )

    def scaled_about_origin(self, factor: float) -> Stroke:
        return replace(self, control=_tuple2(np.asarray(self.control) * factor))


@dataclass(frozen=True)
class Dome:
    """An elliptic dome: semi-axes ``axes`` (mm), rotated by ``angle`` (rad); a pellet when the axes are
    equal."""

    centre: tuple[float, float]
    axes: tuple[float, float]
    height: float
    angle: float = 0.0
    sharpness: float = 0.6
    layer: int = 1
    minor: bool = False

    def centroid(self) -> FloatArray:
        return np.asarray(self.centre, dtype=np.float64)

    def rasterise(self, grid: Grid) -> Patch | None:
        return _raster.ellipse(grid, self.centre, self.axes, self.angle, self.height, self.sharpness)

    def moved(self, shift: FloatArray, rotation: float, jitter: FloatArray) -> Dome:
        centre = np.asarray(self.centre) + shift + jitter[0]
        return replace(self, centre=(float(centre[0]), float(centre[1])), angle=self.angle + rotation)

    def resized(self, width: float, height: float) -> Dome:
        return replace(self, axes=(self.axes[0] * width, self.axes[1] * width), height=self.height * height)

    def scaled_about_origin(self, factor: float) -> Dome:
        return replace(self, centre=(self.centre[0] * factor, self.centre[1] * factor))


Primitive = Stroke | Dome


def n_control(primitive: Primitive) -> int:
    """Number of control points a die engraver may jitter (one for a dome: its centre)."""
    return len(primitive.control) if isinstance(primitive, Stroke) else 1


def rasterise_relief(primitives: tuple[Primitive, ...], grid: Grid, scale: float = 1.0) -> FloatArray:
    """Height field (float64, grid.shape) of a design: max of the masses + max of the details."""
    layers = [np.zeros(grid.shape), np.zeros(grid.shape)]
    for primitive in primitives:
        _raster.paste_max(layers[primitive.layer], primitive.rasterise(grid))
    return (layers[0] + layers[1]) * scale


def pellet(x: float, y: float, radius: float, height: float, minor: bool = False) -> Dome:
    return Dome((x, y), (radius, radius), height, sharpness=0.55, minor=minor)


def _along(values: tuple[float, ...], s: FloatArray) -> FloatArray:
    if len(values) == 1:
        return np.full(len(s), float(values[0]))
    return np.interp(s, np.linspace(0.0, 1.0, len(values)), np.asarray(values, dtype=np.float64))


def _rotate(xy: FloatArray, angle: float) -> FloatArray:
    c, s = np.cos(angle), np.sin(angle)
    return xy @ np.array([[c, s], [-s, c]])


def _tuple2(xy: FloatArray) -> tuple[tuple[float, float], ...]:
    return tuple((float(x), float(y)) for x, y in xy)
