"""The files of a generated hoard, next to its PLYs (one per face, ``L0001D.ply``, the dataset's format).

- ``labels.csv``: ``coin_id,die_id``, one row per face (``coindie.io.read_labels`` reads it).
- ``splits.csv``: ``face_id,split``, one row per (face, split); a face may be in a registration split and
  in a clustering split.
- ``truth.json``: per face its die, family, coin, splits, strike time, die age, ``T_scan_die`` (4x4, maps
  die-frame points into the face's scan frame), the drawn face spec and the physics' own record; per die
  its family, size and life. The true rigid transform from face a's scan frame to face b's, for two faces
  of one die, is ``T_b_a = T_scan_die[b] @ inv(T_scan_die[a])`` (:func:`true_transform`).
- ``hoard.json``: preset, scale, seed, every parameter, coindie version, generation time.

JSON is written with sorted keys so that the same hoard gives the same bytes.
"""

from __future__ import annotations

import csv
import hashlib
import json
import math
from dataclasses import fields, is_dataclass
from enum import Enum
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from coindie.errors import CoinDieError, ParameterError
from coindie.io import write_labels
from coindie.synth.plan import HoardPlan
from coindie.synth.presets import SPLITS

LABELS_FILE = "labels.csv"
SPLITS_FILE = "splits.csv"
TRUTH_FILE = "truth.json"
HOARD_FILE = "hoard.json"
#: Per-face records written as faces are made (so an interrupted run can resume); removed at the end.
PARTS_DIR = ".synth-parts"
SPLITS_HEADER = ("face_id", "split")


def to_jsonable(value: Any) -> Any:
    """Plain JSON types from dataclasses, enums, numpy arrays and scalars, tuples, paths.

    A dataclass field marked ``omit_default`` (the wide world's axes, added after hoards were first made) is
    left out while it holds its default, so that the records and settings digest of a hoard made without
    those axes stay byte-identical to what earlier versions wrote.
    """
    if is_dataclass(value) and not isinstance(value, type):
        return {
            f.name: to_jsonable(getattr(value, f.name))
            for f in fields(value)
            if not (f.metadata.get("omit_default") and getattr(value, f.name) == f.default)
        }
    if isinstance(value, dict):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [to_jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return to_jsonable(value.tolist())
    if isinstance(value, Enum):
        return to_jsonable(value.value)
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, Path):
        return str(value)
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    return value


def write_json(path: Path, value: Any) -> Path:
    path.write_text(json.dumps(to_jsonable(value), sort_keys=True, indent=1) + "\n", encoding="utf-8")
    return path


def read_json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        raise CoinDieError(f"{path}: cannot read JSON ({error})") from None


def digest(value: Any) -> str:
    """sha256 of a value's canonical JSON: identifies the settings a hoard was made with."""
    text = json.dumps(to_jsonable(value), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def file_sha256(path: Path) -> str:
    with path.open("rb") as stream:
        return hashlib.file_digest(stream, "sha256").hexdigest()


def write_tables(out_dir: Path, plan: HoardPlan) -> None:
    """``labels.csv`` and ``splits.csv`` of a plan."""
    write_labels(out_dir / LABELS_FILE, plan.labels())
    write_splits(out_dir / SPLITS_FILE, plan.split_rows())


def write_splits(path: Path, rows: list[tuple[str, str]]) -> Path:
    with path.open("w", newline="", encoding="utf-8") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(SPLITS_HEADER)
        writer.writerows(sorted(rows, key=lambda row: (SPLITS.index(row[1]), row[0])))
    return path


def read_splits(path: str | Path) -> dict[str, list[str]]:
    """``splits.csv`` as split -> face ids (every known split present, maybe empty)."""
    path = Path(path)
    splits: dict[str, list[str]] = {name: [] for name in SPLITS}
    try:
        with path.open(newline="", encoding="utf-8") as stream:
            rows = list(csv.reader(stream))
    except OSError as error:
        raise CoinDieError(f"{path}: cannot read the splits ({error.strerror})") from None
    if not rows or tuple(c.strip() for c in rows[0]) != SPLITS_HEADER:
        raise CoinDieError(f"{path}: the header must be {','.join(SPLITS_HEADER)}")
    for line, row in enumerate(rows[1:], start=2):
        if len(row) != 2 or row[1].strip() not in splits:
            raise CoinDieError(f"{path}: line {line}: expected face_id,split with a known split, got {row}")
        splits[row[1].strip()].append(row[0].strip())
    return splits


def truth_document(plan: HoardPlan, records: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """The content of ``truth.json``: the plan's facts per face and die, plus each face's physics record."""
    faces = {
        f.face_id: {
            "coin": f.coin,
            "family": f.family,
            "die_id": f.die_id,
            "splits": list(f.splits),
            "strike_time": f.strike_time,
            "die_age": f.die_age,
            **records[f.face_id],
        }
        for f in plan.faces
    }
    dies = {
        d.die_id: {
            "family": d.family,
            "size": d.size,
            "start": d.start,
            "end": d.end,
            "splits": list(d.splits),
        }
        for d in plan.dies
    }
    return {
        "frames": "T_scan_die maps die-frame points (mm) into the face's scan frame; "
        "T_b_a = T_scan_die[b] @ inv(T_scan_die[a]) maps face a's scan onto face b's (same die).",
        "seed": plan.seed,
        "faces": faces,
        "dies": dies,
    }


def read_truth(path: str | Path) -> dict[str, Any]:
    """``truth.json`` of a hoard (a folder or the file)."""
    path = Path(path)
    return read_json(path / TRUTH_FILE if path.is_dir() else path)


def scan_from_die(truth: dict[str, Any], face_id: str) -> NDArray[np.float64]:
    """``T_scan_die`` of a face, as a 4x4 array."""
    try:
        return np.asarray(truth["faces"][face_id]["T_scan_die"], dtype=np.float64)
    except KeyError:
        raise ParameterError(f"face {face_id!r} is not in the hoard's truth") from None


def true_transform(truth: dict[str, Any], a: str, b: str) -> NDArray[np.float64]:
    """``T_b_a``: maps face ``a``'s scan frame onto face ``b``'s, for two faces struck by the same die."""
    die_a, die_b = truth["faces"][a]["die_id"], truth["faces"][b]["die_id"]
    if die_a != die_b:
        raise ParameterError(f"{a} (die {die_a}) and {b} (die {die_b}) were not struck by the same die")
    return scan_from_die(truth, b) @ np.linalg.inv(scan_from_die(truth, a))
