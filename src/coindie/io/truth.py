"""The ground truth of a hoard folder: which die struck each face, its family, its splits and its pose.

A hoard folder holds one scan per face, ``labels.csv`` (``coin_id,die_id``), ``splits.csv``
(``face_id,split``, one row per face and split) and ``truth.json`` whose ``faces`` map each face id to at
least ``T_scan_die`` (4x4: die-frame points into the face's scan frame). ``coindie synth`` writes all of
them; for real scans, the transforms come from a manual registration written in the same format (every
face of a die registered to one reference face of that die plays the role of the die frame).
"""

from __future__ import annotations

import csv
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from coindie.errors import CoinDieError
from coindie.ids import Face, parse_face_id
from coindie.io import SCAN_SUFFIXES, read_labels

#: Families of the paper's tables: reverses, obverses with beard, obverses without beard.
FAMILY_CODES = {"reverse": "R", "beard": "DB", "obverse": "D"}


class TruthError(CoinDieError, ValueError):
    """A hoard folder lacks the ground truth a benchmark needs."""


@dataclass(frozen=True)
class FaceTruth:
    face_id: str
    die: str
    family: str  # "R", "DB" or "D"
    path: Path
    T_scan_die: NDArray[np.float64] | None


@dataclass(frozen=True)
class HoardTruth:
    root: Path
    faces: dict[str, FaceTruth]
    splits: dict[str, set[str]]  # split -> face ids

    def faces_in(self, split: str) -> list[FaceTruth]:
        if split not in self.splits:
            known = ", ".join(sorted(self.splits)) or "none"
            raise TruthError(f"{self.root / 'splits.csv'}: no split {split!r} (splits: {known})")
        return [self.faces[f] for f in sorted(self.splits[split]) if f in self.faces]

    def T_true(self, source: str, target: str) -> NDArray[np.float64]:
        """T_target_source of two faces of one die: T_scan_die[target] @ inv(T_scan_die[source])."""
        a, b = self.faces[source], self.faces[target]
        if a.T_scan_die is None or b.T_scan_die is None:
            raise TruthError(f"{self.root / 'truth.json'}: no transform for {source} or {target}")
        return b.T_scan_die @ np.linalg.inv(a.T_scan_die)


def load_truth(root: str | Path, transforms: str | Path | None = None) -> HoardTruth:
    """Read the ground truth of a hoard folder (``transforms`` overrides ``root/truth.json``)."""
    root = Path(root)
    labels = read_labels(root / "labels.csv")
    records = _records(Path(transforms) if transforms else root / "truth.json")
    scans = [p for p in sorted(root.iterdir()) if p.suffix.lower() in SCAN_SUFFIXES]
    paths = {parse_face_id(p.stem).key: p for p in scans}
    faces = {}
    for face_id, die in labels.items():
        key = face_id.key
        if key not in paths:
            continue
        record = records.get(key, {})
        T = np.asarray(record["T_scan_die"], dtype=np.float64) if "T_scan_die" in record else None
        family = _family(record.get("family"), die, face_id.face)
        faces[key] = FaceTruth(key, die, family, paths[key], T)
    return HoardTruth(root, faces, _splits(root / "splits.csv"))


def _records(path: Path) -> dict[str, dict]:
    if not path.is_file():
        return {}
    try:
        faces = json.loads(path.read_text())["faces"]
    except (json.JSONDecodeError, KeyError, TypeError) as error:
        raise TruthError(f"{path}: not a truth file with a 'faces' object ({error})") from None
    return {parse_face_id(k).key: v for k, v in faces.items()}


def _family(recorded: str | None, die: str, face: Face) -> str:
    if recorded in FAMILY_CODES:
        return FAMILY_CODES[recorded]
    if die.upper().startswith("DB"):
        return "DB"
    return "R" if face is Face.REVERSE or die.upper().startswith("R") else "D"


def _splits(path: Path) -> dict[str, set[str]]:
    if not path.is_file():
        raise TruthError(f"{path}: missing (a benchmark needs the hoard's splits)")
    splits: dict[str, set[str]] = {}
    with path.open(newline="") as handle:
        for row in csv.DictReader(handle):
            splits.setdefault(row["split"].strip(), set()).add(parse_face_id(row["face_id"]).key)
    return splits


def hoard_recipe(root: Path) -> dict[str, object]:
    """The generator settings of a synthetic hoard (preset, scale, seed: enough to make it again), or
    nothing for a folder of real scans; the folder's path alone names a place on one machine only."""
    try:
        document = json.loads((Path(root) / "hoard.json").read_text())
    except (OSError, ValueError):
        return {}
    return {key: document[key] for key in ("preset", "scale", "seed", "coindie_version") if key in document}
