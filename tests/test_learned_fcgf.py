"""FCGF: descriptor shapes and invariances, the loss on a tiny overfit problem, model files, training runs."""

from __future__ import annotations

import json

import numpy as np
import pytest

torch = pytest.importorskip("torch")
pytest.importorskip("safetensors")

from safetensors.torch import load_file  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402
from typer.testing import CliRunner  # noqa: E402

from coindie.errors import ParameterError  # noqa: E402
from coindie.registration.clouds import Cloud  # noqa: E402
from coindie.registration.learned import fcgf as fcgf_module  # noqa: E402
from coindie.registration.learned.fcgf import (  # noqa: E402
    FCGFConfig,
    FCGFDescriptor,
    ModelFileError,
    describe_cloud,
    load_model,
    new_model,
    save_model,
)
from coindie.registration.learned.losses import ContrastiveLoss  # noqa: E402
from coindie.registration.learned.train import CHECKPOINT, CURVES, LOG, MODEL, TrainOptions, train_fcgf  # noqa: E402

#: A coarse voxel keeps the clouds small (~1-4k voxels) so that every test runs in seconds.
COARSE = FCGFConfig(voxel=0.3)


@pytest.fixture(autouse=True)
def _one_thread():
    threads = torch.get_num_threads()
    torch.set_num_threads(1)  # the test machine is shared: several threads only wait on each other
    yield
    torch.set_num_threads(threads)


@pytest.fixture(scope="module")
def surface() -> np.ndarray:
    """A wavy 8 x 8 mm patch, 6000 points (mm)."""
    rng = np.random.default_rng(0)
    xy = rng.uniform(-4, 4, (6000, 2))
    z = 0.4 * np.sin(1.5 * xy[:, 0]) * np.cos(2 * xy[:, 1]) + 0.2 * np.sin(3 * xy[:, 1])
    return np.column_stack([xy, z])


@pytest.fixture(scope="module")
def hoard(training_hoard):
    return training_hoard


def test_descriptors_are_unit_vectors_one_per_point_shared_within_a_voxel(surface) -> None:
    model = new_model(COARSE).eval()
    descriptors = describe_cloud(model, surface)
    assert descriptors.shape == (len(surface), 32)
    np.testing.assert_allclose(np.linalg.norm(descriptors, axis=1), 1.0, atol=1e-5)
    cells = np.floor(surface / COARSE.voxel).astype(np.int64)
    _, first, inverse = np.unique(cells, axis=0, return_index=True, return_inverse=True)
    np.testing.assert_array_equal(descriptors, descriptors[first][inverse.ravel()])
    assert np.ptp(descriptors, axis=0).max() > 0.1  # not one constant vector


def test_descriptors_do_not_depend_on_the_order_of_the_points(surface) -> None:
    model = new_model(COARSE).eval()
    order = np.random.default_rng(1).permutation(len(surface))
    np.testing.assert_allclose(
        describe_cloud(model, surface[order]), describe_cloud(model, surface)[order], atol=1e-6
    )


def test_a_batch_of_clouds_gives_each_cloud_its_own_descriptors(surface) -> None:
    model = new_model(COARSE).eval()
    points = torch.as_tensor(np.concatenate([surface, surface[:3000]]))
    batch = torch.cat([torch.zeros(len(surface)), torch.ones(3000)]).long()
    with torch.no_grad():
        both = model.describe_points(points, batch).numpy()
    np.testing.assert_allclose(both[: len(surface)], describe_cloud(model, surface), atol=1e-5)
    np.testing.assert_allclose(both[len(surface) :], describe_cloud(model, surface[:3000]), atol=1e-5)


def test_the_model_has_the_announced_size() -> None:
    parameters = sum(p.numel() for p in new_model().parameters())
    assert 1_000_000 < parameters < 2_000_000  # ~6.6 MB in float32


def test_training_steps_lower_the_contrastive_loss_of_a_pair(surface) -> None:
    turn = Rotation.from_euler("xyz", [10, -5, 60], degrees=True).as_matrix()
    target = surface @ turn.T + [1.0, 2.0, 0.5]
    x = torch.as_tensor(np.concatenate([surface, target]))
    batch = torch.cat([torch.zeros(len(surface)), torch.ones(len(target))]).long()
    matches = torch.arange(len(surface))[:, None].repeat(1, 2)
    loss = ContrastiveLoss(n_positives=512, n_candidates=128, negative_radius=0.5)
    model = new_model(COARSE)
    optimizer = torch.optim.SGD(model.parameters(), lr=0.1, momentum=0.8, weight_decay=1e-4)

    def pair_loss(seed: int) -> torch.Tensor:
        f_source, f_target = model.describe_points(x, batch).split(len(surface))
        return loss(
            f_source,
            f_target,
            matches,
            x[: len(surface)],
            x[len(surface) :],
            torch.Generator().manual_seed(seed),
        )["loss"]

    with torch.no_grad():
        before = float(pair_loss(99))
    for step in range(10):
        optimizer.zero_grad()
        pair_loss(step).backward()
        optimizer.step()
    with torch.no_grad():
        after = float(pair_loss(99))
    assert after < 0.9 * before


def test_the_loss_is_zero_for_perfect_descriptors_and_sees_hard_negatives() -> None:
    x = torch.arange(32, dtype=torch.float64)[:, None] * torch.tensor([[1.0, 0.0, 0.0]])  # 1 mm apart
    perfect = torch.eye(32)  # orthonormal: every other point is sqrt(2) > m- = 1.4 away
    matches = torch.arange(32)[:, None].repeat(1, 2)
    loss = ContrastiveLoss(n_candidates=32, negative_radius=0.5)
    assert float(loss(perfect, perfect, matches, x, x)["loss"]) == pytest.approx(0.0, abs=1e-5)
    confused = perfect.clone()
    confused[1] = confused[0]  # point 1 looks like point 0: a hard negative of 0
    terms = loss(confused, confused, matches, x, x)
    assert float(terms["negative"]) > 0 and float(terms["positive"]) == pytest.approx(0.0, abs=1e-5)


def test_a_saved_model_loads_with_the_same_weights_and_config(surface, tmp_path) -> None:
    model = new_model(FCGFConfig(voxel=0.3, channels=(8, 16, 32), out_dim=16), seed=4).eval()
    path = save_model(model, tmp_path / "m.safetensors", {"note": "test"})
    header = json.loads((tmp_path / "m.json").read_text())
    assert header["config"] == {
        "voxel": 0.3,
        "channels": [8, 16, 32],
        "out_dim": 16,
        "in_channels": 1,
        "level": False,
        "spins": 1,
    }
    loaded = load_model(path)
    assert loaded.config == model.config and not loaded.training
    for key, value in model.state_dict().items():
        torch.testing.assert_close(loaded.state_dict()[key], value, rtol=0, atol=0)
    np.testing.assert_array_equal(describe_cloud(loaded, surface), describe_cloud(model, surface))


def test_broken_model_files_get_clear_errors(tmp_path) -> None:
    with pytest.raises(ModelFileError, match="no such model file"):
        load_model(tmp_path / "none.safetensors")
    path = save_model(new_model(COARSE), tmp_path / "m.safetensors")
    (tmp_path / "m.json").write_text(
        '{"format": "other", "config": {"voxel": 0.1, "channels": [4, 8], "out_dim": 8}}'
    )
    with pytest.raises(ModelFileError, match="format"):
        load_model(path)
    (tmp_path / "m.json").write_text(
        json.dumps({"format": "coindie-fcgf", "config": FCGFConfig(channels=(4, 8)).to_json()})
    )
    with pytest.raises(ModelFileError, match="do not fit"):
        load_model(path)
    (tmp_path / "m.json").unlink()
    with pytest.raises(ModelFileError, match="JSON config"):
        load_model(path)


def test_the_descriptor_part_reads_a_model_file_and_says_when_weights_are_missing(
    surface, tmp_path, monkeypatch
) -> None:
    path = save_model(new_model(COARSE).eval(), tmp_path / "m.safetensors")
    extractor = FCGFDescriptor(weights=str(path))
    cloud = Cloud(surface, np.tile([0.0, 0.0, 1.0], (len(surface), 1)))
    support = extractor.support(cloud)
    assert len(support.points) < len(surface)  # one point per occupied 0.3 mm voxel
    at = np.arange(0, len(support.points), 7)
    descriptors = extractor.describe(support, at)
    assert descriptors.shape == (len(at), 32) and descriptors.dtype == np.float64
    np.testing.assert_allclose(extractor.describe(support, at[:3]), descriptors[:3])
    monkeypatch.setattr(fcgf_module, "SHIPPED_WEIGHTS", tmp_path / "absent" / "fcgf.safetensors")
    with pytest.raises(ModelFileError, match="coindie train fcgf"):
        FCGFDescriptor().support(cloud)
    with pytest.raises(ParameterError, match="device"):
        FCGFDescriptor(device="tpu")


def test_training_writes_its_files_and_a_resumed_run_ends_where_an_uninterrupted_one_does(
    hoard, tmp_path
) -> None:
    options = TrainOptions(epochs=3, model=COARSE, fmr_points=500, max_pairs=1)
    straight = train_fcgf(hoard, tmp_path / "straight", options)
    assert [r["epoch"] for r in straight] == [1, 2, 3]
    for name in (CHECKPOINT, LOG, CURVES, MODEL):
        assert (tmp_path / "straight" / name).is_file()
    assert straight[-1]["val"]["pairs"] == 1 and 0 <= straight[-1]["val"]["fmr"] <= 1

    first = train_fcgf(
        hoard, tmp_path / "resumed", TrainOptions(epochs=2, model=COARSE, fmr_points=500, max_pairs=1)
    )
    assert len(first) == 2
    with pytest.raises(ParameterError, match="resume"):
        train_fcgf(hoard, tmp_path / "resumed", options)
    resumed = train_fcgf(hoard, tmp_path / "resumed", options, resume=True)
    assert [r["epoch"] for r in resumed] == [1, 2, 3]
    assert resumed[:2] == json.loads(json.dumps(first))
    assert resumed[-1]["train"]["loss"] == pytest.approx(straight[-1]["train"]["loss"], rel=1e-5)
    # Same weights and optimizer state at the end (momentum buffers included).
    a, b = (load_file(str(tmp_path / run / CHECKPOINT)) for run in ("straight", "resumed"))
    assert a.keys() == b.keys() and any(k.startswith("optimizer.") for k in a)
    for key, value in a.items():
        torch.testing.assert_close(b[key], value, rtol=1e-4, atol=1e-6)


def test_the_train_command_runs_and_refuses_bad_options(hoard, tmp_path) -> None:
    from coindie.cli import train as _train  # noqa: F401  (registers `coindie train`)
    from coindie.cli.app import app

    args = [
        "train",
        "fcgf",
        str(hoard),
        "--out",
        str(tmp_path / "m"),
        "--epochs",
        "1",
        "--voxel",
        "0.3",
        "--quiet",
    ]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "epoch 1:" in result.output and (tmp_path / "m" / MODEL).is_file()
    again = CliRunner().invoke(app, args)
    assert again.exit_code == 2 and "resume" in again.output
    bad = CliRunner().invoke(app, [*args[:5], "--channels", "16,x"])
    assert bad.exit_code == 2 and "--channels" in bad.output
    assert CliRunner().invoke(app, [*args[:5], "--lr", "0"]).exit_code == 2
