"""Cloud-to-cloud distance histograms of a registered pair (Riedones3D, section 3.2.2).

Once two faces are aligned, faces struck by the same die lie within a few hundredths of a millimetre of each
other over the whole design, faces of different dies do not. The paper summarises this by the histogram of
nearest-neighbour distances from the source to the target: both clouds grid-sampled (source 0.1 mm, target
0.05 mm in the paper's text; the authors' code swaps them), distances over 0.6 mm dropped (they come from
parts that do not overlap, not from the die), only points whose normal is within 1 rad of the face's main
normal (the rim and the steep flanks carry scanner noise, not the die's design), and
``np.histogram(bins=70, range=(0, 0.6), density=True)``. The symmetric variant averages the histograms of
both directions.

Per-face work (grid sampling, the normal filter, the k-d tree) depends only on the face and the settings: it
is kept in a small cache keyed by the face's content, so that scoring many sources against one target pays
for the target once.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from functools import cached_property
from typing import Any

import numpy as np
from scipy.spatial import cKDTree

from coindie.arrays import FloatArray
from coindie.caches import LRUCache
from coindie.errors import ParameterError
from coindie.params import Configurable, param
from coindie.scan import Scan

#: Faces kept ready by default (sampled points and k-d tree): a 0.05 mm face of 150k points takes ~10 MB.
FACE_CACHE_SIZE = 16


@dataclass(frozen=True)
class HistogramSettings(Configurable):
    """How a registered pair becomes a histogram; the defaults are the paper's.

    Attributes:
        bins: number of histogram bins (paper: 70).
        max_distance_mm: histogram range 0..max (mm); larger distances are dropped (paper: 0.6).
        max_normal_angle_rad: points whose normal is farther than this from the face's main normal are left
            out (paper: 1 rad).
        source_grid_mm: grid-sampling cell of the source (paper's text: 0.1 mm; the authors' code: 0.05).
        target_grid_mm: grid-sampling cell of the target (paper's text: 0.05 mm; the authors' code: 0.1).
        symmetric: mean of the source->target and target->source histograms (the paper's text) instead of
            the source->target one only.
    """

    bins: int = param(70, doc="number of histogram bins", low=1)
    max_distance_mm: float = param(0.6, doc="histogram range 0..max", unit="mm", low=0.0, low_open=True)
    max_normal_angle_rad: float = param(
        1.0, doc="normals farther from the face's main normal are left out", unit="rad", low=0.0,
        low_open=True, high=float(np.pi),
    )  # fmt: skip
    source_grid_mm: float = param(
        0.1, doc="grid-sampling cell of the source", unit="mm", low=0.0, low_open=True
    )
    target_grid_mm: float = param(
        0.05, doc="grid-sampling cell of the target", unit="mm", low=0.0, low_open=True
    )
    symmetric: bool = param(False, doc="mean of both directions' histograms")

    @property
    def bin_edges(self) -> FloatArray:
        return np.linspace(0.0, self.max_distance_mm, self.bins + 1)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> HistogramSettings:
        known = {k: data[k] for k in cls.__dataclass_fields__ if k in data}
        return cls(**known)

    @classmethod
    def authors_code(cls, **changes: Any) -> HistogramSettings:
        """The grids of the authors' code (source 0.05 mm, target 0.1 mm) instead of the paper's text."""
        return cls(**{"source_grid_mm": 0.05, "target_grid_mm": 0.1, **changes})


@dataclass(frozen=True, eq=False)
class SampledFace:
    """A face grid-sampled at one cell size, restricted to the points facing its main normal."""

    points: FloatArray
    main_normal: FloatArray

    @cached_property
    def tree(self) -> cKDTree:
        return cKDTree(self.points)


#: Grid-sampled faces keyed by content and sampling settings.
FaceCache = LRUCache[bytes, SampledFace]

#: The cache of the calls that pass none.
_FACES: FaceCache = LRUCache(FACE_CACHE_SIZE)


def c2c_distances(
    source: Scan,
    target: Scan,
    T_target_source: FloatArray,
    settings: HistogramSettings | None = None,
    faces: FaceCache | None = None,
    *,
    up_to: float | None = None,
) -> FloatArray:
    """Nearest-neighbour distances (mm) from the kept source points, mapped into the target frame, to the
    kept target points; distances over ``settings.max_distance_mm`` are included (the histogram drops them).
    ``faces``: where the sampled faces are kept (the module's cache of ``FACE_CACHE_SIZE`` faces by default).
    ``up_to``: distances beyond it come back as ``inf`` (the search stops there: a third to half of the
    time on registered pairs, most of whose far points are ones the histogram drops).
    """
    settings = settings or HistogramSettings()
    T = _checked_transform(T_target_source)
    if up_to is not None and not up_to > 0:
        raise ParameterError(f"The 'up_to' parameter of c2c_distances must be > 0 mm or None. Got {up_to!r}.")
    src = sampled_face(source, settings.source_grid_mm, settings.max_normal_angle_rad, faces)
    tgt = sampled_face(target, settings.target_grid_mm, settings.max_normal_angle_rad, faces)
    return _distances(src.points, tgt, T, up_to)


def c2c_histogram(
    source: Scan,
    target: Scan,
    T_target_source: FloatArray,
    settings: HistogramSettings | None = None,
    faces: FaceCache | None = None,
) -> FloatArray:
    """The density histogram (``settings.bins`` values, integrating to 1 over 0..max distance) of the
    cloud-to-cloud distances of a registered pair; all zeros when no distance is under the maximum (the
    faces do not overlap at all)."""
    settings = settings or HistogramSettings()
    T = _checked_transform(T_target_source)
    # distances over the maximum are dropped: the search need not find them (np.nextafter: scipy's bound
    # is strict, the histogram keeps a distance equal to the maximum)
    reach = float(np.nextafter(settings.max_distance_mm, np.inf))
    histogram = density_histogram(c2c_distances(source, target, T, settings, faces, up_to=reach), settings)
    if settings.symmetric:
        # The other direction: the target (at the source's grid) onto the source (at the target's grid).
        backward = c2c_distances(target, source, np.linalg.inv(T), settings, faces, up_to=reach)
        histogram = 0.5 * (histogram + density_histogram(backward, settings))
    return histogram


def density_histogram(distances: FloatArray, settings: HistogramSettings) -> FloatArray:
    """``np.histogram(d, bins, range=(0, max), density=True)`` over the distances up to the maximum (the
    authors' convention: far distances are dropped before normalising); zeros when none is left."""
    kept = distances[distances <= settings.max_distance_mm]
    if len(kept) == 0:
        return np.zeros(settings.bins)
    values, _ = np.histogram(kept, bins=settings.bins, range=(0.0, settings.max_distance_mm), density=True)
    return values.astype(np.float64)


def main_normal(normals: FloatArray) -> FloatArray:
    """The face's main normal: the mean of its unit normals, normalised. On a coin face the design's
    flanks cancel out and the mean points away from the field; the rim's wall is a small share."""
    mean = normals.mean(axis=0)
    length = float(np.linalg.norm(mean))
    if length < 1e-6:  # normals pointing every way: no face direction, fall back to the best-fit axis
        return np.linalg.eigh(normals.T @ normals)[1][:, -1]
    return mean / length


def sampled_face(
    scan: Scan, grid_mm: float, max_normal_angle_rad: float, faces: FaceCache | None = None
) -> SampledFace:
    """The scan grid-sampled at ``grid_mm`` with the points facing away from its main normal removed,
    from a cache (``faces``, the module's by default) keyed by the scan's content and the two settings."""
    from coindie.registration.clouds import content_key

    key = content_key(scan.points, scan.normals if scan.normals is not None else np.empty(0))
    key += np.array([grid_mm, max_normal_angle_rad], dtype=np.float64).tobytes()
    faces = _FACES if faces is None else faces
    return faces.get(key, lambda: _sample(scan, grid_mm, max_normal_angle_rad))


def clear_cache() -> None:
    """Forget every face of the module's cache (tests, memory)."""
    _FACES.clear()


def _sample(scan: Scan, grid_mm: float, max_normal_angle_rad: float) -> SampledFace:
    from coindie.preprocess.sampling import grid_sample
    from coindie.registration.clouds import with_normals

    sampled = grid_sample(with_normals(scan), grid_mm)
    normals = sampled.normals
    assert normals is not None  # with_normals guarantees them, grid sampling keeps them
    up = main_normal(normals)
    keep = normals @ up >= np.cos(max_normal_angle_rad)
    return SampledFace(points=np.ascontiguousarray(sampled.points[keep]), main_normal=up)


def _distances(
    query_points: FloatArray, target: SampledFace, T_target_source: FloatArray, up_to: float | None = None
) -> FloatArray:
    if len(query_points) == 0 or len(target.points) == 0:
        return np.empty(0)
    moved = query_points @ T_target_source[:3, :3].T + T_target_source[:3, 3]
    bound = np.inf if up_to is None else up_to
    distances, _ = target.tree.query(moved, k=1, workers=1, distance_upper_bound=bound)
    return np.asarray(distances, dtype=np.float64)


def _checked_transform(T: FloatArray) -> FloatArray:
    T = np.asarray(T, dtype=np.float64)
    if T.shape != (4, 4) or not np.isfinite(T).all():
        raise ParameterError(f"T_target_source must be a finite 4x4 matrix. Got shape {T.shape}.")
    return T
