"""What the benchmarks share to write their results: tables as CSV, JSON and markdown, and plots."""

from __future__ import annotations

import csv
import json
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np


def write_records(out: Path, stem: str, records: Sequence[Any], table: str) -> None:
    """``stem``.csv and .json (one record per dataclass) and ``stem``.md (the table) in ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    with (out / f"{stem}.csv").open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(asdict(records[0])))
        writer.writeheader()
        writer.writerows(asdict(r) for r in records)
    (out / f"{stem}.json").write_text(json.dumps([asdict(r) for r in records], indent=1) + "\n")
    (out / f"{stem}.md").write_text(table)


def fmi_bars(
    keys: Sequence[str], series: Mapping[str, Mapping[str, float]], path: Path, *, title: str, ylabel: str
) -> None:
    """Grouped bars: one group per key, one bar per series (label -> {key: FMI}); the 0.95 floor drawn."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(max(6.0, 0.5 * len(keys) + 2), 4.0))
    width = 0.8 / max(len(series), 1)
    for k, (label, values) in enumerate(series.items()):
        xs = np.arange(len(keys)) + (k - (len(series) - 1) / 2) * width
        ax.bar(xs, [values.get(key, np.nan) for key in keys], width, label=label)
    ax.axhline(0.95, color="grey", lw=0.8, ls="--")
    ax.set_xticks(np.arange(len(keys)), list(keys), rotation=60, ha="right", fontsize=8)
    ax.set_ylim(0, 1.02)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
