"""Scanning: what a structured-light scanner (the paper's AICON SmartScan) returns for one coin face.

- points like the vertices of the scanner's mesh: a lattice aligned with the scanner's axes at
  ``spacing_mm`` (default 0.05 mm; the scanner resolves 0.04 mm), each vertex jittered;
- the coin's edge wall: the scanner also sees the top of the flan's side, which leans outward going down;
  these points (normals pointing outward) are the edges that perturb registration;
- Gaussian noise along the normal (0.005-0.01 mm), normals from the noise-free surface (as the scanner
  software's smoothed mesh normals) with a small angular noise, colours from the normals;
- a random pose: coins are scanned four at a time on a plate, each turned at random about z, tilted a
  few degrees, at one of four positions.

Other scanners and their software (the wide world's axes, off by default): smoothed meshes
(``smoothing_mm``: the heights diffused over the mesh's neighbours, a Gaussian of that sd), normals
estimated from the noisy points instead of the mesh (``estimated_normals``: PCA over
``normal_neighbours`` neighbours, oriented towards the side the surface faces, as software without mesh
normals gives them), and holes (``hole_share``: a share of the face's vertices missing, in a few blobs).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy import ndimage, sparse
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

from coindie.arrays import FloatArray
from coindie.params import Configurable
from coindie.synth._params import new_field, param
from coindie.synth.strike import StrikeSpec, Surface, max_radius, outline_radius

#: Face vertices closer than this share of the spacing to the outline are left to the wall.
_RIM_GAP = 0.3


@dataclass(frozen=True)
class ScanParams(Configurable):
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
    smoothing_mm: float = param(
        0.0,
        unit="mm",
        lo=0.0,
        hi=0.5,
        new=True,
        doc="sd of the mesh smoothing of the scanned heights (Laplacian diffusion over neighbours; 0: raw)",
    )
    estimated_normals: float = param(
        0.0,
        unit="probability",
        lo=0.0,
        hi=1.0,
        new=True,
        doc="chance that a face's normals are estimated from its noisy points (PCA) instead of the mesh",
    )
    normal_neighbours: int = param(
        16, unit="count", lo=4, hi=100, new=True, doc="neighbours of the PCA that estimates a normal"
    )
    hole_share: tuple[float, float] = param(
        (0.0, 0.0),
        unit="fraction",
        lo=0.0,
        hi=0.5,
        pair=True,
        new=True,
        doc="range of the share of the face's vertices missing (holes in the scan)",
    )
    holes_max: int = param(3, unit="count", lo=1, hi=10, new=True, doc="at most this many hole blobs")


@dataclass(frozen=True)
class Hole:
    """One blob of missing data: an ellipse (coin frame) of relative ``weight`` (its share of the holes'
    area), axis ratio ``elongation`` (>= 1), long axis at ``angle_deg``."""

    centre: tuple[float, float]
    weight: float
    elongation: float
    angle_deg: float


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
    smoothing_mm: float = new_field(0.0)
    estimated_normals: bool = new_field(False)
    normal_neighbours: int = new_field(16)
    hole_share: float = new_field(0.0)
    holes: tuple[Hole, ...] = new_field(())

    def T_scan_coin(self) -> FloatArray:
        """4x4 rigid transform from the coin frame to the scanner's frame."""
        az = np.radians(self.tilt_azimuth_deg)
        tilt = Rotation.from_rotvec(np.radians(self.tilt_deg) * np.array([np.cos(az), np.sin(az), 0.0]))
        R = (tilt * Rotation.from_euler("z", self.yaw_deg, degrees=True)).as_matrix()
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = R, self.position_mm
        return T


def sample_scan(rng: np.random.Generator, params: ScanParams, flan_radius_mm: float = 10.5) -> ScanSpec:
    """Draw one scan from ``params`` (``flan_radius_mm`` places the holes).

    The wide world's axes are drawn after today's draws and only where they are switched on, so that a
    scan of the default parameters is the same as before they existed.
    """
    slot = np.array([[1, 1], [-1, 1], [-1, -1], [1, -1]])[rng.integers(4)] * params.plate_offset_mm
    xy = slot + rng.normal(0.0, params.plate_jitter_mm, 2)
    spec = ScanSpec(
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
    p = params.estimated_normals
    estimated = p >= 1.0 or (p > 0.0 and bool(rng.random() < p))
    share = float(rng.uniform(*params.hole_share)) if params.hole_share[1] > 0 else 0.0
    holes = _holes(rng, params, flan_radius_mm) if share > 0 else ()
    return replace(
        spec,
        smoothing_mm=params.smoothing_mm,
        estimated_normals=estimated,
        normal_neighbours=params.normal_neighbours if estimated else 16,
        hole_share=share,
        holes=holes,
    )


def _holes(rng: np.random.Generator, params: ScanParams, radius: float) -> tuple[Hole, ...]:
    n = int(rng.integers(1, params.holes_max + 1))
    weights = rng.dirichlet(np.full(n, 2.0))
    holes = []
    for w in weights:
        r, a = 0.8 * radius * np.sqrt(rng.random()), rng.uniform(0, 2 * np.pi)
        centre = (float(r * np.cos(a)), float(r * np.sin(a)))
        holes.append(Hole(centre, float(w), float(rng.uniform(1.0, 2.5)), float(rng.uniform(0, 180))))
    return tuple(holes)


def face_points(
    surface: Surface, strike: StrikeSpec, scan: ScanSpec, rng: np.random.Generator
) -> tuple[FloatArray, FloatArray]:
    """Coin-frame vertices on the face (inside the outline) and their normals from the surface gradient."""
    xy = _lattice(scan, max_radius(strike), rng)
    inside = outline_radius(strike, np.arctan2(xy[:, 1], xy[:, 0])) - np.hypot(xy[:, 0], xy[:, 1])
    xy = xy[inside > _RIM_GAP * scan.spacing_mm]
    if scan.holes:
        xy = xy[~hole_mask(xy, scan)]
    height = surface.height
    gy, gx = np.gradient(height, surface.grid.pitch)
    index = surface.grid.fractional_index(xy)
    z, dzdx, dzdy = (ndimage.map_coordinates(f, index, order=1, mode="nearest") for f in (height, gx, gy))
    normals = np.column_stack([-dzdx, -dzdy, np.ones(len(xy))])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return np.column_stack([xy, z]), normals


def hole_mask(xy: FloatArray, scan: ScanSpec) -> np.ndarray:
    """Which of the face's vertices ``xy`` (coin frame) fall in the scan's holes: exactly ``hole_share`` of
    them (rounded), the ones nearest to a blob's centre in that blob's own metric (ellipses whose areas go
    as their weights), so the blobs grow together until the share is reached."""
    n_missing = int(round(scan.hole_share * len(xy)))
    if n_missing == 0:
        return np.zeros(len(xy), dtype=bool)
    distance = np.full(len(xy), np.inf)
    for hole in scan.holes:
        a = np.radians(hole.angle_deg)
        d = xy - np.asarray(hole.centre)
        along = d @ np.array([np.cos(a), np.sin(a)])
        across = d @ np.array([-np.sin(a), np.cos(a)])
        # Area of {along^2 / e + e across^2 <= t^2} is pi t^2: equal t gives areas in proportion to weight.
        t = np.sqrt(along**2 / hole.elongation + hole.elongation * across**2) / np.sqrt(hole.weight)
        distance = np.minimum(distance, t)
    mask = np.zeros(len(xy), dtype=bool)
    mask[np.argsort(distance, kind="stable")[:n_missing]] = True
    return mask


def smooth_heights(points: FloatArray, sigma_mm: float) -> FloatArray:
    """The points' heights (z, coin frame) smoothed over the mesh like a scanner software's smoothing: a
    diffusion over each vertex's 8 nearest neighbours in xy, iterated until it amounts to a Gaussian of sd
    ``sigma_mm``. Written by hand (a sparse averaging operator applied n times): no library smooths a
    height function on scattered points. Only heights move, so the outline does not shrink, and the
    flan's curvature shifts by 2 c sigma^2 (< 0.001 mm), so Taubin's inflating counter-step is not needed.
    """
    if sigma_mm <= 0 or len(points) < 9:
        return points
    distance, index = cKDTree(points[:, :2]).query(points[:, :2], k=9)
    distance, index = distance[:, 1:], index[:, 1:]
    # One step z += lam (mean of neighbours - z) adds lam * <dx^2> = lam * <d^2> / 2 of variance per axis.
    mean_dx2 = float(np.mean(distance**2)) / 2
    steps = max(1, int(np.ceil(sigma_mm**2 / (0.5 * mean_dx2))))
    lam = sigma_mm**2 / (steps * mean_dx2)
    n = len(points)
    rows = np.repeat(np.arange(n), 8)
    average = sparse.csr_matrix((np.full(8 * n, 1 / 8), (rows, index.ravel())), shape=(n, n))
    step = (1 - lam) * sparse.identity(n, format="csr") + lam * average
    z = points[:, 2].copy()
    for _ in range(steps):
        z = step @ z
    out = points.copy()
    out[:, 2] = z
    return out


def estimate_normals(points: FloatArray, reference: FloatArray, k: int) -> FloatArray:
    """Normals estimated from the points alone: the direction of least spread (PCA) of each point's ``k``
    nearest neighbours, turned to the side of ``reference`` (the surface's true normals: the side the
    scanner saw, as a viewpoint orientation gives it)."""
    k = min(k, len(points))
    tree = cKDTree(points)
    normals = np.empty_like(points)
    for start in range(0, len(points), 65536):
        block = slice(start, start + 65536)
        _, index = tree.query(points[block], k=k)
        near = points[index] - points[index].mean(axis=1, keepdims=True)
        _, vectors = np.linalg.eigh(np.einsum("nki,nkj->nij", near, near))
        normals[block] = vectors[:, :, 0]
    flip = np.einsum("ij,ij->i", normals, reference) < 0
    normals[flip] *= -1
    return normals


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
