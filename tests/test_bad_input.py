"""Bad scan files: each gives a typed error whose one-line message starts with the path and says why."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from plyfile import PlyData, PlyElement

from coindie.errors import InvalidScanError, ParameterError, ScanReadError
from coindie.io import MAX_SCAN_BYTES, read_scan, write_ply
from coindie.scan import Scan

N_POINTS = 40


def good_ply(path: Path, *, binary: bool = True) -> Path:
    rng = np.random.default_rng(3)
    scan = Scan(rng.normal(size=(N_POINTS, 3)), normals=rng.normal(size=(N_POINTS, 3)))
    return write_ply(path, scan, binary=binary)


def header_size(path: Path) -> int:
    data = path.read_bytes()
    return data.index(b"end_header\n") + len(b"end_header\n")


def vertex_ply(path: Path, names: str = "x y z", rows: np.ndarray | None = None, **options) -> Path:
    """A PLY with one float vertex element with the named properties (rows default to zeros)."""
    fields = names.split()
    values = np.zeros((3, len(fields))) if rows is None else np.asarray(rows, float)
    records = np.empty(len(values), dtype=[(name, "f4") for name in fields])
    for column, name in enumerate(fields):
        records[name] = values[:, column]
    PlyData([PlyElement.describe(records, "vertex")], **options).write(str(path))
    return path


def expect(error_type: type[Exception], path: Path, problem: str, **options) -> ScanReadError:
    with pytest.raises(error_type, match=problem) as caught:
        read_scan(path, **options)
    message = str(caught.value)
    assert message.startswith(f"{path}: "), message
    assert "\n" not in message
    assert caught.value.path == path
    return caught.value


def test_missing_file(tmp_path):
    expect(ScanReadError, tmp_path / "L0001D.ply", "no such file")


def test_directory_instead_of_file(tmp_path):
    folder = tmp_path / "L0001D.ply"
    folder.mkdir()
    expect(ScanReadError, folder, "is a directory")


def test_broken_symbolic_link(tmp_path):
    link = tmp_path / "L0001D.ply"
    link.symlink_to(tmp_path / "gone.ply")
    expect(ScanReadError, link, "broken symbolic link")


@pytest.mark.parametrize(
    "name, shown", [("scan.xyz", "'.xyz'"), ("scan", "'(no suffix)'"), ("a.ply.gz", "'.gz'")]
)
def test_unknown_suffix(tmp_path, name, shown):
    path = tmp_path / name
    path.write_text("ply\n")
    expect(ScanReadError, path, re.escape(f"unknown scan format {shown}"))


@pytest.mark.parametrize("suffix", [".ply", ".stl", ".obj"])
def test_empty_file(tmp_path, suffix):
    path = tmp_path / f"empty{suffix}"
    path.touch()
    expect(ScanReadError, path, r"empty file \(0 bytes\)")


def test_truncated_binary_says_expected_and_found_bytes(tmp_path):
    path = good_ply(tmp_path / "t.ply")
    kept = 100
    row_bytes = 6 * 4 + 3  # six float32 and three uchar
    path.write_bytes(path.read_bytes()[: header_size(path) + kept])

    expect(
        ScanReadError,
        path,
        f"truncated file.*{N_POINTS} vertex.*{N_POINTS * row_bytes:,} bytes.*has {kept} bytes",
    )


def test_truncated_mesh_faces(tmp_path):
    vertices = np.array(
        [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], dtype=[("x", "f4"), ("y", "f4"), ("z", "f4")]
    )
    faces = np.empty(2, dtype=[("vertex_indices", "i4", (3,))])
    faces["vertex_indices"] = [[0, 1, 2], [1, 3, 2]]
    path = tmp_path / "mesh.ply"
    PlyData([PlyElement.describe(vertices, "vertex"), PlyElement.describe(faces, "face")]).write(str(path))
    path.write_bytes(path.read_bytes()[:-5])

    expect(ScanReadError, path, "truncated file: the data ends in row 1 of 2 of 'face'")


def test_truncated_ascii(tmp_path):
    path = good_ply(tmp_path / "a.ply", binary=False)
    lines = path.read_text().splitlines(keepends=True)
    path.write_text("".join(lines[:-3]))
    expect(ScanReadError, path, f"truncated file: the data ends in row {N_POINTS - 3} of {N_POINTS}")


def test_ascii_header_announcing_far_more_rows_than_the_file_holds(tmp_path):
    path = good_ply(tmp_path / "a.ply", binary=False)
    text = path.read_text().replace(f"element vertex {N_POINTS}", "element vertex 1000000000000")
    path.write_text(text)
    expect(ScanReadError, path, "truncated file: .* at least 18,000,000,000,000 bytes of ASCII data")


def test_malformed_ascii_value(tmp_path):
    path = good_ply(tmp_path / "a.ply", binary=False)
    text = path.read_text()
    path.write_text(text[: header_size(path)] + "1.0 abc" + text[header_size(path) + 3 :])
    expect(ScanReadError, path, "bad PLY data .*malformed input")


@pytest.mark.parametrize(
    "content, problem",
    [
        (b"\x00\x01binary garbage" * 50, "not a PLY file"),
        (b"solid cube\nfacet normal 0 0 1\n", "not a PLY file"),
        (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + b"\x00" * 64, "no 'end_header'"),
        (b"ply\nformat fancy 1.0\nelement vertex 1\nproperty float x\nend_header\n", "bad PLY header"),
        (b"ply\nformat ascii 1.0\nelement vertex 1\nproperty floot x\nend_header\n0\n", "bad PLY header"),
        (b"ply\nformat ascii 1.0\ncomment caf\xe9\nelement vertex 1\nend_header\n", "not ASCII text"),
    ],
)
def test_wrong_or_garbage_header(tmp_path, content, problem):
    path = tmp_path / "g.ply"
    path.write_bytes(content)
    expect(ScanReadError, path, problem)


def test_no_vertex_element(tmp_path):
    path = tmp_path / "p.ply"
    points = np.zeros(3, dtype=[("x", "f4"), ("y", "f4"), ("z", "f4")])
    PlyData([PlyElement.describe(points, "point")]).write(str(path))
    expect(ScanReadError, path, r"no 'vertex' element \(the file has: point\)")


def test_vertex_without_z(tmp_path):
    path = vertex_ply(tmp_path / "p.ply", "x y intensity")
    expect(ScanReadError, path, r"lacks z \(it has: x, y, intensity\)")


def test_zero_points(tmp_path):
    path = vertex_ply(tmp_path / "p.ply", rows=np.zeros((0, 3)))
    expect(InvalidScanError, path, "zero points")


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("binary", [True, False])
def test_non_finite_coordinates(tmp_path, bad, binary):
    rows = np.ones((5, 3))
    rows[3, 1] = bad
    path = vertex_ply(tmp_path / "p.ply", rows=rows, text=not binary)
    expect(InvalidScanError, path, r"1 of 5 points have NaN or infinite coordinates \(first at index 3\)")


def test_zero_length_normals(tmp_path):
    rows = np.column_stack([np.ones((4, 3)), np.tile([0.0, 0.0, 1.0], (4, 1))])
    rows[2, 3:] = 0.0
    path = vertex_ply(tmp_path / "p.ply", "x y z nx ny nz", rows=rows)
    expect(InvalidScanError, path, "1 of 4 normals are zero-length")


def test_file_over_the_default_limit_is_refused_before_reading(tmp_path):
    path = tmp_path / "huge.ply"
    with path.open("wb") as stream:
        stream.truncate(5 * 2**30)  # sparse: costs no disk
    expect(ScanReadError, path, f"file too large: {5 * 2**30:,} bytes, the limit is {MAX_SCAN_BYTES:,} bytes")


def test_file_over_a_given_limit(tmp_path):
    path = good_ply(tmp_path / "p.ply")
    size = path.stat().st_size
    expect(ScanReadError, path, f"file too large: {size:,} bytes", max_bytes=size - 1)
    assert read_scan(path, max_bytes=size).n_points == N_POINTS
    with pytest.raises(ParameterError, match="max_bytes"):
        read_scan(path, max_bytes=0)


@pytest.mark.parametrize("suffix", [".stl", ".obj"])
def test_garbage_mesh_files(tmp_path, suffix):
    path = tmp_path / f"m{suffix}"
    path.write_bytes(b"\x13garbage that is no mesh\n" * 20)
    expect(ScanReadError, path, "no triangles|cannot read")


def test_mesh_with_a_face_out_of_range(tmp_path):
    path = tmp_path / "m.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    expect(ScanReadError, path, "cannot read the OBJ mesh .*out of bounds")
