"""Meshes as scans: STL and OBJ through trimesh, and the vertex normals of any triangle mesh.

A mesh scan keeps its vertices as points. Each vertex gets the **area-weighted** mean of the normals of
the faces around it. trimesh's own ``Trimesh.vertex_normals`` weights faces by their corner angle at the
vertex (Thürrner & Wüthrich 1998), which gives a sliver triangle (common along the borders of scanner
meshes) as much say as a large one; weighting by area follows the surface that each face covers.

trimesh takes ~0.6 s to import, more than the rest of ``coindie info`` on a 200k-point scan, so it is
imported only to load STL/OBJ files or to triangulate polygons; the area-weighted normals of a PLY mesh
are a few lines of numpy (``area_weighted_normals``).

An STL file stores each triangle's three corners anew, so its vertices are merged here
(``merge_duplicate_vertices``) rather than by trimesh's ``process=True``: trimesh rounds every coordinate and
hashes the rounded rows, 1.6 s of the 2.5 s a scanner's STL face of 380,000 vertices took to read, where
the corners of one vertex, written from one float, are equal to the bit.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import FloatArray
from coindie.errors import InvalidScanError, ScanReadError
from coindie.ids import FaceId, face_id_of
from coindie.scan import Scan


def read_mesh(path: str | Path, face_id: FaceId | None = None) -> Scan:
    """Read an STL or OBJ mesh: vertices (duplicates merged) with area-weighted unit vertex normals."""
    path = Path(path)
    vertices, faces = _load(path)
    if len(faces) == 0:
        raise ScanReadError(f"the {path.suffix.lstrip('.').upper()} file holds no triangles", path)
    vertices, faces = merge_duplicate_vertices(vertices, faces)
    return mesh_scan(vertices, faces, face_id=face_id or face_id_of(path), path=path)


def merge_duplicate_vertices(
    vertices: FloatArray, faces: NDArray[np.integer]
) -> tuple[FloatArray, NDArray[np.int64]]:
    """The distinct vertices, in the order they first appear, and the faces re-indexed onto them.

    Vertices are equal when their coordinates are (``-0.0`` and ``0.0`` alike). Each row is hashed to one
    64-bit key and the keys sorted, under half the time of sorting the rows themselves; a collision of
    keys between different rows is detected, and the rows are then sorted whole."""
    points = np.ascontiguousarray(vertices, dtype=np.float64) + 0.0  # + 0.0: -0.0 becomes 0.0
    bits = points.view(np.uint64).reshape(-1, 3)
    keys = _mixed(_mixed(_mixed(bits[:, 0]) ^ bits[:, 1]) ^ bits[:, 2])
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    if not np.array_equal(points[first[inverse]], points, equal_nan=True):  # two rows share a key
        _, first, inverse = np.unique(points, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    order = np.argsort(first, kind="stable")  # first appearance, as the file has them
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return points[first[order]], rank[inverse][np.asarray(faces, dtype=np.int64)]


def mesh_scan(
    points: FloatArray,
    faces: np.ndarray,
    *,
    colors: NDArray[np.uint8] | None = None,
    face_id: FaceId,
    path: Path | None = None,
) -> Scan:
    """A scan from mesh vertices and faces, with area-weighted normals.

    ``faces`` is an (F, 3) index array or a ragged sequence of polygons (fan-triangulated by trimesh).
    Vertices that lie on no face of non-zero area (unused or only in degenerate faces) have no normal and
    are dropped; vertices with non-finite coordinates are kept so that ``Scan`` refuses them by name.
    """
    points = np.asarray(points, dtype=np.float64)
    triangles = _triangles(faces, len(points), path)
    normals = area_weighted_normals(points, triangles)
    keep = ~np.isfinite(points).all(axis=1) | np.any(normals != 0, axis=1)
    if not keep.all():
        points, normals = points[keep], normals[keep]
        colors = None if colors is None else colors[keep]
    return Scan(points=points, normals=normals, colors=colors, id=face_id, path=path)


def area_weighted_normals(vertices: FloatArray, triangles: NDArray[np.integer]) -> FloatArray:
    """Unit vertex normals: the sum of the adjacent faces' normals weighted by face area.

    A vertex whose faces are all degenerate (zero area) gets a zero vector, which ``Scan`` rejects.
    """
    corners = vertices[triangles]
    # the cross product of two edges has length 2 x area: summing it weights each face by its area
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    corner_of = triangles.ravel()  # bincount, not np.add.at: a tenth of the time on a scanner's mesh
    summed = np.column_stack(
        [np.bincount(corner_of, np.repeat(cross[:, k], 3), minlength=len(vertices)) for k in range(3)]
    )
    length = np.linalg.norm(summed, axis=1, keepdims=True)
    return np.divide(summed, length, out=np.zeros_like(summed), where=length > 0)


def _mixed(x: NDArray[np.uint64]) -> NDArray[np.uint64]:
    """splitmix64's finaliser (Steele et al. 2014): every input bit moves about half the output bits.
    A float32 coordinate read as float64 has 29 zero low bits, which a plain product keeps zero."""
    with np.errstate(over="ignore"):
        x = (x ^ (x >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        x = (x ^ (x >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return x ^ (x >> np.uint64(31))


def _load(path: Path) -> tuple[FloatArray, NDArray[np.integer]]:
    """The file's vertices and triangles as written (an STL's corners unmerged)."""
    import trimesh

    kind = path.suffix.lower().lstrip(".")
    try:
        with path.open("rb") as stream:
            if kind == "stl":  # the loader alone: a Trimesh built and copied from it cost 0.3 s a face
                loaded = trimesh.exchange.stl.load_stl(stream)
                return np.asarray(loaded["vertices"]), np.asarray(loaded["faces"])
            mesh = trimesh.load_mesh(stream, file_type=kind, process=False)
    except OSError as error:
        raise ScanReadError(f"cannot read the file ({error.strerror})", path) from None
    except Exception as error:  # trimesh's loaders raise many types (ValueError, KeyError, IndexError, ...)
        reason = str(error).splitlines()[0] if str(error) else type(error).__name__
        raise ScanReadError(f"cannot read the {kind.upper()} mesh ({reason})", path) from None
    if not isinstance(mesh, trimesh.Trimesh):
        raise ScanReadError(f"the {kind.upper()} file holds no triangle mesh", path)
    return np.asarray(mesh.vertices), np.asarray(mesh.faces)


def _triangles(faces: np.ndarray, n_points: int, path: Path | None) -> NDArray[np.int64]:
    if faces.dtype == object:  # ragged polygons (plyfile's row-by-row read)
        import trimesh

        triangles = trimesh.geometry.triangulate_quads(list(faces), use_fan=True)
    else:
        triangles = np.asarray(faces, dtype=np.int64)
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    if len(triangles) == 0:
        raise InvalidScanError("the mesh has no triangles", path)
    bad = (triangles < 0) | (triangles >= n_points)
    if bad.any():
        index = int(triangles[bad][0])
        raise InvalidScanError(f"a face refers to vertex {index}, but the mesh has {n_points} vertices", path)
    return triangles
