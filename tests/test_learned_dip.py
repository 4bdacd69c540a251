"""DIP: local reference frames, patches, the PointNet descriptor and its saved weights."""

from __future__ import annotations

import numpy as np
import pytest
import torch
from scipy.spatial.transform import Rotation

from coindie.errors import CoinDieError, ParameterError
from coindie.registration.clouds import Cloud
from coindie.registration.learned.dip import DIPConfig, DIPDescriptor, load_model, save_model
from coindie.registration.learned.dip_network import DIPNet, embed
from coindie.registration.learned.lrf import canonical_patches, local_frames, patch_indices, patches, to_local
from coindie.transforms import euler_rigid, transform_points
from synthetic_pairs import make_coin_pair

RADIUS = 1.0
SMALL = DIPConfig(radius=RADIUS, n_points=64, widths=(16, 32), head=(16,), dim=32)


def bumpy_patches(rng: np.random.Generator, m: int = 20, n: int = 200) -> tuple[np.ndarray, np.ndarray]:
    """(m, n, 3) points on uneven surfaces z = f(x, y) within RADIUS of the origin, and their centres."""
    xy = rng.uniform(-0.7, 0.7, (m, n, 2))
    a, b, c = (rng.uniform(0.2, 0.5, (m, 1)) for _ in range(3))
    z = a * xy[..., 0] ** 2 - b * xy[..., 1] ** 2 + c * xy[..., 0] * xy[..., 1] ** 2 + 0.3 * xy[..., 0]
    points = np.concatenate([xy, z[..., None]], axis=2)
    return points, np.zeros((m, 3))


def random_rotation(seed: int) -> np.ndarray:
    return Rotation.random(random_state=seed).as_matrix()


@pytest.mark.numeric  # local frames from covariances (eigh)
def test_a_rotated_patch_has_a_rotated_frame_and_the_same_local_coordinates() -> None:
    points, centres = bumpy_patches(np.random.default_rng(0))
    normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))
    R, shift = random_rotation(1), np.array([3.0, -7.0, 12.0])
    moved, moved_centres = points @ R.T + shift, centres @ R.T + shift
    frames = local_frames(points, centres, RADIUS, normals)
    moved_frames = local_frames(moved, moved_centres, RADIUS, normals @ R.T)
    np.testing.assert_allclose(moved_frames, R @ frames, atol=1e-9)
    np.testing.assert_allclose(
        to_local(moved, moved_centres, moved_frames), to_local(points, centres, frames), atol=1e-6
    )


@pytest.mark.numeric  # local frames from covariances (eigh)
def test_frames_are_right_handed_rotations_with_z_along_the_given_normal() -> None:
    points, centres = bumpy_patches(np.random.default_rng(2))
    for normal in ([0.0, 0.0, 1.0], [0.0, 0.0, -1.0]):
        frames = local_frames(points, centres, RADIUS, np.tile(normal, (len(points), 1)))
        np.testing.assert_allclose(
            frames.transpose(0, 2, 1) @ frames, np.broadcast_to(np.eye(3), frames.shape), atol=1e-12
        )
        np.testing.assert_allclose(np.linalg.det(frames), 1.0, atol=1e-12)
        assert np.all(frames[:, :, 2] @ normal > 0.9)


def test_x_points_toward_the_part_of_the_patch_that_leaves_the_plane() -> None:
    # A flat disc with one bump in direction (cos 40°, sin 40°): the height weights pull x toward it.
    rng = np.random.default_rng(3)
    xy = rng.uniform(-0.7, 0.7, (1, 500, 2))
    towards = np.array([np.cos(np.radians(40)), np.sin(np.radians(40))])
    z = 0.2 * np.exp(-((xy - 0.5 * towards) ** 2).sum(axis=2) / 0.02)
    frames = local_frames(
        np.concatenate([xy, z[..., None]], axis=2), np.zeros((1, 3)), RADIUS, np.array([[0, 0, 1.0]])
    )
    assert frames[0, :2, 0] @ towards > 0.95


def test_patches_draw_distinct_points_when_enough_and_all_points_plus_repeats_otherwise() -> None:
    rng = np.random.default_rng(4)
    cloud = rng.uniform(-3, 3, (4000, 3))
    centres = np.array([[0.0, 0.0, 0.0], [2.9, 2.9, 2.9], [50.0, 0.0, 0.0]])
    found = patch_indices(cloud, centres, 1.0, 64, rng)
    in_reach = [np.flatnonzero(np.linalg.norm(cloud - c, axis=1) <= 1.0) for c in centres]
    assert len(in_reach[0]) > 64 and 0 < len(in_reach[1]) < 64
    assert len(set(found[0])) == 64 and set(found[0]) <= set(in_reach[0])
    assert set(found[1]) == set(in_reach[1])
    assert np.all(found[2] == -1)
    gathered = patches(cloud, centres, 1.0, 64, np.random.default_rng(5))
    assert gathered.shape == (3, 64, 3)
    np.testing.assert_array_equal(gathered[2], np.tile(centres[2], (64, 1)))


def test_degenerate_patches_get_finite_frames_and_descriptors() -> None:
    line = np.column_stack([np.linspace(-0.5, 0.5, 64), np.zeros(64), np.zeros(64)])
    single = np.zeros((64, 3))
    flat = np.column_stack([np.random.default_rng(6).uniform(-0.5, 0.5, (64, 2)), np.zeros(64)])
    points = np.stack([line, single, flat])
    frames = local_frames(points, np.zeros((3, 3)), RADIUS, np.tile([0.0, 0.0, 1.0], (3, 1)))
    np.testing.assert_allclose(
        frames.transpose(0, 2, 1) @ frames, np.broadcast_to(np.eye(3), (3, 3, 3)), atol=1e-12
    )
    assert np.all(np.isfinite(to_local(points, np.zeros((3, 3)), frames)))
    descriptors = embed(DIPNet(SMALL), to_local(points, np.zeros((3, 3)), frames) / RADIUS)
    assert np.all(np.isfinite(descriptors))


@pytest.fixture(scope="module")
def coin() -> Cloud:
    return Cloud.of(make_coin_pair(seed=1, radius=4.0).target)


@pytest.fixture(scope="module")
def network() -> DIPNet:
    torch.manual_seed(0)
    model = DIPNet(SMALL)
    _settle_batch_norm(model)
    return model


def _settle_batch_norm(model: DIPNet) -> None:
    """Give the batch-norm layers non-trivial running statistics, as training would."""
    model.train()
    with torch.no_grad():
        model(torch.randn(64, SMALL.n_points, 3) * 0.4)
    model.eval()


def test_descriptors_of_a_moved_cloud_are_unchanged_and_unit_norm(coin: Cloud, network: DIPNet) -> None:
    T = euler_rigid((20, -10, 135), (3, 4, 5))
    moved = Cloud(transform_points(T, coin.points), coin.normals @ T[:3, :3].T)
    dip = DIPDescriptor(voxel=0, model=network, batch=100)
    at = np.arange(0, len(coin.points), 53)
    descriptors = dip.describe(coin, at)
    assert descriptors.shape == (len(at), SMALL.dim)
    np.testing.assert_allclose(np.linalg.norm(descriptors, axis=1), 1.0, atol=1e-5)
    np.testing.assert_allclose(dip.describe(moved, at), descriptors, atol=1e-5)
    # Distinct places get distinct descriptors (the invariance is not from a constant output).
    assert np.median(np.linalg.norm(descriptors[1:] - descriptors[:-1], axis=1)) > 1e-3


def test_saved_weights_load_into_a_network_with_identical_outputs(
    tmp_path, coin: Cloud, network: DIPNet
) -> None:
    weights = save_model(tmp_path / "dip", network, SMALL)
    assert weights.is_file() and weights.with_suffix(".json").is_file()
    loaded = load_model(weights)
    assert loaded.config == SMALL
    at = np.arange(0, len(coin.points), 211)
    patch = canonical_patches(
        coin.points, coin.points[at], coin.normals[at], RADIUS, SMALL.n_points, np.random.default_rng(0)
    )
    np.testing.assert_array_equal(embed(loaded, patch), embed(network, patch))
    from_file = DIPDescriptor(voxel=0, weights=str(weights))
    np.testing.assert_array_equal(
        from_file.describe(coin, at), DIPDescriptor(voxel=0, model=network).describe(coin, at)
    )


def test_missing_or_foreign_weights_are_clear_errors(tmp_path, coin: Cloud) -> None:
    with pytest.raises(CoinDieError, match="no DIP weights"):
        DIPDescriptor(weights=str(tmp_path / "absent.safetensors")).describe(coin, np.arange(3))
    save_model(tmp_path / "other", DIPNet(DIPConfig(widths=(8,), head=(), dim=32)), SMALL)
    with pytest.raises(CoinDieError, match="other.safetensors"):
        load_model(tmp_path / "other.safetensors")
    (tmp_path / "bad.safetensors").write_bytes(b"x")
    (tmp_path / "bad.json").write_text('{"colour": 1}')
    with pytest.raises(CoinDieError, match="bad.json"):
        load_model(tmp_path / "bad.safetensors")


def test_the_configuration_round_trips_through_json() -> None:
    assert DIPConfig.from_json(SMALL.to_json()) == SMALL
    with pytest.raises(CoinDieError, match="radius"):
        DIPConfig(radius=0)


def test_the_support_is_the_cloud_on_the_voxel_grid(coin: Cloud) -> None:
    support = DIPDescriptor(voxel=0.3, model=DIPNet(SMALL)).support(coin)
    assert len(support.points) < len(coin.points)
    keys = np.floor(support.points / 0.3).astype(np.int64)
    assert len(np.unique(keys, axis=0)) == len(keys)


def test_inference_folds_batch_norm_without_changing_the_network(network: DIPNet) -> None:
    patch = torch.randn(5, SMALL.n_points, 3) * 0.4
    with torch.no_grad():
        x = patch
        for dense in network.points:
            x = torch.relu(dense.norm(dense.linear(x.reshape(-1, x.shape[-1]))).reshape(*x.shape[:-1], -1))
        x = x.max(dim=1).values
        for layer in network.head:
            x = torch.relu(layer.norm(layer.linear(x))) if hasattr(layer, "norm") else layer(x)
        expected = torch.nn.functional.normalize(x, dim=1)
        torch.testing.assert_close(network(patch), expected, atol=1e-5, rtol=1e-5)


# ------------------------------------------------------------------------------------------ training

TRAINABLE = DIPConfig(radius=1.5, n_points=64, voxel=0.2, widths=(16, 32), head=(32,), dim=16)


def test_training_steps_lower_the_loss_of_a_pair_of_faces(training_hoard) -> None:
    from coindie.registration.learned.learners import DIPLearner
    from coindie.registration.learned.pairs import VALIDATION, PairSet
    from coindie.registration.learned.train import TrainOptions

    pair = PairSet(training_hoard, voxel=TRAINABLE.voxel).make(0, [0, 1, 0], VALIDATION)
    options = TrainOptions(model=TRAINABLE, patches=128)
    learner = DIPLearner()
    model = learner.new(TRAINABLE, seed=0)
    optimizer = torch.optim.SGD(model.parameters(), lr=0.1, momentum=0.8)

    def loss() -> torch.Tensor:  # the same patches every step: an overfit problem
        return learner.losses(model, [pair], options, torch.Generator().manual_seed(5))["loss"]

    model.train()
    first = float(loss().detach())
    for _ in range(25):
        optimizer.zero_grad()
        value = loss()
        value.backward()
        optimizer.step()
    assert float(loss().detach()) < 0.7 * first


def test_a_training_run_writes_a_model_that_the_descriptor_loads(training_hoard, tmp_path) -> None:
    from coindie.registration.learned.train import DIP_MODEL, TrainOptions, train_dip

    options = TrainOptions(model=TRAINABLE, epochs=2, max_pairs=1, fmr_points=300, patches=64)
    log = train_dip(training_hoard, tmp_path / "run", options)
    assert [r["epoch"] for r in log] == [1, 2] and 0 <= log[-1]["val"]["fmr"] <= 1
    weights = tmp_path / "run" / DIP_MODEL
    dip = DIPDescriptor(weights=str(weights))
    assert dip.network.config == TRAINABLE
    coin = Cloud.of(make_coin_pair(seed=2, radius=3.0).target)
    support = dip.support(coin)
    assert dip.describe(support, np.arange(10)).shape == (10, TRAINABLE.dim)
    with pytest.raises(ParameterError, match="DIPConfig"):
        train_dip(training_hoard, tmp_path / "other", TrainOptions(epochs=1))
