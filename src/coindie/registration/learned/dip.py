"""DIP descriptors (Poiesi & Boscaini 2021): a PointNet on patches expressed in their local reference frame.

The network (:class:`~coindie.registration.learned.dip_network.DIPNet`) maps a batch of canonical patches
(points in their local reference frame, :func:`coindie.registration.learned.lrf.canonical_patches`) to unit
descriptors; rotation invariance comes from the frame, not from the network. torch is imported only when a
network is built or loaded, so that registering the methods costs nothing.

``DIPDescriptor`` is the registration-side :class:`~coindie.registration.features.FeatureExtractor`. Its
weights are a safetensors state dict plus a JSON :class:`DIPConfig` next to it (never pickled objects);
the packaged ones live in ``weights/dip.safetensors`` + ``weights/dip.json``.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field, fields
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from coindie.arrays import FloatArray, IntArray
from coindie.errors import CoinDieError
from coindie.params import Configurable, param
from coindie.registration.clouds import Cloud, content_key
from coindie.registration.features import grid_support
from coindie.registration.learned.cache import DescriptorCache
from coindie.registration.learned.lrf import canonical_patches

if TYPE_CHECKING:
    from coindie.registration.learned.dip_network import DIPNet

#: The packaged weights (trained by `coindie train dip`, see BENCHMARK.md).
PACKAGED_WEIGHTS = Path(__file__).parent / "weights" / "dip.safetensors"
#: Descriptors of the last clouds described, per process (see coindie.registration.learned.cache).
_descriptor_cache = DescriptorCache(8)


@dataclass(frozen=True)
class DIPConfig(Configurable):
    """The network's shape and the patch geometry it was trained on (saved with the weights)."""

    radius: float = param(2.0, doc="patch radius", unit="mm", low=0.0, low_open=True)
    n_points: int = param(256, doc="points per patch", low=1)
    voxel: float = param(0.1, doc="grid of the clouds it was trained on", unit="mm", low=0.0)
    widths: tuple[int, ...] = param((32, 64, 128), doc="shared per-point MLP", item=int, low=1, min_length=1)
    head: tuple[int, ...] = param((64,), doc="hidden layers after the max pooling", item=int, low=1)
    dim: int = param(32, doc="descriptor length (FCGF's)", low=1)

    def to_json(self) -> str:
        return json.dumps(asdict(self), indent=2)

    @classmethod
    def from_json(cls, text: str, source: str | Path = "DIP configuration") -> DIPConfig:
        """The configuration from JSON text; a CoinDieError naming ``source`` when it cannot be one."""
        try:
            data = json.loads(text)
            known = {f.name for f in fields(cls)}
            if not isinstance(data, dict) or not set(data) <= known:
                raise ValueError(f"expected an object with keys among {sorted(known)}")
            lists = {key: tuple(int(w) for w in data[key]) for key in ("widths", "head") if key in data}
            return cls(**{**data, **lists})
        except (ValueError, TypeError) as error:
            raise CoinDieError(f"{source}: not a DIP configuration: {error}") from None


def save_model(path: str | Path, model: DIPNet, config: DIPConfig | None = None) -> Path:
    """Write ``path`` (.safetensors, the state dict) and the same name .json (the config); returns the
    weights' path."""
    from safetensors.torch import save_file

    weights = Path(path).with_suffix(".safetensors")
    weights.parent.mkdir(parents=True, exist_ok=True)
    state = {name: tensor.detach().cpu().contiguous() for name, tensor in model.state_dict().items()}
    save_file(state, str(weights))
    weights.with_suffix(".json").write_text((config or model.config).to_json() + "\n")
    return weights


def load_model(path: str | Path) -> DIPNet:
    """The network saved by :func:`save_model` at ``path`` (the .safetensors file or its stem)."""
    from safetensors import SafetensorError
    from safetensors.torch import load_file

    weights = Path(path).with_suffix(".safetensors")
    description = weights.with_suffix(".json")
    for required in (weights, description):
        if not required.is_file():
            raise CoinDieError(
                f"{required}: no such file; DIP weights need {weights.name} and {description.name}"
            )
    from coindie.registration.learned.dip_network import DIPNet

    model = DIPNet(DIPConfig.from_json(description.read_text(), description))
    try:
        model.load_state_dict(load_file(str(weights)))
    except (SafetensorError, RuntimeError) as error:
        raise CoinDieError(f"{weights}: not weights of this DIP network: {_first_line(error)}") from None
    return model.eval()


def _first_line(error: Exception) -> str:
    return str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__


@dataclass(frozen=True, kw_only=True)
class DIPDescriptor(Configurable):
    """DIP descriptors on a coarser grid: random patches around each point, canonicalised, through the
    network. Pass ``model`` (e.g. a network being trained) or let it load ``weights``."""

    NAME = "dip"

    voxel: float = param(
        0.1, unit="mm", low=0, doc="grid size of the support cloud (0: the input points as they are)"
    )
    weights: str = param(
        "", doc="the network's .safetensors file, a .json beside it (empty: the packaged one)"
    )
    batch: int = param(1024, low=1, doc="patches per pass of the network")
    seed: int = param(0, low=0, doc="seed of the points drawn in each patch")
    model: DIPNet | None = field(default=None, compare=False, repr=False)

    @cached_property
    def network(self) -> DIPNet:
        """The given model, or the weights loaded (CoinDieError when there are none)."""
        if self.model is not None:
            return self.model
        path = Path(self.weights) if self.weights else PACKAGED_WEIGHTS
        if not path.with_suffix(".safetensors").is_file():
            raise CoinDieError(
                f"{path}: no DIP weights there; train a network and pass its file as dip.weights, "
                "or pass a model"
            )
        return load_model(path)

    def support(self, cloud: Cloud) -> Cloud:
        return grid_support(cloud, self.voxel)

    def describe(self, support: Cloud, at: IntArray) -> FloatArray:
        if self.model is not None:  # a network being trained changes: nothing to keep
            return self._describe(support, at)
        key = (self.weights, self.seed, content_key(support.points, support.normals, at))
        return _descriptor_cache.get(key, lambda: self._describe(support, at))

    def _describe(self, support: Cloud, at: IntArray) -> FloatArray:
        from coindie.registration.learned.dip_network import embed

        model, rng = self.network, np.random.default_rng(self.seed)
        config: DIPConfig = model.config
        parts = []
        for start in range(0, len(at), self.batch):  # bounded memory: the neighbour lists of one batch
            chosen = at[start : start + self.batch]
            patches = canonical_patches(
                support.points,
                support.points[chosen],
                support.normals[chosen],
                config.radius,
                config.n_points,
                rng,
                tree=support.tree,
            )
            parts.append(embed(model, patches, self.batch))
        return np.concatenate(parts) if parts else np.zeros((0, config.dim))

    def values(self) -> dict[str, Any]:
        return {name: getattr(self, name) for name in self.declared()}
