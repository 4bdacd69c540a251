"""One struck and scanned coin face: the generator's single entry point, ``make_face``.

Everything random about a face is drawn up-front into a ``FaceSpec`` (``sample_face_spec``), so that a
face is a pure function of (die, spec, face id, seed); the seed only drives the scanner's vertex jitter and
noise. Frames (mm): DIE (the die's working face at z = 0, design centred), COIN (origin at the flan's
centre: a coin point p lies over die point p + offset), SCAN (where the scanner put the coin).
``SynthFace.T_scan_die`` maps die-frame points of the struck relief into the scan frame, so the true
transform between two faces a, b of one die is ``T_scan_die[b] @ inv(T_scan_die[a])``.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from coindie.arrays import FloatArray
from coindie.params import Configurable, param
from coindie.scan import Scan, normal_colors
from coindie.synth.circulation import CirculationParams, CirculationSpec, circulate, sample_circulation
from coindie.synth.design import Die
from coindie.synth.scanner import (
    ScanParams,
    ScanSpec,
    add_noise,
    estimate_normals,
    face_points,
    sample_scan,
    smooth_heights,
    wall_points,
)
from coindie.synth.strike import StrikeParams, StrikeSpec, bend_points, coin_grid, sample_strike, strike
from coindie.synth.writer import to_jsonable

_DEFAULT_STRIKE, _DEFAULT_CIRCULATION, _DEFAULT_SCAN = StrikeParams(), CirculationParams(), ScanParams()
#: Coarsest pixel of a coin's height field (mm).
MAX_SURFACE_PITCH_MM = 0.05


@dataclass(frozen=True)
class FaceSpec(Configurable):
    """Everything random about one struck and scanned face.

    ``die_age``: the share (0-1) of the die's life spent when the coin was struck (wear, crack growth).
    """

    die_age: float = param(
        kind=numbers.Real, doc="share of the die's life spent at the strike", low=0.0, high=1.0
    )
    strike: StrikeSpec
    circulation: CirculationSpec
    scan: ScanSpec


def sample_face_spec(
    rng: np.random.Generator,
    die_age: float,
    *,
    strike: StrikeParams = _DEFAULT_STRIKE,
    circulation: CirculationParams = _DEFAULT_CIRCULATION,
    scan: ScanParams = _DEFAULT_SCAN,
) -> FaceSpec:
    """Draw a face's strike, circulation damage and scan from the documented ranges."""
    strike_spec = sample_strike(rng, strike)
    damage = sample_circulation(rng, circulation, strike_spec.flan_radius_mm)
    scan_spec = sample_scan(rng, scan, strike_spec.flan_radius_mm)
    if strike.cup_added_mm > 0:
        # Drawn last, so that the coin is the same coin with another cupping.
        added = float(rng.uniform(-strike.cup_added_mm, strike.cup_added_mm))
        strike_spec = replace(strike_spec, cup_mm=strike_spec.cup_mm + added)
    return FaceSpec(float(die_age), strike_spec, damage, scan_spec)


@dataclass(frozen=True, eq=False)
class SynthFace:
    """A generated face: the scan (face vertices first, then ``info['n_wall_points']`` wall vertices), the
    exact die-to-scan transform, and what was applied (``info``: JSON-ready)."""

    scan: Scan
    T_scan_die: FloatArray
    info: dict[str, Any] = field(default_factory=dict)

    @property
    def is_wall(self) -> np.ndarray:
        """Boolean mask of the points on the flan's side."""
        mask = np.zeros(self.scan.n_points, dtype=bool)
        mask[self.info["n_face_points"] :] = True
        return mask


def make_face(die: Die, spec: FaceSpec, face_id: str, seed: int) -> SynthFace:
    """Strike, circulate and scan one face of ``die``; pure and deterministic (same inputs, same bits)."""
    rng = np.random.default_rng([seed, 5381])
    grid = coin_grid(spec.strike, surface_pitch(die, spec.scan))
    # Strike the flan, then damage it in circulation
    surface = strike(die, spec.die_age, spec.strike, grid)
    circulate(surface, spec.circulation)
    # Scan: mesh vertices on the face and down the flan's side
    face_xyz, face_n = face_points(surface, spec.strike, spec.scan, rng)
    wall_xyz, wall_n = wall_points(surface, spec.strike, spec.scan, rng)
    points, normals = np.vstack([face_xyz, wall_xyz]), np.vstack([face_n, wall_n])
    if spec.strike.bend is not None:
        points, normals = bend_points(spec.strike.bend, points, normals)
    points, normals = add_noise(points, normals, spec.scan, rng)
    n_face = len(face_xyz)
    if spec.scan.smoothing_mm > 0:
        points[:n_face] = smooth_heights(points[:n_face], spec.scan.smoothing_mm)
    if spec.scan.estimated_normals:
        normals = estimate_normals(points, normals, spec.scan.normal_neighbours)
    # Pose on the scanner's plate
    T_scan_coin = spec.scan.T_scan_coin()
    R, t = T_scan_coin[:3, :3], T_scan_coin[:3, 3]
    points, normals = points @ R.T + t, normals @ R.T
    scan = Scan(points, normals, normal_colors(normals), id=face_id)
    T_scan_die = T_scan_coin @ _translation(-spec.strike.offset_mm[0], -spec.strike.offset_mm[1])
    return SynthFace(scan, T_scan_die, _info(die, spec, len(face_xyz), len(wall_xyz), grid.pitch))


def surface_pitch(die: Die, scan: ScanSpec) -> float:
    """Pixel (mm) of the coin's height field: half the vertex spacing, but no finer than the die's field and
    no coarser than 0.05 mm (below that, scratches and pits would vanish between pixels)."""
    return max(die.params.pitch_mm, min(scan.spacing_mm / 2, MAX_SURFACE_PITCH_MM))


def _translation(x: float, y: float) -> FloatArray:
    T = np.eye(4)
    T[:2, 3] = x, y
    return T


def _info(die: Die, spec: FaceSpec, n_face: int, n_wall: int, pitch: float) -> dict[str, Any]:
    open_cracks = [i for i, c in enumerate(die.cracks) if c.opening(spec.die_age) > 0]
    return {
        "die_id": die.die_id,
        "family": die.family.value,
        "type_seed": die.type.seed,
        "die_seed": die.seed,
        "n_face_points": n_face,
        "n_wall_points": n_wall,
        "surface_pitch_mm": pitch,
        "open_cracks": open_cracks,
        "spec": to_jsonable(spec),
    }
