"""The FCGF network: a sparse U-Net giving each occupied voxel a unit descriptor (see
coindie.registration.learned.fcgf).

Levels ``i = 0..L-1`` have voxels of ``voxel * 2**i`` and ``channels[i]`` channels. The encoder is a
3x3x3 convolution then, at each coarser level, a stride-2 2x2x2 convolution; every level ends in a
residual block of two 3x3x3 convolutions. The decoder goes back up with transposed convolutions, joins
the encoder's output of each level (skip connection) and fuses the two with a 3x3x3 convolution. A head of
two per-voxel linear layers gives ``out_dim`` channels, normalised to unit length. Every convolution but
the head's is followed by batch normalisation and a ReLU.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import torch
from torch import Tensor, nn

from coindie.registration.learned.sparse import (
    BatchNorm,
    DownConv,
    PointwiseConv,
    Pyramid,
    SparseTensor,
    SubmanifoldConv,
    UpConv,
    concat,
    relu,
    voxel_map,
)

if TYPE_CHECKING:
    from coindie.registration.learned.fcgf import FCGFConfig


class ConvNormReLU(nn.Module):
    def __init__(self, conv: nn.Module, channels: int) -> None:
        super().__init__()
        self.conv, self.norm = conv, BatchNorm(channels)

    def forward(self, x: SparseTensor) -> SparseTensor:
        return relu(self.norm(self.conv(x)))


class ResidualBlock(nn.Module):
    def __init__(self, channels: int) -> None:
        super().__init__()
        self.first = ConvNormReLU(SubmanifoldConv(channels, channels), channels)
        self.conv, self.norm = SubmanifoldConv(channels, channels), BatchNorm(channels)

    def forward(self, x: SparseTensor) -> SparseTensor:
        return relu(x.replace(x.features + self.norm(self.conv(self.first(x))).features))


class Down(nn.Module):
    """One level down: stride-2 convolution, then a residual block."""

    def __init__(self, c_in: int, c_out: int) -> None:
        super().__init__()
        self.conv, self.norm, self.block = DownConv(c_in, c_out), BatchNorm(c_out), ResidualBlock(c_out)

    def forward(self, x: SparseTensor) -> tuple[SparseTensor, Pyramid]:
        y, link = self.conv(x)
        return self.block(relu(self.norm(y))), link


class Up(nn.Module):
    """One level up: transposed convolution onto the encoder's voxels, join its output, fuse."""

    def __init__(self, c_in: int, c_skip: int, c_out: int) -> None:
        super().__init__()
        self.conv, self.norm = UpConv(c_in, c_skip), BatchNorm(c_skip)
        self.fuse = ConvNormReLU(SubmanifoldConv(2 * c_skip, c_out), c_out)

    def forward(self, x: SparseTensor, skip: SparseTensor, link: Pyramid) -> SparseTensor:
        return self.fuse(concat(relu(self.norm(self.conv(x, link))), skip))


class FCGFNet(nn.Module):
    """Sparse U-Net: per-voxel unit descriptors of ``config.out_dim`` dimensions."""

    def __init__(self, config: FCGFConfig) -> None:
        super().__init__()
        self.config = config
        c, top = config.channels, max(config.channels[0], config.out_dim)
        self.stem = ConvNormReLU(SubmanifoldConv(config.in_channels, c[0]), c[0])
        self.stem_block = ResidualBlock(c[0])
        self.down = nn.ModuleList(Down(c[i - 1], c[i]) for i in range(1, len(c)))
        # Decoder, coarse to fine: level i outputs c[i] channels, the finest level max(c[0], out_dim).
        self.up = nn.ModuleList(
            Up(c[i], c[i - 1], top if i == 1 else c[i - 1]) for i in range(len(c) - 1, 0, -1)
        )
        self.head = nn.ModuleList([PointwiseConv(top, top), PointwiseConv(top, config.out_dim)])

    def forward(self, x: SparseTensor) -> SparseTensor:
        # Encoder: keep each level's output and the link to the next level.
        x = self.stem_block(self.stem(x))
        skips, links = [], []
        for down in self.down:
            skips.append(x)
            x, link = down(x)
            links.append(link)
        # Decoder: up one level, join the encoder's output of that level.
        for up, skip, link in zip(self.up, reversed(skips), reversed(links), strict=True):
            x = up(x, skip, link)
        # Head: per-voxel layers, unit length.
        x = self.head[1](relu(self.head[0](x)))
        return x.replace(nn.functional.normalize(x.features, dim=1))

    def describe_points(self, points: Tensor, batch: Tensor | None = None) -> Tensor:
        """(N, out_dim) unit descriptors of points (N, 3) in mm: each point gets its voxel's.
        ``batch`` (N,) int64 puts the points of several clouds through in one pass."""
        cells = torch.floor(points.double() / self.config.voxel).long()
        if batch is None:
            batch = torch.zeros(len(points), dtype=torch.int64, device=points.device)
        cmap, inverse = voxel_map(torch.cat([batch[:, None], cells], dim=1))
        ones = torch.ones(len(cmap), self.config.in_channels, device=points.device)
        return self(SparseTensor(ones, cmap)).features[inverse]
