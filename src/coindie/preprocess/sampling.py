"""Grid sampling: one point per occupied cubic cell."""

from __future__ import annotations

from dataclasses import replace
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from coindie.arrays import FloatArray, IntArray
from coindie.errors import ParameterError
from coindie.preprocess.defaults import GRID_SIZE_MM
from coindie.scan import Scan


def cell_keys(points: FloatArray, size: float) -> IntArray:
    """One int64 key per point naming its cell ``floor(p / size)``.

    The three integer cell coordinates are packed into one scalar so that ``np.unique`` sorts scalars
    instead of rows (several times faster).
    """
    if not size > 0:
        raise ParameterError(f"The grid size must be a positive number of mm. Got {size!r}.")
    cells = np.floor(points / size).astype(np.int64)
    cells -= cells.min(axis=0)
    dims = cells.max(axis=0) + 1
    if float(np.prod(dims.astype(np.float64))) >= 2.0**62:
        raise ParameterError(f"The grid size {size} mm is too small for a scan this large ({dims} cells).")
    return (cells[:, 0] * dims[1] + cells[:, 1]) * dims[2] + cells[:, 2]


def grid_sample(scan: Scan, size: float = GRID_SIZE_MM, mode: Literal["mean", "last"] = "mean") -> Scan:
    """One point per occupied cell of edge ``size`` (mm), cells in key order.

    ``mode="mean"`` averages the cell's points, normals (re-normalised) and colours;
    ``mode="last"`` keeps the cell's last point in input order, unchanged (torch-points3d's convention).
    """
    if mode == "last":
        return scan.subset(last_in_cell(scan.points, size))
    if mode != "mean":
        raise ParameterError(f"The grid-sampling mode must be 'mean' or 'last'. Got {mode!r}.")
    keys = cell_keys(scan.points, size)
    _, inverse = np.unique(keys, return_inverse=True)
    counts = np.bincount(inverse).astype(np.float64)
    return replace(
        scan,
        points=_cell_means(scan.points, inverse, counts),
        normals=None if scan.normals is None else _mean_normals(scan.normals, keys, inverse, counts),
        colors=None if scan.colors is None else _mean_colors(scan.colors, inverse, counts),
    )


def last_in_cell(points: FloatArray, size: float) -> IntArray:
    """Index of the last input point of each occupied cell (cells in key order)."""
    return _last_of_keys(cell_keys(points, size))


def _last_of_keys(keys: IntArray) -> IntArray:
    # The first occurrence in the reversed order is the last one in input order.
    _, first_reversed = np.unique(keys[::-1], return_index=True)
    return len(keys) - 1 - first_reversed


def _cell_means(values: FloatArray, inverse: IntArray, counts: FloatArray) -> FloatArray:
    columns = [np.bincount(inverse, weights=values[:, j], minlength=len(counts)) for j in range(3)]
    return np.stack(columns, axis=1) / counts[:, None]


def _mean_normals(normals: FloatArray, keys: IntArray, inverse: IntArray, counts: FloatArray) -> FloatArray:
    mean = _cell_means(normals, inverse, counts)
    length = np.linalg.norm(mean, axis=1, keepdims=True)
    # Opposite normals in one cell cancel out: keep one of the cell's own normals there instead.
    degenerate = length[:, 0] < 1e-6
    if degenerate.any():
        mean[degenerate] = normals[_last_of_keys(keys)[degenerate]]
        length[degenerate] = 1.0
    return mean / length


def _mean_colors(colors: NDArray[np.uint8], inverse: IntArray, counts: FloatArray) -> NDArray[np.uint8]:
    mean = _cell_means(colors.astype(np.float64), inverse, counts)
    return np.clip(np.rint(mean), 0, 255).astype(np.uint8)
