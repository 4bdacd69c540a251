"""Read one scan file, whatever its format: check the file, then hand it to the reader for its suffix."""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

from coindie.errors import ParameterError, ScanReadError
from coindie.ids import face_id_of
from coindie.io.orientation import outward_normals
from coindie.io.units import checked_unit, in_millimetres
from coindie.scan import Scan

#: Largest scan file read by default (2 GiB); checked on the file size before any byte is read.
MAX_SCAN_BYTES = 2 * 2**30

#: Suffixes of the scan formats read (compared in lower case).
SCAN_SUFFIXES = (".ply", ".stl", ".obj")


def read_scan(path: str | Path, *, max_bytes: int = MAX_SCAN_BYTES, unit: str | None = None) -> Scan:
    """Read a scan (PLY point cloud or mesh, STL, OBJ); its id is parsed from the file name.

    Coordinates are read in millimetres (:mod:`coindie.io.units`). With ``unit`` (``mm``, ``cm``, ``m``,
    ``um``, ``in``) they are scaled from it as declared. Without, coordinates written in metres or
    micrometres (a face 0.02 or 20,000 units across) are found by the face's size and rescaled, with a
    warning naming the file.

    Normals whose signs disagree (never oriented, or a mesh wound either way) are turned to point out of
    the coin (:func:`~coindie.io.orientation.outward_normals`); normals that agree are kept as written.

    Raises:
        ScanReadError: the file is missing, not a file, empty, too large, of an unknown format or unreadable.
        InvalidScanError: the file was read but its content is unusable (no points, NaN coordinates, ...).
    """
    path = Path(path)
    checked_unit(unit)
    suffix = checked_scan_file(path, max_bytes=max_bytes)
    face_id = face_id_of(path)
    if suffix == ".ply":
        from coindie.io.ply import read_ply

        scan = read_ply(path, face_id)
    else:
        from coindie.io.mesh import read_mesh  # imports trimesh (~0.5 s): only when a mesh is read

        scan = read_mesh(path, face_id)
    points, unit = in_millimetres(scan.points, path, unit)
    if unit != "mm":
        scan = replace(scan, points=points)
    if scan.normals is None:
        return scan
    normals = outward_normals(scan.points, scan.normals)
    return scan if normals is scan.normals else scan.with_normals(normals)


def is_scan_name(path: Path) -> bool:
    """Whether the file name has a known scan suffix (the file itself is not looked at)."""
    return path.suffix.lower() in SCAN_SUFFIXES


def checked_scan_file(path: Path, *, max_bytes: int = MAX_SCAN_BYTES) -> str:
    """Check that ``path`` is a readable scan file of a sane size; return its lower-case suffix."""
    if max_bytes <= 0:
        raise ParameterError(f"max_bytes must be a positive number of bytes, got {max_bytes}")
    suffix = path.suffix.lower()
    if suffix not in SCAN_SUFFIXES:
        known = ", ".join(SCAN_SUFFIXES)
        raise ScanReadError(f"unknown scan format {path.suffix or '(no suffix)'!r} (known: {known})", path)
    size = _file_size(path)
    if size == 0:
        raise ScanReadError("empty file (0 bytes)", path)
    if size > max_bytes:
        raise ScanReadError(f"file too large: {size:,} bytes, the limit is {max_bytes:,} bytes", path)
    return suffix


def _file_size(path: Path) -> int:
    if path.is_symlink() and not path.exists():
        raise ScanReadError(f"broken symbolic link (to {os.readlink(path)})", path)
    if not path.exists():
        raise ScanReadError("no such file", path)
    if path.is_dir():
        raise ScanReadError("is a directory, not a scan file", path)
    if not path.is_file():
        raise ScanReadError("not a regular file", path)
    try:
        return path.stat().st_size
    except OSError as error:
        raise ScanReadError(f"cannot read the file ({error.strerror})", path) from None
