#!/usr/bin/env python3
"""Blind synthetic hoards of die-linked coin scans (a third, independent generator).

Writes, for each requested *kind*, a folder ``OUT/<kind>-<seed>/`` holding one PLY
point cloud per coin face (``L0001D.ply`` obverse, ``L0001R.ply`` reverse), the die
labels (``labels.csv``), the true rigid pose of every scan relative to its die
(``poses.json``; the same in ``truth.json`` and ``splits.csv``, the form ``coindie bench registration``
reads) and everything each face was drawn with (``faces.json``).
Units are millimetres throughout.

Written blind at stop 49 (from issue 13's ranges and the paper, without reading coindie's code, tests,
docs or its two other generators, ``coindie synth`` and ``benchmarks/outsider_hoards.py``), to measure
how much of coindie's figures hold only on the generators it was built on (BENCHMARK.md, "A third,
blindly written generator"). It imports nothing of coindie. A measurement, not a test: no pass/fail.

What is modelled, and how
-------------------------
Types and dies.  A *type* (the design of one side) is a composition of relief
primitives built from first principles, not an image:

* ellipsoid-like *blobs* with one of four cross-section profiles (``dome``: a
  steep-walled half ellipsoid, ``round``: a soft bump, ``sharp``: a wedge with a
  crest, ``mesa``: flat top with steep walls);
* *strokes*: tubes swept along Catmull-Rom splines or polylines, tapering at the
  ends (necks, legs, tails, hair locks, wreath stems, die cracks, letters);
* *rings* (linear borders, wheels, annulets).

Obverses are stylised heads (cranium, face, nose, lips, chin, neck, an eye, hair
drawn as parallel ridges or S-shaped locks ending in pellets, an optional laurel
wreath, small field symbols); reverses are a horse (body, chest, rump, neck, head,
four jointed legs with hooves, tail, mane) with a wheel / boar / rosette below and
a rosette / bird / crescent above.  Both carry a legend written with a small
hand-made stroke alphabet along an arc, and a pellet or linear border.  Elements
are combined by ``max`` (cuts of the engraver), surface details (hair, eye, mane,
tool marks, cracks) are *added* on top.

Every die of a type is engraved separately by hand: each group of elements (the
head, one letter, one leg ...) is shifted by about ``delta`` mm, rotated and
resized by the amount that moves its far end by a similar distance, and then each
element and each stroke control point is jittered by a third of that.  Border
pellets are re-laid per die (their count differs by up to two).  Each die also gets
a few tool marks, sometimes a crack (raised random-walk line) or a cud (a raised
lump at the rim where the die broke), a faint field texture (a few microns) and a
slightly convex or concave face.  The die relief is rasterised once on a 0.02 mm
lattice in *die coordinates* (x, y in the die face, z up out of the coin).

Strike.  The coin's height field, on a sub-block of the same lattice, is
``base + relief``: the base is the flan surface (die curvature + per-coin cupping or
doming measured at 10 mm from the flan centre + a tilt + an optional bend along a
line, a soft hinge), anchored to touch z = 0 at the die centre.  The flan outline is
irregular (a few cosine harmonics), centred off the die by up to a fraction of its
diameter; outside the die face the unstruck metal stands slightly proud.  Weak
strikes: inside a smooth half-plane zone (up to half the face) the relief is scaled
down and soft-capped (the metal did not reach the bottom of the die's cavities).
Double strikes: the max of the relief and a shifted/rotated, partial second
impression.  Broken flans: a piece beyond a jagged line is missing.

Wear and corrosion.  Abrasion soft-caps the relief at (1 - wear) of its maximum,
unevenly over the face, then blurs it (rounding) and lowers it slightly; a few
fine scratches.  Crusts are thresholded smooth random fields standing proud with a
rough top; pits are clusters of Gaussian hollows inside another thresholded field.
The coin edge is rounded (a quarter ellipse), broken edges stay sharp.

Scanner.  Points are taken at jittered-lattice positions (random orientation, from
near-regular to fully stratified), heights interpolated with cubic splines from the
coin grid; the edge is seen as a vertical band of points below the rounded rim (no
points on the back face).  Noise is added along a slanted viewing direction (or
along the normal), larger at grazing angles; grazing points may be missing; a
low-frequency warp of a few microns, a tiny scale error, and for some raw scanners
a fringe ripple are added; holes are irregular missing patches.  Some scanners
smooth the cloud (Laplacian steps along the normal).  Normals are either the true
surface normals, "mesh" normals (PCA over 8 neighbours of the noisy points) or
estimated by PCA over 16-24 neighbours, always oriented away from the coin.
Finally every scan gets a uniformly random rotation and a translation of tens of mm;
``T_scan_die`` maps die coordinates to scan coordinates.

Kinds: ``ordinary`` (good scanner, 2 types per side, moderate everything),
``hard`` (one type per side, dies differing by ~0.25 mm, heavy wear, bends,
breaks, corrosion, weak and double strikes, off-centre strikes, estimated
normals), ``coarse`` (0.15 mm / 0.03 mm scanner), ``mixed`` (a fine smoothed and a
coarse raw scanner in one hoard) and ``flat`` (flat, round, centred, well struck
flans, good scanner).

Only numpy and scipy are used.  Example::

    python benchmarks/blind_hoards.py /tmp/hoards --kinds ordinary,hard --seed 1
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from scipy import ndimage
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

F64 = npt.NDArray[np.float64]
I64 = npt.NDArray[np.int64]
BoolA = npt.NDArray[np.bool_]
Rng = np.random.Generator

GRID_H = 0.02  # mm, lattice of die reliefs and coin height grids
MAX_POINTS = 380_000  # per face, the scanner spacing is widened above this
KIND_NAMES = ("ordinary", "hard", "coarse", "mixed", "flat")


# ----------------------------------------------------------------------------
# small geometric helpers
# ----------------------------------------------------------------------------


def rot2(theta: float) -> F64:
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


def unit(theta: float) -> F64:
    return np.array([math.cos(theta), math.sin(theta)])


def smoothstep(x: F64) -> F64:
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3.0 - 2.0 * x)


def smin(a: F64, b: F64 | float, k: float) -> F64:
    """Smooth minimum (soft cap) with softness k (mm)."""
    m = np.minimum(a, b)
    return m - k * np.log1p(np.exp(-np.abs(a - b) / k))


def profile(q: F64, kind: str) -> F64:
    """Cross-section of a relief element: 1 at the crest (q=0), 0 at its edge (q=1)."""
    q = np.clip(q, 0.0, 1.0)
    if kind == "dome":
        return np.sqrt(1.0 - q * q)
    if kind == "round":
        return (1.0 - q * q) ** 2
    if kind == "sharp":
        return 1.0 - q
    if kind == "mesa":
        return smoothstep((1.0 - q) / 0.35)
    raise ValueError(kind)


def catmull_rom(ctrl: F64, step: float) -> F64:
    """Dense polyline through control points (centripetal-ish uniform Catmull-Rom)."""
    p = np.vstack([2 * ctrl[0] - ctrl[1], ctrl, 2 * ctrl[-1] - ctrl[-2]])
    out = []
    for i in range(1, len(p) - 2):
        p0, p1, p2, p3 = p[i - 1], p[i], p[i + 1], p[i + 2]
        n = max(2, int(math.ceil(np.linalg.norm(p2 - p1) / step)))
        t = np.linspace(0.0, 1.0, n, endpoint=False)[:, None]
        seg = 0.5 * (
            (2 * p1)
            + (-p0 + p2) * t
            + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t**2
            + (-p0 + 3 * p1 - 3 * p2 + p3) * t**3
        )
        out.append(seg)
    out.append(ctrl[-1:])
    return np.vstack(out)


def densify(poly: F64, step: float) -> F64:
    out = []
    for a, b in zip(poly[:-1], poly[1:], strict=True):
        n = max(1, int(math.ceil(np.linalg.norm(b - a) / step)))
        out.append(a + (b - a) * np.linspace(0, 1, n, endpoint=False)[:, None])
    out.append(poly[-1:])
    return np.vstack(out)


def arc(cx: float, cy: float, rx: float, ry: float, a0: float, a1: float, n: int) -> F64:
    a = np.radians(np.linspace(a0, a1, n))
    return np.stack([cx + rx * np.cos(a), cy + ry * np.sin(a)], axis=1)


def smooth_noise(rng: Rng, shape: tuple[int, int], corr_cells: float) -> F64:
    """Zero-mean, unit-std smooth random field with correlation length ~corr_cells."""
    step = max(1.0, corr_cells / 2.0)
    cs = (max(4, int(shape[0] / step) + 4), max(4, int(shape[1] / step) + 4))
    coarse = ndimage.gaussian_filter(rng.normal(size=cs), 1.0, mode="wrap")
    f = ndimage.zoom(coarse, (shape[0] / (cs[0] - 3), shape[1] / (cs[1] - 3)), order=3)
    f = f[: shape[0], : shape[1]]
    if f.shape != shape:  # zoom rounding
        f = np.pad(f, ((0, shape[0] - f.shape[0]), (0, shape[1] - f.shape[1])), mode="edge")
    return (f - f.mean()) / (f.std() + 1e-12)


# ----------------------------------------------------------------------------
# relief primitives
# ----------------------------------------------------------------------------


@dataclass
class Blob:
    c: F64
    ax: float
    ay: float
    ang: float
    h: float
    prof: str = "dome"
    add: bool = False

    def key_points(self) -> F64:
        return self.c[None, :]

    def affine(self, A: F64, b: F64) -> Blob:
        ea, eb = A @ unit(self.ang), A @ unit(self.ang + math.pi / 2)
        return Blob(
            A @ self.c + b,
            self.ax * float(np.linalg.norm(ea)),
            self.ay * float(np.linalg.norm(eb)),
            math.atan2(ea[1], ea[0]),
            self.h,
            self.prof,
            self.add,
        )

    def jitter(self, rng: Rng, amt: float) -> Blob:
        return Blob(
            self.c + rng.normal(0, amt, 2),
            self.ax * (1 + rng.normal(0, 0.04)),
            self.ay * (1 + rng.normal(0, 0.04)),
            self.ang + rng.normal(0, 0.04),
            self.h * (1 + rng.normal(0, 0.05)),
            self.prof,
            self.add,
        )

    def bbox(self) -> tuple[float, float, float, float]:
        r = max(self.ax, self.ay)
        return self.c[0] - r, self.c[0] + r, self.c[1] - r, self.c[1] + r

    def render(self, X: F64, Y: F64) -> F64:
        dx, dy = X - self.c[0], Y - self.c[1]
        ca, sa = math.cos(self.ang), math.sin(self.ang)
        u = (dx * ca + dy * sa) / self.ax
        v = (-dx * sa + dy * ca) / self.ay
        q = np.sqrt(u * u + v * v)
        return np.where(q < 1.0, self.h * profile(q, self.prof), 0.0)


@dataclass
class Stroke:
    pts: F64
    w: float  # half width at the middle, mm
    h: float
    prof: str = "round"
    taper: float = 0.6  # width fraction left at the ends
    smooth: bool = True  # spline through the points, else a polyline
    add: bool = False

    def key_points(self) -> F64:
        return self.pts

    def affine(self, A: F64, b: F64) -> Stroke:
        s = math.sqrt(abs(np.linalg.det(A)))
        return Stroke(self.pts @ A.T + b, self.w * s, self.h, self.prof, self.taper, self.smooth, self.add)

    def jitter(self, rng: Rng, amt: float) -> Stroke:
        return Stroke(
            self.pts + rng.normal(0, amt, self.pts.shape),
            self.w * (1 + rng.normal(0, 0.07)),
            self.h * (1 + rng.normal(0, 0.05)),
            self.prof,
            self.taper,
            self.smooth,
            self.add,
        )

    def dense(self) -> F64:
        return catmull_rom(self.pts, 0.08) if self.smooth and len(self.pts) > 2 else densify(self.pts, 0.08)

    def bbox(self) -> tuple[float, float, float, float]:
        P = self.dense()
        return (
            P[:, 0].min() - self.w,
            P[:, 0].max() + self.w,
            P[:, 1].min() - self.w,
            P[:, 1].max() + self.w,
        )

    def render(self, X: F64, Y: F64) -> F64:
        """Distance to the swept centre line, segment by segment in small windows."""
        P = self.dense()
        xs, ys = X[0], Y[:, 0]
        h = xs[1] - xs[0] if len(xs) > 1 else GRID_H
        dmin = np.full((len(ys), len(xs)), np.inf)
        tpar = np.zeros_like(dmin)
        seg = np.diff(P, axis=0)
        slen = np.linalg.norm(seg, axis=1)
        cum = np.concatenate([[0.0], np.cumsum(slen)])
        total = max(cum[-1], 1e-9)
        for i in range(len(seg)):
            a, d, L = P[i], seg[i], max(slen[i], 1e-9)
            lo, hi = np.minimum(a, a + d) - self.w, np.maximum(a, a + d) + self.w
            i0 = max(0, int((lo[0] - xs[0]) / h))
            i1 = min(len(xs), int((hi[0] - xs[0]) / h) + 2)
            j0 = max(0, int((lo[1] - ys[0]) / h))
            j1 = min(len(ys), int((hi[1] - ys[0]) / h) + 2)
            if i1 <= i0 or j1 <= j0:
                continue
            gx = xs[None, i0:i1] - a[0]
            gy = ys[j0:j1, None] - a[1]
            u = np.clip((gx * d[0] + gy * d[1]) / (L * L), 0.0, 1.0)
            d2 = (gx - u * d[0]) ** 2 + (gy - u * d[1]) ** 2
            sub = dmin[j0:j1, i0:i1]
            upd = d2 < sub
            sub[upd] = d2[upd]
            tsub = tpar[j0:j1, i0:i1]
            tsub[upd] = ((cum[i] + u * L) / total)[upd]
        taperf = 1.0 - (1.0 - self.taper) * (2.0 * tpar - 1.0) ** 4
        q = np.sqrt(dmin) / (self.w * taperf)
        return np.where(q < 1.0, self.h * np.sqrt(taperf) * profile(q, self.prof), 0.0)


@dataclass
class Ring:
    c: F64
    r: float
    w: float
    h: float
    prof: str = "round"
    add: bool = False

    def key_points(self) -> F64:
        return self.c[None, :]

    def affine(self, A: F64, b: F64) -> Ring:
        s = math.sqrt(abs(np.linalg.det(A)))
        return Ring(A @ self.c + b, self.r * s, self.w * s, self.h, self.prof, self.add)

    def jitter(self, rng: Rng, amt: float) -> Ring:
        return Ring(
            self.c + rng.normal(0, amt, 2),
            self.r * (1 + rng.normal(0, 0.02)),
            self.w * (1 + rng.normal(0, 0.06)),
            self.h * (1 + rng.normal(0, 0.05)),
            self.prof,
            self.add,
        )

    def bbox(self) -> tuple[float, float, float, float]:
        R = self.r + self.w
        return self.c[0] - R, self.c[0] + R, self.c[1] - R, self.c[1] + R

    def render(self, X: F64, Y: F64) -> F64:
        q = np.abs(np.hypot(X - self.c[0], Y - self.c[1]) - self.r) / self.w
        return np.where(q < 1.0, self.h * profile(q, self.prof), 0.0)


Element = Blob | Stroke | Ring


@dataclass
class Group:
    """Elements the engraver cut as one unit (moved together from die to die)."""

    name: str
    elems: list[Element]

    def centroid(self) -> F64:
        return np.vstack([e.key_points() for e in self.elems]).mean(axis=0)

    def radius(self) -> float:
        P = np.vstack([e.key_points() for e in self.elems])
        return float(max(0.5, np.linalg.norm(P - P.mean(axis=0), axis=1).max()))

    def affine(self, A: F64, b: F64) -> Group:
        return Group(self.name, [e.affine(A, b) for e in self.elems])


@dataclass
class Border:
    kind: str  # "pellets" or "line"
    r: float
    size: float  # pellet radius or ring half width
    n: int  # nominal pellet count
    h: float


@dataclass
class TypeDesign:
    side: str
    index: int
    H: float  # nominal relief height, mm
    groups: list[Group]
    border: Border
    die_radius: float
    meta: dict[str, Any] = field(default_factory=dict)


# ----------------------------------------------------------------------------
# stroke alphabet and legends
# ----------------------------------------------------------------------------


def _letter_strokes() -> dict[str, tuple[float, list[tuple[F64, bool]]]]:
    """Letter -> (advance width, [(points in a 1-high box, smooth?)])."""
    P = lambda *xy: np.array(xy, float)  # noqa: E731
    return {
        "A": (0.75, [(P((0, 0), (0.37, 1), (0.74, 0)), False), (P((0.17, 0.4), (0.57, 0.4)), False)]),
        "C": (0.7, [(arc(0.42, 0.5, 0.4, 0.5, 55, 305, 9), True)]),
        "D": (
            0.7,
            [(P((0, 0), (0, 1)), False), (P((0, 1), (0.42, 0.9), (0.65, 0.5), (0.42, 0.1), (0, 0)), True)],
        ),
        "E": (0.6, [(P((0.58, 1), (0, 1), (0, 0), (0.58, 0)), False), (P((0, 0.5), (0.45, 0.5)), False)]),
        "I": (0.25, [(P((0.1, 0), (0.1, 1)), False)]),
        "L": (0.55, [(P((0, 1), (0, 0), (0.52, 0)), False)]),
        "M": (0.9, [(P((0, 0), (0.1, 1), (0.45, 0.3), (0.8, 1), (0.9, 0)), False)]),
        "N": (0.75, [(P((0, 0), (0, 1), (0.68, 0), (0.68, 1)), False)]),
        "O": (0.8, [(arc(0.4, 0.5, 0.38, 0.5, 0, 360, 13), True)]),
        "P": (
            0.6,
            [(P((0, 0), (0, 1)), False), (P((0, 1), (0.4, 0.96), (0.58, 0.76), (0.4, 0.54), (0, 0.5)), True)],
        ),
        "R": (
            0.65,
            [
                (P((0, 0), (0, 1)), False),
                (P((0, 1), (0.4, 0.96), (0.58, 0.76), (0.4, 0.54), (0, 0.5)), True),
                (P((0.22, 0.5), (0.62, 0)), False),
            ],
        ),
        "S": (
            0.6,
            [
                (
                    P(
                        (0.58, 0.88),
                        (0.32, 1),
                        (0.04, 0.84),
                        (0.12, 0.58),
                        (0.48, 0.42),
                        (0.58, 0.16),
                        (0.3, 0),
                        (0, 0.1),
                    ),
                    True,
                )
            ],
        ),
        "T": (0.7, [(P((0, 1), (0.7, 1)), False), (P((0.35, 1), (0.35, 0)), False)]),
        "V": (0.72, [(P((0, 1), (0.36, 0), (0.72, 1)), False)]),
        "X": (0.7, [(P((0, 0), (0.7, 1)), False), (P((0, 1), (0.7, 0)), False)]),
        "G": (0.75, [(arc(0.42, 0.5, 0.4, 0.5, 55, 340, 10), True), (P((0.8, 0.35), (0.45, 0.35)), False)]),
    }


ALPHABET = _letter_strokes()
LEGENDS = (
    "ATISIOS",
    "EPAD",
    "VIIRICA",
    "TOGIRIX",
    "LVCCIOS",
    "SOLIMA",
    "ARIVOS",
    "CALIIAGIIS",
    "ATEVLA",
    "DVRNACOS",
    "ANDOS",  # every letter of a legend must be in ALPHABET
    "CRICIRV",
    "PIXTILOS",
    "SEDVLLVS",
)


def legend_groups(
    rng: Rng, text: str, r: float, a_start: float, letter_h: float, w: float, h: float, prof: str
) -> list[Group]:
    """Letters laid clockwise along a circle of radius r, tops outward."""
    groups = []
    a = math.radians(a_start)
    gap = 0.28
    for ch in text:
        adv, strokes = ALPHABET[ch]
        up = unit(a)
        tang = np.array([math.sin(a), -math.cos(a)])
        base = r * up
        A = np.stack([tang, up], axis=1) * letter_h
        b = base - 0.5 * adv * letter_h * tang
        elems: list[Element] = [
            Stroke(pts @ A.T + b, w, h, prof, 0.8, smooth, False) for pts, smooth in strokes
        ]
        groups.append(Group(f"letter {ch}", elems))
        a -= (adv + gap) * letter_h / r
    return groups


# ----------------------------------------------------------------------------
# type designs
# ----------------------------------------------------------------------------


def _place(groups: list[Group], A: F64, b: F64) -> list[Group]:
    return [g.affine(A, b) for g in groups]


def _fit_affine(groups: list[Group], rng: Rng, facing: int, target: float) -> tuple[F64, F64]:
    P = np.vstack([e.key_points() for g in groups for e in g.elems])
    c = 0.5 * (P.min(axis=0) + P.max(axis=0))
    extent = np.linalg.norm(P - c, axis=1).max() + 1.0
    s = target / extent
    A = rot2(rng.normal(0, 0.12)) @ np.diag([facing * s, s])
    return A, -A @ c


def head_type(rng: Rng, index: int, facing: int) -> TypeDesign:
    """Stylised head (canonical: facing +x), hair, optional wreath, legend, border."""
    H = rng.uniform(0.5, 0.95)
    j = lambda x, y, s=0.25: np.array([x, y]) + rng.normal(0, s, 2)  # noqa: E731
    prof = str(rng.choice(["dome", "round", "mesa"]))
    g_head = Group(
        "head",
        [
            Blob(j(-0.8, 1.0), rng.uniform(3.8, 4.6), rng.uniform(4.2, 5.0), rng.normal(0, 0.2), H, prof),
            Blob(
                j(1.8, 0.0),
                rng.uniform(1.8, 2.3),
                rng.uniform(3.2, 3.9),
                0.2 + rng.normal(0, 0.1),
                0.92 * H,
                prof,
            ),
        ],
    )
    g_nose = Group(
        "nose",
        [Blob(j(3.6, 0.6, 0.15), rng.uniform(0.8, 1.1), rng.uniform(0.4, 0.6), -0.5, 0.96 * H, "round")],
    )
    g_mouth = Group(
        "mouth",
        [
            Blob(j(3.3, -0.7, 0.1), 0.42, 0.25, 0.1, 0.86 * H, "round"),
            Blob(j(3.2, -1.3, 0.1), 0.4, 0.24, -0.1, 0.86 * H, "round"),
        ],
    )
    g_chin = Group("chin", [Blob(j(2.6, -2.4, 0.15), 0.85, 0.62, 0.3, 0.88 * H, "round")])
    g_neck = Group(
        "neck",
        [
            Stroke(
                np.array([j(0.6, -2.0), j(0.0, -4.0), j(-0.6, -5.6)]),
                rng.uniform(1.6, 2.0),
                0.8 * H,
                "round",
                0.8,
            )
        ],
    )
    eye_c = j(2.3, 1.0, 0.12)
    g_eye = Group(
        "eye",
        [
            Stroke(arc(eye_c[0], eye_c[1], 0.6, 0.35, 0, 360, 11), 0.07, 0.1, "sharp", 1.0, True, True),
            Blob(eye_c, 0.18, 0.18, 0.0, 0.12, "dome", True),
        ],
    )
    hair: list[Group] = []
    style = "arcs" if rng.random() < 0.5 else "locks"
    hh, hw = rng.uniform(0.07, 0.14), rng.uniform(0.1, 0.15)
    if style == "arcs":
        hc = j(-1.4, 1.4, 0.2)
        n = int(rng.integers(7, 11))
        for k in range(n):
            rr = 1.4 + k * rng.uniform(0.42, 0.55)
            a0, a1 = rng.uniform(70, 100), rng.uniform(220, 260)
            pts = arc(hc[0], hc[1], rr, rr * 1.08, a0, a1, 7)
            pts += rng.normal(0, 0.08, pts.shape)
            hair.append(Group(f"hair {k}", [Stroke(pts, hw, hh, "sharp", 0.4, True, True)]))
    else:
        n = int(rng.integers(5, 8))
        for k in range(n):
            a = math.radians(70 + k * 150 / n)
            p0 = np.array([-0.8, 1.0]) + 2.2 * unit(a)
            d = unit(a + rng.normal(0, 0.2))
            pts = np.array(
                [
                    p0,
                    p0 + 1.2 * d + 0.5 * unit(a + 1.4),
                    p0 + 2.4 * d - 0.4 * unit(a + 1.4),
                    p0 + 3.3 * d + 0.3 * unit(a + 1.4),
                ]
            )
            hair.append(
                Group(
                    f"lock {k}",
                    [
                        Stroke(pts, 1.6 * hw, 1.3 * hh, "round", 0.5, True, True),
                        Blob(pts[-1] + 0.3 * d, 0.32, 0.32, 0.0, 0.35 * H, "dome", False),
                    ],
                )
            )
    groups = [g_head, g_nose, g_mouth, g_chin, g_neck, g_eye, *hair]
    wreath = rng.random() < 0.6
    if wreath:
        stem = np.array([j(3.0, 3.6), j(0.0, 4.4), j(-3.0, 2.6), j(-4.2, -0.8)])
        dense = catmull_rom(stem, 0.1)
        leaves: list[Element] = [Stroke(stem, 0.12, 0.08, "round", 0.8, True, True)]
        for k, i in enumerate(range(4, len(dense) - 2, max(4, len(dense) // 9))):
            t = dense[i + 1] - dense[i - 1]
            ta = math.atan2(t[1], t[0]) + (0.7 if k % 2 else -0.7)
            leaves.append(Blob(dense[i] + 0.45 * unit(ta), 0.55, 0.2, ta, 0.14, "round", True))
        groups.append(Group("wreath", leaves))
    A, b = _fit_affine(groups, rng, facing, rng.uniform(6.8, 7.5))
    groups = _place(groups, A, b)
    groups += field_symbols(rng, H, n=int(rng.integers(1, 3)), r=rng.uniform(7.2, 8.0))
    text = str(rng.choice(LEGENDS))
    lh = rng.uniform(1.2, 1.6)
    groups += legend_groups(
        rng,
        text,
        rng.uniform(8.4, 8.8),
        rng.uniform(160, 260),
        lh,
        rng.uniform(0.1, 0.14),
        rng.uniform(0.35, 0.5) * H,
        str(rng.choice(["sharp", "round"])),
    )
    border = make_border(rng, H)
    return TypeDesign(
        "D",
        index,
        H,
        groups,
        border,
        border.r + 0.6,
        {
            "design": "head",
            "facing": facing,
            "hair": style,
            "wreath": wreath,
            "legend": text,
            "relief_profile": prof,
            "border": border.kind,
        },
    )


def horse_type(rng: Rng, index: int, facing: int, below: str, above: str) -> TypeDesign:
    """Horse (canonical: facing +x) with an accessory below and above, legend, border."""
    H = rng.uniform(0.45, 0.9)
    j = lambda x, y, s=0.2: np.array([x, y]) + rng.normal(0, s, 2)  # noqa: E731
    prof = str(rng.choice(["dome", "round", "mesa"]))
    groups = [
        Group(
            "body",
            [
                Blob(j(0, 1), rng.uniform(3.5, 4.1), rng.uniform(1.7, 2.1), rng.normal(0.05, 0.05), H, prof),
                Blob(j(2.6, 0.8), 1.5, 1.6, 0.0, 0.95 * H, prof),
                Blob(j(-2.8, 1.2), 1.6, 1.6, 0.0, 0.95 * H, prof),
            ],
        ),
        Group(
            "neck", [Stroke(np.array([j(2.9, 1.8), j(4.0, 3.5), j(4.6, 4.6)]), 1.15, 0.85 * H, "round", 0.7)]
        ),
        Group(
            "head",
            [
                Blob(j(5.3, 4.2, 0.15), 1.4, 0.62, -0.7 + rng.normal(0, 0.15), 0.85 * H, "round"),
                Stroke(np.array([j(4.7, 4.9, 0.1), j(4.5, 5.7, 0.1)]), 0.22, 0.6 * H, "round", 0.4, False),
            ],
        ),
    ]
    gallop = rng.uniform(-0.6, 0.6)
    legs = [
        ((2.4, -0.5), (2.7 + gallop, -2.5), (2.5 + 1.5 * gallop, -4.5)),
        ((1.8, -0.5), (1.2, -2.5), (1.6, -4.4)),
        ((-2.4, -0.3), (-2.9 - gallop, -2.5), (-2.4, -4.5)),
        ((-3.0, -0.3), (-3.8, -2.2), (-4.2 - gallop, -4.0)),
    ]
    for k, leg in enumerate(legs):
        pts = np.array([j(*p, 0.15) for p in leg])
        groups.append(
            Group(
                f"leg {k}",
                [
                    Stroke(pts, rng.uniform(0.38, 0.48), 0.7 * H, "round", 0.65),
                    Blob(pts[-1] + np.array([0.15, -0.1]), 0.36, 0.26, 0.0, 0.72 * H, "dome"),
                ],
            )
        )
    groups.append(
        Group(
            "tail",
            [
                Stroke(
                    np.array([j(-4.2, 1.6), j(-5.6, 0.5), j(-5.8, -1.5), j(-5.2, -2.8)]),
                    0.4,
                    0.65 * H,
                    "sharp",
                    0.35,
                )
            ],
        )
    )
    mane = [
        Stroke(
            np.array([p, p + np.array([-0.7, 0.35]) + rng.normal(0, 0.1, 2)]),
            0.1,
            0.1,
            "sharp",
            0.5,
            False,
            True,
        )
        for p in catmull_rom(np.array([[3.2, 2.2], [3.9, 3.6], [4.4, 4.7]]), 0.45)
    ]
    groups.append(Group("mane", mane))
    groups += accessory(rng, below, np.array([0.0, -7.0]), H)
    groups += accessory(rng, above, np.array([-0.8, 6.2]), H)
    A, b = _fit_affine(groups, rng, facing, rng.uniform(7.2, 7.8))
    groups = _place(groups, A, b)
    text = str(rng.choice(LEGENDS))[:5]
    groups += legend_groups(
        rng,
        text,
        rng.uniform(8.5, 8.9),
        rng.uniform(40, 120),
        rng.uniform(1.1, 1.5),
        rng.uniform(0.1, 0.13),
        rng.uniform(0.35, 0.5) * H,
        str(rng.choice(["sharp", "round"])),
    )
    border = make_border(rng, H)
    return TypeDesign(
        "R",
        index,
        H,
        groups,
        border,
        border.r + 0.6,
        {
            "design": "horse",
            "facing": facing,
            "below": below,
            "above": above,
            "legend": text,
            "relief_profile": prof,
            "border": border.kind,
        },
    )


def accessory(rng: Rng, kind: str, c: F64, H: float) -> list[Group]:
    if kind == "wheel":
        r = rng.uniform(1.4, 1.7)
        n = int(rng.integers(6, 9))
        el: list[Element] = [Ring(c, r, 0.22, 0.55 * H), Blob(c, 0.38, 0.38, 0, 0.6 * H, "dome")]
        el += [
            Stroke(np.array([c, c + r * unit(2 * math.pi * k / n)]), 0.13, 0.45 * H, "round", 0.9, False)
            for k in range(n)
        ]
        return [Group("wheel", el)]
    if kind == "boar":
        el = [
            Blob(c, 1.7, 0.75, 0.0, 0.6 * H, "round"),
            Blob(c + np.array([1.8, 0.1]), 0.7, 0.45, -0.3, 0.55 * H, "round"),
        ]
        el += [
            Stroke(np.array([c + [dx, -0.4], c + [dx + 0.1, -1.4]]), 0.2, 0.5 * H, "round", 0.7, False)
            for dx in (-1.1, -0.6, 0.6, 1.1)
        ]
        el += [
            Stroke(np.array([c + [dx, 0.55], c + [dx - 0.2, 1.1]]), 0.08, 0.1, "sharp", 0.5, False, True)
            for dx in np.linspace(-1.2, 1.0, 6)
        ]
        return [Group("boar", el)]
    if kind == "rosette":
        el = [Blob(c, 0.38, 0.38, 0, 0.55 * H, "dome")]
        el += [Blob(c + 0.85 * unit(2 * math.pi * k / 6), 0.28, 0.28, 0, 0.5 * H, "dome") for k in range(6)]
        return [Group("rosette", el)]
    if kind == "bird":
        el = [
            Blob(c, 0.8, 0.4, 0.2, 0.55 * H, "round"),
            Stroke(
                np.array([c + [-0.3, 0.2], c + [-0.6, 1.2], c + [0.4, 1.6]]), 0.18, 0.45 * H, "sharp", 0.4
            ),
            Stroke(np.array([c + [0.7, 0.2], c + [1.2, 0.4]]), 0.1, 0.4 * H, "sharp", 0.5, False),
        ]
        return [Group("bird", el)]
    if kind == "crescent":
        return [
            Group("crescent", [Stroke(arc(c[0], c[1], 1.0, 1.0, 200, 340, 7), 0.25, 0.5 * H, "round", 0.3)])
        ]
    raise ValueError(kind)


def field_symbols(rng: Rng, H: float, n: int, r: float) -> list[Group]:
    out = []
    for k in range(n):
        c = r * unit(rng.uniform(0, 2 * math.pi))
        kind = rng.choice(["annulet", "pellets", "cross"])
        if kind == "annulet":
            el: list[Element] = [
                Ring(c, 0.45, 0.1, 0.35 * H, "round"),
                Blob(c, 0.16, 0.16, 0, 0.4 * H, "dome"),
            ]
        elif kind == "pellets":
            el = [Blob(c + 0.5 * unit(a), 0.22, 0.22, 0, 0.45 * H, "dome") for a in (0.3, 2.4, 4.5)]
        else:
            el = [
                Stroke(np.array([c - 0.6 * unit(a), c + 0.6 * unit(a)]), 0.12, 0.4 * H, "sharp", 0.7, False)
                for a in (0.4, 0.4 + math.pi / 2)
            ]
        out.append(Group(f"symbol {k}", el))
    return out


def make_border(rng: Rng, H: float) -> Border:
    r = rng.uniform(10.5, 10.9)
    if rng.random() < 0.65:
        size = rng.uniform(0.25, 0.34)
        return Border("pellets", r, size, int(2 * math.pi * r / (size * rng.uniform(3.0, 3.8))), 0.5 * H)
    return Border("line", r, rng.uniform(0.13, 0.2), 0, 0.4 * H)


def make_types(rng: Rng, side: str, n: int) -> list[TypeDesign]:
    facings = [1, -1] if rng.random() < 0.5 else [-1, 1]
    if side == "D":
        return [head_type(rng, k, facings[k % 2]) for k in range(n)]
    pairs = rng.permutation(
        [("wheel", "rosette"), ("boar", "bird"), ("rosette", "crescent"), ("wheel", "bird")]
    )
    return [horse_type(rng, k, facings[k % 2], str(pairs[k][0]), str(pairs[k][1])) for k in range(n)]


# ----------------------------------------------------------------------------
# dies: hand engraving of a type, rasterised relief
# ----------------------------------------------------------------------------


@dataclass
class Canvas:
    """Height field on the lattice x = (i - n0) * GRID_H (row = y, column = x)."""

    half: float
    z: F64 = field(init=False)
    n0: int = field(init=False)

    def __post_init__(self) -> None:
        n = 2 * int(math.ceil(self.half / GRID_H)) + 1
        self.n0 = n // 2
        self.z = np.zeros((n, n))

    def coords(self, i: np.ndarray) -> F64:
        return (np.asarray(i, float) - self.n0) * GRID_H

    def draw(self, e: Element) -> None:
        x0, x1, y0, y1 = e.bbox()
        n = self.z.shape[0]
        i0 = max(0, int(math.floor(x0 / GRID_H)) + self.n0)
        i1 = min(n, int(math.ceil(x1 / GRID_H)) + self.n0 + 1)
        j0 = max(0, int(math.floor(y0 / GRID_H)) + self.n0)
        j1 = min(n, int(math.ceil(y1 / GRID_H)) + self.n0 + 1)
        if i1 <= i0 + 1 or j1 <= j0 + 1:
            return
        X = self.coords(np.arange(i0, i1))[None, :]
        Y = self.coords(np.arange(j0, j1))[:, None]
        val = e.render(X, Y)
        sub = self.z[j0:j1, i0:i1]
        if e.add:
            sub += val
        else:
            np.maximum(sub, val, out=sub)


@dataclass
class Die:
    name: str
    side: str
    type_index: int
    radius: float  # die face radius, mm
    curvature: float  # sag of the die face at 10 mm, mm (coins inherit it)
    canvas: Canvas
    rmax: float
    meta: dict[str, Any]


def engrave(rng: Rng, typ: TypeDesign, name: str, delta: float, curv_max: float) -> Die:
    """One hand-cut die of a type: per-group and per-element displacements ~delta mm."""
    cv = Canvas(typ.die_radius + 0.3)
    elems: list[Element] = []
    for g in typ.groups:
        c, rg = g.centroid(), g.radius()
        shift = unit(rng.uniform(0, 2 * math.pi)) * delta * rng.uniform(0.5, 1.3)
        th = float(np.clip(rng.normal(0, 0.7 * delta / rg), -0.3, 0.3))
        s = 1.0 + float(np.clip(rng.normal(0, 0.5 * delta / max(rg, 1.5)), -0.15, 0.15))
        A = s * rot2(th)
        moved = g.affine(A, c + shift - A @ c)
        fine = 0.03 + 0.08 * delta if g.name.startswith("letter") else delta / 3.0  # letters: shape kept
        elems += [e.jitter(rng, fine) for e in moved.elems]
    elems += border_elements(rng, typ, delta)
    extras = die_marks(rng, typ, delta)
    for e in sorted(elems, key=lambda e: e.add):
        cv.draw(e)
    for e in extras:
        cv.draw(e)
    tex_amp = rng.uniform(0.002, 0.004)
    cv.z += tex_amp * smooth_noise(rng, cv.z.shape, 0.4 / GRID_H)
    X = cv.coords(np.arange(cv.z.shape[1]))[None, :]
    Y = cv.coords(np.arange(cv.z.shape[0]))[:, None]
    cv.z[np.hypot(X, Y) > typ.die_radius] = 0.0
    rmax = float(np.percentile(cv.z, 99.9))
    meta = {
        "type": typ.index,
        "delta_mm": round(delta, 3),
        "texture_mm": round(tex_amp, 4),
        "marks": [m.__class__.__name__ for m in extras],
    }
    return Die(name, typ.side, typ.index, typ.die_radius, rng.uniform(-curv_max, curv_max), cv, rmax, meta)


def border_elements(rng: Rng, typ: TypeDesign, delta: float) -> list[Element]:
    b = typ.border
    r = b.r * (1 + rng.normal(0, 0.004))
    off = rng.normal(0, delta / 3, 2)
    if b.kind == "line":
        return [Ring(off, r, b.size * (1 + rng.normal(0, 0.06)), b.h, "round")]
    n = b.n + int(rng.integers(-2, 3))
    a0 = rng.uniform(0, 2 * math.pi)
    out: list[Element] = []
    for k in range(n):
        a = a0 + 2 * math.pi * k / n + rng.normal(0, 0.15 * delta / r)
        s = b.size * (1 + rng.normal(0, 0.08))
        out.append(
            Blob(
                off + r * unit(a) + rng.normal(0, delta / 6, 2),
                s,
                s,
                0.0,
                b.h * (1 + rng.normal(0, 0.06)),
                "dome",
            )
        )
    return out


def die_marks(rng: Rng, typ: TypeDesign, delta: float) -> list[Element]:
    """Die-specific small details: tool marks, a crack, a cud."""
    R = typ.border.r
    out: list[Element] = []
    for _ in range(int(rng.integers(3, 9))):
        p = rng.uniform(0, 0.9 * R) * unit(rng.uniform(0, 2 * math.pi))
        q = p + rng.uniform(0.3, 1.5) * unit(rng.uniform(0, 2 * math.pi))
        out.append(
            Stroke(
                np.array([p, q]),
                rng.uniform(0.025, 0.045),
                rng.uniform(0.015, 0.045),
                "sharp",
                0.3,
                False,
                True,
            )
        )
    if rng.random() < 0.45:
        a = rng.uniform(0, 2 * math.pi)
        p, heading = (R + 0.4) * unit(a), a + math.pi + rng.normal(0, 0.4)
        pts = [p]
        for _ in range(int(rng.integers(12, 40))):
            heading += rng.normal(0, 0.45)
            pts.append(pts[-1] + 0.22 * unit(heading))
        out.append(
            Stroke(np.array(pts), rng.uniform(0.03, 0.05), rng.uniform(0.04, 0.1), "sharp", 0.5, False, True)
        )
    if rng.random() < 0.15:
        a = rng.uniform(0, 2 * math.pi)
        for _ in range(3):
            c = (R - 0.2 + rng.normal(0, 0.3)) * unit(a + rng.normal(0, 0.08))
            out.append(
                Blob(
                    c,
                    rng.uniform(0.6, 1.2),
                    rng.uniform(0.4, 0.9),
                    rng.uniform(0, math.pi),
                    typ.H * rng.uniform(0.4, 0.8),
                    "mesa",
                )
            )
    return out


# ----------------------------------------------------------------------------
# the world: kinds
# ----------------------------------------------------------------------------


@dataclass
class ScannerSpec:
    name: str
    spacing: tuple[float, float]
    noise: tuple[float, float]
    normals: tuple[str, ...]  # drawn among "surface", "mesh", "pca"
    smooth_prob: float
    holes_max: int
    warp: tuple[float, float]
    ripple_prob: float
    jitter: tuple[float, float]


@dataclass
class KindSpec:
    n_types: int
    delta: tuple[float, float]
    diam_spread: float
    irregular: float
    offcentre: float  # max fraction of the flan diameter
    die_curv: float
    cup_var: float
    tilt: float
    bend_prob: float
    bend_deg: float
    broken_prob: float
    weak_prob: float
    weak_frac: float
    weak_strength: tuple[float, float]
    double_prob: float
    wear: tuple[float, float]
    corrosion_prob: float
    corrosion_max: float
    scanners: tuple[tuple[ScannerSpec, float], ...]


GOOD = ScannerSpec(
    "good", (0.03, 0.05), (0.004, 0.006), ("surface", "mesh"), 0.3, 3, (0.001, 0.003), 0.0, (0.3, 1.0)
)
MID = ScannerSpec(
    "mid-estimated", (0.045, 0.055), (0.008, 0.012), ("pca",), 0.0, 5, (0.002, 0.005), 0.3, (0.3, 1.0)
)
COARSE = ScannerSpec(
    "coarse", (0.14, 0.16), (0.025, 0.035), ("pca",), 0.0, 4, (0.003, 0.006), 0.3, (0.3, 1.0)
)
FINE_SMOOTH = ScannerSpec(
    "fine-smoothed",
    (0.03, 0.04),
    (0.003, 0.005),
    ("surface", "mesh"),
    1.0,
    2,
    (0.001, 0.003),
    0.0,
    (0.1, 0.4),
)
COARSE_RAW = ScannerSpec(
    "coarse-raw", (0.10, 0.13), (0.02, 0.03), ("pca",), 0.0, 5, (0.003, 0.006), 0.5, (0.6, 1.0)
)

_ORD = dict(
    n_types=2,
    delta=(0.4, 1.0),
    diam_spread=1.2,
    irregular=0.025,
    offcentre=0.12,
    die_curv=0.15,
    cup_var=0.15,
    tilt=0.003,
    bend_prob=0.1,
    bend_deg=3.0,
    broken_prob=0.05,
    weak_prob=0.3,
    weak_frac=0.3,
    weak_strength=(0.2, 0.6),
    double_prob=0.05,
    wear=(0.0, 0.35),
    corrosion_prob=0.3,
    corrosion_max=0.1,
)

KINDS: dict[str, KindSpec] = {
    "ordinary": KindSpec(**_ORD, scanners=((GOOD, 1.0),)),
    "hard": KindSpec(
        n_types=1,
        delta=(0.2, 0.3),
        diam_spread=1.5,
        irregular=0.045,
        offcentre=1 / 3,
        die_curv=0.2,
        cup_var=0.3,
        tilt=0.008,
        bend_prob=0.5,
        bend_deg=8.0,
        broken_prob=0.3,
        weak_prob=0.7,
        weak_frac=0.5,
        weak_strength=(0.3, 0.9),
        double_prob=0.2,
        wear=(0.2, 0.7),
        corrosion_prob=0.9,
        corrosion_max=0.3,
        scanners=((MID, 1.0),),
    ),
    "coarse": KindSpec(**_ORD, scanners=((COARSE, 1.0),)),
    "mixed": KindSpec(**_ORD, scanners=((FINE_SMOOTH, 0.5), (COARSE_RAW, 0.5))),
    "flat": KindSpec(
        n_types=2,
        delta=(0.4, 1.0),
        diam_spread=0.0,
        irregular=0.0,
        offcentre=0.0,
        die_curv=0.0,
        cup_var=0.0,
        tilt=0.0,
        bend_prob=0.0,
        bend_deg=0.0,
        broken_prob=0.0,
        weak_prob=0.0,
        weak_frac=0.0,
        weak_strength=(0.0, 0.0),
        double_prob=0.0,
        wear=(0.0, 0.12),
        corrosion_prob=0.1,
        corrosion_max=0.05,
        scanners=((GOOD, 1.0),),
    ),
}


# ----------------------------------------------------------------------------
# flan and strike
# ----------------------------------------------------------------------------


@dataclass
class Flan:
    c: F64  # flan centre in die coordinates
    R0: float
    harm: F64  # (k, amplitude, phase) rows
    edge_e: float  # horizontal size of the rounded rim
    edge_ez: float  # vertical drop of the rounded rim
    broken: dict[str, float] | None

    def radius_at(self, phi: F64) -> F64:
        r = np.ones_like(phi)
        for k, a, ph in self.harm:
            r = r + a * np.cos(k * phi + ph)
        return self.R0 * r

    def dradius_at(self, phi: F64) -> F64:
        d = np.zeros_like(phi)
        for k, a, ph in self.harm:
            d = d - a * k * np.sin(k * phi + ph)
        return self.R0 * d

    def sdf_outline(self, x: F64, y: F64) -> F64:
        dx, dy = x - self.c[0], y - self.c[1]
        return np.hypot(dx, dy) - self.radius_at(np.arctan2(dy, dx))

    def _break_frame(self) -> tuple[F64, F64]:
        assert self.broken is not None
        n = unit(self.broken["angle"])
        return n, np.array([-n[1], n[0]])

    def wobble(self, tau: F64) -> F64:
        assert self.broken is not None
        b = self.broken
        return b["amp"] * (np.sin(tau * b["f1"] + b["p1"]) + 0.5 * np.sin(tau * b["f2"] + b["p2"]))

    def sdf_break(self, x: F64, y: F64) -> F64:
        if self.broken is None:
            return np.full(np.broadcast(x, y).shape, -np.inf)
        n, t = self._break_frame()
        dx, dy = x - self.c[0], y - self.c[1]
        s, tau = dx * n[0] + dy * n[1], dx * t[0] + dy * t[1]
        return s - self.broken["d0"] - self.wobble(tau)

    def edge_params(self, x: F64, y: F64) -> tuple[F64, F64, F64]:
        so, sb = self.sdf_outline(x, y), self.sdf_break(x, y)
        is_b = sb > so
        return np.maximum(so, sb), np.where(is_b, 0.12, self.edge_e), np.where(is_b, 0.08, self.edge_ez)


def draw_flan(rng: Rng, spec: KindSpec, typ: TypeDesign, nominal_d: float) -> Flan:
    d = nominal_d + rng.uniform(-1, 1) * spec.diam_spread
    d = float(np.clip(d, 18.0, 24.0))
    off = (
        rng.uniform(0, spec.offcentre) ** 1.5 / max(spec.offcentre, 1e-9) ** 0.5 * d
        if spec.offcentre
        else 0.0
    )
    c = off * unit(rng.uniform(0, 2 * math.pi))
    harm = np.array(
        [[k, rng.normal(0, spec.irregular / k), rng.uniform(0, 2 * math.pi)] for k in range(2, 7)]
    )
    broken = None
    if rng.random() < spec.broken_prob:
        broken = {
            "angle": rng.uniform(0, 2 * math.pi),
            "d0": d / 2 * rng.uniform(0.35, 0.75),
            "amp": rng.uniform(0.05, 0.2),
            "f1": rng.uniform(1.5, 4),
            "p1": rng.uniform(0, 6.3),
            "f2": rng.uniform(5, 12),
            "p2": rng.uniform(0, 6.3),
        }
    return Flan(c, d / 2, harm, rng.uniform(0.4, 0.9), rng.uniform(0.25, 0.6), broken)


def weak_mask(rng: Rng, flan: Flan, X: F64, Y: F64, frac: float) -> F64:
    """Smooth zone covering ~frac of the flan: a soft half plane, unevenly feathered."""
    u = unit(rng.uniform(0, 2 * math.pi))
    s = ((X - flan.c[0]) * u[0] + (Y - flan.c[1]) * u[1]) / flan.R0
    inside = np.hypot(X - flan.c[0], Y - flan.c[1]) < flan.R0
    s0 = float(np.quantile(np.broadcast_to(s, inside.shape)[inside], 1.0 - frac))
    mod = 0.15 * smooth_noise(rng, inside.shape, 2.0 / GRID_H)
    return 1.0 / (1.0 + np.exp(-(s - s0 + mod) / 0.08))


def coin_height(rng: Rng, spec: KindSpec, die: Die, flan: Flan, info: dict[str, Any]) -> tuple[F64, F64, F64]:
    """The struck, worn and corroded coin surface z(x, y) on a die-lattice block."""
    cv = die.canvas
    Rb = flan.R0 * (1 + np.abs(flan.harm[:, 1]).sum()) + 0.3
    i0 = int(math.floor((flan.c[0] - Rb) / GRID_H)) + cv.n0
    i1 = int(math.ceil((flan.c[0] + Rb) / GRID_H)) + cv.n0 + 1
    j0 = int(math.floor((flan.c[1] - Rb) / GRID_H)) + cv.n0
    j1 = int(math.ceil((flan.c[1] + Rb) / GRID_H)) + cv.n0 + 1
    xs, ys = cv.coords(np.arange(i0, i1)), cv.coords(np.arange(j0, j1))
    X, Y = xs[None, :], ys[:, None]
    n = cv.z.shape[0]
    R = np.zeros((j1 - j0, i1 - i0))
    a0, a1, b0, b1 = max(i0, 0), min(i1, n), max(j0, 0), min(j1, n)
    R[b0 - j0 : b1 - j0, a0 - i0 : a1 - i0] = cv.z[b0:b1, a0:a1]
    shape = R.shape

    if rng.random() < spec.double_prob:  # second, partial impression
        th, t = (
            math.radians(rng.uniform(1, 6)) * rng.choice([-1, 1]),
            rng.uniform(0.3, 1.5) * unit(rng.uniform(0, 6.3)),
        )
        q = rng.uniform(0.5, 0.9)
        Xb, Yb = np.broadcast_to(X, shape) - t[0], np.broadcast_to(Y, shape) - t[1]
        xd = math.cos(th) * Xb + math.sin(th) * Yb
        yd = -math.sin(th) * Xb + math.cos(th) * Yb
        R2 = ndimage.map_coordinates(cv.z, [yd / GRID_H + cv.n0, xd / GRID_H + cv.n0], order=1, cval=0.0)
        R = np.maximum(R, q * R2)
        info["double_strike"] = {
            "rot_deg": round(math.degrees(th), 2),
            "shift_mm": [round(float(v), 3) for v in t],
            "depth": round(q, 2),
        }

    rho_die = np.hypot(X, Y)  # outside the die face the metal stands proud
    s_out = smoothstep((rho_die - die.radius + 0.1) / 0.6)
    h_out = rng.uniform(0.05, 0.25)
    R = R * (1 - s_out) + h_out * s_out

    if rng.random() < spec.weak_prob:  # weak strike: scaled down and soft-capped
        frac = rng.uniform(0.1, spec.weak_frac)
        stren = rng.uniform(*spec.weak_strength)
        m = weak_mask(rng, flan, X, Y, frac)
        R = smin(R * (1 - 0.35 * stren * m), die.rmax * (1 - stren * m) + 0.02, 0.03)
        info["weak_zone"] = {"fraction": round(frac, 3), "strength": round(stren, 3)}

    wear = rng.uniform(*spec.wear)
    if wear > 0.01:  # abrasion of the high points
        uneven = smooth_noise(rng, shape, 6.0 / GRID_H)
        cap = die.rmax * (1 - wear * (0.8 + 0.2 * np.tanh(uneven)))
        R = smin(R, cap, 0.02)
        R = ndimage.gaussian_filter(R, (0.01 + 0.1 * wear) / GRID_H)
        R *= 1 - 0.15 * wear
    info["wear"] = round(wear, 3)

    base = flan_base(rng, spec, die, flan, X, Y, info)
    Z = base + R
    if wear > 0.1:
        Z += scratches(rng, wear, flan, xs, ys)
    Z += corrosion(rng, spec, flan, X, Y, shape, info)
    sdf, e, ez = flan.edge_params(X, Y)
    t = np.clip((sdf + e) / e, 0.0, 1.0)
    Z = Z - ez * (1 - np.sqrt(1 - t * t)) - 5.0 * np.maximum(sdf, 0.0)
    return Z, xs, ys


def flan_base(rng: Rng, spec: KindSpec, die: Die, flan: Flan, X: F64, Y: F64, info: dict[str, Any]) -> F64:
    """Die curvature + coin cupping/doming + tilt + bend, zero at the die centre."""
    cup = rng.uniform(-spec.cup_var, spec.cup_var)
    g = rng.normal(0, spec.tilt / 2, 2)

    def f(x: Any, y: Any) -> Any:
        return (
            die.curvature * (x**2 + y**2) / 100.0
            + cup * ((x - flan.c[0]) ** 2 + (y - flan.c[1]) ** 2) / 100.0
            + g[0] * x
            + g[1] * y
        )

    base = f(X, Y) - f(0.0, 0.0)
    info.update(
        cupping_mm_at_10mm=round(cup, 3),
        die_curvature_mm_at_10mm=round(die.curvature, 3),
        tilt=[round(float(v), 5) for v in g],
    )
    if rng.random() < spec.bend_prob:
        alpha = math.radians(rng.uniform(1.0, spec.bend_deg))
        nb = unit(rng.uniform(0, 2 * math.pi))
        p = flan.c + nb * flan.R0 * rng.uniform(-0.4, 0.4)
        wdt = rng.uniform(0.8, 2.0)

        def hinge(x: Any, y: Any) -> Any:
            return math.tan(alpha) * wdt * np.logaddexp(0.0, ((x - p[0]) * nb[0] + (y - p[1]) * nb[1]) / wdt)

        base = base + hinge(X, Y) - hinge(np.array(0.0), np.array(0.0))
        info["bend"] = {"deg": round(math.degrees(alpha), 2), "width_mm": round(wdt, 2)}
    return base


def scratches(rng: Rng, wear: float, flan: Flan, xs: F64, ys: F64) -> F64:
    cv = np.zeros((len(ys), len(xs)))
    for _ in range(int(rng.integers(1, 3 + int(8 * wear)))):
        p = flan.c + rng.uniform(0, flan.R0) * unit(rng.uniform(0, 6.3))
        q = p + rng.uniform(1, 6) * unit(rng.uniform(0, 6.3))
        st = Stroke(
            np.array([p, q]), rng.uniform(0.02, 0.04), -rng.uniform(0.005, 0.02), "round", 0.3, False, True
        )
        x0, x1, y0, y1 = st.bbox()
        i0, i1 = np.searchsorted(xs, [x0, x1])
        j0, j1 = np.searchsorted(ys, [y0, y1])
        if i1 - i0 > 1 and j1 - j0 > 1:
            cv[j0:j1, i0:i1] += st.render(xs[None, i0:i1], ys[j0:j1, None])
    return cv


def corrosion(
    rng: Rng, spec: KindSpec, flan: Flan, X: F64, Y: F64, shape: tuple[int, int], info: dict[str, Any]
) -> F64:
    """Crusts (proud, rough, irregular) and pit clusters, over a chosen fraction of the face."""
    out = np.zeros(shape)
    if rng.random() >= spec.corrosion_prob:
        info["crust_fraction"] = info["pit_fraction"] = 0.0
        return out
    total = rng.uniform(0.02, spec.corrosion_max)
    fc = total * rng.uniform(0.2, 0.8)
    fp = total - fc
    inside = np.broadcast_to(flan.sdf_outline(X, Y) < 0, shape)
    F = smooth_noise(rng, shape, 0.7 / GRID_H) + 0.5 * smooth_noise(rng, shape, 0.25 / GRID_H)
    thr = np.quantile(F[inside], 1 - fc)
    hc = rng.uniform(0.04, 0.25)
    rough = 1 + 0.3 * smooth_noise(rng, shape, 0.06 / GRID_H)
    out += hc * smoothstep((F - thr) / 0.4) * rough
    G = smooth_noise(rng, shape, 1.0 / GRID_H)
    pit_zone = G > np.quantile(G[inside], 1 - fp)
    for sigma_mm, dens in ((0.05, 6.0), (0.15, 1.5)):
        imp = (rng.random(shape) < dens * GRID_H**2) & pit_zone
        depth = rng.uniform(0.02, 0.12) * (2 * math.pi * (sigma_mm / GRID_H) ** 2)
        out -= ndimage.gaussian_filter(imp.astype(float), sigma_mm / GRID_H) * depth * rng.uniform(0.5, 1.0)
    info["crust_fraction"], info["pit_fraction"] = round(fc, 3), round(fp, 3)
    info["crust_height_mm"] = round(hc, 3)
    return out


# ----------------------------------------------------------------------------
# scanner
# ----------------------------------------------------------------------------


@dataclass
class Scanner:
    spec: ScannerSpec
    spacing: float
    noise: float
    normals: str
    smooth: bool
    view: F64
    noise_mode: str
    warp: float
    ripple: float
    jitter: float


def draw_scanner(rng: Rng, spec: KindSpec) -> Scanner:
    specs, probs = zip(*spec.scanners, strict=True)
    ss: ScannerSpec = specs[int(rng.choice(len(specs), p=np.array(probs) / sum(probs)))]
    tilt = math.radians(rng.uniform(0, 25))
    az = rng.uniform(0, 2 * math.pi)
    view = np.array([math.sin(tilt) * math.cos(az), math.sin(tilt) * math.sin(az), math.cos(tilt)])
    noise = rng.uniform(*ss.noise)
    return Scanner(
        ss,
        rng.uniform(*ss.spacing),
        noise,
        str(rng.choice(ss.normals)),
        bool(rng.random() < ss.smooth_prob),
        view,
        "view" if rng.random() < 0.7 else "normal",
        rng.uniform(*ss.warp),
        noise * rng.uniform(0.2, 0.5) if rng.random() < ss.ripple_prob else 0.0,
        rng.uniform(*ss.jitter),
    )


def lattice_xy(rng: Rng, c: F64, radius: float, s: float, jitter: float) -> F64:
    n = int(math.ceil(radius / s)) + 1
    ii, jj = np.meshgrid(np.arange(-n, n + 1), np.arange(-n, n + 1))
    uv = np.stack([ii.ravel(), jj.ravel()], axis=1) + rng.uniform(-jitter / 2, jitter / 2, (ii.size, 2))
    uv = uv * s + rng.uniform(0, s, 2)
    return uv @ rot2(rng.uniform(0, math.pi)).T + c


def wall_points(flan: Flan, s: float, depth: float) -> tuple[F64, F64]:
    """Contour points (xy) and outward horizontal normals, outline and break line."""
    phi = np.linspace(0, 2 * math.pi, int(2 * math.pi * flan.R0 / s), endpoint=False)
    r, dr = flan.radius_at(phi), flan.dradius_at(phi)
    er, ep = np.stack([np.cos(phi), np.sin(phi)], 1), np.stack([-np.sin(phi), np.cos(phi)], 1)
    P = flan.c + r[:, None] * er
    N = er - (dr / r)[:, None] * ep
    keep = flan.sdf_break(P[:, 0], P[:, 1]) < 0
    P, N = P[keep], N[keep]
    if flan.broken is not None:
        n, t = flan._break_frame()
        tau = np.arange(-flan.R0 * 1.3, flan.R0 * 1.3, s)
        w = flan.wobble(tau)
        dw = np.gradient(w, tau)
        Q = flan.c + (flan.broken["d0"] + w)[:, None] * n + tau[:, None] * t
        M = n[None, :] - dw[:, None] * t[None, :]
        k2 = flan.sdf_outline(Q[:, 0], Q[:, 1]) < 0
        P, N = np.vstack([P, Q[k2]]), np.vstack([N, M[k2]])
    N = N / np.linalg.norm(N, axis=1, keepdims=True)
    return P, N


def pca_normals(P: F64, k: int, ref: F64) -> F64:
    tree = cKDTree(P)
    out = np.empty_like(P)
    for a in range(0, len(P), 60_000):
        _, idx = tree.query(P[a : a + 60_000], k=k)
        Q = P[idx]
        Q = Q - Q.mean(axis=1, keepdims=True)
        C = np.einsum("mki,mkj->mij", Q, Q)
        _, v = np.linalg.eigh(C)
        out[a : a + 60_000] = v[:, :, 0]
    flip = (out * ref).sum(axis=1) < 0
    out[flip] *= -1
    return out


def laplacian_smooth(P: F64, N: F64, iters: int, lam: float) -> F64:
    _, idx = cKDTree(P).query(P, k=9)
    for _ in range(iters):
        d = ((P[idx[:, 1:]].mean(axis=1) - P) * N).sum(axis=1)
        P = P + lam * d[:, None] * N
    return P


def scan(
    rng: Rng, sc: Scanner, flan: Flan, Z: F64, xs: F64, ys: F64, info: dict[str, Any]
) -> tuple[F64, F64]:
    """Sample the coin surface as a scanner would (points and normals in die coordinates)."""
    area = math.pi * flan.R0**2
    s = max(sc.spacing, math.sqrt(area / (0.93 * MAX_POINTS)))
    spl = ndimage.spline_filter(Z, order=3)
    gy, gx = np.gradient(Z, GRID_H)
    to_ij = lambda x, y: [(y - ys[0]) / GRID_H, (x - xs[0]) / GRID_H]  # noqa: E731

    xy = lattice_xy(rng, flan.c, flan.R0 * 1.2 + 0.3, s, sc.jitter)
    sdf, e, _ = flan.edge_params(xy[:, 0], xy[:, 1])
    xy = xy[(sdf + e) / e < 0.985]
    ij = to_ij(xy[:, 0], xy[:, 1])
    z = ndimage.map_coordinates(spl, ij, order=3, prefilter=False)
    n_top = np.stack(
        [
            -ndimage.map_coordinates(gx, ij, order=1),
            -ndimage.map_coordinates(gy, ij, order=1),
            np.ones(len(z)),
        ],
        axis=1,
    )
    P_top = np.column_stack([xy, z])

    depth = float(rng.uniform(0.3, 1.2))
    sw = max(s, 0.05) * 1.2
    C, Nc = wall_points(flan, sw, depth)
    zc = ndimage.map_coordinates(spl, to_ij(C[:, 0], C[:, 1]), order=3, prefilter=False)
    us = np.arange(sw / 2, depth, sw)
    P_wall = np.column_stack([np.repeat(C, len(us), 0), (zc[:, None] - us[None, :]).ravel()])
    tang = np.repeat(np.column_stack([-Nc[:, 1], Nc[:, 0]]), len(us), 0)
    P_wall[:, :2] += rng.normal(0, 0.3 * sw, (len(P_wall), 1)) * tang  # not a perfect lattice
    N_wall = np.column_stack([np.repeat(Nc, len(us), 0), np.zeros(len(P_wall))])

    P = np.vstack([P_top, P_wall])
    N = np.vstack([n_top, N_wall])
    N /= np.linalg.norm(N, axis=1, keepdims=True)

    cosv = N @ sc.view  # grazing points are missed
    keep = rng.random(len(P)) < np.clip((cosv + 0.05) / 0.2, 0.0, 1.0)
    keep &= remove_holes(rng, P, sc.spec.holes_max, info)
    P, N, cosv = P[keep], N[keep], cosv[keep]

    sig = sc.noise / np.sqrt(np.clip(np.abs(cosv), 0.3, 1.0))
    eps = rng.normal(0, 1, len(P)) * sig
    P = P + eps[:, None] * (sc.view[None, :] if sc.noise_mode == "view" else N)
    P[:, 2] += low_freq(rng, P, sc.warp, (12.0, 40.0))
    if sc.ripple > 0:
        d, lam = unit(rng.uniform(0, 6.3)), rng.uniform(0.3, 1.0)
        P[:, 2] += sc.ripple * np.sin(2 * math.pi * (P[:, :2] @ d) / lam + rng.uniform(0, 6.3))
    scale = 1.0 + rng.normal(0, 0.00015)
    P[:, :2] = flan.c + (P[:, :2] - flan.c) * scale
    if sc.smooth:
        P = laplacian_smooth(P, N, int(rng.integers(1, 4)), 0.5)
    if sc.normals == "mesh":
        N = pca_normals(P, 8, N)
    elif sc.normals == "pca":
        N = pca_normals(P, int(rng.integers(16, 25)), N)
    info["scanner"] = {
        "name": sc.spec.name,
        "spacing_mm": round(s, 4),
        "nominal_spacing_mm": round(sc.spacing, 4),
        "noise_mm": round(sc.noise, 4),
        "noise_along": sc.noise_mode,
        "view_dir_die": [round(float(v), 4) for v in sc.view],
        "normals": sc.normals,
        "smoothed": sc.smooth,
        "warp_mm": round(sc.warp, 4),
        "ripple_mm": round(sc.ripple, 4),
        "jitter": round(sc.jitter, 2),
        "scale_error": round(scale - 1, 6),
        "edge_depth_mm": round(depth, 3),
        "n_edge_points": int(len(P_wall)),
    }
    return P, N


def remove_holes(rng: Rng, P: F64, nmax: int, info: dict[str, Any]) -> BoolA:
    keep = np.ones(len(P), bool)
    holes = []
    for _ in range(int(rng.integers(0, nmax + 1))):
        c = P[rng.integers(len(P)), :2]
        r = rng.uniform(0.2, 1.8)
        for _ in range(3):
            cc = c + rng.normal(0, r / 2, 2)
            rr = r * rng.uniform(0.4, 1.0)
            keep &= np.hypot(P[:, 0] - cc[0], P[:, 1] - cc[1]) > rr
        holes.append([round(float(c[0]), 2), round(float(c[1]), 2), round(r, 2)])
    info["holes"] = holes
    return keep


def low_freq(rng: Rng, P: F64, amp: float, wl: tuple[float, float]) -> F64:
    out = np.zeros(len(P))
    for _ in range(3):
        d = unit(rng.uniform(0, 6.3))
        out += np.sin(2 * math.pi * (P[:, :2] @ d) / rng.uniform(*wl) + rng.uniform(0, 6.3))
    return amp * out / math.sqrt(1.5)


# ----------------------------------------------------------------------------
# hoard assembly, labels, output
# ----------------------------------------------------------------------------


def uneven_counts(rng: Rng, n_items: int, n_bins: int) -> I64:
    """Each bin >= 1, the rest Zipf-like: a few bins take most items."""
    w = 1.0 / np.arange(1, n_bins + 1) ** rng.uniform(1.0, 1.6)
    w = rng.permutation(w)
    return 1 + rng.multinomial(n_items - n_bins, w / w.sum())


def split_dies(rng: Rng, n_dies: int, n_types: int) -> I64:
    sizes = np.full(n_types, 1) + rng.multinomial(n_dies - n_types, np.full(n_types, 1 / n_types))
    return sizes


def assign(
    rng: Rng, n_coins: int, n_dies: int, n_types: int
) -> tuple[list[int], list[int], list[int], list[int]]:
    """Per coin obverse die and reverse die indices (0-based) + die -> type maps.

    Coins of a series (type pair) are ordered by obverse die, as struck, and the
    reverse dies take contiguous runs of that sequence, which makes die links."""
    if n_coins < n_dies:
        raise SystemExit("need at least as many coins as dies")
    sizes_d = split_dies(rng, n_dies, n_types)
    type_d = rng.permutation(np.repeat(np.arange(n_types), sizes_d))
    cnt_d = uneven_counts(rng, n_coins, n_dies)
    N_s = np.array([cnt_d[type_d == s].sum() for s in range(n_types)])
    want = n_dies * N_s / n_coins
    m_s = np.ones(n_types, int)
    while m_s.sum() < n_dies:  # largest shortfall first, never more dies than coins
        room = np.where(m_s < N_s, want - m_s, -np.inf)
        m_s[int(np.argmax(room))] += 1
    type_r = np.concatenate([np.full(m, s) for s, m in enumerate(m_s)])
    perm_r = rng.permutation(n_dies)
    type_r = type_r[np.argsort(perm_r)]  # reverse die index -> type, shuffled
    obv: list[int] = []
    rev: list[int] = []
    for s in range(n_types):
        dies_s = rng.permutation(np.flatnonzero(type_d == s))
        seq = [int(d) for d in dies_s for _ in range(cnt_d[d])]
        rdies = rng.permutation(np.flatnonzero(type_r == s))
        rc = uneven_counts(rng, len(seq), len(rdies))
        rseq = [int(r) for r, c in zip(rdies, rc, strict=True) for _ in range(c)]
        obv += seq
        rev += rseq
    order = rng.permutation(n_coins)
    return (
        [obv[i] for i in order],
        [rev[i] for i in order],
        [int(t) for t in type_d],
        [int(t) for t in type_r],
    )


def random_pose(rng: Rng) -> F64:
    T = np.eye(4)
    T[:3, :3] = Rotation.random(random_state=rng).as_matrix()
    T[:3, 3] = rng.uniform(-40, 40, 3)
    return T


def write_ply(path: Path, P: F64, N: F64, encoding: str) -> None:
    typ = {"float32": "float", "ascii": "float", "float64": "double"}[encoding]
    fmt = "ascii" if encoding == "ascii" else "binary_little_endian"
    props = "".join(f"property {typ} {n}\n" for n in ("x", "y", "z", "nx", "ny", "nz"))
    header = (
        f"ply\nformat {fmt} 1.0\ncomment blind_hoards synthetic coin scan, units mm\n"
        f"element vertex {len(P)}\n{props}end_header\n"
    )
    data = np.hstack([P, N])
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        if encoding == "ascii":
            np.savetxt(f, data, fmt="%.6f")
        else:
            f.write(data.astype("<f4" if encoding == "float32" else "<f8").tobytes())


def read_ply(path: Path) -> F64:
    """Minimal reader for the files written here (used by the self check)."""
    with open(path, "rb") as f:
        head = b""
        while not head.endswith(b"end_header\n"):
            head += f.readline()
        lines = head.decode().splitlines()
        n = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
        props = [l.split() for l in lines if l.startswith("property")]
        if "ascii" in lines[1]:
            return np.loadtxt(f, max_rows=n).reshape(n, len(props))
        dt = "<f8" if props[0][1] in ("double", "float64") else "<f4"
        return np.frombuffer(f.read(), dtype=dt).reshape(n, len(props)).astype(float)


def make_face(
    rng: Rng, spec: KindSpec, die: Die, typ: TypeDesign, nominal_d: float
) -> tuple[F64, F64, F64, dict[str, Any]]:
    info: dict[str, Any] = {"die": die.name, "type": typ.index, "die_meta": die.meta}
    flan = draw_flan(rng, spec, typ, nominal_d)
    info.update(
        flan_diameter_mm=round(2 * flan.R0, 3),
        flan_centre_in_die_mm=[round(float(v), 3) for v in flan.c],
        offcentre_fraction=round(float(np.linalg.norm(flan.c)) / (2 * flan.R0), 3),
        outline_harmonics=[[int(k), round(float(a), 4)] for k, a, _ in flan.harm],
        rim_mm=[round(flan.edge_e, 3), round(flan.edge_ez, 3)],
        broken=None if flan.broken is None else {k: round(v, 3) for k, v in flan.broken.items()},
    )
    Z, xs, ys = coin_height(rng, spec, die, flan, info)
    sc = draw_scanner(rng, spec)
    P, N = scan(rng, sc, flan, Z, xs, ys, info)
    T = random_pose(rng)
    return P @ T[:3, :3].T + T[:3, 3], N @ T[:3, :3].T, T, info


def make_hoard(out: Path, kind: str, seed: int, n_coins: int, n_dies: int) -> dict[str, Any]:
    spec = KINDS[kind]
    rng = np.random.default_rng([seed, KIND_NAMES.index(kind)])
    folder = out / f"{kind}-{seed}"
    folder.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    obv, rev, type_d, type_r = assign(rng, n_coins, n_dies, spec.n_types)
    sides: dict[str, tuple[list[TypeDesign], list[Die], list[float]]] = {}
    for side, tmap in (("D", type_d), ("R", type_r)):
        types = make_types(rng, side, spec.n_types)
        dies = [
            engrave(rng, types[t], f"{side}{k + 1}", rng.uniform(*spec.delta), spec.die_curv)
            for k, t in enumerate(tmap)
        ]
        nominal = [rng.uniform(19.0, 23.0) if spec.diam_spread else rng.uniform(19.5, 22.5) for _ in types]
        sides[side] = (types, dies, nominal)
    t_dies = time.time() - t0
    labels, poses, faces = [], {}, {}
    counts = []
    for c in range(n_coins):
        for side, die_idx in (("D", obv[c]), ("R", rev[c])):
            types, dies, nominal = sides[side]
            die = dies[die_idx]
            name = f"L{c + 1:04d}{side}"
            P, N, T, info = make_face(rng, spec, die, types[die.type_index], nominal[die.type_index])
            enc = str(rng.choice(["float32", "ascii", "float64"], p=[0.7, 0.15, 0.15]))
            write_ply(folder / f"{name}.ply", P, N, enc)
            info.update(ply_encoding=enc, n_points=int(len(P)), side=side, kind=kind)
            labels.append(f"{name},{die.name}")
            poses[name] = {"T_scan_die": T.tolist()}
            faces[name] = info
            counts.append(len(P))
    (folder / "labels.csv").write_text("coin_id,die_id\n" + "\n".join(labels) + "\n")
    (folder / "poses.json").write_text(json.dumps(poses, indent=1))
    # the same poses as ``coindie bench registration`` reads them (every face in its test split)
    (folder / "truth.json").write_text(json.dumps({"faces": poses}, indent=1))
    (folder / "splits.csv").write_text(
        "face_id,split\n" + "".join(f"{f},registration_test\n" for f in sorted(poses))
    )
    (folder / "faces.json").write_text(json.dumps(faces, indent=1))
    types_meta = {
        side: [dict(t.meta, H_mm=round(t.H, 3), die_radius_mm=round(t.die_radius, 3)) for t in sides[side][0]]
        for side in sides
    }
    (folder / "types.json").write_text(json.dumps(types_meta, indent=1))
    return {
        "kind": kind,
        "folder": str(folder),
        "seconds": round(time.time() - t0, 1),
        "die_seconds": round(t_dies, 1),
        "points_min": int(min(counts)),
        "points_median": int(np.median(counts)),
        "points_max": int(max(counts)),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="Kinds: " + ", ".join(KIND_NAMES) + ". See the module docstring for the model.",
    )
    ap.add_argument("out", type=Path, help="output folder; one sub-folder <kind>-<seed> per kind")
    ap.add_argument("--kinds", default="ordinary,hard,coarse,mixed,flat", help="comma separated kinds")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--coins", type=int, default=40, help="coins per hoard (two faces each)")
    ap.add_argument("--dies", type=int, default=12, help="dies per side")
    a = ap.parse_args(argv)
    kinds = [k.strip() for k in a.kinds.split(",") if k.strip()]
    for k in kinds:
        if k not in KINDS:
            ap.error(f"unknown kind {k!r}; choose among {', '.join(KIND_NAMES)}")
    if not 1 <= a.dies <= a.coins:
        ap.error(f"--dies must be at least 1 and at most --coins ({a.coins}); got {a.dies}")
    for k in kinds:
        print(json.dumps(make_hoard(a.out, k, a.seed, a.coins, a.dies)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
