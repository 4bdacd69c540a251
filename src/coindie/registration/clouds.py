"""Shared geometry of the registration methods: input checks, point clouds with a search tree, rigid fits."""

from __future__ import annotations

import hashlib
import weakref
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike
from scipy.spatial import cKDTree

from coindie.arrays import FloatArray, IntArray
from coindie.errors import InvalidScanError
from coindie.scan import Scan

#: Fewer points than this cannot define a rigid transform with any redundancy.
MIN_POINTS = 10
#: Queries of fewer points run on one thread (scipy starts new threads on every parallel query: ~1 ms).
_PARALLEL_QUERY = 20_000


def as_scan(data: Scan | ArrayLike, role: str) -> Scan:
    """A Scan from a Scan or an (N, 3) array; a clear InvalidScanError naming the role otherwise."""
    if isinstance(data, Scan):
        scan = data
    else:
        try:
            scan = Scan(points=np.asarray(data, dtype=np.float64), id=role)
        except InvalidScanError as error:
            raise InvalidScanError(f"the {role} cloud is unusable: {error.problem}") from None
        except (TypeError, ValueError) as error:
            raise InvalidScanError(f"the {role} cloud is not an (N, 3) array of numbers: {error}") from None
    if scan.n_points < MIN_POINTS:
        raise InvalidScanError(
            f"the {role} cloud has {scan.n_points} points; registration needs at least {MIN_POINTS}",
            scan.path,
        )
    return scan


def canonical_permutation(points: FloatArray) -> IntArray:
    """The order that sorts points by (x, y, z), as ``np.lexsort(points.T[::-1])``: every method then sees
    the same input whatever the order of the file, so that a permutation of the points cannot change a
    result.

    Written out: a stable sort by x alone, then a lexicographic sort of only the points that share an x
    with another (a few thousand of a 0.05 mm grid's 190,000 float32 points). The full lexicographic sort
    took 28 ms a cloud, this one 5 ms, the same order.
    """
    order = np.argsort(points[:, 0], kind="stable")
    x = points[order, 0]
    tie = x[1:] == x[:-1]
    if tie.any():
        tied = np.zeros(len(order), dtype=bool)
        tied[1:] |= tie
        tied[:-1] |= tie
        at = np.flatnonzero(tied)  # runs of one x, each contiguous in the x order
        run = np.cumsum(np.concatenate([[True], ~tie]))[at]
        chosen = order[at]
        order[at] = chosen[np.lexsort((points[chosen, 2], points[chosen, 1], run))]
    return order


def canonical_order(scan: Scan) -> Scan:
    """The scan with its points in :func:`canonical_permutation` order."""
    return scan.subset(canonical_permutation(scan.points))


def with_normals(scan: Scan) -> Scan:
    """The scan itself if it has normals; otherwise normals by local PCA, turned out of the coin: up on
    the side the face's geometry says is up (its edge wall below, its relief raised:
    :func:`~coindie.io.orientation.face_up`), not the scanner's +z, which a scan in any pose does not keep."""
    if scan.normals is not None:
        return scan
    from coindie.io.orientation import face_up, turned_away_from_below
    from coindie.preprocess.normals import estimate_normals

    unsigned = estimate_normals(scan.points)
    return scan.with_normals(turned_away_from_below(scan.points, unsigned, face_up(scan.points, unsigned)))


def content_key(*arrays: FloatArray) -> bytes:
    """A 16-byte digest of the arrays' contents (SHA-256: about 0.6 ms per MB with CPU support).

    An array that owns its data and is read-only cannot change under us: its digest is kept for as long
    as the array lives (a project's worker freezes the faces it loads, and each pair asks for the keys of
    both faces three times: about 9 ms a pair of hashing the same 7 MB again)."""
    digest = hashlib.sha256()
    for array in map(np.asarray, arrays):
        digest.update(_array_digest(array))
        digest.update(repr((array.dtype.str, array.shape)).encode())
    return digest.digest()[:16]


#: Digests of read-only arrays by id, each with a weak reference that drops it when its array goes.
_DIGESTS: dict[int, tuple[weakref.ref[np.ndarray], bytes]] = {}


def _array_digest(array: np.ndarray) -> bytes:
    frozen = array.flags.owndata and not array.flags.writeable
    if frozen:
        known = _DIGESTS.get(id(array))
        if known is not None and known[0]() is array:
            return known[1]
    digest = hashlib.sha256(np.ascontiguousarray(array).tobytes()).digest()
    if frozen:
        key = id(array)
        _DIGESTS[key] = (weakref.ref(array, lambda _, key=key: _DIGESTS.pop(key, None)), digest)
    return digest


def freeze(scan: Scan) -> Scan:
    """Make the scan's points and normals read-only where they own their data (their content keys are
    then computed once); a view of another array is left as it is, and hashed each time."""
    for array in (scan.points, scan.normals):
        if array is not None and array.flags.owndata:
            array.setflags(write=False)
    return scan


def content_rng(points: FloatArray, seed: int) -> np.random.Generator:
    """A random generator seeded by ``seed`` and the points themselves: a cloud gets the same random draws
    whether it is the source or the target of a pair, so swapping them swaps the draws."""
    digest = hashlib.blake2b(np.ascontiguousarray(points).tobytes(), digest_size=8).digest()
    return np.random.default_rng([seed, int.from_bytes(digest, "little")])


@dataclass(frozen=True, eq=False)
class Cloud:
    """Points and unit normals (mm) with a k-d tree built on first use."""

    points: FloatArray
    normals: FloatArray
    known_key: bytes | None = field(default=None, repr=False)  # a content key already computed

    @classmethod
    def of(cls, scan: Scan) -> Cloud:
        scan = with_normals(scan)
        assert scan.normals is not None
        return cls(scan.points, scan.normals)

    @classmethod
    def canonical(cls, scan: Scan, key: bytes | None = None) -> Cloud:
        """The scan's points and normals (estimated when missing) in canonical order; ``key``, when
        given, identifies the scan's content (see :attr:`key`)."""
        scan = with_normals(scan)
        assert scan.normals is not None
        order = canonical_permutation(scan.points)
        return cls(np.take(scan.points, order, axis=0), np.take(scan.normals, order, axis=0), key)

    @cached_property
    def tree(self) -> cKDTree:
        return cKDTree(self.points)

    @cached_property
    def plane(self) -> Plane:
        """The face's best-fit plane, its up side towards the relief (see :class:`Plane`)."""
        return Plane.fit(self.points, self.normals)

    @cached_property
    def footprint(self) -> Footprint:
        """The face's outline in its best-fit plane (see :class:`Footprint`)."""
        return Footprint.of(self.points, self.normals, plane=self.plane)

    @cached_property
    def key(self) -> bytes:
        """A digest of the content: equal clouds have equal keys (per-face caches are keyed by it)."""
        return self.known_key if self.known_key is not None else content_key(self.points, self.normals)

    def subset(self, index: IntArray) -> Cloud:
        return Cloud(self.points[index], self.normals[index])

    def nearest(self, points: FloatArray, max_distance: float) -> tuple[FloatArray, IntArray]:
        """Distance to and index of the nearest point of this cloud (inf and len(points) beyond
        ``max_distance``)."""
        workers = -1 if len(points) >= _PARALLEL_QUERY else 1
        distances, index = self.tree.query(points, distance_upper_bound=max_distance, workers=workers)
        return distances, index


#: Points of a face that fit its footprint's plane (a regular subsample of larger clouds).
_FOOTPRINT_FIT_POINTS = 5000


@dataclass(frozen=True)
class Plane:
    """A face's best-fit plane: ``origin``, in-plane ``axes`` (2, 3) and ``up``, the side the normals
    face (towards the relief). A source face needs only its up direction (the tilt test), a target face
    its :class:`Footprint` too: the plane is kept apart so that a face seen only as a source never pays for
    the footprint's cells."""

    origin: FloatArray
    axes: FloatArray
    up: FloatArray

    @classmethod
    def fit(cls, points: FloatArray, normals: FloatArray | None = None) -> Plane:
        fit = points[:: -(-len(points) // _FOOTPRINT_FIT_POINTS)]
        origin = fit.mean(axis=0)
        _, _, vt = np.linalg.svd(fit - origin, full_matrices=False)
        up = vt[2]
        towards = normals.mean(axis=0) if normals is not None and len(normals) else np.array([0.0, 0.0, 1.0])
        if float(up @ towards) < 0:
            up = -up
        return cls(origin, vt[:2], up)


@dataclass(frozen=True, eq=False)
class Footprint:
    """Where a face is, seen from above: its best-fit plane (``origin``, in-plane ``axes`` (2, 3), ``up``
    towards the relief) and the cells of a square grid of side ``pixel`` over that plane that its points
    cover (one cell of dilation closes the gaps between the vertices of any scanner coarser than the grid's
    third). Tells which points of another face, once moved, lie over this one: the overlap of two faces as
    a share of area, whatever the scanner's noise, the flans' shapes or a bend."""

    origin: FloatArray
    axes: FloatArray
    up: FloatArray
    pixel: float
    corner: FloatArray  # (2,) in-plane coordinates of cell (0, 0)
    cells: np.ndarray  # (rows, cols) bool

    #: Side of the cells (mm): a coin's outline at a tenth of a flaw's size, several vertices of the
    #: coarsest scanner (0.15 mm) per cell.
    PIXEL_MM = 0.5

    @classmethod
    def of(
        cls,
        points: FloatArray,
        normals: FloatArray | None = None,
        pixel: float = PIXEL_MM,
        *,
        plane: Plane | None = None,
    ) -> Footprint:
        """The footprint of ``points`` over their best-fit plane (``plane`` when already fitted)."""
        from scipy import ndimage

        plane = Plane.fit(points, normals) if plane is None else plane
        origin, axes, up = plane.origin, plane.axes, plane.up
        uv = (points - origin) @ axes.T
        corner = uv.min(axis=0) - pixel
        index = np.floor((uv - corner) / pixel).astype(np.int64)
        shape = tuple(int(v) for v in index.max(axis=0) + 2)
        cells = np.zeros(shape, dtype=bool)
        cells[index[:, 0], index[:, 1]] = True
        cells = ndimage.binary_dilation(cells)
        return cls(origin, axes, up, pixel, corner, cells)

    def covers(self, points: FloatArray) -> np.ndarray:
        """(n,) whether each point (mm, this face's frame) lies over a covered cell."""
        index = np.floor(((points - self.origin) @ self.axes.T - self.corner) / self.pixel).astype(np.int64)
        rows, cols = self.cells.shape
        inside = (index[:, 0] >= 0) & (index[:, 0] < rows) & (index[:, 1] >= 0) & (index[:, 1] < cols)
        out = np.zeros(len(points), dtype=bool)
        out[inside] = self.cells[index[inside, 0], index[inside, 1]]
        return out
