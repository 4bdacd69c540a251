"""What the review app shows: a die-study project (graph, scans, pair transforms) or a bare graph file.

A project opens on the clusters ``coindie cluster --auto`` makes of it, each side cut where its own scores
say (:mod:`coindie.serve.cuts`), or, given a threshold, on the paper's components at that threshold. A
bare ``graph.json`` (the paper's node-link format) or pairs CSV opens at a threshold (the paper's 0.95 by
default) and has no scans: the graph, clusters, edits and exports work, the image views say there is no
image. Its edit log is a sidecar SQLite file (:func:`coindie.project.edits.sidecar_path`) unless another
path is given.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from coindie.clustering import PAPER_THRESHOLD, Clustering, ProbabilityGraph, read_graph
from coindie.clustering.algorithms import ConsensusLinkage
from coindie.clustering.corrections import Corrections, corrected_graph, pair
from coindie.errors import CoinDieError
from coindie.ids import parse_face_id
from coindie.project import open_project
from coindie.project.edits import EditLog, sidecar_path
from coindie.project.store import DB_NAME, scored
from coindie.serve.cuts import START, ReviewLinks, SideCut, auto_links, components_at, threshold_links
from coindie.serve.layout import cluster_layout
from coindie.similarity.calibration import HoardCalibration, log_odds


class ReviewError(CoinDieError):
    """The thing to review cannot be opened."""


@dataclass
class PairRecord:
    """A scored pair as the app needs it (transform into the target's scan frame)."""

    source: str
    target: str
    probability: float
    valid: bool
    reason: str
    method: str
    T_target_source: np.ndarray | None
    histogram: np.ndarray | None
    origin: str = "automatic"


@dataclass
class ReviewSource:
    """The graph under review, its scans (when any) and its edit log.

    ``cuts``: each side's cut as ``coindie cluster --auto`` makes it, ``graph`` then holding every side's
    graph; none: the paper's components of ``graph`` at the slider's τ. ``threshold``: the slider's start.
    """

    name: str
    path: Path
    graph: ProbabilityGraph
    log: EditLog
    threshold: float
    scan_paths: dict[str, Path] = field(default_factory=dict)
    pairs: dict[tuple[str, str], PairRecord] = field(default_factory=dict)
    sides: dict[str, str] = field(default_factory=dict)
    labels: dict[str, str] = field(default_factory=dict)  # given at init; for evaluation, never shown
    cuts: list[SideCut] = field(default_factory=list)
    unit: str | None = None  # the scans' declared unit (a project's coindie init --unit); None: by size
    #: pairs standing apart above the rest of their side that the scorer judges different-die all the same
    #: (:attr:`coindie.similarity.HoardCalibration.apart`), each with why, for the review queue
    apart: dict[tuple[str, str], str] = field(default_factory=dict)
    _links: tuple[int, ReviewLinks] | None = field(default=None, repr=False)

    @property
    def has_images(self) -> bool:
        return bool(self.scan_paths)

    @property
    def method(self) -> str:
        """The clustering the slider cuts: the sides' own (``coindie cluster --auto``) or components."""
        return "/".join(sorted({cut.method for cut in self.cuts})) or "components"

    @property
    def how(self) -> str:
        """Where the start comes from, in words."""
        if not self.cuts:
            return f"components of the probabilities above τ = {self.threshold:g}"
        return "; ".join(
            f"{cut.side}: {cut.method} cut at {cut.threshold:.3f} ({cut.how})" for cut in self.cuts
        )

    def links(self, corrections: Corrections | None = None) -> ReviewLinks:
        """The links the slider cuts, the log's edits applied (computed again after each edit)."""
        seq = self.log.last_seq()
        if self._links is not None and self._links[0] == seq:
            return self._links[1]
        if self.cuts:
            links = auto_links(self.cuts, self.graph.nodes, self.log.edits())
        else:
            links = threshold_links(self.graph, self.corrections() if corrections is None else corrections)
        self._links = (seq, links)
        return links

    def clusters(self, threshold: float, corrections: Corrections | None = None) -> Clustering:
        """The current clusters at slider value ``threshold`` (what the browser shows)."""
        return components_at(self.links(corrections), threshold, self.method)

    @cached_property
    def layout(self) -> dict[str, tuple[float, float]]:
        """Node positions, computed once (the clusters at the start)."""
        return cluster_layout(self.graph, self.clusters(self.threshold).clusters())

    def face(self, face: str) -> str:
        """The canonical key of a face of the graph; ``KeyError`` with a message when it is not one."""
        try:
            key = parse_face_id(face).key
        except ValueError:
            raise KeyError(f"no face {face!r} in {self.name}") from None
        if key not in self._nodes:
            raise KeyError(f"no face {face!r} in {self.name}")
        return key

    @cached_property
    def _nodes(self) -> set[str]:
        return set(self.graph.nodes)

    def corrections(self) -> Corrections:
        return self.log.corrections(self.graph)

    def neighbours(self, face: str, corrections: Corrections) -> list[dict[str, Any]]:
        """The face's scored partners, most probable first (expert probabilities, cut and forced links)."""
        key = self.face(face)
        corrected = corrected_graph(self.graph, corrections)
        out = []
        for a, b, p in corrected.edges():
            if key in (a, b):
                other = b if a == key else a
                state = (
                    "cut"
                    if pair(a, b) in corrections.cut
                    else "forced"
                    if pair(a, b) in corrections.forced
                    else "auto"
                )
                automatic = self.pairs.get(pair(a, b))
                out.append(
                    {
                        "face": other,
                        "probability": p,
                        "state": state,
                        "automatic": automatic.probability if automatic else None,
                    }
                )
        return sorted(out, key=lambda n: (-n["probability"], n["face"]))

    def pair_record(self, a: str, b: str) -> PairRecord:
        """The scored pair a–b (either direction), transform taking ``b`` (source) into ``a``'s frame
        (target); with the latest expert registration in effect when there is one."""
        ka, kb = self.face(a), self.face(b)
        record = self.pairs.get(pair(ka, kb))
        expert = self._expert_registration(ka, kb)
        if expert is not None:
            record = expert
        if record is None:
            raise KeyError(f"the pair {ka}-{kb} was not scored")
        if (record.target, record.source) == (ka, kb):
            return record
        T = None if record.T_target_source is None else np.linalg.inv(record.T_target_source)
        return PairRecord(
            kb,
            ka,
            record.probability,
            record.valid,
            record.reason,
            record.method,
            T,
            record.histogram,
            record.origin,
        )

    def _expert_registration(self, ka: str, kb: str) -> PairRecord | None:
        corrections = self.corrections()
        found = None
        for edit in self.log.edits():
            if (
                edit.action == "register"
                and edit.edit_id in corrections.active
                and pair(ka, kb) == pair(edit.a or "", edit.b or "")
            ):
                p = edit.payload
                found = PairRecord(
                    str(p["source"]),
                    str(p["target"]),
                    float(p["probability"]),
                    True,
                    str(p.get("reason", "")),
                    "expert points + icp",
                    np.asarray(p["T_target_source"], dtype=np.float64),
                    np.asarray(p["histogram"], dtype=np.float64),
                    "expert",
                )
        return found


def open_source(
    path: str | Path, *, threshold: float | None = None, edits: str | Path | None = None
) -> ReviewSource:
    """A project folder or a graph file, ready to review.

    Raises:
        ReviewError: the path is neither a project nor a readable graph.
    """
    path = Path(path)
    if path.is_dir():
        if not (path / DB_NAME).is_file():
            raise ReviewError(f"{path}: not a coindie project (no {DB_NAME}) and not a graph file")
        return _from_project(path, threshold)
    if not path.is_file():
        raise ReviewError(f"{path}: no such project folder or graph file")
    graph = read_graph(path)
    log = EditLog(Path(edits) if edits else sidecar_path(path))
    tau = PAPER_THRESHOLD if threshold is None else threshold
    pairs = {pair(a, b): PairRecord(b, a, p, True, "", "", None, None) for a, b, p in graph.edges()}
    sides = {node: parse_face_id(node).face.value for node in graph.nodes}
    return ReviewSource(path.name, path.resolve(), graph, log, tau, pairs=pairs, sides=sides)


def _from_project(folder: Path, threshold: float | None) -> ReviewSource:
    project = open_project(folder)
    cuts, calibrations = ([], {}) if threshold is not None else _auto_cuts(project)
    if cuts:
        edges = [edge for cut in cuts for edge in cut.graph.edges()]
        graph = ProbabilityGraph.from_edges(edges, [face for cut in cuts for face in cut.graph.nodes])
    else:
        graph = project.probability_graph()
    scans = {s.face_id: s for s in project.scans("ok")}
    pairs: dict[tuple[str, str], PairRecord] = {}
    for row in project.scored_pairs():
        key = pair(row["source"], row["target"])
        if key in pairs:
            continue
        pairs[key] = PairRecord(
            row["source"],
            row["target"],
            float(row["probability"] or 0.0),
            bool(row["valid"]),
            row["reason"] or "",
            row["method"] or "",
            row.get("T_target_source"),
            row.get("histogram"),
            row["origin"] or "automatic",
        )
    tau = START if cuts else PAPER_THRESHOLD if threshold is None else threshold
    paths = {face: Path(s.path) for face, s in scans.items()}
    sides = {face: s.side for face, s in scans.items()}
    labels = project.labels()
    unit = project.unit
    apart = _apart_pairs(project, calibrations)
    project.close()
    return ReviewSource(
        folder.name, folder.resolve(), graph, EditLog.of_project(folder), tau, paths, pairs, sides, labels,
        cuts, unit, apart=apart,
    )  # fmt: skip


def _apart_pairs(project: Any, calibrations: dict[str, HoardCalibration]) -> dict[tuple[str, str], str]:
    """The pairs of each side whose calibration found them standing apart above the rest though the scorer
    judges them different-die (:attr:`coindie.similarity.HoardCalibration.apart`), each with why."""
    apart: dict[tuple[str, str], str] = {}
    for side, calibration in calibrations.items():
        if calibration.apart is None:
            continue
        lowest = calibration.apart[1]
        for row in project.scored_pairs(None, side):
            z = float(log_odds(float(row["probability"] or 0.0)))
            if scored(row) and z >= lowest:
                apart[pair(row["source"], row["target"])] = (
                    f"stands apart above the rest of side {side} (log-odds {z:.2f}), though the scorer "
                    "judges it different-die: on scans that lower every score, perhaps one die"
                )
    return apart


def _auto_cuts(project: Any) -> tuple[list[SideCut], dict[str, HoardCalibration]]:
    """Each side's cut as ``coindie cluster --auto`` makes it, and the calibration of each side scored;
    none before any pair is scored (then the paper's components at its τ)."""
    scored_sides = project.scored_sides(project.current_params())
    if not scored_sides:
        return [], {}
    cuts, calibrations = [], {}
    for side in ("D", "R"):
        why = "no pair scored yet"  # its faces alone, as the paper's components leave them
        if side in scored_sides:
            try:
                calibrations[side] = project.calibration(side)
                graph, tau, how, params = project.auto_graph(side, ConsensusLinkage.NAME, calibrations[side])
            except CoinDieError as error:
                why = f"no cut without labels: {error}"
            else:
                if graph.n_nodes:
                    cuts.append(SideCut(side, graph, ConsensusLinkage.NAME, tau, params, how))
                continue
        graph = project.probability_graph(side)  # the side still opens, on the paper's components, saying why
        if graph.n_nodes:
            cuts.append(SideCut(side, graph, "components", PAPER_THRESHOLD, {}, why))
    return cuts, calibrations
