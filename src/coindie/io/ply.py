"""PLY scans through plyfile: read point clouds and meshes in any PLY encoding, write the Riedones3D format.

Reading checks the header before the data, so that a short, foreign or incomplete file gets a precise
message (expected versus found bytes, missing ``vertex`` element or ``x``/``y``/``z``) instead of a
parser error deep in a row. Extra vertex properties and extra elements are ignored.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.lib.recfunctions import structured_to_unstructured
from numpy.typing import DTypeLike, NDArray
from plyfile import (
    PlyData,
    PlyElement,
    PlyElementParseError,
    PlyListProperty,
    PlyParseError,
    PlyProperty,
)

from coindie.errors import InvalidScanError, ParameterError, ScanReadError
from coindie.ids import FaceId, face_id_of
from coindie.scan import Scan, normal_colors

#: The header must end within this many bytes (a guard against scanning a huge garbage file byte by byte).
HEADER_LIMIT = 2**20

POSITION = ("x", "y", "z")
NORMAL = ("nx", "ny", "nz")
COLOR = ("red", "green", "blue")
#: Names of the face list property, in order of preference (the PLY convention and a common variant).
FACE_LISTS = ("vertex_indices", "vertex_index")


@dataclass(frozen=True)
class _Header:
    ply: PlyData  # elements with their counts and properties, no data
    size: int  # bytes up to and including the ``end_header`` line


def read_ply(path: str | Path, face_id: FaceId | None = None) -> Scan:
    """Read a PLY point cloud or mesh (binary little/big endian or ASCII).

    A PLY with faces is a mesh: its own normals are kept if it has them, otherwise each vertex gets the
    area-weighted normal of its faces (vertices on no face of non-zero area are dropped, see
    ``coindie.io.mesh.mesh_scan``).
    """
    path = Path(path)
    header = _read_header(path)
    _check_vertex_element(header.ply, path)
    _check_data_size(header, path)
    ply = _read_data(path, header.ply)
    return _scan_from(ply, face_id or face_id_of(path), path)


def write_ply(
    path: str | Path,
    scan: Scan,
    *,
    binary: bool = True,
    byte_order: Literal["<", ">"] = "<",
    dtype: DTypeLike = np.float32,
) -> Path:
    """Write a scan as the Riedones3D files are: ``x y z nx ny nz red green blue`` (colours uchar).

    The colours are computed from the normals (``normal_colors``) when the scan has normals, as in the
    dataset; otherwise the scan's own colours are written, if any. ``dtype`` (float32 or float64) is used
    for coordinates and normals. ``binary=False`` writes ASCII (``byte_order`` is then irrelevant).
    """
    path = Path(path)
    if byte_order not in ("<", ">"):
        raise ParameterError(f"byte_order must be '<' or '>', got {byte_order!r}")
    records = _vertex_records(scan, _checked_float_dtype(dtype))
    ply = PlyData([PlyElement.describe(records, "vertex")], text=not binary, byte_order=byte_order)
    if binary:
        ply.write(str(path))
    else:
        _write_ascii(path, ply.header, records)
    return path


# --- reading: header ------------------------------------------------------------------------------------


def _read_header(path: Path) -> _Header:
    head = _read_head(path)
    if not head.startswith(b"ply"):
        raise ScanReadError(f"not a PLY file: it starts with {head[:12]!r}, not 'ply'", path)
    if b"end_header" not in head:
        raise ScanReadError(f"bad PLY header: no 'end_header' line in the first {len(head):,} bytes", path)
    stream = io.BytesIO(head)
    try:
        # plyfile has no public header-only parser; this static method is what PlyData.read calls first.
        ply = PlyData._parse_header(stream)
    except UnicodeDecodeError:
        raise ScanReadError("bad PLY header: it is not ASCII text", path) from None
    except (PlyParseError, ValueError) as error:
        raise ScanReadError(f"bad PLY header ({error})", path) from None
    return _Header(ply, stream.tell())


def _read_head(path: Path) -> bytes:
    try:
        with path.open("rb") as stream:
            return stream.read(HEADER_LIMIT)
    except OSError as error:
        raise ScanReadError(f"cannot open the file ({error.strerror})", path) from None


def _check_vertex_element(ply: PlyData, path: Path) -> None:
    names = [element.name for element in ply.elements]
    if "vertex" not in names:
        raise ScanReadError(f"no 'vertex' element (the file has: {', '.join(names) or 'no elements'})", path)
    vertex = ply["vertex"]
    properties = [prop.name for prop in vertex.properties]
    missing = [axis for axis in POSITION if axis not in properties]
    if missing:
        has = ", ".join(properties) or "no properties"
        raise ScanReadError(f"the 'vertex' element lacks {', '.join(missing)} (it has: {has})", path)
    if vertex.count == 0:
        raise InvalidScanError("the scan has zero points (the header says 0 vertices)", path)


def _check_data_size(header: _Header, path: Path) -> None:
    """A file shorter than its header announces is truncated: say by how much, before reading it.

    This also keeps a lying header (a billion vertices in a small file) from allocating memory.
    """
    needed, exact = _announced_bytes(header.ply)
    found = path.stat().st_size - header.size
    if found < needed:
        counts = ", ".join(f"{element.count:,} {element.name}" for element in header.ply.elements)
        bound = "" if exact else "at least "
        kind = "ASCII " if header.ply.text else ""
        raise ScanReadError(
            f"truncated file: the header announces {counts}, i.e. {bound}{needed:,} bytes of {kind}data, "
            f"but the file has {found:,} bytes after the header",
            path,
        )


def _announced_bytes(ply: PlyData) -> tuple[int, bool]:
    """Bytes of data the header announces: exact for binary elements without lists, else a lower bound."""
    total, exact = 0, not ply.text
    for element in ply.elements:
        total += element.count * sum(_min_bytes(prop, ply) for prop in element.properties)
        exact = exact and not any(isinstance(prop, PlyListProperty) for prop in element.properties)
    return total, exact


def _min_bytes(prop: PlyProperty, ply: PlyData) -> int:
    if ply.text:
        return 2  # at least one character and a separator or line end per value (or list length)
    if isinstance(prop, PlyListProperty):
        return np.dtype(prop.list_dtype(ply.byte_order)[0]).itemsize  # an empty list holds only its length
    return np.dtype(prop.dtype(ply.byte_order)).itemsize


# --- reading: data --------------------------------------------------------------------------------------


def _read_data(path: Path, header: PlyData) -> PlyData:
    triangles = _triangle_lists(header)
    try:
        try:
            return PlyData.read(str(path), known_list_len=triangles)
        except PlyElementParseError as error:
            if not triangles or error.message != "unexpected list length":
                raise
            return PlyData.read(str(path))  # not all triangles: plyfile's slower row-by-row read
    except UnicodeDecodeError:
        raise ScanReadError("bad PLY data: the ASCII body is not ASCII text", path) from None
    except PlyElementParseError as error:
        raise ScanReadError(_data_problem(error), path) from None
    except (PlyParseError, ValueError) as error:
        raise ScanReadError(f"bad PLY data ({error})", path) from None
    except OSError as error:
        raise ScanReadError(f"cannot read the file ({error.strerror})", path) from None


def _data_problem(error: PlyElementParseError) -> str:
    element = error.element
    if error.message == "early end-of-file" and element is not None and error.row is not None:
        return f"truncated file: the data ends in row {error.row:,} of {element.count:,} of '{element.name}'"
    return f"bad PLY data ({error})"


def _triangle_lists(header: PlyData) -> dict[str, dict[str, int]]:
    """Face lists assumed to hold 3 indices, which lets plyfile memory-map them (much faster)."""
    if header.text or "face" not in header:
        return {}
    lists = {prop.name: 3 for prop in header["face"].properties if isinstance(prop, PlyListProperty)}
    return {"face": lists} if lists else {}


def _scan_from(ply: PlyData, face_id: FaceId, path: Path) -> Scan:
    vertex = ply["vertex"].data
    points = _columns(vertex, POSITION)
    normals = _columns(vertex, NORMAL) if _has(vertex, NORMAL) else None
    colors = _colors(vertex)
    faces = _faces(ply)
    if faces is not None and normals is None:
        from coindie.io.mesh import mesh_scan

        return mesh_scan(points, faces, colors=colors, face_id=face_id, path=path)
    return Scan(points=points, normals=normals, colors=colors, id=face_id, path=path)


def _has(data: np.ndarray, names: tuple[str, ...]) -> bool:
    return all(name in data.dtype.names for name in names)


def _columns(data: np.ndarray, names: tuple[str, ...]) -> NDArray[np.float64]:
    return structured_to_unstructured(data[list(names)], dtype=np.float64)


def _colors(vertex: np.ndarray) -> NDArray[np.uint8] | None:
    """RGB as uint8; float colours in [0, 1] are scaled to 0-255, other integers clipped."""
    if not _has(vertex, COLOR):
        return None
    rgb = _columns(vertex, COLOR)
    if np.issubdtype(vertex.dtype["red"], np.floating) and rgb.size and np.nanmax(rgb) <= 1.0:
        rgb = rgb * 255.0
    return np.clip(np.rint(np.nan_to_num(rgb)), 0, 255).astype(np.uint8)


def _faces(ply: PlyData) -> np.ndarray | None:
    """The face index lists (an (F, 3) array, or an object array of ragged lists), if the file has faces."""
    if "face" not in ply or ply["face"].count == 0:
        return None
    data = ply["face"].data
    names = [prop.name for prop in ply["face"].properties if isinstance(prop, PlyListProperty)]
    if not names:
        return None
    name = next((wanted for wanted in FACE_LISTS if wanted in names), names[0])
    return data[name]


# --- writing --------------------------------------------------------------------------------------------


def _checked_float_dtype(dtype: DTypeLike) -> np.dtype:
    try:
        checked = np.dtype(dtype)
    except TypeError:
        checked = None
    if checked not in (np.dtype(np.float32), np.dtype(np.float64)):
        raise ParameterError(f"dtype must be float32 or float64, got {dtype!r}")
    return checked


def _vertex_records(scan: Scan, dtype: np.dtype) -> np.ndarray:
    colors = normal_colors(scan.normals) if scan.normals is not None else scan.colors
    fields = [(name, dtype) for name in POSITION]
    fields += [(name, dtype) for name in NORMAL] if scan.normals is not None else []
    fields += [(name, np.uint8) for name in COLOR] if colors is not None else []
    records = np.empty(scan.n_points, dtype=fields)
    _fill(records, POSITION, scan.points)
    if scan.normals is not None:
        _fill(records, NORMAL, scan.normals)
    if colors is not None:
        _fill(records, COLOR, colors)
    return records


def _fill(records: np.ndarray, names: tuple[str, ...], values: np.ndarray) -> None:
    for column, name in enumerate(names):
        records[name] = values[:, column]


def _write_ascii(path: Path, header: str, records: np.ndarray) -> None:
    """plyfile's header, then the rows formatted in one pass.

    plyfile writes ASCII with one ``np.savetxt`` call per row (~45 us a point: 9 s for 200k points);
    formatting all rows at once takes ~2 us a point. ``%.9g`` and ``%.17g`` round-trip float32 and float64.
    """
    formats = {np.dtype(np.float32): "%.9g", np.dtype(np.float64): "%.17g", np.dtype(np.uint8): "%d"}
    line = " ".join(formats[records.dtype[name]] for name in records.dtype.names)
    with path.open("w", encoding="ascii", newline="\n") as stream:
        stream.write(header + "\n")
        stream.write("".join(line % row + "\n" for row in records.tolist()))
