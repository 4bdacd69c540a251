"""Normals by local PCA: planes and spheres with known normals."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.preprocess import estimate_normals

# Linear algebra under test (normals from local covariances (eigh)):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric


def _angles_deg(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    cos = (a * b).sum(axis=1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
    return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))


def test_a_tilted_noisy_plane_gets_its_normal_on_the_requested_side():
    rng = np.random.default_rng(0)
    normal = np.array([0.2, -0.3, 0.93])
    normal /= np.linalg.norm(normal)
    u = np.cross(normal, [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    st = rng.uniform(-5, 5, (4000, 2))
    points = st[:, :1] * u + st[:, 1:] * v + rng.normal(0, 0.002, (4000, 1)) * normal
    up = estimate_normals(points, k=16)
    assert np.percentile(_angles_deg(up, np.tile(normal, (4000, 1))), 99) < 2.0
    down = estimate_normals(points, k=16, toward=(0, 0, -1))
    assert np.allclose(down, -up)


def test_sphere_normals_are_radial():
    rng = np.random.default_rng(1)
    directions = rng.normal(size=(20000, 3))
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    cap = directions[directions[:, 2] > 0.2]
    normals = estimate_normals(5.0 * cap, k=12)
    assert np.median(_angles_deg(normals, cap)) < 1.0
    assert np.percentile(_angles_deg(normals, cap), 99) < 4.0


def test_a_radius_smaller_than_the_spacing_falls_back_to_the_k_nearest():
    ticks = np.arange(0.0, 2.0, 0.1)
    x, y = np.meshgrid(ticks, ticks)
    points = np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], axis=1)
    normals = estimate_normals(points, k=8, radius=0.01)
    assert np.allclose(normals, [0.0, 0.0, 1.0])


def test_the_radius_keeps_a_neighbour_on_another_sheet_out():
    # Two parallel sheets 0.3 mm apart: with many neighbours and no radius, the sheets mix near
    # their edge; a radius below the gap keeps each normal on its own sheet.
    ticks = np.arange(0.0, 1.0, 0.1)
    x, y = (a.ravel() for a in np.meshgrid(ticks, ticks))
    lower = np.stack([x, y, np.zeros_like(x)], axis=1)
    upper = np.stack([x + 0.95, y, np.full_like(x, 0.3)], axis=1)
    normals = estimate_normals(np.vstack([lower, upper]), k=20, radius=0.25)
    assert np.allclose(normals, [0.0, 0.0, 1.0], atol=1e-6)


@pytest.mark.parametrize(("k", "radius"), [(2, None), (8, 0.0), (8, -1.0)])
def test_bad_parameters_are_refused(k, radius):
    with pytest.raises(ParameterError):
        estimate_normals(np.random.default_rng(0).normal(size=(50, 3)), k=k, radius=radius)


def test_too_few_points_are_refused():
    with pytest.raises(ParameterError, match="N >= 3"):
        estimate_normals(np.zeros((2, 3)))
