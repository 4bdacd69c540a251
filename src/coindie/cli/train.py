"""``coindie train ...``: train the learned descriptors on a hoard's registration training split."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from coindie.cli.common import exits_cleanly
from coindie.errors import ParameterError

train = typer.Typer(
    help="Train the learned models (FCGF, DIP descriptors) on a hoard with known transforms.",
    no_args_is_help=True,
)


# Options shared by both networks (the paper's training settings as defaults).
Data = Annotated[Path, typer.Argument(help="Hoard folder: scans, labels.csv, splits.csv, truth.json.")]
Out = Annotated[Path, typer.Option("--out", help="Folder for the model, checkpoint, log.json, curves.png.")]
Epochs = Annotated[int, typer.Option(help="Epochs in all (a resumed run counts those done).")]
Device = Annotated[str, typer.Option(help="cpu or cuda.")]
Resume = Annotated[bool, typer.Option(help="Continue the run whose checkpoint is in OUT.")]
LR = Annotated[float, typer.Option(help="SGD learning rate of the first epoch.")]
LRDecay = Annotated[float, typer.Option(help="Learning-rate factor after each epoch.")]
Momentum = Annotated[float, typer.Option(help="SGD momentum.")]
WeightDecay = Annotated[float, typer.Option(help="SGD weight decay.")]
BatchPairs = Annotated[int, typer.Option(help="Pairs of faces per SGD step.")]
MaxPairs = Annotated[int, typer.Option(help="Training pairs per epoch, drawn anew each epoch (0: all).")]
ValFraction = Annotated[float, typer.Option(help="Share of the pairs held out, by whole dies.")]
Split = Annotated[str, typer.Option(help="Split whose same-die pairs train the model.")]
Seed = Annotated[int, typer.Option(help="Seed of the weights, pair order and augmentation.")]
Threads = Annotated[
    int, typer.Option(help="PyTorch CPU threads (0: its default; more than the idle cores is far slower).")
]
Voxel = Annotated[float, typer.Option(help="Grid of the clouds the network sees (mm).")]
Quiet = Annotated[bool, typer.Option(help="No progress bar.")]
ValPairs = Annotated[int, typer.Option(help="Held-out pairs measured after each epoch, at most.")]
FMRPoints = Annotated[int, typer.Option(help="Random points per cloud matched to measure the FMR.")]
Crop = Annotated[
    float,
    typer.Option(help="Train on balls of this radius (mm) around a random true match (0: whole faces)."),
]


@train.command("fcgf")
@exits_cleanly
def fcgf(
    data: Data,
    out: Out,
    epochs: Epochs = 380,
    device: Device = "cpu",
    resume: Resume = False,
    lr: LR = 0.1,
    lr_decay: LRDecay = 0.99,
    momentum: Momentum = 0.8,
    weight_decay: WeightDecay = 1e-4,
    batch_pairs: BatchPairs = 1,
    max_pairs: MaxPairs = 0,
    val_fraction: ValFraction = 0.1,
    split: Split = "registration_train",
    seed: Seed = 0,
    threads: Threads = 1,
    voxel: Voxel = 0.1,
    channels: Annotated[
        str, typer.Option(help="Encoder channels per level, comma-separated.")
    ] = "16,32,64,128",
    level: Annotated[
        bool,
        typer.Option(
            help="Turn each face's fitted plane to z = 0 before voxelising (exact tilt invariance)."
        ),
    ] = False,
    spins: Annotated[
        int,
        typer.Option(
            help="Turns of the target searched when matching; training pairs are then turned alike within "
            "±180°/spins (1: the paper's, invariance learned from ±180° augmentation)."
        ),
    ] = 1,
    crop_radius: Crop = 0.0,
    max_val_pairs: ValPairs = 32,
    fmr_points: FMRPoints = 5000,
    quiet: Quiet = False,
) -> None:
    """Train FCGF as the paper did: contrastive loss with hardest negatives, SGD, augmented pairs."""
    from coindie.errors import CoinDieError
    from coindie.registration.learned.fcgf import FCGFConfig

    try:
        model = FCGFConfig(voxel=voxel, channels=_channels(channels), level=level, spins=spins)
    except CoinDieError as error:
        raise ParameterError(str(error)) from None
    _run(data, out, model, _shared(locals()), resume, quiet)


@train.command("dip")
@exits_cleanly
def dip(
    data: Data,
    out: Out,
    epochs: Epochs = 40,
    device: Device = "cpu",
    resume: Resume = False,
    lr: LR = 0.1,
    lr_decay: LRDecay = 0.99,
    momentum: Momentum = 0.8,
    weight_decay: WeightDecay = 1e-4,
    batch_pairs: BatchPairs = 1,
    max_pairs: MaxPairs = 0,
    val_fraction: ValFraction = 0.1,
    split: Split = "registration_train",
    seed: Seed = 0,
    threads: Threads = 1,
    voxel: Voxel = 0.1,
    radius: Annotated[float, typer.Option(help="Patch radius (mm).")] = 2.0,
    patch_points: Annotated[int, typer.Option(help="Points per patch.")] = 256,
    patches: Annotated[int, typer.Option(help="Patch pairs (true matches) per training pair.")] = 256,
    crop_radius: Crop = 0.0,
    max_val_pairs: ValPairs = 16,
    fmr_points: FMRPoints = 1000,
    quiet: Quiet = False,
) -> None:
    """Train DIP (a PointNet on patches in their local frame) with the same loss, optimiser and pairs."""
    from coindie.errors import CoinDieError
    from coindie.registration.learned.dip import DIPConfig

    try:
        model = DIPConfig(radius=radius, n_points=patch_points, voxel=voxel)
    except CoinDieError as error:
        raise ParameterError(str(error)) from None
    _run(data, out, model, _shared(locals()) | {"patches": patches}, resume, quiet)


#: The command options that go to TrainOptions as they are.
_SHARED = (
    "epochs", "lr", "momentum", "weight_decay", "lr_decay", "batch_pairs", "max_pairs", "val_fraction",
    "split", "seed", "device", "threads", "crop_radius", "max_val_pairs", "fmr_points",
)  # fmt: skip


def _shared(options: dict[str, Any]) -> dict[str, Any]:
    return {name: options[name] for name in _SHARED}


def _run(data: Path, out: Path, model: Any, settings: dict[str, Any], resume: bool, quiet: bool) -> None:
    from coindie.registration.learned.train import CURVES, TrainOptions, train_fcgf

    options = TrainOptions(model=model, **settings)
    if quiet:
        log = train_fcgf(data, out, options, resume=resume, report=_echo_epoch)
    else:
        from coindie.cli.progress import counting_progress

        with counting_progress("pairs") as progress:
            log = train_fcgf(data, out, options, resume=resume, progress=progress, report=_echo_epoch)
    typer.echo(
        f"{len(log)} epoch(s) in {out}: model {out / options.model_file} (best epoch), curves {out / CURVES}"
    )


def _channels(text: str) -> tuple[int, ...]:
    try:
        channels = tuple(int(c) for c in text.split(","))
    except ValueError:
        channels = ()
    if len(channels) < 2 or min(channels) < 1:
        raise ParameterError(
            f"--channels must be two or more positive integers such as 16,32,64. Got {text!r}."
        )
    return channels


def _echo_epoch(record: dict[str, Any]) -> None:
    """One line per epoch: training loss, validation loss, FMR, time."""
    loss = record["train"].get("loss", float("nan"))
    line = f"epoch {record['epoch']}: lr {record['lr']:.4g}  loss {loss:.4f}"
    val = record["val"]
    if val:
        line += f"  val loss {val['loss']:.4f}  FMR {val['fmr']:.3f}  inlier ratio {val['inlier_ratio']:.3f}"
    typer.echo(line + f"  ({record['train'].get('seconds', 0.0):.0f} s)")
