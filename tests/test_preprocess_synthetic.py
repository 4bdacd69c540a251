"""A synthetic coin face with known truth, shared by the preprocessing, render and CLI tests.

The face is ``z = f(x, y) = -dome (x² + y²) + Σ Gaussian bumps`` on a disc (jittered grid, analytic
normals), plus the coin's edge wall: a cylinder going down from the rim with horizontal normals. The tests
at the end check the generator itself (its normals are the surface's).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from coindie.scan import Scan
from coindie.transforms import rigid

#: (x mm, y mm, height mm, sigma mm): a few bumps of known heights, away from the rim.
BUMPS = ((-3.0, 2.5, 0.30, 0.7), (2.5, 3.0, 0.20, 0.5), (0.5, -3.5, 0.25, 0.8), (4.0, -1.0, 0.15, 0.4))


@dataclass(frozen=True)
class SyntheticCoin:
    """Parameters of a synthetic face; lengths in mm."""

    radius: float = 10.0
    spacing: float = 0.1
    dome: float = 0.004
    bumps: tuple[tuple[float, float, float, float], ...] = BUMPS
    wall_height: float = 1.5
    noise: float = 0.0
    seed: int = 0

    def height(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        return self.dome_height(x, y) + self.relief(x, y)

    def dome_height(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        return -self.dome * (x * x + y * y)

    def relief(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        z = np.zeros(np.broadcast(x, y).shape)
        for cx, cy, h, s in self.bumps:
            z = z + h * np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s))
        return z

    def gradient(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        gx, gy = -2 * self.dome * x, -2 * self.dome * y
        for cx, cy, h, s in self.bumps:
            g = h * np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s)) / (s * s)
            gx, gy = gx - g * (x - cx), gy - g * (y - cy)
        return gx, gy


def face_points(coin: SyntheticCoin, *, hole: tuple[float, float, float] | None = None) -> tuple:
    """(points, normals) of the face; ``hole`` = (x, y, r) removes a disc of points."""
    rng = np.random.default_rng(coin.seed)
    ticks = np.arange(-coin.radius, coin.radius + coin.spacing, coin.spacing)
    x, y = (a.ravel() for a in np.meshgrid(ticks, ticks))
    x = x + rng.uniform(-0.25, 0.25, x.shape) * coin.spacing
    y = y + rng.uniform(-0.25, 0.25, y.shape) * coin.spacing
    keep = x * x + y * y <= coin.radius**2
    if hole is not None:
        keep &= (x - hole[0]) ** 2 + (y - hole[1]) ** 2 > hole[2] ** 2
    x, y = x[keep], y[keep]
    gx, gy = coin.gradient(x, y)
    normals = np.stack([-gx, -gy, np.ones_like(x)], axis=1)
    points = np.stack([x, y, coin.height(x, y) + rng.normal(0, coin.noise, x.shape)], axis=1)
    return points, normals / np.linalg.norm(normals, axis=1, keepdims=True)


def wall_points(coin: SyntheticCoin) -> tuple:
    """(points, normals) of the edge wall: from the rim down by ``wall_height``, normals outward."""
    angles = np.arange(0.0, 2 * np.pi, coin.spacing / coin.radius)
    depths = np.arange(coin.spacing, coin.wall_height, coin.spacing)
    a, d = (v.ravel() for v in np.meshgrid(angles, depths))
    rim = coin.dome_height(coin.radius, 0.0)
    points = np.stack([coin.radius * np.cos(a), coin.radius * np.sin(a), rim - d], axis=1)
    normals = np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], axis=1)
    return points, normals


def make_scan(
    coin: SyntheticCoin | None = None,
    *,
    T_scan_coin: np.ndarray | None = None,
    normals: bool = True,
    wall: bool = True,
    hole: tuple[float, float, float] | None = None,
    colors: bool = False,
    name: str = "L0001D",
) -> Scan:
    """The synthetic face as a scan, moved by ``T_scan_coin`` (the coin frame has the face up at z = f)."""
    coin = SyntheticCoin() if coin is None else coin
    points, n = face_points(coin, hole=hole)
    if wall:
        wp, wn = wall_points(coin)
        points, n = np.vstack([points, wp]), np.vstack([n, wn])
    scan = Scan(points=points, normals=n if normals else None, id=name)
    if colors:
        scan = Scan(points=points, normals=scan.normals, colors=np.full(points.shape, 128, np.uint8), id=name)
    return scan if T_scan_coin is None else scan.transformed(T_scan_coin)


def random_pose(seed: int, *, max_tilt_deg: float | None = None, shift: float = 5.0) -> np.ndarray:
    """A random rigid transform; with ``max_tilt_deg``, a tilt up to that angle and any spin about z."""
    rng = np.random.default_rng(seed)
    if max_tilt_deg is None:
        R = Rotation.random(random_state=seed).as_matrix()
    else:
        axis = np.array([*rng.normal(size=2), 0.0])
        tilt = Rotation.from_rotvec(axis / np.linalg.norm(axis) * np.radians(rng.uniform(1, max_tilt_deg)))
        R = (tilt * Rotation.from_euler("z", rng.uniform(-180, 180), degrees=True)).as_matrix()
    return rigid(R, rng.uniform(-shift, shift, 3))


# The generator's own checks.


def test_normals_are_perpendicular_to_the_surface():
    coin = SyntheticCoin(spacing=0.5)
    points, normals = face_points(coin)
    h = 1e-5
    x, y = points[:, 0], points[:, 1]
    tangent_x = np.stack([np.full_like(x, h), np.zeros_like(x), coin.height(x + h, y) - coin.height(x, y)], 1)
    tangent_y = np.stack([np.zeros_like(x), np.full_like(x, h), coin.height(x, y + h) - coin.height(x, y)], 1)
    for tangent in (tangent_x, tangent_y):
        cos = np.abs((tangent * normals).sum(1)) / np.linalg.norm(tangent, axis=1)
        assert cos.max() < 1e-3


def test_points_lie_on_the_disc_and_the_wall_below_the_rim():
    coin = SyntheticCoin(spacing=0.5)
    face, _ = face_points(coin)
    wall, wall_normals = wall_points(coin)
    assert np.hypot(face[:, 0], face[:, 1]).max() <= coin.radius
    assert np.allclose(np.hypot(wall[:, 0], wall[:, 1]), coin.radius)
    assert wall[:, 2].max() < coin.dome_height(coin.radius, 0.0)
    assert np.allclose(wall_normals[:, 2], 0.0)
