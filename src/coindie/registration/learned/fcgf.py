"""Fully Convolutional Geometric Features (Choy et al. 2019): a sparse U-Net giving each voxel a unit
32-d descriptor, as the Riedones3D paper uses it (voxel 0.1 mm, input feature "ones").

The network (:class:`~coindie.registration.learned.fcgf_network.FCGFNet`) is smaller than the original (8.8 M
parameters, kernel 7 first layer) so that it trains on a CPU: encoder channels 16-32-64-128 over four levels
(0.1, 0.2, 0.4, 0.8 mm voxels), each level a 3x3x3 convolution or a stride-2 2x2x2 convolution then a
residual block of two 3x3x3 convolutions; a decoder of transposed convolutions whose outputs are joined to
the encoder's (skip connections) and fused by a 3x3x3 convolution; a per-voxel head of two linear layers;
unit-normalised outputs. About 1.7 M parameters (6.6 MB in float32). Its receptive field spans ~5 mm, a few
letters or a curl of hair.

The paper's FCGF learns invariance to rotations from augmentation alone; on a CPU it does not (its held-out
inlier ratio stays at chance, docs/learned.md), so a model can instead level each face (its fitted plane
to z = 0: exact invariance to tilts) and learn only small turns about the coin's axis (±180°/``spins``),
the target then being described at ``spins`` turns and matched against all of them
(:mod:`coindie.registration.learned.turns`). The shipped model does so with 16 turns.

:class:`FCGFDescriptor` is the registration's :class:`~coindie.registration.features.FeatureExtractor`:
descriptors of the cloud grid-sampled at the model's voxel, from the shipped weights
(``weights/fcgf.safetensors`` and its ``fcgf.json``) or from a model file given as ``weights``.
Model files are a safetensors state dict with a JSON config beside it: no pickled objects.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from coindie.arrays import FloatArray, IntArray
from coindie.errors import CoinDieError, ParameterError
from coindie.params import Configurable, param
from coindie.registration.clouds import Cloud, content_key
from coindie.registration.learned.cache import DescriptorCache
from coindie.transforms import transform_points

if TYPE_CHECKING:
    import torch

#: The shipped model: a safetensors state dict and its JSON config.
SHIPPED_WEIGHTS = Path(__file__).parent / "weights" / "fcgf.safetensors"
FORMAT = "coindie-fcgf"
#: Support clouds whose descriptors are kept (an all-pairs study meets every face many times).
_DESCRIPTOR_CACHE_SIZE = 8


class ModelFileError(CoinDieError, ValueError):
    """A model file is missing or is not a coindie FCGF model."""

    def __init__(self, problem: str, path: str | Path) -> None:
        self.path, self.problem = Path(path), problem
        super().__init__(f"{self.path}: {problem}")


@dataclass(frozen=True)
class FCGFConfig(Configurable):
    """The architecture and its input (saved with the weights: a model is rebuilt from it).

    ``level`` and ``spins`` are coindie's answer to what a CPU can learn (docs/learned.md): the network's
    descriptors do not learn invariance to turns about the coin's axis from augmentation within CPU hours
    (held-out inlier ratio at chance after 3,000 steps of the paper's ±180° training, while pairs turned
    alike learn at once), so a model may instead be trained on pairs turned alike up to ±180°/``spins``,
    and describe the target face at ``spins`` turns about its axis when matching. ``level`` turns each
    face so that its fitted plane is z = 0 before voxelising: the invariance to tilts is then exact.
    ``spins = 1`` and ``level = False`` is the paper's FCGF."""

    voxel: float = param(0.1, doc="the finest grid", unit="mm", low=0.0, low_open=True)
    channels: tuple[int, ...] = param(
        (16, 32, 64, 128),
        doc="encoder channels per level (stride 1, 2, 4, ...)",
        item=int,
        low=1,
        min_length=1,
    )
    out_dim: int = param(32, doc="descriptor length", low=1)
    in_channels: int = param(1, doc='input features per voxel (the input feature is "ones")', low=1)
    level: bool = param(False, doc="turn each face's fitted plane to z = 0 before voxelising")
    spins: int = param(1, doc="turns of the target about its axis searched when matching (1: none)", low=1)

    @property
    def turn_tolerance_deg(self) -> float:
        """The largest turn between the two faces of a training pair: half the step between spins."""
        return 180.0 / self.spins

    def to_json(self) -> dict[str, Any]:
        return asdict(self) | {"channels": list(self.channels)}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> FCGFConfig:
        return cls(
            voxel=float(data["voxel"]),
            channels=tuple(int(c) for c in data["channels"]),
            out_dim=int(data["out_dim"]),
            in_channels=int(data.get("in_channels", 1)),
            level=bool(data.get("level", False)),
            spins=int(data.get("spins", 1)),
        )


def levelling(points: FloatArray, normals: FloatArray) -> FloatArray:
    """``T_level_cloud``: the smallest rotation, about the centroid, that turns the face's robustly
    fitted plane (:func:`coindie.preprocess.canonical.canonical_frame`) to z, face up. The smallest one
    keeps the face's own turn about its axis (no canonical spin is imposed)."""
    from coindie.preprocess.canonical import canonical_frame
    from coindie.scan import Scan
    from coindie.transforms import rigid, rotation_between

    frame = canonical_frame(Scan(points=points, normals=normals))
    up = frame.T_canonical_scan[:3, :3].T @ np.array([0.0, 0.0, 1.0])
    R = rotation_between(up, np.array([0.0, 0.0, 1.0]))
    centre = points.mean(axis=0)
    return rigid(R, centre - R @ centre)


def spin(angle_deg: float, centre: FloatArray) -> FloatArray:
    """The 4x4 turn by ``angle_deg`` about the z axis through ``centre``."""
    from coindie.transforms import rigid

    c, s = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return rigid(R, centre - R @ centre)


def _build_network(config: FCGFConfig) -> torch.nn.Module:
    from coindie.registration.learned.fcgf_network import (
        FCGFNet,  # torch is imported here, not with this module
    )

    return FCGFNet(config)


def new_model(config: FCGFConfig | None = None, seed: int = 0) -> torch.nn.Module:
    """A freshly initialised network (weights drawn from ``seed``)."""
    import torch

    with torch.random.fork_rng(devices=[]):
        torch.manual_seed(seed)
        return _build_network(config or FCGFConfig())


def count_parameters(model: torch.nn.Module) -> int:
    return sum(p.numel() for p in model.parameters())


def config_path(weights: str | Path) -> Path:
    """The JSON config beside a model's safetensors file."""
    return Path(weights).with_suffix(".json")


def save_model(model: torch.nn.Module, path: str | Path, info: dict[str, Any] | None = None) -> Path:
    """Write ``path`` (safetensors state dict) and its JSON config beside it; returns ``path``."""
    from safetensors.torch import save_file

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    state = {k: v.detach().cpu().contiguous() for k, v in model.state_dict().items()}
    save_file(state, str(path.with_suffix(".tmp")))
    path.with_suffix(".tmp").replace(path)
    header = {"format": FORMAT, "version": 1, "config": model.config.to_json(), "info": info or {}}
    config_path(path).write_text(json.dumps(header, indent=1) + "\n")
    return path


def read_header(path: str | Path) -> dict[str, Any]:
    """The JSON config of a model file, checked."""
    header_path = config_path(path)
    if not header_path.is_file():
        raise ModelFileError("missing: a model's JSON config must sit beside its .safetensors", header_path)
    try:
        header = json.loads(header_path.read_text())
        FCGFConfig.from_json(header["config"])
    except (json.JSONDecodeError, KeyError, TypeError, ValueError) as error:
        raise ModelFileError(
            f"not an FCGF model config ({type(error).__name__}: {error})", header_path
        ) from None
    if header.get("format") != FORMAT:
        raise ModelFileError(f"format is {header.get('format')!r}, expected {FORMAT!r}", header_path)
    return header


def load_model(path: str | Path, device: str = "cpu") -> torch.nn.Module:
    """The network saved by :func:`save_model`, in evaluation mode on ``device``."""
    from safetensors import SafetensorError
    from safetensors.torch import load_file

    path = Path(path)
    if not path.is_file():
        raise ModelFileError("no such model file", path)
    model = _build_network(FCGFConfig.from_json(read_header(path)["config"]))
    try:
        state = load_file(str(path))
    except (SafetensorError, OSError) as error:
        raise ModelFileError(f"not a safetensors file ({error})", path) from None
    try:
        model.load_state_dict(state)
    except RuntimeError as error:
        first = str(error).splitlines()[0]
        raise ModelFileError(f"weights do not fit the config beside them ({first})", path) from None
    return model.to(device).eval()


def _cuda_available() -> bool:
    import torch

    return torch.cuda.is_available()


@lru_cache(maxsize=4)
def _cached_model(path: str, device: str) -> torch.nn.Module:
    return load_model(path, device)


_descriptor_cache = DescriptorCache(_DESCRIPTOR_CACHE_SIZE)


@dataclass(frozen=True, kw_only=True)
class FCGFDescriptor(Configurable):
    """FCGF descriptors (32-d, unit norm) on the cloud grid-sampled at the model's voxel (0.1 mm)."""

    NAME = "fcgf"

    weights: str = param(
        "", kind=str, doc="model file (.safetensors, its .json beside it); empty: the shipped weights"
    )
    device: str = param("cpu", kind=str, choices=("cpu", "cuda"), doc="where the network runs")
    threads: int = param(
        1,
        low=0,
        doc="PyTorch CPU threads (0: its default; 1 is fastest when pairs run in parallel processes)",
    )

    @property
    def weights_path(self) -> Path:
        return Path(self.weights) if self.weights else SHIPPED_WEIGHTS

    def model(self) -> torch.nn.Module:
        path = self.weights_path
        if not self.weights and not path.is_file():
            raise ModelFileError(
                "no shipped FCGF weights; train them with `coindie train fcgf HOARD --out DIR` and copy "
                "DIR/fcgf.safetensors and DIR/fcgf.json here, or pass fcgf.weights=PATH",
                path,
            )
        if self.device == "cuda" and not _cuda_available():
            raise ParameterError("fcgf.device is 'cuda' but this PyTorch build sees no CUDA device")
        return _cached_model(str(path.resolve()), self.device)

    def support(self, cloud: Cloud) -> Cloud:
        from coindie.registration.features import grid_support

        return grid_support(cloud, self.model().config.voxel)

    def describe(self, support: Cloud, at: IntArray) -> FloatArray:
        """Descriptors of the face as it lies (the source's: one pass of the network)."""
        return self._views(support, 1)[0][at]

    def describe_views(self, support: Cloud, at: IntArray) -> FloatArray:
        """(spins, len(at), D): the descriptors of the points ``at`` with the face turned by
        ``k * 360° / spins`` about its axis, k = 0..spins-1 (one view when the model has ``spins = 1``)."""
        return self._views(support, self.model().config.spins)[:, at]

    def _views(self, support: Cloud, spins: int) -> FloatArray:
        def compute() -> FloatArray:
            with torch_threads(self.threads):
                return describe_views(self.model(), support.points, support.normals, self.device, spins)

        key = (str(self.weights_path), self.device, spins, content_key(support.points))
        return _descriptor_cache.get(key, compute)


def describe_cloud(
    model: torch.nn.Module, points: FloatArray, device: str = "cpu", normals: FloatArray | None = None
) -> FloatArray:
    """(N, out_dim) float64 descriptors of an (N, 3) cloud in mm, by a model in evaluation mode (unit
    normals needed when the model levels its input)."""
    return describe_views(model, points, normals, device, spins=1)[0]


def describe_views(
    model: torch.nn.Module,
    points: FloatArray,
    normals: FloatArray | None,
    device: str = "cpu",
    spins: int | None = None,
) -> FloatArray:
    """(spins, N, out_dim) descriptors of an (N, 3) cloud: levelled when the model's config says so (its
    unit normals are then needed), then turned ``spins`` times (the config's unless given) about its
    axis, all turns through the network in one batch."""
    import torch

    config: FCGFConfig = model.config
    spins = config.spins if spins is None else spins
    if config.level:
        if normals is None:
            raise ParameterError("This FCGF model levels its input: the cloud's normals are needed.")
        points = transform_points(levelling(points, normals), points)
    centre = points.mean(axis=0)
    turned = [transform_points(spin(360.0 * k / spins, centre), points) for k in range(spins)]
    with torch.inference_mode():
        tensor = torch.as_tensor(np.concatenate(turned), dtype=torch.float64, device=device)
        batch = torch.arange(spins, device=device).repeat_interleave(len(points))
        features = model.describe_points(tensor, batch).double().cpu().numpy()
    return features.reshape(spins, len(points), -1)


@contextmanager
def torch_threads(n: int) -> Iterator[None]:
    """PyTorch's CPU threads set to ``n`` (0: unchanged) for the duration."""
    import torch

    before = torch.get_num_threads()
    if n:
        torch.set_num_threads(n)
    try:
        yield
    finally:
        torch.set_num_threads(before)
