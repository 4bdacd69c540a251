"""Hoards from a second, independent coin generator, to measure coindie on scans it was not built on.

    .venv/bin/python benchmarks/outsider_hoards.py OUT [--kinds K,...] [--seed 1] [--dies 12] [--meshes]
    .venv/bin/python benchmarks/outsider_hoards.py OUT --kinds ordinary --scale 0.55   # coins of 10-12 mm
    .venv/bin/python benchmarks/outsider_hoards.py OUT --evaluate      # init, run, cluster --auto, eval

Every figure of issue 13's matrix comes from `coindie.synth`: the shipped models were trained on hoards of
that generator and the thresholds chosen on them. This script shares none of its code or models. It
imports nothing of coindie (the PLYs and ``labels.csv`` are written here) and makes its coins another way:

- **Dies**: a beaded border, a legend of stroke glyphs on a ring and a bust of anisotropic Gaussian blobs
  crossed by engraved curves; the dies of one type are the type's elements, each moved by up to
  ``die_jitter`` mm and re-engraved (coindie.synth's dies are rasterised motif libraries).
- **Strikes**: irregular flan outlines, broken flans cut by a chord, the die off centre, weak zones from
  a thresholded smooth noise field, double strikes as the maximum of two shifted strikes, cupping as a
  paraboloid and bends as a one-sided quadratic fold.
- **Wear and corrosion**: high points of the relief lowered in proportion to their height above a local
  mean, craters and crusts.
- **Scanners**: jittered sampling grids, noise along z, heights smoothed or not, normals from the sampled
  grid's gradient or estimated by PCA of 16 neighbours, holes, each scan in a random pose.

Hoards of 40 coins (80 faces), 12 dies a side, as the issue's held-out hoards; coins of 18-22 mm, or
``--scale`` times that (the whole coin and its relief, the scanner unchanged). The kinds follow the issue's
table: ``ordinary``, ``hard`` (worn, bent, broken, crusted; one type a side, dies 0.25 mm apart),
``coarse`` (0.15 mm spacing, 0.03 mm noise), ``mixed`` (two scanners in one hoard), ``flat`` (flat,
uniform, centred flans), and ``fine`` (the finest scanner of the issue's range, 0.02 mm spacing and 0.003 mm
noise, smoothed); ``sametype``, ``offcentre``, ``bent``, ``weak`` and ``worn`` take the hard kind apart (the
ordinary kind with one group of the hard kind's settings: one type a side with dies 0.25 mm apart; strikes
off centre and broken flans; cupping and bends; weak zones and double strikes; wear and corrosion).
Beside the PLYs and ``labels.csv``: ``poses.json`` (each face's T_scan_die: for two
faces of one die, T_b_a = T_scan_die[b] @ inv(T_scan_die[a])) and ``faces.json`` (what each face was
drawn with: flan, share of the die on it, off-centre share, double strike, weak zone, wear, corrosion,
cupping, bend, scanner). ``truth.json`` and ``splits.csv`` hold the same poses in the form
``coindie bench registration`` reads (every face in the ``registration_test`` split), so that its
registration benchmark runs on these hoards as it is: ``coindie bench registration OUT/hard-1 --out R
--methods relief,fcgf+icp``. ``--evaluate`` runs the shipped defaults on each hoard as a user would and prints
its evaluation (FMI, ARI, clusters against dies). No pass/fail: a measurement (BENCHMARK.md, "An independent
generator").
"""

from __future__ import annotations

import argparse
import csv
import json
import subprocess
import sys
import time
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from scipy import ndimage
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

Array = NDArray[np.float64]
RENDER_MM = 0.025  # the pixel of every rendered height field
FIELD_MM = 30.0  # side of the square the coins are rendered on


@dataclass(frozen=True)
class Scanner:
    spacing: float  # mm between samples
    noise: float  # mm, standard deviation along z
    smoothed: bool  # heights blurred over about a sample spacing (a meshing scanner's smoothing)
    estimated_normals: bool  # PCA of neighbours rather than the sampled grid's gradient
    holes: int  # holes at most


@dataclass(frozen=True)
class Kind:
    types: int  # die types a side (dies of one type share their elements, moved by die_jitter)
    die_jitter: float  # mm
    off_centre: float  # share of the diameter, at most
    flan_spread: float  # flan radius / die radius drawn in 1 +- this
    outline_wobble: float  # relative amplitude of the outline's irregularity
    broken: float  # share of coins whose flan is broken
    cupping: float  # mm at 10 mm from the centre, drawn in +- this per face
    bend: float  # mm at the edge, at most (a share of coins)
    weak: float  # share of the face in a weak zone, at most
    double: float  # share of double strikes
    wear: float  # share of the relief height lost on high points, at most
    corrosion: float  # share of the face under pits and crusts, at most
    scanners: tuple[Scanner, ...]


GOOD = Scanner(spacing=0.03, noise=0.006, smoothed=False, estimated_normals=False, holes=2)
ORDINARY = Kind(
    types=2, die_jitter=0.5, off_centre=0.12, flan_spread=0.06, outline_wobble=0.02, broken=0.0,
    cupping=0.15, bend=0.0, weak=0.2, double=0.0, wear=0.3, corrosion=0.05, scanners=(GOOD,),
)  # fmt: skip
# worn, bent, broken, crusted, double-struck, off centre; one type a side, dies 0.25 mm apart
HARD = Kind(
    types=1, die_jitter=0.25, off_centre=0.3, flan_spread=0.1, outline_wobble=0.04, broken=0.25,
    cupping=0.3, bend=0.3, weak=0.5, double=0.2, wear=0.7, corrosion=0.3,
    scanners=(Scanner(spacing=0.05, noise=0.012, smoothed=False, estimated_normals=True, holes=4),),
)  # fmt: skip
KINDS = {
    "ordinary": ORDINARY,
    "hard": HARD,
    "coarse": replace(
        ORDINARY,
        scanners=(Scanner(spacing=0.15, noise=0.03, smoothed=False, estimated_normals=True, holes=2),),
    ),
    "mixed": replace(
        ORDINARY,
        scanners=(GOOD, Scanner(spacing=0.1, noise=0.02, smoothed=True, estimated_normals=True, holes=3)),
    ),
    "flat": replace(ORDINARY, off_centre=0.0, flan_spread=0.0, outline_wobble=0.0, cupping=0.0),
    # the issue's finest scanner (0.02 mm, 0.003 mm noise, a smoothed mesh): about a million points a face
    "fine": replace(
        ORDINARY,
        scanners=(Scanner(spacing=0.02, noise=0.003, smoothed=True, estimated_normals=False, holes=2),),
    ),
    # the hard kind taken apart: the ordinary kind with one of its groups of axes at the hard kind's extremes
    "sametype": replace(ORDINARY, types=1, die_jitter=HARD.die_jitter),
    "offcentre": replace(
        ORDINARY, off_centre=HARD.off_centre, broken=HARD.broken, flan_spread=HARD.flan_spread
    ),
    "bent": replace(ORDINARY, cupping=HARD.cupping, bend=HARD.bend, outline_wobble=HARD.outline_wobble),
    "weak": replace(ORDINARY, weak=HARD.weak, double=HARD.double),
    "worn": replace(ORDINARY, wear=HARD.wear, corrosion=HARD.corrosion),
}

#: The kinds of issue 13's held-out hoards (the default).
ISSUE_KINDS = ("ordinary", "hard", "coarse", "mixed", "flat")

# ------------------------------------------------------------------------------------------------ drawing


class Canvas:
    """A square height field centred on (0, 0), RENDER_MM a pixel; elements are added in place."""

    def __init__(self, side_mm: float) -> None:
        self.n = int(round(side_mm / RENDER_MM))
        self.z = np.zeros((self.n, self.n))

    def coords(self, x0: float, x1: float, y0: float, y1: float) -> tuple[slice, slice, Array, Array]:
        half = (self.n - 1) / 2.0
        c0 = max(int(np.floor(x0 / RENDER_MM + half)), 0)
        c1 = min(int(np.ceil(x1 / RENDER_MM + half)) + 1, self.n)
        r0 = max(int(np.floor(y0 / RENDER_MM + half)), 0)
        r1 = min(int(np.ceil(y1 / RENDER_MM + half)) + 1, self.n)
        ys, xs = np.mgrid[r0:r1, c0:c1].astype(np.float64)
        return slice(r0, r1), slice(c0, c1), (xs - half) * RENDER_MM, (ys - half) * RENDER_MM

    def stroke(self, a: Array, b: Array, width: float, height: float, add: bool = False) -> None:
        """A ridge along segment ab, of rounded profile: kept as the maximum with what is there, or
        added to it (``add``; a negative height is then a groove)."""
        pad = width
        rows, cols, x, y = self.coords(
            min(a[0], b[0]) - pad, max(a[0], b[0]) + pad, min(a[1], b[1]) - pad, max(a[1], b[1]) + pad
        )
        if x.size == 0:
            return
        ab = b - a
        t = np.clip(((x - a[0]) * ab[0] + (y - a[1]) * ab[1]) / max(ab @ ab, 1e-12), 0.0, 1.0)
        d = np.hypot(x - a[0] - t * ab[0], y - a[1] - t * ab[1])
        profile = height * np.sqrt(np.clip(1.0 - (d / (width / 2.0)) ** 2, 0.0, 1.0))
        if add:
            self.z[rows, cols] += profile
        else:
            self.z[rows, cols] = np.maximum(self.z[rows, cols], profile)

    def dome(self, centre: Array, radius: float, height: float) -> None:
        rows, cols, x, y = self.coords(
            centre[0] - radius, centre[0] + radius, centre[1] - radius, centre[1] + radius
        )
        d2 = ((x - centre[0]) ** 2 + (y - centre[1]) ** 2) / radius**2
        self.z[rows, cols] = np.maximum(self.z[rows, cols], height * np.sqrt(np.clip(1.0 - d2, 0.0, 1.0)))

    def blob(self, centre: Array, sigmas: Array, angle: float, height: float) -> None:
        reach = 3.0 * float(sigmas.max())
        rows, cols, x, y = self.coords(
            centre[0] - reach, centre[0] + reach, centre[1] - reach, centre[1] + reach
        )
        c, s = np.cos(angle), np.sin(angle)
        u, v = c * (x - centre[0]) + s * (y - centre[1]), -s * (x - centre[0]) + c * (y - centre[1])
        self.z[rows, cols] += height * np.exp(-0.5 * ((u / sigmas[0]) ** 2 + (v / sigmas[1]) ** 2))


@dataclass(frozen=True)
class DieType:
    radius: float
    beads: int
    glyphs: list[list[tuple[Array, Array]]]  # per glyph, strokes in the glyph's box (mm, centred)
    glyph_angles: Array
    blobs: list[tuple[Array, Array, float, float]]
    curves: list[Array]  # polylines (k, 2)
    curve_heights: Array


def new_type(rng: np.random.Generator) -> DieType:
    radius = rng.uniform(9.0, 11.0)
    n_glyphs = int(rng.integers(9, 16))
    start = rng.uniform(0, 2 * np.pi)
    span = rng.uniform(1.2, 1.8) * np.pi
    glyphs = []
    for _ in range(n_glyphs):
        strokes = []
        for _ in range(int(rng.integers(2, 4))):
            a, b = rng.uniform(-0.55, 0.55, 2) * [1.0, 1.4], rng.uniform(-0.55, 0.55, 2) * [1.0, 1.4]
            strokes.append((a, b))
        glyphs.append(strokes)
    blobs = []
    for _ in range(int(rng.integers(6, 12))):
        centre = rng.normal(0, radius * 0.22, 2)
        blobs.append((centre, rng.uniform(0.7, 2.6, 2), rng.uniform(0, np.pi), rng.uniform(0.25, 0.7)))
    curves = []
    for _ in range(int(rng.integers(15, 30))):
        point = rng.normal(0, radius * 0.25, 2)
        heading = rng.uniform(0, 2 * np.pi)
        line = [point]
        for _ in range(int(rng.integers(5, 14))):
            heading += rng.normal(0, 0.35)
            point = point + 0.45 * np.array([np.cos(heading), np.sin(heading)])
            line.append(point)
        curves.append(np.array(line))
    return DieType(
        radius=radius,
        beads=int(2 * np.pi * (radius - 0.7) / rng.uniform(0.8, 1.1)),
        glyphs=glyphs,
        glyph_angles=start + np.linspace(0, span, n_glyphs),
        blobs=blobs,
        curves=curves,
        curve_heights=rng.choice([-1.0, 1.0], len(curves)) * rng.uniform(0.06, 0.14, len(curves)),
    )


def engrave(kind: DieType, jitter: float, rng: np.random.Generator) -> Array:
    """One die of ``kind``: every element moved by up to ``jitter`` mm and cut again."""
    canvas = Canvas(FIELD_MM)
    r = kind.radius
    phase = rng.uniform(-1, 1) * jitter / r
    for k in range(kind.beads):
        angle = 2 * np.pi * k / kind.beads + phase
        centre = (r - 0.7) * np.array([np.cos(angle), np.sin(angle)]) + rng.normal(0, jitter / 4, 2)
        canvas.dome(centre, 0.28, 0.22)
    for strokes, angle in zip(kind.glyphs, kind.glyph_angles, strict=True):
        angle = angle + rng.uniform(-1, 1) * jitter / (r - 2.2)
        centre = (r - 2.2) * np.array([np.cos(angle), np.sin(angle)]) + rng.uniform(-1, 1, 2) * jitter / 2
        # the glyph's up points outwards
        up = np.array([np.cos(angle), np.sin(angle)])
        across = np.array([-up[1], up[0]])
        for a, b in strokes:
            a = a + rng.normal(0, jitter / 3, 2)
            b = b + rng.normal(0, jitter / 3, 2)
            canvas.stroke(centre + a[0] * across + a[1] * up, centre + b[0] * across + b[1] * up, 0.24, 0.22)
    for centre, sigmas, angle, height in kind.blobs:
        canvas.blob(
            centre + rng.uniform(-1, 1, 2) * jitter,
            sigmas * rng.uniform(0.93, 1.07, 2),
            angle + rng.normal(0, 0.05),
            height * rng.uniform(0.9, 1.1),
        )
    # the engraved lines are cut into the bust or stand on it (added: overlapping segments double up at
    # the joints, as a graver's overlapping cuts do)
    for line, height in zip(kind.curves, kind.curve_heights, strict=True):
        moved = line + rng.uniform(-1, 1, 2) * jitter + rng.normal(0, jitter / 4, line.shape)
        for a, b in zip(moved[:-1], moved[1:], strict=True):
            canvas.stroke(a, b, 0.16, height, add=True)
    relief = canvas.z
    half = (canvas.n - 1) / 2.0
    y, x = (np.mgrid[0 : canvas.n, 0 : canvas.n] - half) * RENDER_MM
    relief[np.hypot(x, y) > r] = 0.0
    return relief


# ------------------------------------------------------------------------------------------------ coins


def smooth_noise(rng: np.random.Generator, n: int, sigma_px: float) -> Array:
    field = ndimage.gaussian_filter(rng.standard_normal((n, n)), sigma_px, mode="wrap")
    return (field - field.mean()) / max(field.std(), 1e-12)


def strike(
    die: Array, die_radius: float, kind: Kind, rng: np.random.Generator, record: dict[str, object]
) -> tuple[Array, Array, Array]:
    """The struck face's height field (mm), its flan mask, on the coin's own grid, and T_coin_die (the
    die's frame in the coin's, in the plane); what was drawn goes into ``record``."""
    n = die.shape[0]
    half = (n - 1) / 2.0
    y, x = (np.mgrid[0:n, 0:n] - half) * RENDER_MM
    radius = die_radius * (1.0 + rng.uniform(-1, 1) * kind.flan_spread)
    theta = np.arctan2(y, x)
    wobble = sum(
        rng.normal(0, kind.outline_wobble / k) * np.cos(k * theta + rng.uniform(0, 2 * np.pi))
        for k in range(2, 7)
    )
    flan = np.hypot(x, y) <= radius * (1.0 + wobble)
    record["broken"] = bool(rng.random() < kind.broken)
    if record["broken"]:
        direction = rng.uniform(0, 2 * np.pi)
        flan &= x * np.cos(direction) + y * np.sin(direction) < rng.uniform(0.45, 0.8) * radius
    # the die's position on the flan
    direction = rng.uniform(0, 2 * np.pi)
    offset = (
        rng.uniform(0, kind.off_centre) * 2 * die_radius * np.array([np.cos(direction), np.sin(direction)])
    )
    turn = rng.uniform(0, 2 * np.pi)
    record["flan_radius_mm"] = float(radius)
    record["off_centre"] = float(np.hypot(*offset) / (2 * die_radius))  # share of the die's diameter
    # the share of the die's face that lands on the flan
    on_die = np.hypot(x - offset[0], y - offset[1]) <= die_radius
    record["die_on_flan"] = float((on_die & flan).sum() / max(on_die.sum(), 1))

    def struck(shift: Array, angle: float) -> Array:
        c, s = np.cos(angle), np.sin(angle)
        u, v = c * (x - shift[0]) + s * (y - shift[1]), -s * (x - shift[0]) + c * (y - shift[1])
        return ndimage.map_coordinates(die, [v / RENDER_MM + half, u / RENDER_MM + half], order=1, cval=0.0)

    relief = struck(offset, turn)
    record["double"] = bool(rng.random() < kind.double)
    if record["double"]:
        second = struck(
            offset + rng.uniform(0.3, 1.0) * rng.choice([-1, 1], 2), turn + np.radians(rng.uniform(-5, 5))
        )
        relief = np.maximum(relief, 0.6 * second)
    if kind.weak > 0:
        share = rng.uniform(0, kind.weak)
        field = smooth_noise(rng, n, 4.0 / RENDER_MM)
        weak = field > np.quantile(field, 1.0 - share)
        depth = rng.uniform(0.4, 0.8)
        record["weak_share"], record["weak_depth"] = float(share), float(depth)
        relief *= 1.0 - depth * ndimage.gaussian_filter(weak.astype(np.float64), 0.8 / RENDER_MM)
    if kind.wear > 0:
        loss = rng.uniform(0, kind.wear)
        record["wear"] = float(loss)
        local = ndimage.gaussian_filter(relief, 1.2 / RENDER_MM)
        high = np.maximum(relief - local, 0.0)
        relief = relief - loss * high * (relief / max(relief.max(), 1e-9))
        relief = ndimage.gaussian_filter(relief, 0.05 / RENDER_MM * (0.5 + loss))
    if kind.corrosion > 0:
        share = rng.uniform(0, kind.corrosion)
        record["corrosion_share"] = float(share)
        field = smooth_noise(rng, n, 0.6 / RENDER_MM)
        crust = field > np.quantile(field, 1.0 - share / 2)
        relief += rng.uniform(0.05, 0.2) * ndimage.gaussian_filter(crust.astype(np.float64), 0.1 / RENDER_MM)
        area = share / 2 * np.pi * radius**2
        pits = Canvas(n * RENDER_MM)
        for _ in range(int(area / (np.pi * 0.25**2))):
            pits.dome(rng.uniform(-radius, radius, 2), rng.uniform(0.1, 0.4), rng.uniform(0.03, 0.15))
        relief -= pits.z
    # the flan's own shape
    cup = rng.uniform(-1, 1) * kind.cupping / 100.0  # mm at 10 mm: c * 100
    shape = cup * (x**2 + y**2)
    record["cupping_mm_at_10"] = float(cup * 100.0)
    record["bent"] = bool(kind.bend > 0 and rng.random() < 0.5)
    if record["bent"]:
        direction = rng.uniform(0, 2 * np.pi)
        u = x * np.cos(direction) + y * np.sin(direction)
        start = rng.uniform(0.0, 0.5) * radius
        shape += (
            rng.uniform(-1, 1) * kind.bend * np.maximum(u - start, 0.0) ** 2 / max(radius - start, 1.0) ** 2
        )
    # the relief fades over the last 0.3 mm of the flan
    inside = ndimage.distance_transform_edt(flan) * RENDER_MM
    relief *= np.clip(inside / 0.3, 0.0, 1.0)
    # die point d lands on the coin at p = R(turn)^T d + offset (``struck`` samples d = R (p - offset))
    T_coin_die = np.eye(4)
    c, s = np.cos(turn), np.sin(turn)
    T_coin_die[:2, :2] = [[c, -s], [s, c]]
    T_coin_die[:2, 3] = offset
    return shape + relief, flan, T_coin_die


def scan(
    height: Array,
    flan: Array,
    scanner: Scanner,
    rng: np.random.Generator,
    *,
    mesh: bool = False,
    scale: float = 1.0,
) -> tuple[Array, Array, Array, NDArray[np.int64] | None]:
    """Points and normals of one face and its edge wall, in a random pose, T_scan_coin, and no triangles;
    with ``mesh``, the face's sampling grid as a triangle mesh instead (two triangles a grid cell whose four
    corners were kept, facing up; no edge wall): its vertices, their grid normals and the triangles.
    ``scale``: the coin scanned is the rendered one ``scale`` times as large in every direction (the
    scanner, its spacing, noise and holes, is not scaled)."""
    pixel = RENDER_MM * scale  # mm of the scanned coin a rendered pixel covers
    if scanner.smoothed:
        height = ndimage.gaussian_filter(height, 0.7 * scanner.spacing / pixel)
    n = height.shape[0]
    half = (n - 1) / 2.0
    step = scanner.spacing
    m = int(FIELD_MM * scale / step)
    grid = (np.arange(m) - (m - 1) / 2.0) * step
    gy, gx = np.meshgrid(grid, grid, indexing="ij")
    jitter = rng.uniform(-0.3, 0.3, (2, m, m)) * step
    px, py = gx + jitter[0], gy + jitter[1]
    rows, cols = py / pixel + half, px / pixel + half
    on = ndimage.map_coordinates(flan.astype(np.float64), [rows, cols], order=1) > 0.5
    z = ndimage.map_coordinates(height, [rows, cols], order=1) * scale + rng.normal(0, scanner.noise, (m, m))
    zy, zx = np.gradient(np.where(on, z, np.nan), step)
    keep = on & np.isfinite(zx) & np.isfinite(zy)
    for _ in range(int(rng.integers(0, scanner.holes + 1))):
        cx, cy = rng.uniform(-8, 8, 2) * scale
        a, b = rng.uniform(0.3, 1.5, 2)
        keep &= ((px - cx) / a) ** 2 + ((py - cy) / b) ** 2 > 1
    points = np.stack([px[keep], py[keep], z[keep]], axis=1)
    normals = np.stack([-zx[keep], -zy[keep], np.ones(keep.sum())], axis=1)
    triangles = _grid_triangles(keep) if mesh else None
    if not mesh:
        points, normals = _with_wall(points, normals, height, flan, scanner, rng, scale)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    pose = Rotation.random(random_state=rng)
    T_scan_coin = np.eye(4)
    T_scan_coin[:3, :3] = pose.as_matrix()
    T_scan_coin[:3, 3] = rng.uniform(-40, 40, 3)
    return pose.apply(points) + T_scan_coin[:3, 3], pose.apply(normals), T_scan_coin, triangles


def _grid_triangles(keep: NDArray[np.bool_]) -> NDArray[np.int64]:
    """Two triangles (facing up) for each cell of the sampling grid whose four corners were kept, as
    indices into the kept samples in row-major order."""
    index = np.full(keep.shape, -1, dtype=np.int64)
    index[keep] = np.arange(int(keep.sum()))
    a, b, c, d = index[:-1, :-1], index[:-1, 1:], index[1:, :-1], index[1:, 1:]
    whole = (a >= 0) & (b >= 0) & (c >= 0) & (d >= 0)
    a, b, c, d = a[whole], b[whole], c[whole], d[whole]
    return np.concatenate([np.stack([a, b, d], axis=1), np.stack([a, d, c], axis=1)])


def _with_wall(
    points: Array,
    normals: Array,
    height: Array,
    flan: Array,
    scanner: Scanner,
    rng: np.random.Generator,
    scale: float = 1.0,
) -> tuple[Array, Array]:
    """The face's samples with its edge wall added, and their normals (estimated, for such a scanner)."""
    step = scanner.spacing
    pixel = RENDER_MM * scale
    half = (height.shape[0] - 1) / 2.0
    # the edge wall: 1.2 mm down from the outline (for a coin of the rendered size), normals outwards
    edge = ndimage.binary_erosion(flan) ^ flan
    er, ec = np.nonzero(edge)
    every = max(int(round(step / pixel)), 1)
    er, ec = er[::every], ec[::every]
    ex, ey = (ec - half) * pixel, (er - half) * pixel
    outward = np.stack([ex, ey], axis=1) / np.maximum(np.hypot(ex, ey), 1e-9)[:, None]
    top = height[er, ec] * scale
    depths = np.arange(step, 1.2 * scale, step)
    wall = np.concatenate(
        [np.stack([ex, ey, top - d], axis=1) + rng.normal(0, scanner.noise, (len(ex), 3)) for d in depths]
    )
    wall_normals = np.tile(np.concatenate([outward, np.zeros((len(ex), 1))], axis=1), (len(depths), 1))
    points = np.concatenate([points, wall])
    normals = np.concatenate([normals, wall_normals])
    if scanner.estimated_normals:
        _, neighbours = cKDTree(points).query(points, k=16)
        centred = points[neighbours] - points[neighbours].mean(axis=1, keepdims=True)
        _, _, vt = np.linalg.svd(centred, full_matrices=False)
        estimated = vt[:, -1, :]
        flip = np.einsum("ij,ij->i", estimated, normals) < 0
        estimated[flip] *= -1
        normals = estimated
    return points, normals


def write_stl(path: Path, points: Array, triangles: NDArray[np.int64]) -> None:
    """A binary STL of the triangles (facet normals from their corners; written here, not by coindie)."""
    corners = points[triangles]
    facet = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    facet /= np.maximum(np.linalg.norm(facet, axis=1, keepdims=True), 1e-12)
    data = np.zeros(len(triangles), dtype=[("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attr", "<u2")])
    data["normal"], data["corners"] = facet, corners
    with path.open("wb") as out:
        out.write(b"outsider_hoards.py".ljust(80, b" "))
        out.write(np.uint32(len(triangles)).tobytes())
        out.write(data.tobytes())


def write_ply(path: Path, points: Array, normals: Array) -> None:
    """A binary little-endian PLY of float32 x, y, z, nx, ny, nz (written here, not by coindie)."""
    data = np.empty(len(points), dtype=[(k, "<f4") for k in ("x", "y", "z", "nx", "ny", "nz")])
    for k, column in zip(("x", "y", "z"), points.T, strict=True):
        data[k] = column
    for k, column in zip(("nx", "ny", "nz"), normals.T, strict=True):
        data[k] = column
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(points)}\n"
        + "".join(f"property float {k}\n" for k in ("x", "y", "z", "nx", "ny", "nz"))
        + "end_header\n"
    )
    with path.open("wb") as out:
        out.write(header.encode("ascii"))
        out.write(data.tobytes())


def make_hoard(
    folder: Path,
    name: str,
    seed: int,
    coins: int = 40,
    dies: int = 12,
    meshes: bool = False,
    scale: float = 1.0,
) -> None:
    kind = KINDS[name]
    dies = min(dies, coins)
    rng = np.random.default_rng(seed)
    folder.mkdir(parents=True, exist_ok=True)
    labels, poses, faces = [], {}, {}
    for side in ("D", "R"):
        types = [new_type(rng) for _ in range(kind.types)]
        die_types = [types[k % len(types)] for k in range(dies)]
        die_reliefs = [engrave(t, kind.die_jitter, rng) for t in die_types]
        # every die strikes a coin; the rest by uneven shares (a few dies struck most of the hoard)
        shares = rng.dirichlet(np.full(dies, 0.7))
        which = np.concatenate([np.arange(dies), rng.choice(dies, coins - dies, p=shares)])
        rng.shuffle(which)
        for coin, die in enumerate(which, start=1):
            face = f"L{coin:04d}{side}"
            faces[face] = {}
            height, flan, T_coin_die = strike(die_reliefs[die], die_types[die].radius, kind, rng, faces[face])
            scanner = kind.scanners[int(rng.integers(len(kind.scanners)))]
            faces[face]["scanner"] = kind.scanners.index(scanner)
            points, normals, T_scan_coin, triangles = scan(
                height, flan, scanner, rng, mesh=meshes, scale=scale
            )
            T_coin_die[:3, 3] *= scale  # the die is scaled with its coin: a rigid motion between the two
            faces[face]["flan_radius_mm"] = faces[face]["flan_radius_mm"] * scale
            poses[face] = (T_scan_coin @ T_coin_die).tolist()
            if triangles is None:
                write_ply(folder / f"{face}.ply", points, normals)
            else:
                write_stl(folder / f"{face}.stl", points, triangles)
            labels.append((face, f"{side}{die + 1}"))
            print(f"{name} {face}: die {side}{die + 1}, {len(points):,} points", flush=True)
    with (folder / "labels.csv").open("w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["coin_id", "die_id"])
        writer.writerows(sorted(labels))
    # T_scan_die per face: for two faces of one die, T_b_a = T_scan_die[b] @ inv(T_scan_die[a])
    (folder / "poses.json").write_text(json.dumps(poses, indent=1, sort_keys=True))
    # what each face was drawn with (flan, strike, wear, scanner), to tell which coins a method fails on
    (folder / "faces.json").write_text(json.dumps(faces, indent=1, sort_keys=True))
    write_truth(folder, poses)


def write_truth(folder: Path, poses: dict[str, list[list[float]]]) -> None:
    """``truth.json`` and ``splits.csv`` of a hoard from its faces' poses (``poses.json``), in the form of
    coindie's registration benchmark (written here as plain JSON and CSV, with nothing of coindie)."""
    truth = {"faces": {face: {"T_scan_die": T} for face, T in sorted(poses.items())}}
    (folder / "truth.json").write_text(json.dumps(truth, indent=1))
    with (folder / "splits.csv").open("w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["face_id", "split"])
        writer.writerows((face, "registration_test") for face in sorted(poses))


def evaluate(folder: Path, coindie: str) -> dict[str, object]:
    """The issue's protocol: init, run --workers 2, cluster --auto, eval against the labels."""
    project = folder.with_name(folder.name + "-project")
    clusters = folder.with_name(folder.name + "-clusters.csv")
    started = time.perf_counter()
    if not project.exists():
        subprocess.run([coindie, "init", str(project), str(folder)], check=True)
    subprocess.run([coindie, "run", str(project), "--workers", "2"], check=True)
    ran = time.perf_counter() - started
    subprocess.run([coindie, "cluster", str(project), "--auto", "-o", str(clusters)], check=True)
    out = subprocess.run(
        [coindie, "eval", str(clusters), str(folder / "labels.csv"), "--json"],
        check=True,
        capture_output=True,
        text=True,
    )
    return {"scores": json.loads(out.stdout), "run_seconds": ran}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", type=Path)
    parser.add_argument(
        "--kinds",
        default=",".join(ISSUE_KINDS),
        help=f"comma-separated, among {', '.join(KINDS)} (default: issue 13's five)",
    )
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--coins", type=int, default=40)
    parser.add_argument(
        "--dies", type=int, default=12, help="dies a side (as many as coins: every die known from one coin)"
    )
    parser.add_argument(
        "--meshes",
        action="store_true",
        help="write each face as a binary STL mesh of its sampling grid (no normals, no edge wall)",
    )
    parser.add_argument(
        "--scale",
        type=float,
        default=1.0,
        help="coins this many times as large in every direction as the kinds' 18-22 mm (the scanner is not "
        "scaled): 0.55 for obols and small bronzes of 10-12 mm, 1.6 for sestertii of 29-35 mm",
    )
    parser.add_argument("--evaluate", action="store_true")
    parser.add_argument("--coindie", default=str(Path(sys.executable).with_name("coindie")))
    args = parser.parse_args()
    kinds = args.kinds.split(",")
    unknown = [name for name in kinds if name not in KINDS]
    if unknown:
        parser.error(f"--kinds: unknown {', '.join(unknown)} (known: {', '.join(KINDS)})")
    if args.coins < 2:
        parser.error(f"--coins must be at least 2 (a hoard needs pairs). Got {args.coins}.")
    if args.dies < 1:
        parser.error(f"--dies must be at least 1. Got {args.dies}.")
    if not 0.2 <= args.scale <= 3.0:
        parser.error(f"--scale must be within 0.2 and 3. Got {args.scale}.")
    for name in kinds:
        folder = args.out / (
            f"{name}-{args.seed}"
            + ("" if args.dies == 12 else f"-{args.dies}dies")
            + ("-stl" if args.meshes else "")
            + ("" if args.scale == 1.0 else f"-x{args.scale:g}")
        )
        if not (folder / "labels.csv").exists():
            seed = args.seed * 100 + list(KINDS).index(name)
            make_hoard(
                folder, name, seed, coins=args.coins, dies=args.dies, meshes=args.meshes, scale=args.scale
            )
        elif not (folder / "truth.json").exists():  # a hoard made before the script wrote it
            write_truth(folder, json.loads((folder / "poses.json").read_text()))
        if args.evaluate:
            try:
                result = evaluate(folder, args.coindie)
            except subprocess.CalledProcessError as failed:  # the other hoards still run
                print(f"{name}: {' '.join(failed.cmd)} failed (exit {failed.returncode})", flush=True)
                continue
            print(name, json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
