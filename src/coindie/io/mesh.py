"""Meshes as scans: STL and OBJ through trimesh, and the vertex normals of any triangle mesh.

A mesh scan keeps its vertices as points. Each vertex gets the **area-weighted** mean of the normals of
the faces around it. trimesh's own ``Trimesh.vertex_normals`` weights faces by their corner angle at the
vertex (Thürrner & Wüthrich 1998), which gives a sliver triangle (common along the borders of scanner
meshes) as much say as a large one; weighting by area follows the surface that each face covers.

trimesh takes ~0.6 s to import, more than the rest of ``coindie info`` on a 200k-point scan, so it is
imported only to load STL/OBJ files or to triangulate polygons; the area-weighted normals of a PLY mesh
are a few lines of numpy (``area_weighted_normals``).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import FloatArray
from coindie.errors import InvalidScanError, ScanReadError
from coindie.ids import FaceId, face_id_of
from coindie.scan import Scan

if TYPE_CHECKING:
    import trimesh


def read_mesh(path: str | Path, face_id: FaceId | None = None) -> Scan:
    """Read an STL or OBJ mesh: vertices (duplicates merged) with area-weighted unit vertex normals."""
    path = Path(path)
    mesh = _load(path)
    if len(mesh.faces) == 0:
        raise ScanReadError(f"the {path.suffix.lstrip('.').upper()} file holds no triangles", path)
    return mesh_scan(mesh.vertices, mesh.faces, face_id=face_id or face_id_of(path), path=path)


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
    summed = np.zeros_like(vertices, dtype=np.float64)
    for corner in range(3):
        np.add.at(summed, triangles[:, corner], cross)
    length = np.linalg.norm(summed, axis=1, keepdims=True)
    return np.divide(summed, length, out=np.zeros_like(summed), where=length > 0)


def _load(path: Path) -> trimesh.Trimesh:
    import trimesh

    kind = path.suffix.lower().lstrip(".")
    try:
        with path.open("rb") as stream:
            mesh = trimesh.load_mesh(stream, file_type=kind, process=True)
    except OSError as error:
        raise ScanReadError(f"cannot read the file ({error.strerror})", path) from None
    except Exception as error:  # trimesh's loaders raise many types (ValueError, KeyError, IndexError, ...)
        reason = str(error).splitlines()[0] if str(error) else type(error).__name__
        raise ScanReadError(f"cannot read the {kind.upper()} mesh ({reason})", path) from None
    if not isinstance(mesh, trimesh.Trimesh):
        raise ScanReadError(f"the {kind.upper()} file holds no triangle mesh", path)
    return mesh


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
