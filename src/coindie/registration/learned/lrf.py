"""Local reference frames of surface patches, as DIP (Poiesi & Boscaini 2021) defines them, and the patches.

A patch is a fixed number of points drawn within ``radius`` mm of a centre. Its frame is:

- z: the patch normal, the eigenvector of the smallest eigenvalue of the patch's covariance, turned toward
  the centre's normal (or, without normals, toward the side the centre stands on, as DIP does);
- x: the weighted sum of the patch points' projections on the tangent plane, with weights that shrink with
  the distance to the centre and grow with the height above or below the plane (DIP's eq. 5);
- y = z x x (right-handed).

Rotating a patch rotates its frame, so the coordinates of the patch in its frame do not change: that is
what makes the descriptor of the patch rotation invariant. Everything is vectorised over patches (M, n, 3).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from coindie.arrays import FloatArray, IntArray

#: A tangent direction shorter than this (relative to its weights x radius) is taken as undefined.
_DEGENERATE = 1e-9


def patches(
    cloud_points: FloatArray,
    centres: FloatArray,
    radius: float,
    n_points: int,
    rng: np.random.Generator,
    *,
    tree: cKDTree | None = None,
) -> FloatArray:
    """(M, n_points, 3) points of ``cloud_points`` within ``radius`` of each centre.

    A patch with at least ``n_points`` points gets a random subset of them (no repeats); a smaller one gets
    all its points, then random repeats to fill the rest. A centre with no point in reach gets a patch
    collapsed on the centre. The draw depends only on ``rng`` and on which points (by index) are in reach,
    so a moved copy of the cloud, with the same rng, gets the same draw.
    """
    found = patch_indices(cloud_points, centres, radius, n_points, rng, tree=tree)
    gathered = cloud_points[np.maximum(found, 0)]
    empty = found[:, 0] < 0
    gathered[empty] = centres[empty, None, :]
    return gathered


def patch_indices(
    cloud_points: FloatArray,
    centres: FloatArray,
    radius: float,
    n_points: int,
    rng: np.random.Generator,
    *,
    tree: cKDTree | None = None,
) -> IntArray:
    """(M, n_points) indices into ``cloud_points`` of the patches of :func:`patches` (-1 for an empty one)."""
    tree = cKDTree(cloud_points) if tree is None else tree
    # Sorted lists make the draw independent of the tree's layout (hence of a rigid motion of the cloud).
    within = tree.query_ball_point(centres, radius, workers=-1, return_sorted=True)
    counts = np.fromiter(map(len, within), dtype=np.int64, count=len(within))
    if not counts.any():
        return np.full((len(counts), n_points), -1, dtype=np.int64)
    flat = np.concatenate([np.asarray(row, dtype=np.int64) for row in within])
    starts = np.cumsum(counts) - counts
    # Shuffle each patch's run of `flat` in place: sort by patch + a random key in [0, 0.5) (one float
    # sort is 9x faster than np.lexsort on the two keys; 0.5 keeps rounding from crossing patches).
    owner = np.repeat(np.arange(len(counts)), counts)
    shuffled = flat[np.argsort(owner + 0.5 * rng.random(len(flat)))]
    # Column j takes the j-th shuffled point while there is one, then a random point of the patch.
    column = np.arange(n_points)[None, :]
    repeats = np.floor(rng.random((len(counts), n_points)) * counts[:, None]).astype(np.int64)
    position = np.where(column < counts[:, None], column, repeats)
    drawn = shuffled[np.minimum(starts[:, None] + position, len(flat) - 1)]
    return np.where(counts[:, None] > 0, drawn, -1)


def local_frames(
    patch_points: FloatArray, centres: FloatArray, radius: float, normals: FloatArray | None = None
) -> FloatArray:
    """(M, 3, 3) rotations ``R_world_lrf`` whose columns are the x, y, z axes of each patch's frame."""
    offsets = patch_points - centres[:, None, :]
    z = _patch_normals(patch_points, offsets, normals)
    x = _tangent_axes(offsets, z, radius)
    return np.stack([x, np.cross(z, x), z], axis=2)


def to_local(patch_points: FloatArray, centres: FloatArray, frames: FloatArray) -> FloatArray:
    """(M, n, 3) coordinates of the patch points in their frames, centred on the centres (mm)."""
    return np.einsum("mni,mij->mnj", patch_points - centres[:, None, :], frames)


def canonical_patches(
    cloud_points: FloatArray,
    centres: FloatArray,
    normals: FloatArray | None,
    radius: float,
    n_points: int,
    rng: np.random.Generator,
    *,
    tree: cKDTree | None = None,
) -> FloatArray:
    """(M, n_points, 3) patches in their local frames, divided by ``radius`` (inside the unit ball): the
    input of the DIP network."""
    points = patches(cloud_points, centres, radius, n_points, rng, tree=tree)
    frames = local_frames(points, centres, radius, normals)
    return to_local(points, centres, frames) / radius


def _patch_normals(patch_points: FloatArray, offsets: FloatArray, normals: FloatArray | None) -> FloatArray:
    """Smallest-eigenvalue eigenvector of each patch's covariance, its sign fixed as the module says."""
    spread = patch_points - patch_points.mean(axis=1, keepdims=True)
    covariance = np.einsum("mni,mnj->mij", spread, spread) / patch_points.shape[1]
    _, vectors = np.linalg.eigh(covariance)  # eigenvalues in ascending order
    z = vectors[:, :, 0]
    # DIP's rule: the centre lies on the positive side, i.e. the patch points mostly below it.
    side = -np.einsum("mni,mi->m", offsets, z)
    if normals is not None:
        toward = np.einsum("mi,mi->m", normals, z)
        side = np.where(toward != 0, toward, side)
    return np.where(side[:, None] < 0, -z, z)


def _tangent_axes(offsets: FloatArray, z: FloatArray, radius: float) -> FloatArray:
    """Unit x axes: DIP's weighted tangent direction, with fallbacks so that flat, collinear or
    single-point patches still get a (then arbitrary but finite) orthonormal frame."""
    heights = np.einsum("mni,mi->mn", offsets, z)
    tangent = offsets - heights[:, :, None] * z[:, None, :]
    closeness = np.maximum(radius - np.linalg.norm(offsets, axis=2), 0.0) ** 2
    x = _weighted_direction(tangent, closeness * heights**2, radius)
    flat = ~np.isfinite(x[:, 0])  # no point off the plane: the distance weights alone
    x[flat] = _weighted_direction(tangent[flat], closeness[flat], radius)
    lost = ~np.isfinite(x[:, 0])  # symmetric or single-point patch: any tangent direction
    x[lost] = _any_perpendicular(z[lost])
    return x


def _weighted_direction(vectors: FloatArray, weights: FloatArray, radius: float) -> FloatArray:
    """Unit (M, 3) directions of sum_i w_i v_i; rows of NaN where that sum is too short to point anywhere."""
    total = np.einsum("mn,mni->mi", weights, vectors)
    length = np.linalg.norm(total, axis=1)
    defined = length > _DEGENERATE * weights.sum(axis=1) * radius
    return np.where(defined[:, None], total / np.where(defined, length, 1.0)[:, None], np.nan)


def _any_perpendicular(z: FloatArray) -> FloatArray:
    """Unit vectors perpendicular to each z: the world axis least aligned with z, made orthogonal."""
    axis = np.eye(3)[np.argmin(np.abs(z), axis=1)]
    x = axis - np.einsum("mi,mi->m", axis, z)[:, None] * z
    return x / np.linalg.norm(x, axis=1, keepdims=True)
