"""Where the dies come from: a project's clusters, or label / cluster CSVs (``name, die`` or
``coin_id,die_id``), split by side (``D`` obverses, ``R`` reverses).

A project's clusters are made here for ``coindie cluster PROJECT --auto`` as for the numismatic results
(:meth:`coindie.project.Project.probability_graph` then :func:`coindie.clustering.cluster`, the paper's
connected components at its threshold 0.95 unless told otherwise), one side at a time, so that a face is
never linked across sides.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from coindie.errors import ParameterError
from coindie.ids import parse_face_id

SIDES = {"D": "obverse", "R": "reverse"}


@dataclass(frozen=True)
class SideDies:
    """Face id (canonical key) -> die label, for the faces of one side."""

    side: str
    dies: dict[str, str]
    source: str
    threshold: float = float("nan")  # the threshold a project's clusters were cut at (NaN: read from a file)

    def members(self) -> dict[str, list[str]]:
        """The faces of each die, largest die first (then by label)."""
        groups: dict[str, list[str]] = {}
        for face, die in sorted(self.dies.items()):
            groups.setdefault(die, []).append(face)
        return dict(sorted(groups.items(), key=lambda item: (-len(item[1]), _natural(item[0]))))


def _natural(label: str) -> tuple[int, int | str]:
    return (0, int(label)) if label.isdigit() else (1, label)


def split_by_side(labels: dict[str, str], source: str) -> dict[str, SideDies]:
    """The labels of each side present (``?`` for ids that name no face)."""
    sides: dict[str, dict[str, str]] = {}
    for face, die in labels.items():
        side = parse_face_id(face).face.value
        sides.setdefault(side, {})[parse_face_id(face).key] = str(die)
    return {side: SideDies(side, dies, source) for side, dies in sorted(sides.items())}


def is_project(path: Path) -> bool:
    from coindie.project.store import DB_NAME

    return path.is_dir() and (path / DB_NAME).is_file()


def project_dies(
    folder: str | Path, method: str = "components", threshold: float | None = None, auto: bool = False
) -> dict[str, SideDies]:
    """The project's die clusters per side, as ``coindie cluster PROJECT`` makes them: at ``threshold``
    (the paper's 0.95 by default) or, with ``auto``, at the threshold of the hoard's own score populations
    (:meth:`coindie.project.Project.auto_graph`: ``coindie cluster --auto``), the experts' edits of the
    review app replayed (``coindie.project.edits``)."""
    from coindie.clustering import PAPER_THRESHOLD
    from coindie.clustering.corrections import corrected_clusters, side_corrections
    from coindie.project import open_project
    from coindie.project.edits import EditLog

    if auto and threshold is not None:
        raise ParameterError("give a threshold or auto, not both")
    project = open_project(folder)
    out: dict[str, SideDies] = {}
    log = EditLog.of_project(project.folder)
    try:
        for side in SIDES:
            if auto:
                graph, tau, how, params = project.auto_graph(side, method)
            else:
                graph, params = project.probability_graph(side), {}
                tau = PAPER_THRESHOLD if threshold is None else threshold
                how = "the paper's" if threshold is None else "given"
            if graph.n_nodes == 0:
                continue
            clusters = corrected_clusters(graph, side_corrections(graph, log.edits()), tau, method, **params)
            labels = {face: f"{side}{label}" for face, label in clusters.labels.items()}
            out[side] = SideDies(side, labels, f"{project.folder} ({method}, threshold {tau:g}, {how})", tau)
    finally:
        log.close()
    if not out:
        raise ParameterError(
            f"{project.folder}: no usable faces yet (prepare and score them with coindie run)"
        )
    return out


def load_dies(
    path: str | Path, method: str = "components", threshold: float | None = None, auto: bool = False
) -> dict[str, SideDies]:
    """Dies per side from a project folder or a label / cluster CSV."""
    from coindie.clustering import read_clusters

    path = Path(path)
    if is_project(path):
        return project_dies(path, method, threshold, auto)
    if path.is_dir():
        raise ParameterError(f"{path}: a folder but not a coindie project (no project.sqlite)")
    return split_by_side(read_clusters(path), str(path))


def load_side(path: str | Path, side: str, **options: object) -> SideDies:
    """One side's dies from a project or a CSV; an error naming the file when it has none of that side.

    In a CSV of one side only, ids that name no face (the experts' obverse file has ``L773R et D``) are
    kept as faces of that side: the file says which side they show."""
    sides = load_dies(path, **options)  # type: ignore[arg-type]
    if side not in sides:
        raise ParameterError(f"{path}: no {SIDES.get(side, side)} faces (ids ending in {side})")
    known = [s for s in sides if s in SIDES]
    if known == [side] and "?" in sides:
        return SideDies(side, {**sides[side].dies, **sides["?"].dies}, sides[side].source)
    return sides[side]
