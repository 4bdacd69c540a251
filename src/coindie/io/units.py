"""Scans written in metres or micrometres, read in millimetres.

coindie works in millimetres, and so do most coin scanners. But a mesh exported from a CAD or 3D tool is
often written in metres (a 20 mm coin 0.02 wide), and a profilometer or a confocal microscope may write
micrometres. Read as millimetres, such a face is 1,000 times too small or too large: every length of the
pipeline (the 0.1 mm grid, the height-map pixels, the search reach) is then wrong by that factor, and the
pipeline fails far from the cause (a cloud of one point after grid sampling).

A coin's size tells these units apart without doubt: a coin face is 2-200 mm across (the smallest Greek
fractions are about 5 mm, the largest medallions about 70 mm), so of millimetres, metres and micrometres,
which are 1,000 times apart, at most one unit puts a face within those bounds. That unit is the file's.
Centimetres and inches are not guessed: a face 0.8 units wide may be 8 mm or 20 mm across. They, and any
of the others, can be declared instead (``coindie init --unit cm``: the project's ``unit``): a declared
unit is used as given, with no guess.
"""

from __future__ import annotations

import logging

import numpy as np

from coindie.arrays import FloatArray
from coindie.errors import ParameterError

#: Millimetres per unit of the units told apart by a face's size (1,000 apart).
MM_PER_UNIT = {"mm": 1.0, "m": 1000.0, "um": 0.001}
#: Millimetres per unit of every unit a scan can be declared in (``unit=`` of :func:`in_millimetres`).
DECLARED_UNITS = {**MM_PER_UNIT, "cm": 10.0, "in": 25.4}
#: Sizes of a coin face in millimetres (across, the largest extent of the scan): the bounds of the units'
#: test. Wide enough for any coin; a factor of 1,000 narrower than the units' spacing.
COIN_SIZE_MM = (2.0, 200.0)
#: Points the size is measured on (a regular subsample).
_SAMPLE = 20_000
#: The size is the extent between these percentiles along each axis (a few stray points do not count).
_PERCENTILES = (0.5, 99.5)

_log = logging.getLogger(__name__)


def face_size(points: FloatArray) -> float:
    """The face's size in the file's units: the largest of its extents along the three axes, each between
    the 0.5th and 99.5th percentiles of the coordinates (0 for an empty cloud)."""
    if len(points) == 0:
        return 0.0
    sample = points[:: max(1, -(-len(points) // _SAMPLE))]
    low, high = np.percentile(sample, _PERCENTILES, axis=0)
    return float(np.max(high - low))


def file_unit(points: FloatArray) -> str:
    """The unit of ``MM_PER_UNIT`` in which the face's size is a coin's (``COIN_SIZE_MM``); "mm" when none
    is (a fragment, a test cloud: read as written)."""
    return _unit_of(face_size(points))


def _unit_of(size: float) -> str:
    """:func:`file_unit` of a face ``size`` units across."""
    for unit, mm in MM_PER_UNIT.items():
        if COIN_SIZE_MM[0] <= size * mm <= COIN_SIZE_MM[1]:
            return unit
    return "mm"


def checked_unit(unit: str | None) -> str | None:
    """``unit`` when it is one of ``DECLARED_UNITS`` or None (guess); ``ParameterError`` otherwise."""
    if unit is not None and unit not in DECLARED_UNITS:
        known = ", ".join(DECLARED_UNITS)
        raise ParameterError(f"unknown unit {unit!r} (known: {known}; or none, to tell it from the size)")
    return unit


def in_millimetres(
    points: FloatArray, source: object = None, unit: str | None = None
) -> tuple[FloatArray, str]:
    """``points`` in millimetres, and their unit: ``unit`` when declared (one of ``DECLARED_UNITS``, used
    as given), else the unit they were found in (:func:`file_unit`). ``source`` (a path) names the scan in
    the warning logged when undeclared points are rescaled."""
    if checked_unit(unit) is not None:
        return (points if unit == "mm" else points * DECLARED_UNITS[unit]), unit
    size = face_size(points)
    unit = _unit_of(size)
    if unit == "mm":
        return points, unit
    _log.warning(
        "%s: a face %.4g wide is no coin in millimetres; read as %s (x %g to mm)",
        source if source is not None else "scan",
        size,
        "metres" if unit == "m" else "micrometres",
        MM_PER_UNIT[unit],
    )
    return points * MM_PER_UNIT[unit], unit
