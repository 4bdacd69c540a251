"""Projective correspondences: the point under a query in the target's plane, against a k-d tree."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.registration.clouds import Cloud
from coindie.registration.projective import ProjectedCloud
from coindie.transforms import euler_rigid

# Linear algebra under test (projective look-ups after rigid transforms):
# make test reruns this module under other OpenBLAS kernels.
pytestmark = pytest.mark.numeric


def _tilted_relief(seed: int) -> tuple[Cloud, np.ndarray]:
    """A wavy relief on a 0.1 mm grid, tilted and moved; and T_plane_cloud that levels it back."""
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.arange(-5, 5, 0.1), np.arange(-5, 5, 0.1))
    z = 0.2 * np.sin(x) * np.cos(0.7 * y)
    points = np.column_stack([x.ravel(), y.ravel(), z.ravel()]) + rng.normal(0, 0.01, (x.size, 3))
    normals = np.column_stack(
        [-0.2 * np.cos(x) * np.cos(0.7 * y), 0.14 * np.sin(x) * np.sin(0.7 * y), np.ones_like(x)]
    )
    normals = (normals / np.linalg.norm(normals, axis=-1, keepdims=True)).reshape(-1, 3)
    T_cloud_plane = euler_rigid((10, -5, 30), (3.0, -1.0, 2.0))
    moved = points @ T_cloud_plane[:3, :3].T + T_cloud_plane[:3, 3]
    return Cloud(moved, normals @ T_cloud_plane[:3, :3].T), np.linalg.inv(T_cloud_plane)


def test_projective_lookup_finds_points_as_close_as_the_nearest_neighbour() -> None:
    cloud, T_plane_cloud = _tilted_relief(0)
    projected = ProjectedCloud.over_plane(cloud, T_plane_cloud, np.ones(len(cloud.points), bool), 0.05)
    rng = np.random.default_rng(1)
    queries = cloud.points[rng.choice(len(cloud.points), 500)] + rng.normal(0, 0.02, (500, 3))
    d_tree, _ = cloud.nearest(queries, 0.2)
    d_proj, index = projected.nearest(queries, 0.2)
    found = np.isfinite(d_proj)
    assert found.mean() > 0.95
    # The point under a query is at most a grid step farther than the nearest one, usually the same.
    assert np.all(d_proj[found] <= d_tree[found] + 0.1)
    assert np.median(d_proj[found] - d_tree[found]) < 0.01
    np.testing.assert_allclose(
        d_proj[found], np.linalg.norm(queries[found] - cloud.points[index[found]], axis=1)
    )


def test_queries_off_the_face_or_beyond_reach_find_nothing() -> None:
    cloud, T_plane_cloud = _tilted_relief(2)
    projected = ProjectedCloud.over_plane(cloud, T_plane_cloud, np.ones(len(cloud.points), bool), 0.1)
    T_cloud_plane = np.linalg.inv(T_plane_cloud)
    off = np.array([[20.0, 0.0, 0.0], [0.0, 0.0, 3.0]]) @ T_cloud_plane[:3, :3].T + T_cloud_plane[:3, 3]
    distances, index = projected.nearest(off, 0.5)
    assert np.all(np.isinf(distances))
    assert np.all(index == len(cloud.points))
