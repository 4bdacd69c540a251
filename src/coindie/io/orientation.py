"""Normals that point out of the coin, whatever the scanner wrote: the side of a face scan's normals.

Every later step reads the face's up side from its normals: the face is turned up by their mean, the
relief and the plane fit keep the points whose normal is near up, the edge wall is told apart by its
normals. A scanner or a mesh tool can write normals whose sign means nothing: normals estimated by local
PCA and never oriented (each point's sign a coin toss), a mesh whose triangles are wound either way. Up is
then lost for about half the faces, and a face turned over is the mirror image of its die: measured on a
held-out hoard of the independent generator (``benchmarks/outsider_hoards.py``, kind ``ordinary``, seed
11) whose normals' signs were drawn at random, the die study fell from FMI 1.000 to 0.474.

What a face scan's geometry says of its up side, without normals' signs:

- **the edge wall** goes down from the face: the points at the outline that do not face along the face's
  axis lie below the surface fitted to those that do (1.6-7 times the face's own spread on the faces of
  both generators);
- **the relief** is raised: a coin's design stands above its field, so the heights above the fitted
  surface have a longer tail upwards than downwards (positive quartile skewness).

Normals whose signs disagree (fewer than ``CONSISTENT`` of the face's on its majority side) are set
from that geometry. Normals that agree are read exactly as written, unless the wall says that all of them
point into the coin: they are then all turned. The wall alone decides this, not the relief: on worn faces
the relief's lean is a weak cue (its skewness pointed the wrong way on 24 of the 80 faces of coindie's
all-hard hoard, seed 5100), while a wall of at least ``_MIN_WALL_SHARE`` of the points never did: on 320
faces of four hoards of both generators, each also cut inside its outline at 0.9 and 0.7 of its radius
(960 scans), the walls that pointed the wrong way held under 1 % of the points, no outward normals were
turned, and all-inward ones were turned on 318 of the 320 whole faces (before: 277). But a die's border at
the flan's edge (steep flanks at or above the field) over a shallow wall can put most of those points above
the surface: on hoards of a third, blindly written generator (``benchmarks/blind_hoards.py``, seed 31), 2
of 400 faces whose normals were written outwards were turned (wall offsets of -0.58 and -1.61 spreads),
each then read face down, a mirror image of its die and a singleton of the die study. So the normals are
turned only if the wall's own normals agree: most of them point towards the face's axis
(:func:`wall_normals_outward`; 0.71-1.00 of them point away on those 400 faces as written, 0.999-1.000 on a
hoard of ``coindie synth --physics wide``). Written by hand: Open3D's
``orient_normals_towards_camera_location`` orients towards a point that must be known, and
``orient_normals_consistent_tangent_plane`` (a spanning tree of the points) leaves the overall sign
undecided and takes seconds on 400,000 points.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import FloatArray

#: Share of the face's normals on the majority side above which their signs are taken as written.
CONSISTENT = 0.9
#: A normal within this angle of the face's axis is on the face; the others are the wall or steep relief.
FACE_ANGLE_DEG = 60.0
#: Points the geometry is read from (a regular subsample): enough for a quadric and a median.
GEOMETRY_SAMPLE = 60_000
#: Fewer face points than this say nothing of the face (a fragment, a test cloud): normals left alone.
_MIN_FACE_POINTS = 100
#: A face is flat: its spread along its axis is at most this share of its narrower spread across (a
#: coin 20 mm wide with 1-2 mm of relief, wall, cupping or bend: about 0.1 at most; a lump: 1).
_MAX_THICKNESS = 0.3
#: The wall is looked for this far out at least (a share of the face's radius).
_WALL_RING = 0.9
#: The wall decides when it holds this share of the points and lies this many spreads off the surface
#: (faces with their wall: 1.1-23 % of the points, 0.55-11 spreads below on both generators, the lowest
#: offsets on a smoothing scanner; cut inside the outline: 1.3 % at most).
_MIN_WALL_SHARE = 0.02
_MIN_WALL_OFFSET = 0.5


@dataclass(frozen=True)
class UpEvidence:
    """What a face's geometry says of its up side along ``axis`` (the smallest principal axis): +1 for
    ``axis``, -1 for its opposite, 0 for nothing; and from which cue."""

    axis: FloatArray
    sign: int
    cue: str  # "wall", "relief" or "none"
    wall_offset: float  # median height of the wall points above the face's surface, in face spreads
    relief_skewness: float  # quartile skewness (10th-50th-90th percentiles) of the face's heights


@dataclass(frozen=True)
class _FaceSample:
    """A regular subsample of a scan (at most ``GEOMETRY_SAMPLE`` points), centred, with its principal axes:
    what every question of this module is asked of, computed once per scan."""

    centred: FloatArray
    normals: FloatArray
    spreads: FloatArray  # eigenvalues of the scatter, ascending
    vectors: FloatArray  # their eigenvectors (columns): the face's axis first

    @classmethod
    def of(cls, points: FloatArray, normals: FloatArray) -> _FaceSample:
        sample = np.arange(0, len(points), max(1, -(-len(points) // GEOMETRY_SAMPLE)))
        centred = points[sample] - points[sample].mean(axis=0)
        spreads, vectors = np.linalg.eigh(centred.T @ centred)
        return cls(centred, normals[sample], spreads, vectors)

    @property
    def axis(self) -> FloatArray:
        return self.vectors[:, 0]

    def facing(self) -> NDArray[np.bool_]:
        """The points whose normal (either sign) is within ``FACE_ANGLE_DEG`` of the axis."""
        return np.abs(self.normals @ self.axis) >= np.cos(np.radians(FACE_ANGLE_DEG))

    @cached_property
    def in_plane(self) -> FloatArray:
        """(3, 2): the face's two larger principal axes, across its axis."""
        return self.vectors[:, [2, 1]]

    @cached_property
    def across(self) -> FloatArray:
        """(n, 2) coordinates across the axis (on :attr:`in_plane`)."""
        return self.centred @ self.in_plane

    @cached_property
    def wall(self) -> NDArray[np.bool_]:
        """The points of the edge wall: not facing along the axis, at the outline (steep relief inside it is
        not the wall)."""
        radial = np.linalg.norm(self.across, axis=1)
        return ~self.facing() & (radial >= _WALL_RING * np.percentile(radial, 99))


def up_evidence(points: FloatArray, normals: FloatArray) -> UpEvidence:
    """The up side of a face scan from its geometry; ``normals`` are read without their signs."""
    return _evidence(_FaceSample.of(points, normals))


def _evidence(sample: _FaceSample) -> UpEvidence:
    axis = sample.axis
    height = sample.centred @ axis
    x, y = sample.across.T
    face = sample.facing()
    if np.count_nonzero(face) < _MIN_FACE_POINTS:
        return UpEvidence(axis, 0, "none", 0.0, 0.0)
    # the face's surface: a quadric (cupping, doming) fitted to the face points, the relief's outliers
    # trimmed twice
    design = np.column_stack([np.ones_like(x), x, y, x * x, x * y, y * y])
    fitted = face.copy()
    for _ in range(3):
        coefficients, *_ = np.linalg.lstsq(design[fitted], height[fitted], rcond=None)
        residual = height - design @ coefficients
        spread = 1.4826 * float(np.median(np.abs(residual[face])))
        if spread <= 0.0:
            return UpEvidence(axis, 0, "none", 0.0, 0.0)
        fitted = face & (np.abs(residual) < 3.0 * spread)
    q10, q50, q90 = np.percentile(residual[face], [10, 50, 90])
    skewness = float(((q90 - q50) - (q50 - q10)) / max(q90 - q10, 1e-12))
    wall = sample.wall
    offset = float(np.median(residual[wall])) / spread if wall.any() else 0.0
    if wall.mean() >= _MIN_WALL_SHARE and abs(offset) >= _MIN_WALL_OFFSET:
        return UpEvidence(axis, -int(np.sign(offset)), "wall", offset, skewness)
    if skewness != 0.0:
        return UpEvidence(axis, int(np.sign(skewness)), "relief", offset, skewness)
    return UpEvidence(axis, 0, "none", offset, skewness)


def wall_normals_outward(points: FloatArray, normals: FloatArray) -> float | None:
    """Share of the edge wall's normals that point away from the face's axis, out of the coin: about 1 for
    normals written outwards, about 0 for the same normals all turned in; None where the scan has too
    little wall to tell (under ``_MIN_WALL_SHARE`` of its points)."""
    return _wall_outward(_FaceSample.of(points, normals))


def _wall_outward(sample: _FaceSample) -> float | None:
    wall = sample.wall
    if wall.mean() < _MIN_WALL_SHARE:
        return None
    normals_across = sample.normals[wall] @ sample.in_plane
    return float(np.mean(np.einsum("ij,ij->i", normals_across, sample.across[wall]) > 0))


def _up(evidence: UpEvidence) -> FloatArray:
    """The unit up direction the evidence gives: the scanner's +z side when it says nothing (as for a
    scan without normals, :func:`coindie.preprocess.orientation.up_axis`)."""
    sign = evidence.sign if evidence.sign != 0 else (1 if evidence.axis[2] >= 0 else -1)
    return sign * evidence.axis


def sign_agreement(points: FloatArray, normals: FloatArray) -> float:
    """Share of the face's normals (within ``FACE_ANGLE_DEG`` of its axis) on their majority side: 1 for
    normals that all point one way, about 0.5 for signs drawn at random; 1 when the cloud is no face (too
    few points facing along its axis, or not flat)."""
    side = _normals_side(_FaceSample.of(points, normals))
    return 1.0 if side is None else side[0]


def _normals_side(sample: _FaceSample) -> tuple[float, int] | None:
    """The share of the face's normals on their majority side and that side (+1: the axis), or None when
    the cloud is no face."""
    if sample.spreads[0] > _MAX_THICKNESS**2 * sample.spreads[1]:  # not flat: no up or down to tell
        return None
    face = sample.facing()
    if np.count_nonzero(face) < _MIN_FACE_POINTS:
        return None
    up = float(np.mean(sample.normals[face] @ sample.axis > 0))
    return max(up, 1.0 - up), 1 if up >= 0.5 else -1


def outward_normals(points: FloatArray, normals: FloatArray) -> FloatArray:
    """``normals`` with their signs set to point out of the coin.

    Normals that agree (at least ``CONSISTENT`` of the face's on one side) are returned as they are, unless
    the wall (:func:`up_evidence`'s decisive cue) says they all point into the coin and most of the wall's
    own normals point towards the face's axis (:func:`wall_normals_outward` under one half): they are then
    all turned (a mesh wound inside out; a hoard from two scanners of opposite conventions would otherwise
    hold faces seen from behind, mirror images of their dies). Without a wall, agreeing normals are
    trusted.
    Normals that disagree are set by :func:`face_up` (the scanner's +z side when the geometry says
    nothing, as for a scan without normals): each is turned away from a point two radii below the face's
    centre, up on the face, outwards on the wall, whatever the cupping."""
    if len(points) == 0:
        return normals
    sample = _FaceSample.of(points, normals)
    side = _normals_side(sample)
    if side is None:
        return normals
    agreement, normals_side = side
    evidence = _evidence(sample)
    if agreement >= CONSISTENT:
        inside_out = (
            evidence.cue == "wall"
            and evidence.sign * normals_side < 0
            and (_wall_outward(sample) or 0.0) < 0.5
        )
        return -normals if inside_out else normals
    return turned_away_from_below(points, normals, _up(evidence))


def face_up(points: FloatArray, normals: FloatArray) -> FloatArray:
    """The face's up direction (unit): the smallest principal axis turned to the side its geometry says
    (:func:`up_evidence`), or to the scanner's +z side when the geometry says nothing."""
    return _up(up_evidence(points, normals))


def turned_away_from_below(points: FloatArray, normals: FloatArray, up: FloatArray) -> FloatArray:
    """Each normal turned to point away from a point two radii below the centroid along ``up``."""
    centre = points.mean(axis=0)
    offsets = points - centre
    radius = float(np.percentile(np.linalg.norm(offsets - np.outer(offsets @ up, up), axis=1), 99))
    below = centre - 2.0 * max(radius, 1e-9) * up
    flip = np.einsum("ij,ij->i", normals, points - below) < 0
    out = normals.copy()
    out[flip] *= -1.0
    return out
