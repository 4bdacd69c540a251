"""A folder of scans (and optionally its ``labels.csv``), listed without being read.

A batch never dies because of one bad scan: ``iter_scans`` and ``load_all`` yield the good scans and
record each bad file, with its one-line problem, in ``failures``.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from coindie.errors import CoinDieError, ScanReadError
from coindie.ids import FaceId, face_id_of, parse_face_id
from coindie.io.labels import Labels, read_labels
from coindie.io.reader import MAX_SCAN_BYTES, is_scan_name, read_scan
from coindie.scan import Scan

#: The label file used when ``open_dataset`` is given none.
LABELS_NAME = "labels.csv"


@dataclass(frozen=True)
class ScanFailure:
    """A scan file that could not be used, and why (one line)."""

    path: Path
    problem: str

    def __str__(self) -> str:
        return f"{self.path}: {self.problem}"


@dataclass
class ScanFolder:
    """The scan files of a folder, one per face id; files are read on demand.

    Attributes:
        folder: the folder listed.
        paths: one scan file per face id, sorted by file name.
        labels: the die labels, if any.
        failures: files that could not be used: same-face duplicates found when listing, plus the bad
            files met by the last ``iter_scans``/``load_all``.
    """

    folder: Path
    paths: list[Path]
    labels: Labels | None = None
    duplicates: list[ScanFailure] = field(default_factory=list)
    failures: list[ScanFailure] = field(default_factory=list)
    max_bytes: int = MAX_SCAN_BYTES

    def __post_init__(self) -> None:
        self._by_id = {face_id_of(path): path for path in self.paths}
        self.failures = list(self.duplicates)

    def __len__(self) -> int:
        return len(self.paths)

    @property
    def ids(self) -> list[FaceId]:
        return [face_id_of(path) for path in self.paths]

    def path_of(self, face_id: FaceId | str) -> Path:
        key = face_id if isinstance(face_id, FaceId) else parse_face_id(face_id)
        if key not in self._by_id:
            raise ScanReadError(f"no scan of face {key} in this folder ({len(self)} scans)", self.folder)
        return self._by_id[key]

    def read(self, face_id: FaceId | str) -> Scan:
        """Read one scan by its face id (``L082D`` finds ``L0082D.ply``)."""
        return read_scan(self.path_of(face_id), max_bytes=self.max_bytes)

    def iter_scans(self) -> Iterator[Scan]:
        """Yield every readable scan; each bad file is recorded in ``failures`` instead of raised."""
        self.failures = list(self.duplicates)
        for path in self.paths:
            try:
                scan = read_scan(path, max_bytes=self.max_bytes)
            except CoinDieError as error:
                self.failures.append(ScanFailure(path, getattr(error, "problem", str(error))))
                continue
            except Exception as error:  # a batch never dies on one file, even on an unforeseen error
                self.failures.append(ScanFailure(path, f"unexpected {type(error).__name__}: {error}"))
                continue
            yield scan

    def load_all(self) -> tuple[list[Scan], list[ScanFailure]]:
        """All readable scans, and the files that could not be used."""
        scans = list(self.iter_scans())
        return scans, list(self.failures)


def open_dataset(
    folder: str | Path,
    labels: Labels | Mapping[str, str] | str | Path | None = None,
    *,
    recursive: bool = False,
    max_bytes: int = MAX_SCAN_BYTES,
) -> ScanFolder:
    """List the scan files of ``folder`` (known suffixes, sorted) without reading them.

    ``labels`` may be a ``Labels``, a mapping, or a CSV path; when None, ``folder/labels.csv`` is read if
    it exists. Names starting with a dot are skipped. A second file naming an already listed face
    (``L0082D.ply`` after ``L082D.ply``) is recorded as a failure, not listed.
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise ScanReadError("no such folder" if not folder.exists() else "not a folder", folder)
    paths, duplicates = _unique_faces(_scan_files(folder, recursive))
    return ScanFolder(folder, paths, _labels(folder, labels), duplicates, max_bytes=max_bytes)


def _scan_files(folder: Path, recursive: bool) -> list[Path]:
    candidates = folder.rglob("*") if recursive else folder.iterdir()
    # names only (no stat): broken links and directories named x.ply are listed and fail when read
    return sorted(path for path in candidates if is_scan_name(path) and not path.name.startswith("."))


def _unique_faces(paths: list[Path]) -> tuple[list[Path], list[ScanFailure]]:
    first: dict[FaceId, Path] = {}
    duplicates = []
    for path in paths:
        face_id = face_id_of(path)
        if face_id in first:
            problem = f"names the same face ({face_id}) as {first[face_id].name}, which is used instead"
            duplicates.append(ScanFailure(path, problem))
        else:
            first[face_id] = path
    return list(first.values()), duplicates


def _labels(folder: Path, labels: Labels | Mapping[str, str] | str | Path | None) -> Labels | None:
    if labels is None:
        default = folder / LABELS_NAME
        return read_labels(default) if default.exists() else None
    if isinstance(labels, str | Path):
        return read_labels(labels)
    return labels if isinstance(labels, Labels) else Labels(labels)
