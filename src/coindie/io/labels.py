"""Die labels: which die struck each coin face, as a two-column CSV.

Two headers are read: ours, ``coin_id,die_id``, and the Riedones3D experts', ``name, die`` (with a space
after the comma). Ids may be padded either way (``L082D`` == ``L0082D``); die ids are kept as text.
Other columns are ignored. Files are written with canonical ids (``L0082D``), sorted.
"""

from __future__ import annotations

import csv
from collections.abc import Iterator, Mapping
from pathlib import Path

from coindie.errors import LabelsError, ParameterError
from coindie.ids import FaceId, parse_face_id

#: Accepted names (lower case) of the face-id column and of the die column.
ID_COLUMNS = ("coin_id", "name")
DIE_COLUMNS = ("die_id", "die")
EXPECTED_HEADERS = "'coin_id,die_id' or 'name, die'"


class Labels(Mapping[FaceId, str]):
    """The die of each labelled face: a read-only mapping ``FaceId -> die id``.

    Keys may also be given as text (``labels["L082D"]``). Two spellings of one face with different dies
    are refused (``LabelsError``); the same die twice is fine.
    """

    def __init__(self, dies: Mapping[FaceId | str, str] | None = None, *, path: Path | None = None) -> None:
        self.path = path
        self._dies: dict[FaceId, str] = {}
        seen: dict[FaceId, str] = {}
        for key, die in (dies or {}).items():
            face_id = _face_id(key)
            _add(self._dies, seen, face_id, str(die), where=face_id.name, path=path)

    def __getitem__(self, key: FaceId | str) -> str:
        return self._dies[_face_id(key)]

    def __contains__(self, key: object) -> bool:
        return isinstance(key, FaceId | str) and bool(str(key).strip()) and _face_id(key) in self._dies

    def __iter__(self) -> Iterator[FaceId]:
        return iter(self._dies)

    def __len__(self) -> int:
        return len(self._dies)

    def __repr__(self) -> str:
        source = f", path={str(self.path)!r}" if self.path is not None else ""
        return f"Labels({len(self)} faces, {self.n_dies} dies{source})"

    def dies(self) -> dict[str, list[FaceId]]:
        """The faces struck by each die, dies and faces sorted."""
        groups: dict[str, list[FaceId]] = {}
        for face_id in sorted(self._dies):
            groups.setdefault(self._dies[face_id], []).append(face_id)
        return dict(sorted(groups.items()))

    @property
    def n_dies(self) -> int:
        return len(set(self._dies.values()))


def read_labels(path: str | Path) -> Labels:
    """Read a label CSV; ``LabelsError`` (naming the file and the line) on anything doubtful."""
    path = Path(path)
    rows = _read_rows(path)
    if not rows:
        raise LabelsError("empty file: no header and no labels", path)
    id_column, die_column = _header_columns(rows[0][1], path)
    dies: dict[FaceId, str] = {}
    where: dict[FaceId, str] = {}
    for line, row in rows[1:]:
        face_id, die = _parse_row(row, id_column, die_column, f"line {line}", path)
        _add(dies, where, face_id, die, where=f"{face_id.name} on line {line}", path=path)
    if not dies:
        raise LabelsError("no labels: the file has a header but no rows", path)
    return Labels(dies, path=path)


def write_labels(
    path: str | Path,
    labels: Mapping[FaceId, str] | Mapping[str, str],
    *,
    header: tuple[str, str] = ("coin_id", "die_id"),
) -> Path:
    """Write labels as CSV: the header, then ``canonical id,die`` rows sorted by id."""
    path = Path(path)
    names = [name.strip().lower() for name in header]
    if len(header) != 2 or names[0] not in ID_COLUMNS or names[1] not in DIE_COLUMNS:
        raise ParameterError(
            f"header must be an id column then a die column ({EXPECTED_HEADERS}), got {header}"
        )
    checked = labels if isinstance(labels, Labels) else Labels(labels)
    with path.open("w", newline="", encoding="utf-8") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(header)
        writer.writerows((face_id.key, checked[face_id]) for face_id in sorted(checked))
    return path


def _face_id(key: FaceId | str) -> FaceId:
    return key if isinstance(key, FaceId) else parse_face_id(str(key))


def _add(
    dies: dict[FaceId, str],
    seen: dict[FaceId, str],
    face_id: FaceId,
    die: str,
    *,
    where: str,
    path: Path | None,
) -> None:
    """Record one label; the same face with another die is an error naming both places."""
    if face_id in dies and dies[face_id] != die:
        raise LabelsError(
            f"{seen[face_id]} and {where} name the same face with different dies "
            f"({dies[face_id]!r} and {die!r})",
            path,
        )
    dies.setdefault(face_id, die)
    seen.setdefault(face_id, where)


def _read_rows(path: Path) -> list[tuple[int, list[str]]]:
    """Non-blank CSV rows with their line numbers (1-based), fields stripped."""
    if not path.exists():
        raise LabelsError("no such file", path)
    if path.is_dir():
        raise LabelsError("is a directory, not a label CSV", path)
    try:
        with path.open(newline="", encoding="utf-8-sig") as stream:
            reader = csv.reader(stream, skipinitialspace=True)
            rows = [(reader.line_num, [field.strip() for field in row]) for row in reader]
    except UnicodeDecodeError:
        raise LabelsError("not a UTF-8 text file", path) from None
    except csv.Error as error:
        raise LabelsError(f"not a readable CSV ({error})", path) from None
    except OSError as error:
        raise LabelsError(f"cannot read the file ({error.strerror})", path) from None
    return [(line, row) for line, row in rows if any(row)]


def _header_columns(header: list[str], path: Path) -> tuple[int, int]:
    names = [name.lower() for name in header]
    id_column = next((i for i, name in enumerate(names) if name in ID_COLUMNS), None)
    die_column = next((i for i, name in enumerate(names) if name in DIE_COLUMNS), None)
    if id_column is not None and die_column is not None:
        return id_column, die_column
    first = ",".join(header)
    if parse_face_id(header[0] or "?").coin is not None:
        raise LabelsError(f"no header: the first line is {first!r}; expected {EXPECTED_HEADERS}", path)
    raise LabelsError(f"unknown header {first!r}; expected {EXPECTED_HEADERS}", path)


def _parse_row(row: list[str], id_column: int, die_column: int, where: str, path: Path) -> tuple[FaceId, str]:
    if len(row) <= max(id_column, die_column):
        raise LabelsError(
            f"{where}: expected at least {max(id_column, die_column) + 1} columns, got {row}", path
        )
    face, die = row[id_column], row[die_column]
    if not face or not die:
        raise LabelsError(f"{where}: empty {'face id' if not face else 'die id'}", path)
    return parse_face_id(face), die
