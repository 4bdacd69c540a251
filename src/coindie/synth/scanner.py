"""Scanning: what a structured-light scanner (the paper's AICON SmartScan) returns for one coin face.

- points like the vertices of the scanner's mesh: a lattice aligned with the scanner's axes at
  ``spacing_mm`` (default 0.05 mm; the scanner resolves 0.04 mm), each vertex jittered;
- the coin's edge wall: the scanner also sees the top of the flan's side, which leans outward going down;
  these points (normals pointing outward) are the edges that perturb registration;
- Gaussian noise along the normal (0.005-0.01 mm), normals from the noise-free surface (as the scanner
  software's smoothed mesh normals) with a small angular noise, colours from the normals;
- a random pose: coins are scanned four at a time on a plate, each turned at random about z, tilted a
  few degrees, at one of four positions.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage
from scipy.spatial.transform import Rotation

from coindie.synth._params import check_ranges, param
from coindie.synth._raster import FloatArray
from coindie.synth.strike import StrikeSpec, Surface, max_radius, outline_radius

#: Face vertices closer than this share of the spacing to the outline are left to the wall.
_RIM_GAP = 0.3


@dataclass(frozen=True)
class ScanParams:
    """Ranges from which each scan is drawn (``sample_scan``). Checked at construction."""

    spacing_mm: float = param(
        0.05,
        unit="mm",
        lo=0.01,
        hi=0.5,
        doc="vertex spacing of the scanner's mesh (SmartScan: 0.04 possible)",
    )
    jitter: float = param(
        0.2,
        unit="fraction",
        lo=0.0,
        hi=0.5,
        doc="vertex displacement, uniform within +-jitter x spacing per axis",
    )
    noise_mm: tuple[float, float] = param(
        (0.005, 0.01),
        unit="mm",
        lo=0.0,
        hi=0.2,
        pair=True,
        doc="range of the sd of the noise along the normal",
    )
    normal_noise_deg: float = param(
        1.0, unit="deg", lo=0.0, hi=30.0, doc="sd of the normals' angular noise about each tangent axis"
    )
    wall_height_mm: tuple[float, float] = param(
        (0.4, 1.2),
        unit="mm",
        lo=0.0,
        hi=4.0,
        pair=True,
        doc="range of the height of flan side scanned (0: none)",
    )
    wall_flare_deg: tuple[float, float] = param(
        (5.0, 25.0), unit="deg", lo=0.0, hi=60.0, pair=True, doc="range of the side's outward lean going down"
    )
    tilt_deg: float = param(3.0, unit="deg", lo=0.0, hi=45.0, doc="largest tilt of the coin on the plate")
    plate_offset_mm: float = param(
        16.0, unit="mm", lo=0.0, hi=500.0, doc="the four coins on the plate sit near (+-a, +-a)"
    )
    plate_jitter_mm: float = param(
        3.0, unit="mm", lo=0.0, hi=100.0, doc="sd of a coin's place around its spot"
    )
    thickness_mm: tuple[float, float] = param(
        (1.6, 2.6), unit="mm", lo=0.0, hi=20.0, pair=True, doc="range of the face's height above the plate"
    )

    def __post_init__(self) -> None:
        check_ranges(self)


@dataclass(frozen=True)
class ScanSpec:
    """One scan: sampling, noise, wall, and the pose of the coin in the scanner's frame."""

    spacing_mm: float
    jitter: float
    noise_mm: float
    normal_noise_deg: float
    wall_height_mm: float
    wall_flare_deg: float
    yaw_deg: float
    tilt_deg: float
    tilt_azimuth_deg: float
    position_mm: tuple[float, float, float]

    def T_scan_coin(self) -> FloatArray:
        """4x4 rigid transform from the coin frame to the scanner's frame."""
        az = np.radians(self.tilt_azimuth_deg)
        tilt = Rotation.from_rotvec(np.radians(self.tilt_deg) * np.array([np.cos(az), np.sin(az), 0.0]))
        R = (tilt * Rotation.from_euler("z", self.yaw_deg, degrees=True)).as_matrix()
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = R, self.position_mm
        return T


def sample_scan(rng: np.random.Generator, params: ScanParams) -> ScanSpec:
    """Draw one scan from ``params``."""
    slot = np.array([[1, 1], [-1, 1], [-1, -1], [1, -1]])[rng.integers(4)] * params.plate_offset_mm
    xy = slot + rng.normal(0.0, params.plate_jitter_mm, 2)
    return ScanSpec(
        spacing_mm=params.spacing_mm,
        jitter=params.jitter,
        noise_mm=float(rng.uniform(*params.noise_mm)),
        normal_noise_deg=params.normal_noise_deg,
        wall_height_mm=float(rng.uniform(*params.wall_height_mm)),
        wall_flare_deg=float(rng.uniform(*params.wall_flare_deg)),
        yaw_deg=float(rng.uniform(0.0, 360.0)),
        tilt_deg=float(params.tilt_deg * np.sqrt(rng.random())),
        tilt_azimuth_deg=float(rng.uniform(0.0, 360.0)),
        position_mm=(float(xy[0]), float(xy[1]), float(rng.uniform(*params.thickness_mm))),
    )


def face_points(
    surface: Surface, strike: StrikeSpec, scan: ScanSpec, rng: np.random.Generator
) -> tuple[FloatArray, FloatArray]:
    """Coin-frame vertices on the face (inside the outline) and their normals from the surface gradient."""
    xy = _lattice(scan, max_radius(strike), rng)
    inside = outline_radius(strike, np.arctan2(xy[:, 1], xy[:, 0])) - np.hypot(xy[:, 0], xy[:, 1])
    xy = xy[inside > _RIM_GAP * scan.spacing_mm]
    height = surface.height
    gy, gx = np.gradient(height, surface.grid.pitch)
    index = surface.grid.fractional_index(xy)
    z, dzdx, dzdy = (ndimage.map_coordinates(f, index, order=1, mode="nearest") for f in (height, gx, gy))
    normals = np.column_stack([-dzdx, -dzdy, np.ones(len(xy))])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return np.column_stack([xy, z]), normals


def _lattice(scan: ScanSpec, radius: float, rng: np.random.Generator) -> FloatArray:
    """The scanner's vertex lattice (aligned with its axes, so turned by -yaw in the coin frame), jittered."""
    s = scan.spacing_mm
    k = np.arange(-int(np.ceil(radius / s)) - 1, int(np.ceil(radius / s)) + 2)
    u, v = np.meshgrid(k * s, k * s)
    uv = np.column_stack([u.ravel(), v.ravel()]) + rng.uniform(0.0, s, 2)
    uv += rng.uniform(-scan.jitter * s, scan.jitter * s, uv.shape)
    uv = uv[np.hypot(uv[:, 0], uv[:, 1]) <= radius]
    a = -np.radians(scan.yaw_deg)
    return uv @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]])


def wall_points(
    surface: Surface, strike: StrikeSpec, scan: ScanSpec, rng: np.random.Generator
) -> tuple[FloatArray, FloatArray]:
    """Coin-frame vertices down the flan's side from its rim, with outward (slightly upward) normals."""
    s = scan.spacing_mm
    rows = int(scan.wall_height_mm / s)
    if rows == 0:
        return np.zeros((0, 3)), np.zeros((0, 3))
    rim, out = _rim(strike, s, rng)
    z_rim = ndimage.map_coordinates(
        surface.height, surface.grid.fractional_index(rim), order=1, mode="nearest"
    )
    t = (np.arange(rows) + 0.5)[None, :] * s + rng.uniform(
        -scan.jitter * s, scan.jitter * s, (len(rim), rows)
    )
    flare = np.radians(scan.wall_flare_deg)
    xy = rim[:, None, :] + out[:, None, :] * (t * np.tan(flare))[..., None]
    points = np.concatenate([xy, (z_rim[:, None] - t)[..., None]], axis=-1).reshape(-1, 3)
    normal = np.column_stack([out * np.cos(flare), np.full(len(rim), np.sin(flare))])
    return points, np.repeat(normal, rows, axis=0)


def _rim(strike: StrikeSpec, s: float, rng: np.random.Generator) -> tuple[FloatArray, FloatArray]:
    """Points every ~``s`` mm along the outline (jittered) and the outline's outward unit normals there."""
    n_fine = int(np.ceil(2 * np.pi * max_radius(strike) / (s / 8)))
    phi = np.linspace(0.0, 2 * np.pi, n_fine, endpoint=False)
    r = outline_radius(strike, phi)
    fine = np.column_stack([r * np.cos(phi), r * np.sin(phi)])
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(fine, axis=0, append=fine[:1]), axis=1))]
    at = np.arange(0.0, arc[-1] - s / 2, s) + rng.uniform(0.0, s)
    at = np.clip(at + rng.uniform(-0.2 * s, 0.2 * s, len(at)), 0.0, arc[-1])
    closed = np.vstack([fine, fine[:1]])
    rim = np.column_stack([np.interp(at, arc, closed[:, 0]), np.interp(at, arc, closed[:, 1])])
    tangent = np.gradient(closed, axis=0)[:-1]
    tangent[0] = closed[1] - closed[-2]
    i = np.minimum(np.searchsorted(arc, at, side="right") - 1, n_fine - 1)
    out = np.column_stack([tangent[i, 1], -tangent[i, 0]])
    return rim, out / np.linalg.norm(out, axis=1, keepdims=True)


def add_noise(
    points: FloatArray, normals: FloatArray, scan: ScanSpec, rng: np.random.Generator
) -> tuple[FloatArray, FloatArray]:
    """Noise along the normal (sd ``noise_mm``) and on the normals' directions (sd ``normal_noise_deg``)."""
    noisy = points + normals * rng.normal(0.0, scan.noise_mm, (len(points), 1))
    tilted = normals + rng.normal(0.0, np.tan(np.radians(scan.normal_noise_deg)), normals.shape)
    return noisy, tilted / np.linalg.norm(tilted, axis=1, keepdims=True)
