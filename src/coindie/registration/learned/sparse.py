"""Sparse 3-D convolutions on occupied voxels, in plain PyTorch.

A :class:`SparseTensor` is a feature row per occupied voxel and a :class:`CoordinateMap` naming the voxels:
integer coordinates ``(batch, x, y, z)`` in units of the finest voxel, all multiples of the map's
``stride``. A convolution finds, for each kernel offset, which input voxel feeds which output voxel (a
hash of the coordinates: packed int64 keys, sorted, looked up with ``searchsorted``), then gathers the
input rows, multiplies them by that offset's weight matrix and adds them into the output rows.

Written by hand because the libraries that do this (MinkowskiEngine, TorchSparse, spconv) need compiled
CUDA extensions; this version runs anywhere PyTorch does, and a coin (~30k voxels at 0.1 mm) is small.

Three layers make a U-Net:

- :class:`SubmanifoldConv` (kernel 3, stride 1): output voxels = input voxels;
- :class:`DownConv` (kernel 2, stride 2): each voxel feeds its parent cell of twice the size, so the
  parent's row is the sum over its (up to 8) children of ``child_features @ W[child position]``;
- :class:`UpConv` (transposed, kernel 2, stride 2): each child gets ``parent_features @ W[its position]``,
  on the child voxels of the encoder (the :class:`Pyramid` link kept by the matching DownConv).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from functools import cached_property

import torch
from torch import Tensor, nn

from coindie.errors import ParameterError

#: Bits per packed spatial coordinate: coordinates must lie within ±2**(_BITS-1) voxels (±13 m at 0.1 mm).
_BITS = 18
_HALF = 1 << (_BITS - 1)
#: Margin kept free at the edges of the range so that neighbour offsets never wrap around.
_MARGIN = 64
#: Clouds per batch: the batch index takes the bits left above the three coordinates (63 - 60).
MAX_BATCH = 1 << (63 - 3 * _BITS)


def pack(coords: Tensor) -> Tensor:
    """One int64 key per row of ``(batch, x, y, z)`` integer coordinates (order-preserving per batch)."""
    b, xyz = coords[:, 0], coords[:, 1:] + _HALF
    return ((b * (1 << _BITS) + xyz[:, 0]) * (1 << _BITS) + xyz[:, 1]) * (1 << _BITS) + xyz[:, 2]


def check_coordinates(coords: Tensor) -> None:
    """A ParameterError when coordinates leave the packed range or the batch index is too large."""
    if len(coords) == 0:
        return
    if int(coords[:, 0].min()) < 0 or int(coords[:, 0].max()) >= MAX_BATCH:
        raise ParameterError(
            f"A sparse batch holds at most {MAX_BATCH} clouds (batch index 0..{MAX_BATCH - 1})."
        )
    if int(coords[:, 1:].abs().max()) >= _HALF - _MARGIN:
        raise ParameterError(
            f"Voxel coordinates must stay within ±{_HALF - _MARGIN} voxels of the origin; "
            "move the cloud nearer to the origin or use a larger voxel."
        )


@dataclass(eq=False)
class CoordinateMap:
    """Occupied voxels, sorted by key, at one stride (coordinates are multiples of ``stride``)."""

    coords: Tensor  # (N, 4) int64: batch, x, y, z
    stride: int

    @cached_property
    def keys(self) -> Tensor:
        return pack(self.coords)

    def __len__(self) -> int:
        return len(self.coords)

    def lookup(self, query: Tensor) -> Tensor:
        """Row of each queried ``(batch, x, y, z)`` voxel, -1 where it is not occupied."""
        keys = pack(query)
        rows = torch.searchsorted(self.keys, keys).clamp_max(len(self.keys) - 1)
        return torch.where(self.keys[rows] == keys, rows, torch.full_like(rows, -1))

    @cached_property
    def neighbours(self) -> list[tuple[Tensor, Tensor]]:
        """For each of the 27 offsets of a 3x3x3 kernel: (input rows, output rows) of the voxel pairs
        ``input = output + offset * stride``. Computed once per map and shared by its convolutions."""
        pairs = []
        for offset in kernel_offsets(3):
            shift = torch.tensor([0, *offset], dtype=torch.int64, device=self.coords.device) * self.stride
            rows = self.lookup(self.coords + shift)
            found = torch.nonzero(rows >= 0).squeeze(1)
            pairs.append((rows[found], found))
        return pairs


def kernel_offsets(size: int) -> list[tuple[int, int, int]]:
    """Offsets of a cubic kernel in (x, y, z) order, z fastest: 3 -> -1..1, 2 -> 0..1."""
    values = range(-(size // 2), size // 2 + 1) if size % 2 else range(size)
    return list(itertools.product(values, repeat=3))


def voxel_map(coords: Tensor) -> tuple[CoordinateMap, Tensor]:
    """The map of the distinct ``(batch, x, y, z)`` rows and, per row, the index of its voxel."""
    check_coordinates(coords)
    keys, inverse = torch.unique(pack(coords), sorted=True, return_inverse=True)
    return CoordinateMap(coords[_one_row_each(inverse, len(keys))], 1), inverse


def _one_row_each(inverse: Tensor, n: int) -> Tensor:
    """A row index of each of the ``n`` groups named by ``inverse`` (rows of a group are equal here)."""
    rows = torch.zeros(n, dtype=torch.int64, device=inverse.device)
    return rows.scatter_(0, inverse, torch.arange(len(inverse), device=inverse.device))


@dataclass(frozen=True, eq=False)
class SparseTensor:
    """Features (N, C) of the voxels of a coordinate map."""

    features: Tensor
    cmap: CoordinateMap

    def replace(self, features: Tensor) -> SparseTensor:
        return SparseTensor(features, self.cmap)


@dataclass(eq=False)
class Pyramid:
    """The link between a map and its coarser map (twice the stride): parent row and child position
    (0..7, x-major as :func:`kernel_offsets`) of each fine voxel."""

    fine: CoordinateMap
    coarse: CoordinateMap
    parent: Tensor  # (N_fine,) rows of the coarse map
    child: Tensor  # (N_fine,) 0..7

    @classmethod
    def of(cls, fine: CoordinateMap) -> Pyramid:
        step = 2 * fine.stride
        xyz = torch.div(fine.coords[:, 1:], step, rounding_mode="floor") * step
        coarse_coords = torch.cat([fine.coords[:, :1], xyz], dim=1)
        keys, parent = torch.unique(pack(coarse_coords), sorted=True, return_inverse=True)
        first = _one_row_each(parent, len(keys))
        bits = torch.div(fine.coords[:, 1:] - xyz, fine.stride, rounding_mode="floor")
        child = bits[:, 0] * 4 + bits[:, 1] * 2 + bits[:, 2]
        return cls(fine, CoordinateMap(coarse_coords[first], step), parent, child)

    @cached_property
    def by_child(self) -> list[Tensor]:
        """Fine rows of each child position."""
        return [torch.nonzero(self.child == k).squeeze(1) for k in range(8)]

    @cached_property
    def restore(self) -> Tensor:
        """The permutation that puts rows grouped by child position back in fine-map order."""
        return torch.argsort(torch.cat(self.by_child))


def _weights(kernel: int, c_in: int, c_out: int) -> nn.Parameter:
    """Kaiming-normal weights for a kernel of ``kernel`` offsets (fan-in = offsets x input channels)."""
    std = math.sqrt(2.0 / (kernel * c_in))
    return nn.Parameter(torch.randn(kernel, c_in, c_out) * std)


class SubmanifoldConv(nn.Module):
    """3x3x3 convolution whose output voxels are its input voxels (no growth of the surface)."""

    def __init__(self, c_in: int, c_out: int, bias: bool = False) -> None:
        super().__init__()
        self.weight = _weights(27, c_in, c_out)
        self.bias = nn.Parameter(torch.zeros(c_out)) if bias else None

    def forward(self, x: SparseTensor) -> SparseTensor:
        out = x.features.new_zeros(len(x.cmap), self.weight.shape[2])
        for w, (rows_in, rows_out) in zip(self.weight, x.cmap.neighbours, strict=True):
            if len(rows_in):
                out.index_add_(0, rows_out, x.features[rows_in] @ w)
        return x.replace(out if self.bias is None else out + self.bias)


class PointwiseConv(nn.Module):
    """1x1x1 convolution: a linear layer on each voxel's features."""

    def __init__(self, c_in: int, c_out: int, bias: bool = True) -> None:
        super().__init__()
        self.linear = nn.Linear(c_in, c_out, bias=bias)

    def forward(self, x: SparseTensor) -> SparseTensor:
        return x.replace(self.linear(x.features))


class DownConv(nn.Module):
    """2x2x2 convolution of stride 2: halves the resolution; returns the pyramid link for the decoder."""

    def __init__(self, c_in: int, c_out: int) -> None:
        super().__init__()
        self.weight = _weights(8, c_in, c_out)

    def forward(self, x: SparseTensor) -> tuple[SparseTensor, Pyramid]:
        link = Pyramid.of(x.cmap)
        out = x.features.new_zeros(len(link.coarse), self.weight.shape[2])
        for w, rows in zip(self.weight, link.by_child, strict=True):
            if len(rows):
                out.index_add_(0, link.parent[rows], x.features[rows] @ w)
        return SparseTensor(out, link.coarse), link


class UpConv(nn.Module):
    """Transposed 2x2x2 convolution of stride 2 onto the fine voxels of an encoder link."""

    def __init__(self, c_in: int, c_out: int) -> None:
        super().__init__()
        self.weight = _weights(8, c_in, c_out)

    def forward(self, x: SparseTensor, link: Pyramid) -> SparseTensor:
        parts = [
            x.features[link.parent[rows]] @ w for w, rows in zip(self.weight, link.by_child, strict=True)
        ]
        return SparseTensor(torch.cat(parts)[link.restore], link.fine)


class BatchNorm(nn.Module):
    """Batch normalisation over the active voxels (each voxel is one sample)."""

    def __init__(self, channels: int, momentum: float = 0.1) -> None:
        super().__init__()
        self.norm = nn.BatchNorm1d(channels, momentum=momentum)

    def forward(self, x: SparseTensor) -> SparseTensor:
        return x.replace(self.norm(x.features))


def relu(x: SparseTensor) -> SparseTensor:
    return x.replace(torch.relu(x.features))


def concat(a: SparseTensor, b: SparseTensor) -> SparseTensor:
    """Channels of ``a`` then ``b`` on the same voxels (a U-Net skip connection)."""
    assert a.cmap is b.cmap, "skip connections join tensors of the same coordinate map"
    return a.replace(torch.cat([a.features, b.features], dim=1))
