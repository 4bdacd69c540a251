"""Training FCGF (or DIP) on a hoard's registration training split, as the paper did (section 4.1).

``train_fcgf(hoard, out, TrainOptions(epochs=380))`` runs SGD (lr 0.1, momentum 0.8, weight decay 1e-4,
lr x 0.99 after each epoch) on the contrastive loss with hardest negatives, one augmented pair of faces of
one die at a time. ``TrainOptions(model=DIPConfig())`` trains DIP the same way, on patches around the
true matches (:mod:`coindie.registration.learned.learners`). An FCGF model that levels its input gets
levelled pairs, and one that searches ``spins`` turns when matching gets pairs turned apart by at most
±180°/spins (:meth:`coindie.registration.learned.pairs.PairSet.make`). After each epoch it measures, on
held-out pairs (whole dies, turned like the benchmark turns them, never scaled), the loss and the
feature-match recall, and writes into ``out``:

- ``checkpoint.safetensors`` + ``checkpoint.json``: weights, optimizer state and epoch (``resume=True``
  continues from there, to the same result as an uninterrupted run);
- ``fcgf.safetensors`` + ``fcgf.json`` (``dip.*`` for DIP): the model of the best epoch (highest FMR,
  then lowest validation loss; the last epoch without validation pairs), ready for ``fcgf.weights=...``;
- ``log.json`` (one record per epoch) and ``curves.png`` (losses, FMR and inlier ratio per epoch).

Feature-match recall (Deng et al. 2018, as FCGF reports it): descriptors of up to ``fmr_points`` random
points per cloud, matched by mutual nearest neighbours; a match is an inlier when the true transform puts
its source point within ``fmr_radius`` (0.3 mm) of its target point; FMR is the share of pairs whose
inlier ratio exceeds ``fmr_ratio`` (5 %).
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, ClassVar

import numpy as np
import torch

from coindie.errors import ParameterError
from coindie.io.truth import hoard_recipe
from coindie.params import Configurable, Rule, param
from coindie.registration.features import MutualNN
from coindie.registration.learned.dip import DIPConfig
from coindie.registration.learned.fcgf import FCGFConfig, config_path, count_parameters, torch_threads
from coindie.registration.learned.learners import Learner, ModelConfig, learner_for
from coindie.registration.learned.losses import ContrastiveLoss
from coindie.registration.learned.pairs import (
    TRAINING,
    VALIDATION,
    Augmentation,
    PairSet,
    TrainingPair,
    crop,
    level_pair,
    split_pairs,
)
from coindie.transforms import transform_points

CHECKPOINT = "checkpoint.safetensors"
MODEL = "fcgf.safetensors"
DIP_MODEL = "dip.safetensors"
LOG = "log.json"
CURVES = "curves.png"
#: Seeds of validation pairs are offset so that they never equal a training draw.
_VALIDATION_SEED = 1_000_003

Progress = Callable[[int, int], None]
EpochReport = Callable[[dict[str, Any]], None]


@dataclass(frozen=True)
class TrainOptions(Configurable):
    """Training settings (defaults: the paper's)."""

    RULES: ClassVar[tuple[Rule, ...]] = (
        Rule(
            ("device",),
            lambda o: o.device != "cuda" or torch.cuda.is_available(),
            "a device this PyTorch build sees (it sees no CUDA device)",
        ),
    )

    epochs: int = param(380, doc="passes over the training pairs", low=1)
    lr: float = param(0.1, doc="SGD learning rate", low=0.0, low_open=True)
    momentum: float = param(0.8, doc="SGD momentum", low=0.0, high=1.0, high_open=True)
    weight_decay: float = param(1e-4, doc="SGD weight decay")
    lr_decay: float = param(0.99, doc="lr factor after each epoch", low=0.0, low_open=True, high=1.0)
    batch_pairs: int = param(1, doc="pairs per SGD step", low=1)
    max_pairs: int = param(0, doc="training pairs per epoch, drawn anew each epoch (0: all)", low=0)
    val_fraction: float = param(
        0.1, doc="share of the pairs held out (whole dies)", low=0.0, high=1.0, high_open=True
    )
    max_val_pairs: int = param(32, doc="validation pairs at most", low=1)
    split: str = param("registration_train", doc="the hoard's split trained on")
    seed: int = param(0, doc="seed of the pairs' draws and of the network's initialisation")
    device: str = param("cpu", doc="where torch trains", choices=("cpu", "cuda"))
    threads: int = param(
        1, doc="torch CPU threads (0: torch's default; more than the idle cores is many times slower)", low=0
    )
    fmr_radius: float = param(
        0.3, doc="a match this close to the truth is an inlier", unit="mm", low=0.0, low_open=True
    )
    fmr_ratio: float = param(0.05, doc="inlier ratio above which a pair counts as matched (FMR)")
    fmr_points: int = param(5000, doc="points per face of the FMR", low=1)
    patches: int = param(256, doc="DIP: true matches (patch pairs) per training pair", low=1)
    crop_radius: float = param(
        0.0,
        doc="train on balls of this radius around a random true match (0: whole faces)",
        unit="mm",
        low=0.0,
    )
    model: ModelConfig = field(default_factory=FCGFConfig)
    loss: ContrastiveLoss = field(default_factory=ContrastiveLoss)

    @property
    def learner(self) -> Learner:
        return learner_for(self.model)

    @property
    def model_file(self) -> str:
        return f"{self.learner.kind}.safetensors"

    def to_json(self) -> dict[str, Any]:
        return asdict(self) | {"model": _config_json(self.model), "kind": self.learner.kind}


def _config_json(config: ModelConfig) -> dict[str, Any]:
    return json.loads(json.dumps(asdict(config)))


def train_dip(
    data: str | Path,
    out: str | Path,
    options: TrainOptions | None = None,
    **kwargs: Any,
) -> list[dict[str, Any]]:
    """:func:`train_fcgf` for DIP: ``options.model`` must be a :class:`DIPConfig` (the default here)."""
    options = options or TrainOptions(model=DIPConfig())
    if not isinstance(options.model, DIPConfig):
        raise ParameterError(f"train_dip needs a DIPConfig model. Got {type(options.model).__name__}.")
    return train_fcgf(data, out, options, **kwargs)


def train_fcgf(
    data: str | Path,
    out: str | Path,
    options: TrainOptions | None = None,
    *,
    resume: bool = False,
    progress: Progress | None = None,
    report: EpochReport | None = None,
) -> list[dict[str, Any]]:
    """Train (or, with ``resume``, continue training) and return the log, one record per epoch."""
    options = options or TrainOptions()
    out = Path(out)
    with torch_threads(options.threads):
        return _train(data, out, options, resume, progress, report)


def _train(
    data: str | Path,
    out: Path,
    options: TrainOptions,
    resume: bool,
    progress: Progress | None,
    report: EpochReport | None,
) -> list[dict[str, Any]]:
    pairs = PairSet(data, options.split, voxel=options.model.voxel)
    train_pairs, val_pairs = split_pairs(pairs.pairs, pairs.truth, options.val_fraction, options.seed)
    train_set, val_set = pairs.subset(train_pairs), pairs.subset(_at_most(val_pairs, options))
    model = options.learner.new(options.model, options.seed).to(options.device)
    optimizer = torch.optim.SGD(
        model.parameters(), lr=options.lr, momentum=options.momentum, weight_decay=options.weight_decay
    )
    log = _start(out, model, optimizer, options, resume)
    steps = _per_epoch(options, train_set) + len(val_set)
    if progress:
        progress(0, max(1, steps * (options.epochs - len(log))))
    for epoch in range(len(log) + 1, options.epochs + 1):
        record = {"epoch": epoch, "lr": options.lr * options.lr_decay ** (epoch - 1)}
        record["train"] = _train_epoch(model, optimizer, train_set, options, epoch, record["lr"], progress)
        record["val"] = _validate(model, val_set, options, progress)
        log.append(record)
        _save(out, model, optimizer, options, log, data)
        if report:
            report(record)
    return log


def _at_most(val_pairs: list, options: TrainOptions) -> list:
    """At most ``max_val_pairs`` validation pairs, drawn evenly from the held-out ones."""
    if len(val_pairs) <= options.max_val_pairs:
        return val_pairs
    keep = np.random.default_rng([options.seed, 11]).choice(
        len(val_pairs), options.max_val_pairs, replace=False
    )
    return [val_pairs[i] for i in sorted(keep)]


# ------------------------------------------------------------------------------------------ one epoch


def _per_epoch(options: TrainOptions, train_set: PairSet) -> int:
    return min(len(train_set), options.max_pairs) if options.max_pairs else len(train_set)


def _train_epoch(
    model: torch.nn.Module,
    optimizer: torch.optim.Optimizer,
    train_set: PairSet,
    options: TrainOptions,
    epoch: int,
    lr: float,
    progress: Progress | None,
) -> dict[str, float]:
    """One pass over (up to ``max_pairs`` of) the training pairs; mean loss terms."""
    for group in optimizer.param_groups:
        group["lr"] = lr
    model.train()
    order = np.random.default_rng([options.seed, epoch]).permutation(len(train_set))
    order = order[: _per_epoch(options, train_set)]
    terms: list[dict[str, float]] = []
    start = time.perf_counter()
    for step, first in enumerate(range(0, len(order), options.batch_pairs)):
        batch = [
            _training_pair(train_set, int(i), options, epoch) for i in order[first:][: options.batch_pairs]
        ]
        generator = torch.Generator().manual_seed(options.seed * 1_000_003 + epoch * 10_007 + step)
        optimizer.zero_grad(set_to_none=True)
        losses = options.learner.losses(model, batch, options, generator)
        losses["loss"].backward()
        optimizer.step()
        terms.append({k: float(v.detach()) for k, v in losses.items()})
        if progress:
            progress(len(batch), 0)
    return _means(terms) | {"seconds": time.perf_counter() - start, "pairs": len(order)}


def _training_pair(train_set: PairSet, index: int, options: TrainOptions, epoch: int) -> TrainingPair:
    """Training pair ``index`` of ``epoch``, augmented, cropped when the options say so."""
    pair = _pair(train_set, index, [options.seed, epoch, index], TRAINING, options)
    if options.crop_radius:
        pair = crop(pair, options.crop_radius, np.random.default_rng([options.seed, epoch, index, 1]))
    return pair


def _pair(
    pairs: PairSet, index: int, seed: list[int], augmentation: Augmentation, options: TrainOptions
) -> TrainingPair:
    """A pair as the model sees it: turned alike within the model's tolerance when it searches turns,
    levelled when it levels its input (whole faces, before any crop)."""
    config = options.model
    if not isinstance(config, FCGFConfig):
        return pairs.make(index, seed, augmentation)
    tolerance = config.turn_tolerance_deg if config.spins > 1 else None
    pair = pairs.make(index, seed, augmentation, turn_tolerance_deg=tolerance)
    return level_pair(pair) if config.level else pair


def _means(terms: list[dict[str, float]]) -> dict[str, float]:
    return {key: float(np.mean([t[key] for t in terms])) for key in terms[0]} if terms else {}


# ------------------------------------------------------------------------------------------ validation


def _validate(
    model: torch.nn.Module, val_set: PairSet, options: TrainOptions, progress: Progress | None
) -> dict[str, Any]:
    """Loss, inlier ratios and FMR on the held-out pairs (fixed augmentation, evaluation mode)."""
    if not len(val_set):
        return {}
    model.eval()
    losses, ratios, seconds = [], [], []
    with torch.no_grad():
        for index in range(len(val_set)):
            pair = _pair(val_set, index, [options.seed, _VALIDATION_SEED, index], VALIDATION, options)
            generator = torch.Generator().manual_seed(options.seed + index)
            rng = np.random.default_rng([options.seed, len(pair.source), len(pair.target)])
            at = (
                _draw(rng, len(pair.source), options.fmr_points),
                _draw(rng, len(pair.target), options.fmr_points),
            )
            start = time.perf_counter()
            terms, f_source, f_target = options.learner.evaluate(model, pair, options, generator, at)
            seconds.append((time.perf_counter() - start) / 2)
            losses.append(float(terms["loss"]))
            ratios.append(inlier_ratio(pair, *at, f_source, f_target, options.fmr_radius))
            if progress:
                progress(1, 0)
    return {
        "loss": float(np.mean(losses)),
        "fmr": float(np.mean(np.asarray(ratios) > options.fmr_ratio)),
        "inlier_ratio": float(np.mean(ratios)),
        "inlier_ratios": ratios,
        "seconds_per_cloud": float(np.mean(seconds)),
        "pairs": len(val_set),
    }


def inlier_ratio(
    pair: TrainingPair,
    s: np.ndarray,
    t: np.ndarray,
    f_source: np.ndarray,
    f_target: np.ndarray,
    radius: float,
) -> float:
    """Share of the mutual nearest neighbours between the descriptors of source points ``s`` and target
    points ``t`` whose source point the truth puts within ``radius`` of its target point."""
    matches = MutualNN().match(f_source, f_target)
    if not len(matches):
        return 0.0
    moved = transform_points(pair.T_target_source, pair.source[s[matches[:, 0]]])
    return float(np.mean(np.linalg.norm(moved - pair.target[t[matches[:, 1]]], axis=1) < radius))


def _draw(rng: np.random.Generator, n: int, k: int) -> np.ndarray:
    return np.sort(rng.choice(n, k, replace=False)) if n > k else np.arange(n)


# ------------------------------------------------------------------------------------------ files


def _start(
    out: Path, model: torch.nn.Module, optimizer: torch.optim.Optimizer, options: TrainOptions, resume: bool
) -> list[dict[str, Any]]:
    """The log so far: empty for a new run, the checkpoint's epochs (model and optimizer restored) when
    resuming. Refuses to overwrite a checkpoint without ``resume``."""
    checkpoint = out / CHECKPOINT
    if not checkpoint.is_file():
        out.mkdir(parents=True, exist_ok=True)
        return []
    if not resume:
        raise ParameterError(
            f"{checkpoint}: a training run is already there; resume it or choose another folder"
        )
    header = json.loads(config_path(checkpoint).read_text())
    if header["options"]["model"] != _config_json(options.model):
        raise ParameterError(
            f"{checkpoint}: trained with model {header['options']['model']}, "
            f"not {_config_json(options.model)}"
        )
    _load_checkpoint(checkpoint, header, model, optimizer, options.device)
    log = json.loads((out / LOG).read_text())
    return log[: header["epoch"]]


def _save(
    out: Path,
    model: torch.nn.Module,
    optimizer: torch.optim.Optimizer,
    options: TrainOptions,
    log: list[dict[str, Any]],
    data: str | Path,
) -> None:
    """Log, curves, best model, then the checkpoint (last: a run stopped in between redoes the epoch)."""
    (out / LOG).write_text(json.dumps(log, indent=1) + "\n")
    plot_curves(log, out / CURVES)
    if _best_epoch(log) == log[-1]["epoch"]:
        info = {
            "epoch": log[-1]["epoch"],
            "val": _without_lists(log[-1]["val"]),
            "data": str(data),
            "hoard": hoard_recipe(Path(data)),
        }
        options.learner.save(
            model,
            str(out / options.model_file),
            info | {"options": options.to_json(), "parameters": count_parameters(model)},
        )
    _save_checkpoint(out / CHECKPOINT, model, optimizer, options, log[-1]["epoch"])


def _best_epoch(log: list[dict[str, Any]]) -> int:
    scored = [r for r in log if r["val"]]
    if not scored:
        return log[-1]["epoch"]
    return max(scored, key=lambda r: (r["val"]["fmr"], -r["val"]["loss"], r["epoch"]))["epoch"]


def _without_lists(record: dict[str, Any]) -> dict[str, Any]:
    return {k: v for k, v in record.items() if not isinstance(v, list)}


def _save_checkpoint(
    path: Path, model: torch.nn.Module, optimizer: torch.optim.Optimizer, options: TrainOptions, epoch: int
) -> None:
    """Weights and optimizer state as safetensors (no pickle), the rest as JSON beside it."""
    from safetensors.torch import save_file

    state = optimizer.state_dict()
    tensors = {f"model.{k}": v.detach().cpu().contiguous() for k, v in model.state_dict().items()}
    for index, slots in state["state"].items():
        tensors |= {
            f"optimizer.{index}.{name}": v.detach().cpu().contiguous()
            for name, v in slots.items()
            if torch.is_tensor(v)
        }
    save_file(tensors, str(path.with_suffix(".tmp")))
    path.with_suffix(".tmp").replace(path)
    header = {"epoch": epoch, "options": options.to_json(), "param_groups": state["param_groups"]}
    config_path(path).write_text(json.dumps(header, indent=1) + "\n")


def _load_checkpoint(
    path: Path, header: dict[str, Any], model: torch.nn.Module, optimizer: torch.optim.Optimizer, device: str
) -> None:
    from safetensors.torch import load_file

    tensors = load_file(str(path), device=device)
    model.load_state_dict({k[len("model.") :]: v for k, v in tensors.items() if k.startswith("model.")})
    slots: dict[int, dict[str, torch.Tensor]] = {}
    for key, value in tensors.items():
        if key.startswith("optimizer."):
            _, index, name = key.split(".", 2)
            slots.setdefault(int(index), {})[name] = value
    optimizer.load_state_dict({"state": slots, "param_groups": header["param_groups"]})


def plot_curves(log: list[dict[str, Any]], path: Path) -> None:
    """Losses (training, validation) and FMR / mean inlier ratio per epoch."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    epochs = [r["epoch"] for r in log]
    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot(epochs, [r["train"].get("loss", np.nan) for r in log], "o-", label="training")
    left.plot(epochs, [r["val"].get("loss", np.nan) for r in log], "s-", label="validation")
    left.set(xlabel="epoch", ylabel="contrastive loss", title="Loss")
    right.plot(epochs, [r["val"].get("fmr", np.nan) for r in log], "o-", label="FMR (inlier ratio > 5 %)")
    right.plot(epochs, [r["val"].get("inlier_ratio", np.nan) for r in log], "s-", label="mean inlier ratio")
    right.set(xlabel="epoch", ylim=(0, 1), title="Feature-match recall (0.3 mm)")
    for axis in (left, right):
        axis.grid(alpha=0.3)
        axis.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)
