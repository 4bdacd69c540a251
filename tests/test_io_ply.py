"""PLY reading and writing: every encoding and property combination round-trips; meshes get normals."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh
from plyfile import PlyData, PlyElement

from coindie.errors import ParameterError
from coindie.ids import parse_face_id
from coindie.io import read_ply, read_scan, write_ply
from coindie.scan import Scan, normal_colors

N_POINTS = 500


def random_scan(*, normals: bool, colors: bool, seed: int = 0) -> Scan:
    rng = np.random.default_rng(seed)
    return Scan(
        points=rng.normal(scale=8.0, size=(N_POINTS, 3)),
        normals=rng.normal(size=(N_POINTS, 3)) if normals else None,
        colors=rng.integers(0, 256, size=(N_POINTS, 3), dtype=np.uint8) if colors else None,
        id="L0007R",
    )


def write_vertex_ply(path: Path, columns: dict[str, np.ndarray], *, extra: list[PlyElement] = (), **options):
    """A PLY written directly with plyfile (not with our writer), from named columns."""
    n = len(next(iter(columns.values())))
    records = np.empty(n, dtype=[(name, values.dtype) for name, values in columns.items()])
    for name, values in columns.items():
        records[name] = values
    PlyData([PlyElement.describe(records, "vertex"), *extra], **options).write(str(path))
    return path


def header_of(path: Path) -> str:
    data = path.read_bytes()
    return data[: data.index(b"end_header")].decode("ascii")


@pytest.mark.parametrize("binary, byte_order", [(True, "<"), (True, ">"), (False, "<")])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("normals", [True, False])
@pytest.mark.parametrize("colors", [True, False])
def test_write_then_read_gives_the_same_scan(tmp_path, binary, byte_order, dtype, normals, colors):
    scan = random_scan(normals=normals, colors=colors)
    path = write_ply(tmp_path / "L007R.ply", scan, binary=binary, byte_order=byte_order, dtype=dtype)
    read = read_scan(path)

    np.testing.assert_array_equal(read.points, scan.points.astype(dtype).astype(np.float64))
    assert read.id == parse_face_id("L0007R")
    assert read.path == path
    if normals:
        np.testing.assert_allclose(read.normals, scan.normals, atol=1e-6 if dtype == np.float32 else 1e-12)
        np.testing.assert_array_equal(read.colors, normal_colors(scan.normals))  # colours from normals
    else:
        assert read.normals is None
        assert (read.colors is None) == (not colors)
        if colors:
            np.testing.assert_array_equal(read.colors, scan.colors)


@pytest.mark.parametrize(
    "byte_order, dtype, expected",
    [("<", np.float32, "binary_little_endian"), (">", np.float64, "binary_big_endian")],
)
def test_written_header_is_the_riedones3d_layout(tmp_path, byte_order, dtype, expected):
    path = write_ply(
        tmp_path / "a.ply", random_scan(normals=True, colors=False), byte_order=byte_order, dtype=dtype
    )
    header = header_of(path)
    kind = "float" if dtype == np.float32 else "double"
    properties = [line.split()[-2:] for line in header.splitlines() if line.startswith("property")]
    assert f"format {expected} 1.0" in header
    assert f"element vertex {N_POINTS}" in header
    assert properties == [[kind, name] for name in ("x", "y", "z", "nx", "ny", "nz")] + [
        ["uchar", name] for name in ("red", "green", "blue")
    ]


def test_ascii_writes_text(tmp_path):
    path = write_ply(tmp_path / "a.ply", random_scan(normals=False, colors=False), binary=False)
    assert "format ascii 1.0" in header_of(path)
    assert len(path.read_text().splitlines()) == N_POINTS + len(header_of(path).splitlines()) + 1


def test_extra_properties_and_elements_are_ignored(tmp_path):
    rng = np.random.default_rng(1)
    xyz = rng.normal(size=(50, 3)).astype(np.float32)
    normals = rng.normal(size=(50, 3)).astype(np.float32)
    columns = {
        "intensity": rng.random(50).astype(np.float32),
        "nz": normals[:, 2],
        "x": xyz[:, 0],
        "y": xyz[:, 1],
        "z": xyz[:, 2],
        "nx": normals[:, 0],
        "ny": normals[:, 1],
        "red": np.full(50, 9, np.uint8),
        "green": np.full(50, 8, np.uint8),
        "blue": np.full(50, 7, np.uint8),
        "alpha": np.full(50, 255, np.uint8),
    }
    camera = np.array([(1.0, 2.0)], dtype=[("fx", "f8"), ("fy", "f8")])
    path = write_vertex_ply(tmp_path / "x.ply", columns, extra=[PlyElement.describe(camera, "camera")])

    scan = read_scan(path)

    np.testing.assert_array_equal(scan.points, xyz)
    np.testing.assert_allclose(
        scan.normals, normals / np.linalg.norm(normals, axis=1, keepdims=True), atol=1e-6
    )
    np.testing.assert_array_equal(scan.colors, np.tile([9, 8, 7], (50, 1)))


def test_float_colours_in_unit_range_are_scaled(tmp_path):
    ones = np.ones(4, np.float32)
    columns = {"x": np.arange(4, dtype=np.float32), "y": ones, "z": ones}
    columns |= {"red": ones * 0.5, "green": ones * 0.0, "blue": ones * 1.0}
    scan = read_scan(write_vertex_ply(tmp_path / "c.ply", columns))
    np.testing.assert_array_equal(scan.colors, np.tile([128, 0, 255], (4, 1)))


@pytest.mark.parametrize("name", ["L0001D.PLY", "L0001D.Ply"])
def test_suffix_is_case_insensitive(tmp_path, name):
    path = write_ply(tmp_path / name, random_scan(normals=True, colors=False))
    assert read_scan(path).n_points == N_POINTS


def test_read_ply_takes_its_id_from_the_file_name(tmp_path):
    path = write_ply(tmp_path / "L082D.ply", random_scan(normals=False, colors=False))
    assert read_ply(path).id == parse_face_id("L0082D")
    assert (
        read_scan(write_ply(tmp_path / "coin 7.ply", random_scan(normals=False, colors=False))).id.key
        == "coin 7"
    )


# --- meshes ---------------------------------------------------------------------------------------------


def mesh_ply(path: Path, vertices, faces, *, normals=None, **options) -> Path:
    columns = {axis: np.asarray(vertices, np.float32)[:, i] for i, axis in enumerate("xyz")}
    if normals is not None:
        columns |= {name: np.asarray(normals, np.float32)[:, i] for i, name in enumerate(("nx", "ny", "nz"))}
    face = np.empty(len(faces), dtype=[("vertex_indices", "O")])
    face["vertex_indices"] = [np.asarray(f, np.int32) for f in faces]
    return write_vertex_ply(path, columns, extra=[PlyElement.describe(face, "face")], **options)


@pytest.mark.parametrize("options", [{}, {"byte_order": ">"}, {"text": True}])
def test_mesh_ply_gets_outward_unit_normals(tmp_path, options):
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=4.0)
    path = mesh_ply(tmp_path / "ball.ply", sphere.vertices, sphere.faces, **options)

    scan = read_scan(path)

    radial = sphere.vertices / np.linalg.norm(sphere.vertices, axis=1, keepdims=True)
    np.testing.assert_allclose(scan.points, sphere.vertices, atol=1e-5)
    np.testing.assert_allclose(np.linalg.norm(scan.normals, axis=1), 1.0)
    assert np.einsum("ij,ij->i", scan.normals, radial).min() > 0.99


def test_mesh_ply_keeps_the_files_normals(tmp_path):
    sphere = trimesh.creation.icosphere(subdivisions=1)
    stored = np.tile([0.0, 0.0, 1.0], (len(sphere.vertices), 1))
    scan = read_scan(mesh_ply(tmp_path / "m.ply", sphere.vertices, sphere.faces, normals=stored))
    np.testing.assert_array_equal(scan.normals, stored)


def test_mesh_ply_with_quads_and_unused_vertices(tmp_path):
    # a unit square as one quad, tilted about x by 30 degrees; vertex 4 belongs to no face
    angle = np.radians(30)
    square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [5, 5, 5]], float)
    rotation = np.array([[1, 0, 0], [0, np.cos(angle), -np.sin(angle)], [0, np.sin(angle), np.cos(angle)]])
    vertices = square @ rotation.T

    scan = read_scan(mesh_ply(tmp_path / "quad.ply", vertices, [[0, 1, 2, 3]]))

    assert scan.n_points == 4  # the unused vertex has no normal and is dropped
    np.testing.assert_allclose(scan.normals, np.tile(rotation[:, 2], (4, 1)), atol=1e-6)


def test_write_ply_refuses_bad_options(tmp_path):
    scan = random_scan(normals=False, colors=False)
    with pytest.raises(ParameterError, match="float32 or float64"):
        write_ply(tmp_path / "a.ply", scan, dtype=np.int32)
    with pytest.raises(ParameterError, match="byte_order"):
        write_ply(tmp_path / "a.ply", scan, byte_order="=")
    assert not (tmp_path / "a.ply").exists()
