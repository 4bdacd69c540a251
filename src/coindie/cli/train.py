"""``coindie train ...``: train the learned descriptors on a hoard's registration training split."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from coindie.cli.app import app, exits_cleanly
from coindie.errors import ParameterError

train = typer.Typer(
    help="Train the learned descriptors (FCGF) on a hoard with known transforms.", no_args_is_help=True
)
app.add_typer(train, name="train")


@train.command("fcgf")
@exits_cleanly
def fcgf(
    data: Annotated[Path, typer.Argument(help="Hoard folder: scans, labels.csv, splits.csv, truth.json.")],
    out: Annotated[
        Path, typer.Option("--out", help="Folder for the model, checkpoint, log.json, curves.png.")
    ],
    epochs: Annotated[int, typer.Option(help="Epochs in all (a resumed run counts those done).")] = 380,
    device: Annotated[str, typer.Option(help="cpu or cuda.")] = "cpu",
    resume: Annotated[bool, typer.Option(help="Continue the run whose checkpoint is in OUT.")] = False,
    lr: Annotated[float, typer.Option(help="SGD learning rate of the first epoch.")] = 0.1,
    lr_decay: Annotated[float, typer.Option(help="Learning-rate factor after each epoch.")] = 0.99,
    momentum: Annotated[float, typer.Option(help="SGD momentum.")] = 0.8,
    weight_decay: Annotated[float, typer.Option(help="SGD weight decay.")] = 1e-4,
    batch_pairs: Annotated[int, typer.Option(help="Pairs of faces per SGD step.")] = 1,
    max_pairs: Annotated[
        int, typer.Option(help="Training pairs per epoch, drawn anew each epoch (0: all).")
    ] = 0,
    val_fraction: Annotated[float, typer.Option(help="Share of the pairs held out, by whole dies.")] = 0.1,
    split: Annotated[
        str, typer.Option(help="Split whose same-die pairs train the model.")
    ] = "registration_train",
    seed: Annotated[int, typer.Option(help="Seed of the weights, pair order and augmentation.")] = 0,
    threads: Annotated[
        int,
        typer.Option(help="PyTorch CPU threads (0: its default; more than the idle cores is far slower)."),
    ] = 1,
    voxel: Annotated[float, typer.Option(help="Voxel of the sparse network (mm).")] = 0.1,
    channels: Annotated[
        str, typer.Option(help="Encoder channels per level, comma-separated.")
    ] = "16,32,64,128",
    quiet: Annotated[bool, typer.Option(help="No progress bar.")] = False,
) -> None:
    """Train FCGF as the paper did: contrastive loss with hardest negatives, SGD, augmented pairs."""
    from coindie.learned.fcgf import FCGFConfig
    from coindie.learned.train import CURVES, MODEL, TrainOptions, train_fcgf

    options = TrainOptions(
        epochs=epochs, lr=lr, momentum=momentum, weight_decay=weight_decay, lr_decay=lr_decay,
        batch_pairs=batch_pairs, max_pairs=max_pairs, val_fraction=val_fraction, split=split, seed=seed,
        device=device, threads=threads, model=FCGFConfig(voxel=voxel, channels=_channels(channels)),
    )  # fmt: skip
    if quiet:
        log = train_fcgf(data, out, options, resume=resume, report=_echo_epoch)
    else:
        from coindie.cli.progress import counting_progress

        with counting_progress("pairs") as progress:
            log = train_fcgf(data, out, options, resume=resume, progress=progress, report=_echo_epoch)
    typer.echo(f"{len(log)} epoch(s) in {out}: model {out / MODEL} (best epoch), curves {out / CURVES}")


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
