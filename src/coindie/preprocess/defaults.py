"""Default preprocessing parameters, shared by the functions' keyword defaults and ``PreprocessConfig``.

Kept free of heavy imports so that the fast CLI commands can use them.
"""

from __future__ import annotations

#: Grid-sampling cell edge (mm). The paper downsamples every scan with a 0.1 mm grid.
GRID_SIZE_MM = 0.1
#: Neighbours used to estimate one normal by local PCA.
NORMALS_K = 16
#: Ignore normal-estimation neighbours farther than this (mm); ``None`` keeps all ``NORMALS_K``.
NORMALS_RADIUS_MM: float | None = None
#: Points whose normal is more than this far from the face's up direction (degrees) are the coin's edge
#: wall or steep flanks: they do not take part in the plane / quadric fit.
FIT_MAX_NORMAL_ANGLE_DEG = 60.0
#: Iterations of the reweighted (Tukey biweight) surface fit.
FIT_ITERATIONS = 8
#: At most this many points (a regular subsample) enter the surface fit; enough for six coefficients.
FIT_MAX_POINTS = 20_000
#: Height-map pixel edge (mm).
HEIGHTMAP_RESOLUTION_MM = 0.05
#: Points steeper than this (degrees between normal and +z) are left out of the height map (edge wall).
RASTER_MAX_NORMAL_ANGLE_DEG = 80.0
#: Empty height-map pixels inside the coin footprint are filled when data lie within this distance (mm).
FILL_MAX_DISTANCE_MM = 0.3
#: A height map larger than this many pixels is refused (a too fine resolution for the scan's extent).
MAX_HEIGHTMAP_PIXELS = 64_000_000
