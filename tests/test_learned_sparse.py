"""Sparse convolutions against dense 3-D convolutions of the same weights on a small random voxel grid."""

from __future__ import annotations

import pytest

torch = pytest.importorskip("torch")

import torch.nn.functional as F  # noqa: E402

from coindie.errors import ParameterError  # noqa: E402
from coindie.registration.learned.sparse import (  # noqa: E402
    DownConv,
    SparseTensor,
    SubmanifoldConv,
    UpConv,
    kernel_offsets,
    voxel_map,
)

SIZE = 8  # the dense grid is SIZE^3, its origin at an even coordinate so that stride-2 cells line up


@pytest.fixture
def grid() -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
    """(dense features (1, C, S, S, S) zero where empty, occupied coordinates (N, 4), their features)."""
    generator = torch.Generator().manual_seed(0)
    occupied = torch.rand(SIZE, SIZE, SIZE, generator=generator) < 0.3
    xyz = torch.nonzero(occupied)
    features = torch.randn(len(xyz), 3, generator=generator, dtype=torch.float64)
    dense = torch.zeros(1, 3, SIZE, SIZE, SIZE, dtype=torch.float64)
    dense[0, :, xyz[:, 0], xyz[:, 1], xyz[:, 2]] = features.T
    coords = torch.cat([torch.zeros(len(xyz), 1, dtype=torch.int64), xyz], dim=1)
    return dense, coords, features


def sparse_input(coords: torch.Tensor, features: torch.Tensor, shuffle: int | None = None) -> SparseTensor:
    if shuffle is not None:
        order = torch.randperm(len(coords), generator=torch.Generator().manual_seed(shuffle))
        coords, features = coords[order], features[order]
    cmap, inverse = voxel_map(coords)
    rows = torch.zeros(len(cmap), features.shape[1], dtype=features.dtype)
    rows[inverse] = features
    return SparseTensor(rows, cmap)


def dense_weight(weight: torch.Tensor, size: int) -> torch.Tensor:
    """(offsets, C_in, C_out) -> torch's (C_out, C_in, k, k, k), offsets in kernel_offsets order."""
    return weight.permute(2, 1, 0).reshape(weight.shape[2], weight.shape[1], size, size, size)


def at(dense: torch.Tensor, coords: torch.Tensor, stride: int = 1) -> torch.Tensor:
    """Rows of a dense (1, C, ...) grid at sparse coordinates (in finest-voxel units)."""
    xyz = torch.div(coords[:, 1:], stride, rounding_mode="floor")
    return dense[0, :, xyz[:, 0], xyz[:, 1], xyz[:, 2]].T


def test_kernel_offsets_are_x_major_like_torch_weights() -> None:
    assert (
        kernel_offsets(3)[1] == (-1, -1, 0)
        and kernel_offsets(3)[3] == (-1, 0, -1)
        and kernel_offsets(3)[9] == (0, -1, -1)
    )
    assert kernel_offsets(2) == [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]


def test_submanifold_conv_equals_a_dense_convolution_at_the_occupied_voxels(grid) -> None:
    dense, coords, features = grid
    conv = SubmanifoldConv(3, 4, bias=True).double()
    with torch.no_grad():
        conv.bias.copy_(torch.randn(4, dtype=torch.float64))
    x = sparse_input(coords, features)
    expected = F.conv3d(dense, dense_weight(conv.weight, 3), conv.bias, padding=1)
    torch.testing.assert_close(conv(x).features, at(expected, x.cmap.coords))


def test_strided_conv_equals_a_dense_stride_two_convolution(grid) -> None:
    dense, coords, features = grid
    conv = DownConv(3, 5).double()
    coarse, link = conv(sparse_input(coords, features))
    expected = F.conv3d(dense, dense_weight(conv.weight, 2), stride=2)
    assert coarse.cmap.stride == 2 and len(link.parent) == len(coords)
    torch.testing.assert_close(coarse.features, at(expected, coarse.cmap.coords, stride=2))
    # Exactly the coarse cells holding an occupied voxel are active.
    occupied = F.max_pool3d((dense.abs().sum(1, keepdim=True) > 0).double(), 2)
    assert len(coarse.cmap) == int(occupied.sum())


def test_transposed_conv_equals_a_dense_transposed_convolution(grid) -> None:
    dense, coords, features = grid
    down, up = DownConv(3, 5).double(), UpConv(5, 2).double()
    coarse, link = down(sparse_input(coords, features))
    fine = up(coarse, link)
    dense_coarse = F.conv3d(dense, dense_weight(down.weight, 2), stride=2)
    expected = F.conv_transpose3d(dense_coarse, up.weight.permute(1, 2, 0).reshape(5, 2, 2, 2, 2), stride=2)
    assert fine.cmap is link.fine
    torch.testing.assert_close(fine.features, at(expected, fine.cmap.coords))


def test_a_second_level_conv_uses_neighbours_two_voxels_apart(grid) -> None:
    dense, coords, features = grid
    down, conv = DownConv(3, 4).double(), SubmanifoldConv(4, 2).double()
    coarse, _ = down(sparse_input(coords, features))
    dense_coarse = F.conv3d(dense, dense_weight(down.weight, 2), stride=2)
    expected = F.conv3d(dense_coarse, dense_weight(conv.weight, 3), padding=1)
    torch.testing.assert_close(conv(coarse).features, at(expected, coarse.cmap.coords, stride=2))


def test_clouds_of_a_batch_do_not_see_each_other(grid) -> None:
    _, coords, features = grid
    conv = SubmanifoldConv(3, 4).double()
    alone = conv(sparse_input(coords, features)).features
    twice = torch.cat([coords, coords + torch.tensor([1, 0, 0, 0])])
    both = conv(sparse_input(twice, torch.cat([features, 2 * features])))
    torch.testing.assert_close(both.features[: len(coords)], alone)
    torch.testing.assert_close(both.features[len(coords) :], 2 * alone)


def test_the_order_of_the_input_voxels_does_not_matter(grid) -> None:
    _, coords, features = grid
    conv = SubmanifoldConv(3, 4).double()
    a, b = conv(sparse_input(coords, features)), conv(sparse_input(coords, features, shuffle=1))
    torch.testing.assert_close(a.cmap.coords, b.cmap.coords, rtol=0, atol=0)
    torch.testing.assert_close(a.features, b.features)


def test_coordinates_out_of_range_are_refused() -> None:
    far = torch.tensor([[0, 1 << 19, 0, 0]])
    with pytest.raises(ParameterError, match="within"):
        voxel_map(far)
    with pytest.raises(ParameterError, match="batch"):
        voxel_map(torch.tensor([[-1, 0, 0, 0]]))
