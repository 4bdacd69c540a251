"""Coin face identifiers.

Riedones3D names each scan ``L`` + coin number + ``D`` (obverse, French *droit*) or ``R`` (reverse,
*revers*): ``L0001D``, ``L0145R``. The experts' files pad the number to three digits (``L082D``), the scans
to four (``L0082D``): both name the same face. Any other file stem is accepted as a free id whose face is
unknown.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import PurePath

_COIN_ID = re.compile(r"^L(?P<number>\d+)(?P<face>[DR])$", re.IGNORECASE)

#: Zero-padding of coin numbers in canonical ids, as in the Riedones3D scan files.
CANONICAL_DIGITS = 4


class Face(StrEnum):
    """Which face of the coin a scan shows."""

    OBVERSE = "D"
    REVERSE = "R"
    UNKNOWN = "?"


@dataclass(frozen=True, order=True)
class FaceId:
    """Identity of one scanned face.

    Two ids are equal when they name the same face: ``L082D == L0082D``. ``name`` keeps the spelling it
    was parsed from (for messages and exports); ``key`` is the canonical form used for equality.
    """

    key: str
    coin: int | None = field(compare=False)
    face: Face = field(compare=False)
    name: str = field(compare=False)

    @property
    def coin_key(self) -> str:
        """Canonical id of the coin (both faces), e.g. ``L0082``; the free id itself if not a coin id."""
        return self.key[:-1] if self.coin is not None else self.key

    def __str__(self) -> str:
        return self.key


def canonical_face_id(coin: int, face: Face) -> str:
    """``canonical_face_id(82, Face.OBVERSE) == "L0082D"``."""
    if face is Face.UNKNOWN:
        raise ValueError("a coin id needs a known face (D or R)")
    return f"L{coin:0{CANONICAL_DIGITS}d}{face.value}"


def parse_face_id(text: str) -> FaceId:
    """Parse a coin face id; any other non-empty text becomes a free id with an unknown face.

    >>> parse_face_id("L082D") == parse_face_id("L0082D")
    True
    >>> parse_face_id("L0145R").face
    <Face.REVERSE: 'R'>
    """
    name = text.strip()
    if not name:
        raise ValueError("empty face id")
    match = _COIN_ID.match(name)
    if match is None:
        return FaceId(key=name, coin=None, face=Face.UNKNOWN, name=name)
    coin = int(match["number"])
    face = Face(match["face"].upper())
    return FaceId(key=canonical_face_id(coin, face), coin=coin, face=face, name=name)


def face_id_of(path: PurePath) -> FaceId:
    """The face id a scan file names: ``L0082D.ply`` -> ``L0082D``."""
    return parse_face_id(path.stem)
