"""The preprocessing parameters in one typed, validated configuration."""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, Literal

from coindie.errors import ParameterError
from coindie.params import Configurable, param
from coindie.preprocess import defaults as d

Orientation = Literal["pca", "canonical", "none"]
GridMode = Literal["mean", "last"]
SurfaceModel = Literal["plane", "quadric"]
_SURFACES = ("plane", "quadric")


def _positive_mm(default: float | None, doc: str, optional: bool = False) -> Any:
    """A length in (0, inf) mm (or None when ``optional``)."""
    return param(default, float, doc=doc, unit="mm", low=0.0, low_open=True, optional=optional)


def _angle_deg(default: float, doc: str) -> Any:
    """An angle in (0, 90] degrees."""
    return param(default, float, doc=doc, unit="degrees", low=0.0, low_open=True, high=90.0)


@dataclass(frozen=True, kw_only=True)
class PreprocessConfig(Configurable):
    """Parameters of :func:`coindie.preprocess.preprocess` and of the canonical frame / height map.

    Defaults follow the Riedones3D paper where it gives a value (PCA orientation to +z, 0.1 mm grid).
    Build with keywords (``PreprocessConfig(grid_size_mm=0.2)``: a bad value raises ``ParameterError``) or
    with :meth:`from_overrides`, which also refuses an unknown name with a ``ParameterError``.
    """

    orientation: Orientation = param(
        "pca",
        doc="How the scan is turned face up: 'pca' (paper: smallest principal axis to +z), "
        "'canonical' (robust best-fit plane to z=0, edge wall ignored), 'none' (only centred).",
        choices=("pca", "canonical", "none"),
    )
    grid_size_mm: float | None = _positive_mm(
        d.GRID_SIZE_MM, "Grid-sampling cell edge; None keeps every point.", optional=True
    )
    grid_mode: GridMode = param(
        "mean",
        doc="'mean': one averaged point per cell; 'last': the cell's last input point.",
        choices=("mean", "last"),
    )
    normals_k: int = param(d.NORMALS_K, doc="Neighbours per normal estimate (count).", low=3, high=256)
    normals_radius_mm: float | None = _positive_mm(
        d.NORMALS_RADIUS_MM, "Neighbours farther than this are ignored; None: no limit.", optional=True
    )
    frame_model: SurfaceModel = param(
        "plane",
        doc="Canonical frame from the best-fit 'plane' or the tangent plane of a 'quadric'.",
        choices=_SURFACES,
    )
    fit_max_normal_angle_deg: float = _angle_deg(
        d.FIT_MAX_NORMAL_ANGLE_DEG,
        "Points whose normal is farther than this from up are left out of the fit.",
    )
    fit_iterations: int = param(
        d.FIT_ITERATIONS, doc="Reweighting iterations of the fit (count).", low=1, high=100
    )
    heightmap_resolution_mm: float = _positive_mm(d.HEIGHTMAP_RESOLUTION_MM, "Height-map pixel edge.")
    detrend: SurfaceModel = param(
        "quadric",
        doc="Height-map values are heights above the best-fit 'plane' or 'quadric'.",
        choices=_SURFACES,
    )
    raster_max_normal_angle_deg: float = _angle_deg(
        d.RASTER_MAX_NORMAL_ANGLE_DEG, "Points steeper than this (from +z) are left out of the height map."
    )
    fill_max_distance_mm: float = param(
        d.FILL_MAX_DISTANCE_MM,
        doc="Empty pixels this close to data inside the coin are filled.",
        unit="mm",
        low=0.0,
    )

    @classmethod
    def from_overrides(cls, **overrides: Any) -> PreprocessConfig:
        """The default configuration with some fields changed; a bad value or name: ``ParameterError``."""
        known = [f.name for f in fields(cls)]
        for name in overrides:
            if name not in known:
                raise ParameterError(
                    f"The {name!r} parameter of PreprocessConfig is not a parameter. Its parameters: "
                    f"{', '.join(known)}."
                )
        return cls(**overrides)
