"""STL and OBJ meshes: vertices with area-weighted unit normals that point out of the surface."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from coindie.errors import InvalidScanError
from coindie.ids import parse_face_id
from coindie.io import mesh as mesh_module
from coindie.io import read_scan
from coindie.io.mesh import area_weighted_normals, merge_duplicate_vertices, mesh_scan


def tilted_grid(angle_deg: float = 25.0, n: int = 6) -> tuple[trimesh.Trimesh, np.ndarray]:
    """A flat n x n grid of triangles (normal +z) rotated about the y axis; returns it and its normal."""
    u, v = np.meshgrid(np.linspace(0, 3, n), np.linspace(0, 2, n))
    vertices = np.column_stack([u.ravel(), v.ravel(), np.zeros(n * n)])
    cells = [(i, j) for i in range(n - 1) for j in range(n - 1)]
    quads = [(i * n + j, i * n + j + 1, (i + 1) * n + j + 1, (i + 1) * n + j) for i, j in cells]
    faces = np.array([[a, b, c] for a, b, c, _ in quads] + [[a, c, d] for a, _, c, d in quads])
    rotation = trimesh.transformations.rotation_matrix(np.radians(angle_deg), [0, 1, 0])[:3, :3]
    mesh = trimesh.Trimesh(vertices @ rotation.T + [1.0, -2.0, 0.5], faces, process=False)
    return mesh, rotation[:, 2]


@pytest.mark.parametrize("suffix", [".stl", ".obj", ".STL", ".OBJ"])
def test_icosphere_normals_point_outwards(tmp_path, suffix):
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=6.0)
    sphere.apply_translation([10.0, -3.0, 2.0])
    path = tmp_path / f"L0003D{suffix}"
    sphere.export(path, file_type=suffix.lower().lstrip("."))

    scan = read_scan(path)

    assert scan.id == parse_face_id("L003D")
    assert scan.n_points == len(sphere.vertices)  # STL's per-triangle copies are merged
    radial = scan.points - [10.0, -3.0, 2.0]
    radial /= np.linalg.norm(radial, axis=1, keepdims=True)
    np.testing.assert_allclose(np.linalg.norm(scan.normals, axis=1), 1.0)
    assert np.einsum("ij,ij->i", scan.normals, radial).min() > 0.99


@pytest.mark.parametrize("suffix", [".stl", ".obj"])
@pytest.mark.parametrize("flip", [False, True])
def test_tilted_plane_normals_follow_the_winding(tmp_path, suffix, flip):
    mesh, normal = tilted_grid()
    if flip:
        mesh.invert()
        normal = -normal
    path = tmp_path / f"plane{suffix}"
    mesh.export(path)

    scan = read_scan(path)

    assert scan.n_points == len(mesh.vertices)
    np.testing.assert_allclose(scan.normals, np.tile(normal, (scan.n_points, 1)), atol=1e-6)  # STL: float32


def test_vertex_normals_are_weighted_by_face_area():
    # vertex 0 is shared by a large face in the z=0 plane and a small face in the x=0 plane
    vertices = np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0], [0, 0, 1], [0, 1, 0]], float)
    faces = np.array([[0, 1, 2], [0, 4, 3]])
    large, small = 8.0, 0.5  # areas
    expected = large * np.array([0, 0, 1.0]) + small * np.array([1.0, 0, 0])
    expected /= np.linalg.norm(expected)

    normals = area_weighted_normals(vertices, faces)

    np.testing.assert_allclose(normals[0], expected, atol=1e-12)
    angle_weighted = trimesh.Trimesh(vertices, faces, process=False).vertex_normals[0]
    assert not np.allclose(angle_weighted, expected, atol=1e-3)  # trimesh's own weighting differs


def test_vertices_on_no_surface_are_dropped_with_their_colours():
    # vertex 3 is unused; vertex 4 lies only on a degenerate (collinear) face
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [9, 9, 9], [2, 0, 0]], float)
    colors = np.arange(15, dtype=np.uint8).reshape(5, 3)
    scan = mesh_scan(points, np.array([[0, 1, 2], [0, 1, 4]]), colors=colors, face_id=parse_face_id("x"))
    np.testing.assert_array_equal(scan.points, points[:3])
    np.testing.assert_array_equal(scan.colors, colors[:3])
    np.testing.assert_allclose(scan.normals, np.tile([0, 0, 1.0], (3, 1)))


def test_mesh_scan_rejects_out_of_range_faces(tmp_path):
    path = tmp_path / "bad.ply"
    with pytest.raises(InvalidScanError, match=r"vertex 7, but the mesh has 3 vertices"):
        mesh_scan(np.eye(3), np.array([[0, 1, 7]]), face_id=parse_face_id("x"), path=path)


def test_mesh_scan_with_nan_vertex_reports_the_coordinates(tmp_path):
    points = np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]])
    with pytest.raises(InvalidScanError, match="NaN or infinite coordinates"):
        mesh_scan(points, np.array([[0, 1, 2]]), face_id=parse_face_id("x"), path=tmp_path / "m.ply")


def stl_corners(seed: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A random triangle mesh as an STL stores it, every triangle's corners anew: the corners, the
    triangles of them (0, 1, 2; 3, 4, 5; ...) and the mesh's own triangles of its vertices."""
    rng = np.random.default_rng(seed)
    vertices = rng.normal(size=(300, 3)).astype(np.float32).astype(np.float64)
    vertices[0] = [0.0, 1.0, 2.0]
    triangles = np.array([rng.choice(len(vertices), 3, replace=False) for _ in range(900)])
    corners = vertices[triangles].reshape(-1, 3)
    corners[triangles.ravel() == 0] = [-0.0, 1.0, 2.0]  # a signed zero is the same coordinate
    return corners, np.arange(len(corners)).reshape(-1, 3), triangles


@pytest.mark.parametrize("colliding", [False, True])
def test_duplicate_corners_merge_into_the_meshes_vertices(monkeypatch, colliding):
    corners, triangles, mesh_triangles = stl_corners()
    if colliding:  # every row hashed to one key: the rows themselves decide
        monkeypatch.setattr(mesh_module, "_mixed", lambda x: np.zeros_like(x))

    merged, faces = merge_duplicate_vertices(corners, triangles)

    assert len(merged) == len(np.unique(mesh_triangles))
    np.testing.assert_array_equal(merged[faces], corners.reshape(-1, 3, 3))
    # one merged vertex for each of the mesh's: the two labellings pair one to one
    assert len(set(zip(faces.ravel(), mesh_triangles.ravel(), strict=True))) == len(merged)
    # first appearance order: the vertex of the file's first corner comes first
    np.testing.assert_array_equal(merged[0], corners[0])


def test_stl_reads_like_trimeshs_merged_mesh(tmp_path):
    corners, triangles, _ = stl_corners(seed=1)
    path = tmp_path / "L0001D.stl"
    trimesh.Trimesh(corners, triangles, process=False).export(path)
    reference = trimesh.load_mesh(path, process=True)

    scan = read_scan(path)

    order, reference_order = np.lexsort(scan.points.T), np.lexsort(reference.vertices.T)
    np.testing.assert_array_equal(scan.points[order], reference.vertices[reference_order])
    expected = area_weighted_normals(np.asarray(reference.vertices), np.asarray(reference.faces))
    np.testing.assert_allclose(scan.normals[order], expected[reference_order], atol=1e-12)
