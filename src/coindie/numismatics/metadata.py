"""Coin metadata: an optional CSV keyed by coin id, with any other columns (weight, findspot, collection,
inventory number, ...), carried into the report and summarised per die.

The key column is the first of ``coin_id``, ``coin``, ``id``, ``name`` present (else the first column).
A key may name the coin (``L0082``, ``L82``) or one of its faces (``L0082D``): both map to the coin. A
column is numeric when every non-empty value parses as a number (decimal comma accepted); a die's summary
gives the mean of each numeric column (and how many coins had a value) and the counts of each value of
the other columns.
"""

from __future__ import annotations

import csv
import re
import statistics
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from coindie.errors import ParameterError
from coindie.ids import parse_face_id

KEY_COLUMNS = ("coin_id", "coin", "id", "name")
_COIN = re.compile(r"^L(?P<number>\d+)$", re.IGNORECASE)


def coin_key(text: str) -> str:
    """Canonical coin id (``L0082``) from a coin or face id; free ids are kept as they are."""
    name = text.strip()
    match = _COIN.match(name)
    if match:
        return parse_face_id(f"L{match['number']}D").coin_key
    return parse_face_id(name).coin_key


@dataclass(frozen=True)
class CoinMetadata:
    """Rows of the metadata CSV by coin, and which columns are numeric."""

    columns: list[str]
    rows: dict[str, dict[str, str]]
    numeric: set[str]
    path: Path | None = None

    def for_coin(self, face_or_coin: str) -> dict[str, str]:
        return self.rows.get(coin_key(face_or_coin), {})

    def summary(self, faces: Iterable[str]) -> dict[str, object]:
        """Per column: ``{"mean": .., "n": ..}`` (numeric) or ``{value: count}`` over the faces' coins."""
        coins = [coin_key(f) for f in faces]
        out: dict[str, object] = {}
        for column in self.columns:
            values = [self.rows[c][column] for c in coins if c in self.rows and self.rows[c].get(column)]
            if not values:
                continue
            if column in self.numeric:
                numbers = [_number(v) for v in values]
                out[column] = {"mean": statistics.fmean(numbers), "n": len(numbers)}
            else:
                out[column] = dict(Counter(values).most_common())
        return out


def _number(text: str) -> float:
    return float(text.replace(",", ".")) if text.count(",") == 1 and "." not in text else float(text)


def _is_number(text: str) -> bool:
    try:
        _number(text)
    except ValueError:
        return False
    return True


def read_metadata(path: str | Path) -> CoinMetadata:
    """Read the CSV; a ``ParameterError`` naming the file for a missing file, no header or no key column."""
    path = Path(path)
    if not path.is_file():
        raise ParameterError(f"{path}: no such metadata file")
    try:
        with path.open(newline="", encoding="utf-8-sig") as stream:
            sample = stream.read(4096)
            stream.seek(0)
            dialect = csv.Sniffer().sniff(sample, delimiters=",;\t") if sample.strip() else csv.excel
            reader = csv.reader(stream, dialect)
            rows = [[cell.strip() for cell in row] for row in reader if any(cell.strip() for cell in row)]
    except (UnicodeDecodeError, csv.Error) as error:
        raise ParameterError(f"{path}: not a readable UTF-8 CSV ({error})") from None
    if len(rows) < 2:
        raise ParameterError(f"{path}: a metadata CSV needs a header and at least one coin")
    header = rows[0]
    lower = [h.lower() for h in header]
    key = next((lower.index(k) for k in KEY_COLUMNS if k in lower), 0)
    columns = [h for i, h in enumerate(header) if i != key]
    table: dict[str, dict[str, str]] = {}
    for line, row in enumerate(rows[1:], start=2):
        if len(row) <= key or not row[key]:
            raise ParameterError(f"{path}: line {line} has no coin id in column {header[key]!r}")
        cells = dict(zip(header, row + [""] * (len(header) - len(row)), strict=False))
        table[coin_key(row[key])] = {c: cells.get(c, "") for c in columns}
    numeric = {
        c
        for c in columns
        if any(r[c] for r in table.values()) and all(_is_number(r[c]) for r in table.values() if r[c])
    }
    return CoinMetadata(columns, table, numeric, path)
