"""The scan of one coin face: points and normals in millimetres, in the scanner's frame."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import FloatArray
from coindie.errors import InvalidScanError
from coindie.ids import Face, FaceId, parse_face_id

#: A normal shorter than this is treated as missing (zero-length normals are bad input).
MIN_NORMAL_LENGTH = 1e-8


@dataclass(frozen=True, eq=False)
class Scan:
    """One scanned coin face.

    Attributes:
        points: (N, 3) float64 coordinates in mm.
        normals: (N, 3) float64 unit normals, or ``None`` when the file had none.
        colors: (N, 3) uint8 RGB, or ``None``.
        id: the face id (``L0001D``) or a free id taken from the file name.
        path: the file it was read from, if any (used in error messages).

    The constructor validates: at least one point, finite coordinates, matching shapes, and normals of
    non-zero length (they are re-normalised to unit length).
    """

    points: FloatArray
    normals: FloatArray | None = None
    colors: NDArray[np.uint8] | None = None
    id: FaceId = field(default_factory=lambda: parse_face_id("scan"))
    path: Path | None = None

    def __post_init__(self) -> None:
        points = np.ascontiguousarray(self.points, dtype=np.float64)
        where = self.path
        if points.ndim != 2 or points.shape[1] != 3:
            raise InvalidScanError(f"points must be an (N, 3) array, got shape {points.shape}", where)
        if len(points) == 0:
            raise InvalidScanError("the scan has zero points", where)
        bad = ~np.isfinite(points).all(axis=1)
        if bad.any():
            raise InvalidScanError(
                f"{int(bad.sum())} of {len(points)} points have NaN or infinite coordinates "
                f"(first at index {int(np.flatnonzero(bad)[0])})",
                where,
            )
        object.__setattr__(self, "points", points)
        if self.normals is not None:
            object.__setattr__(self, "normals", _checked_normals(self.normals, len(points), where))
        if self.colors is not None:
            colors = np.ascontiguousarray(self.colors)
            if colors.shape != (len(points), 3):
                raise InvalidScanError(f"colors must be ({len(points)}, 3), got {colors.shape}", where)
            object.__setattr__(self, "colors", colors.astype(np.uint8, copy=False))
        if isinstance(self.id, str):
            object.__setattr__(self, "id", parse_face_id(self.id))

    @property
    def n_points(self) -> int:
        return len(self.points)

    @property
    def has_normals(self) -> bool:
        return self.normals is not None

    @property
    def face(self) -> Face:
        return self.id.face

    def transformed(self, T_new_old: FloatArray) -> Scan:
        """The same scan with points and normals mapped by the rigid transform ``T_new_old``."""
        T = np.asarray(T_new_old, dtype=np.float64)
        if T.shape != (4, 4) or not np.isfinite(T).all():
            raise InvalidScanError(f"cannot transform a scan by a non-finite or non-4x4 matrix {T.shape}")
        R, t = T[:3, :3], T[:3, 3]
        normals = None if self.normals is None else self.normals @ R.T
        points = self.points @ R.T + t
        if not np.isfinite(points).all():  # finite inputs can still overflow
            return replace(self, points=points, normals=normals)  # validation names the problem
        return self._checked_already(points=points, normals=normals)

    def subset(self, index: NDArray[np.integer] | NDArray[np.bool_]) -> Scan:
        """The scan restricted to some points (an index array or a boolean mask)."""
        points = self.points[index]
        if len(points) == 0:
            raise InvalidScanError("the subset has zero points", self.path)
        return self._checked_already(
            points=points,
            normals=None if self.normals is None else self.normals[index],
            colors=None if self.colors is None else self.colors[index],
        )

    def _checked_already(self, **changes: object) -> Scan:
        """A copy with ``changes`` that keep a valid scan valid (rows of it, a rigid motion of it),
        without the constructor's checks: they cost more than the change on large scans."""
        new = object.__new__(Scan)
        new.__dict__.update(self.__dict__)
        for name, value in changes.items():
            object.__setattr__(new, name, np.ascontiguousarray(value) if value is not None else None)
        return new

    def with_normals(self, normals: FloatArray) -> Scan:
        return replace(self, normals=normals)


def _checked_normals(normals: FloatArray, n_points: int, where: Path | None) -> FloatArray:
    normals = np.asarray(normals, dtype=np.float64)
    if normals.shape != (n_points, 3):
        raise InvalidScanError(f"normals must be ({n_points}, 3), got {normals.shape}", where)
    length = np.linalg.norm(normals, axis=1)
    bad = ~(np.isfinite(length) & (length > MIN_NORMAL_LENGTH))
    if bad.any():
        raise InvalidScanError(
            f"{int(bad.sum())} of {n_points} normals are zero-length or not finite "
            f"(first at index {int(np.flatnonzero(bad)[0])})",
            where,
        )
    return normals / length[:, None]


def normal_colors(normals: FloatArray) -> NDArray[np.uint8]:
    """Colours from normals, as in the Riedones3D files: RGB = (n + 1) / 2 * 255."""
    return np.clip(np.rint((np.asarray(normals) + 1.0) * 127.5), 0, 255).astype(np.uint8)
