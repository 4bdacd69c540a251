"""The preprocessing parameters in one typed, validated model."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from coindie.errors import ParameterError
from coindie.preprocess import defaults as d

Orientation = Literal["pca", "canonical", "none"]
GridMode = Literal["mean", "last"]
SurfaceModel = Literal["plane", "quadric"]


class PreprocessConfig(BaseModel):
    """Parameters of :func:`coindie.preprocess.preprocess` and of the canonical frame / height map.

    Defaults follow the Riedones3D paper where it gives a value (PCA orientation to +z, 0.1 mm grid).
    Build with keywords (``PreprocessConfig(grid_size_mm=0.2)``) or, to get a ``ParameterError`` instead of
    pydantic's ``ValidationError``, with :meth:`from_overrides`.
    """

    model_config = ConfigDict(extra="forbid", frozen=True)

    orientation: Orientation = Field(
        "pca",
        description="How the scan is turned face up: 'pca' (paper: smallest principal axis to +z), "
        "'canonical' (robust best-fit plane to z=0, edge wall ignored), 'none' (only centred).",
    )
    grid_size_mm: float | None = Field(
        d.GRID_SIZE_MM, gt=0, description="Grid-sampling cell edge (mm); None keeps every point."
    )
    grid_mode: GridMode = Field(
        "mean", description="'mean': one averaged point per cell; 'last': the cell's last input point."
    )
    normals_k: int = Field(d.NORMALS_K, ge=3, le=256, description="Neighbours per normal estimate (count).")
    normals_radius_mm: float | None = Field(
        d.NORMALS_RADIUS_MM,
        gt=0,
        description="Neighbours farther than this are ignored (mm); None: no limit.",
    )
    frame_model: SurfaceModel = Field(
        "plane", description="Canonical frame from the best-fit 'plane' or the tangent plane of a 'quadric'."
    )
    fit_max_normal_angle_deg: float = Field(
        d.FIT_MAX_NORMAL_ANGLE_DEG,
        gt=0,
        le=90,
        description="Points whose normal is farther than this from up (degrees) are left out of the fit.",
    )
    fit_iterations: int = Field(
        d.FIT_ITERATIONS, ge=1, le=100, description="Reweighting iterations of the fit (count)."
    )
    heightmap_resolution_mm: float = Field(
        d.HEIGHTMAP_RESOLUTION_MM, gt=0, description="Height-map pixel edge (mm)."
    )
    detrend: SurfaceModel = Field(
        "quadric", description="Height-map values are heights above the best-fit 'plane' or 'quadric' (mm)."
    )
    raster_max_normal_angle_deg: float = Field(
        d.RASTER_MAX_NORMAL_ANGLE_DEG,
        gt=0,
        le=90,
        description="Points steeper than this (degrees from +z) are left out of the height map.",
    )
    fill_max_distance_mm: float = Field(
        d.FILL_MAX_DISTANCE_MM,
        ge=0,
        description="Empty pixels this close to data (mm) inside the coin are filled.",
    )

    @classmethod
    def from_overrides(cls, **overrides: Any) -> PreprocessConfig:
        """The default configuration with some fields changed; a bad value raises ``ParameterError``."""
        try:
            return cls(**overrides)
        except ValidationError as error:
            raise ParameterError(_one_line(error)) from None


def _one_line(error: ValidationError) -> str:
    """'The 'grid_size_mm' parameter of PreprocessConfig must be greater than 0. Got -1.' (first problem)."""
    first = error.errors()[0]
    name = ".".join(str(part) for part in first["loc"]) or "?"
    more = f" (and {error.error_count() - 1} more problems)" if error.error_count() > 1 else ""
    got = f" Got {first['input']!r}." if first["type"] != "extra_forbidden" else ""
    return f"The '{name}' parameter of PreprocessConfig: {first['msg'].lower()}.{got}{more}"
