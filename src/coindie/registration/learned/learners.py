"""What the training loop needs to know of each network: build it, save it, its loss on a batch of pairs,
its descriptors at chosen points. :mod:`coindie.registration.learned.train` runs the same loop for both.

- FCGF describes every voxel of a cloud in one pass of the sparse U-Net; its loss takes the true matches
  of the whole clouds, with hardest negatives among random points of each cloud.
- DIP describes patches: its loss takes ``patches`` true matches (256), cuts a patch around both points
  of each (in the local reference frame, with the points' normals), and seeks the hardest negatives among
  the other patches of the pair. Fewer descriptors per step than FCGF, each from a whole patch.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol

import numpy as np
import torch
from torch import nn

from coindie.arrays import FloatArray, IntArray
from coindie.registration.learned.dip import DIPConfig
from coindie.registration.learned.dip import save_model as save_dip
from coindie.registration.learned.fcgf import FCGFConfig, new_model
from coindie.registration.learned.fcgf import save_model as save_fcgf
from coindie.registration.learned.lrf import canonical_patches
from coindie.registration.learned.pairs import TrainingPair

if TYPE_CHECKING:
    from coindie.registration.learned.train import TrainOptions

ModelConfig = FCGFConfig | DIPConfig
Losses = dict[str, torch.Tensor]


class Learner(Protocol):
    kind: str  # "fcgf" or "dip": the model file is f"{kind}.safetensors"

    def new(self, config: ModelConfig, seed: int) -> nn.Module: ...

    def save(self, model: nn.Module, path: str, info: dict) -> None: ...

    def losses(
        self,
        model: nn.Module,
        batch: list[TrainingPair],
        options: TrainOptions,
        generator: torch.Generator,
    ) -> Losses: ...

    def evaluate(
        self,
        model: nn.Module,
        pair: TrainingPair,
        options: TrainOptions,
        generator: torch.Generator,
        at: tuple[IntArray, IntArray],
    ) -> tuple[Losses, FloatArray, FloatArray]:
        """The pair's loss terms and the descriptors of its source points ``at[0]`` and target points
        ``at[1]`` (validation: no gradients)."""
        ...


def learner_for(config: ModelConfig) -> Learner:
    return DIPLearner() if isinstance(config, DIPConfig) else FCGFLearner()


def _pair_loss(
    options: TrainOptions,
    f_source: torch.Tensor,
    f_target: torch.Tensor,
    pair: TrainingPair,
    generator: torch.Generator,
) -> Losses:
    """The loss of a pair whose every point has a descriptor (rows of ``f_source`` and ``f_target``)."""
    device = options.device
    x_source, x_target = (torch.as_tensor(c, device=device) for c in (pair.source, pair.target))
    matches = torch.as_tensor(pair.matches, device=device)
    return options.loss(f_source, f_target, matches, x_source, x_target, generator)


def _mean_terms(per_pair: list[Losses]) -> Losses:
    return {key: torch.stack([terms[key] for terms in per_pair]).mean() for key in per_pair[0]}


@dataclass(frozen=True)
class FCGFLearner:
    kind: str = "fcgf"

    def new(self, config: ModelConfig, seed: int) -> nn.Module:
        assert isinstance(config, FCGFConfig)
        return new_model(config, seed)

    def save(self, model: nn.Module, path: str, info: dict) -> None:
        save_fcgf(model, path, info)

    def losses(
        self,
        model: nn.Module,
        batch: list[TrainingPair],
        options: TrainOptions,
        generator: torch.Generator,
    ) -> Losses:
        """Mean loss terms of a batch of pairs, all clouds through the network in one pass."""
        device = options.device
        clouds = [c for pair in batch for c in (pair.source, pair.target)]
        sizes = [len(c) for c in clouds]
        points = torch.as_tensor(np.concatenate(clouds), dtype=torch.float64, device=device)
        index = torch.repeat_interleave(torch.arange(len(clouds)), torch.tensor(sizes)).to(device)
        features = model.describe_points(points, index).split(sizes)
        return _mean_terms(
            [
                _pair_loss(options, features[2 * k], features[2 * k + 1], pair, generator)
                for k, pair in enumerate(batch)
            ]
        )

    def evaluate(
        self,
        model: nn.Module,
        pair: TrainingPair,
        options: TrainOptions,
        generator: torch.Generator,
        at: tuple[IntArray, IntArray],
    ) -> tuple[Losses, FloatArray, FloatArray]:
        device = options.device
        f_source, f_target = (
            model.describe_points(torch.as_tensor(c, device=device)) for c in (pair.source, pair.target)
        )
        terms = _pair_loss(options, f_source, f_target, pair, generator)
        s, t = (torch.as_tensor(rows, device=device) for rows in at)
        return terms, f_source[s].double().cpu().numpy(), f_target[t].double().cpu().numpy()


@dataclass(frozen=True)
class DIPLearner:
    kind: str = "dip"

    def new(self, config: ModelConfig, seed: int) -> nn.Module:
        from coindie.registration.learned.dip_network import DIPNet

        assert isinstance(config, DIPConfig)
        with torch.random.fork_rng(devices=[]):
            torch.manual_seed(seed)
            return DIPNet(config)

    def save(self, model: nn.Module, path: str, info: dict) -> None:
        save_dip(path, model)  # the JSON beside it is the config alone; the run's details are in log.json

    def losses(
        self,
        model: nn.Module,
        batch: list[TrainingPair],
        options: TrainOptions,
        generator: torch.Generator,
    ) -> Losses:
        config: DIPConfig = model.config
        loss, device = options.loss, options.device
        per_pair = []
        for pair in batch:
            rng = np.random.default_rng(int(torch.randint(2**62, (1,), generator=generator)))
            k = min(len(pair.matches), options.patches)
            chosen = pair.matches[np.sort(rng.choice(len(pair.matches), k, replace=False))]
            i, j = chosen[:, 0], chosen[:, 1]
            source = canonical_patches(
                pair.source, pair.source[i], pair.source_normals[i], config.radius, config.n_points, rng
            )
            target = canonical_patches(
                pair.target, pair.target[j], pair.target_normals[j], config.radius, config.n_points, rng
            )
            both = torch.as_tensor(np.concatenate([source, target]), dtype=torch.float32, device=device)
            f_source, f_target = model(both).split(k)
            rows = torch.arange(k, device=device)
            per_pair.append(
                loss(
                    f_source,
                    f_target,
                    torch.stack([rows, rows], dim=1),
                    torch.as_tensor(pair.source[i], device=device),
                    torch.as_tensor(pair.target[j], device=device),
                    generator,
                )
            )
        return _mean_terms(per_pair)

    def evaluate(
        self,
        model: nn.Module,
        pair: TrainingPair,
        options: TrainOptions,
        generator: torch.Generator,
        at: tuple[IntArray, IntArray],
    ) -> tuple[Losses, FloatArray, FloatArray]:
        from coindie.registration.learned.dip_network import embed

        config: DIPConfig = model.config
        rng = np.random.default_rng(0)
        described = []
        for points, normals, rows in (
            (pair.source, pair.source_normals, at[0]),
            (pair.target, pair.target_normals, at[1]),
        ):
            patches = canonical_patches(
                points, points[rows], normals[rows], config.radius, config.n_points, rng
            )
            described.append(embed(model, patches))
        return self.losses(model, [pair], options, generator), described[0], described[1]
