"""The experts' corrections of an automatic clustering: a log of edits replayed onto the probability graph.

The current clusters are never stored; they are the replay of the log (:func:`replay`) onto the automatic
graph, then :func:`corrected_clusters` at a threshold τ. The browser (``coindie serve``) and the command line
(``coindie cluster PROJECT``) both call these two functions, so they always agree.

Every edit resolves into link overrides that do not depend on τ, so moving the threshold slider after an
edit keeps the edit's meaning:

- ``cut a b``: the link a–b is absent whatever its probability;
- ``link a b``: the link a–b is present (a forced link); ``merge a b`` is the same between two clusters;
- ``move a b``: every link of ``a`` is cut, then a–b is forced (``b`` empty: ``a`` becomes a singleton);
- ``split``: ``payload["group"]`` leaves its cluster (``payload["rest"]``): every link between the two
  member lists is cut;
- ``verify``: ``payload["members"]`` is a verified die; a cluster is shown verified while its members are
  exactly those;
- ``register a b``: an expert re-registration; ``payload["probability"]`` replaces the pair's probability;
- ``undo``/``redo`` ``payload["target"]``: switch an earlier edit off or on again (themselves log entries).

Cut and forced links win over probabilities; of a cut and a link on one pair, the later edit wins.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from coindie.clustering.algorithms import (
    Clustering,
    ClusteringAlgorithm,
    ConnectedComponents,
    get_algorithm,
    link_components,
)
from coindie.clustering.graph import ProbabilityGraph
from coindie.clustering.merges import LINKAGE_METHODS, MergeLinks, merge_links
from coindie.errors import ParameterError
from coindie.ids import parse_face_id

#: Edit actions that change links or probabilities (the others: verify, undo, redo).
LINK_ACTIONS = ("cut", "link", "merge", "move", "split", "register")
ACTIONS = (*LINK_ACTIONS, "verify", "undo", "redo")

Pair = tuple[str, str]


class EditError(ParameterError):
    """An edit names an unknown face, an unknown action, or contradicts the log (undo of an undone edit)."""


@dataclass(frozen=True)
class Edit:
    """One entry of the log, as stored (``edit_id`` is its sequence number, 1, 2, ...)."""

    edit_id: int
    action: str
    a: str | None = None
    b: str | None = None
    payload: Mapping[str, Any] = field(default_factory=dict)
    at: str = ""
    author: str = ""

    @classmethod
    def of(cls, row: Mapping[str, Any]) -> Edit:
        return cls(
            int(row["edit_id"]),
            str(row["action"]),
            row.get("a"),
            row.get("b"),
            dict(row.get("payload") or {}),
            str(row.get("at", "")),
            str(row.get("author", "")),
        )

    def touched(self) -> set[str]:
        """The faces this edit is about (two edits conflict when these meet)."""
        faces = {f for f in (self.a, self.b) if f}
        for key in ("group", "rest", "members"):
            faces.update(self.payload.get(key, ()))
        return faces


@dataclass
class Corrections:
    """What the active edits of a log amount to, independent of τ.

    Attributes:
        cut: pairs (sorted face keys) that are absent.
        forced: pairs that are present.
        probability: expert re-registrations: pair -> new probability.
        verified: member sets marked verified, latest last.
        active: ids of the edits in effect (not undone); ``undone``: ids switched off by an undo.
    """

    cut: set[Pair] = field(default_factory=set)
    forced: set[Pair] = field(default_factory=set)
    probability: dict[Pair, float] = field(default_factory=dict)
    verified: list[frozenset[str]] = field(default_factory=list)
    active: list[int] = field(default_factory=list)
    undone: set[int] = field(default_factory=set)

    def is_verified(self, members: Iterable[str]) -> bool:
        return frozenset(members) in self.verified


def pair(a: str, b: str) -> Pair:
    ka, kb = parse_face_id(a).key, parse_face_id(b).key
    return (ka, kb) if ka <= kb else (kb, ka)


def undone_edits(edits: Sequence[Edit]) -> set[int]:
    """Ids of the edits switched off by the undo/redo entries of the log."""
    undone: set[int] = set()
    for edit in edits:
        target = int(edit.payload.get("target", 0)) if edit.action in ("undo", "redo") else 0
        if edit.action == "undo":
            undone.add(target)
        elif edit.action == "redo":
            undone.discard(target)
    return undone


def replay(graph: ProbabilityGraph, edits: Sequence[Edit]) -> Corrections:
    """The corrections that the log ``edits`` (in sequence order) make to ``graph``.

    Raises:
        EditError: an edit names a face that is not in the graph or an unknown action.
    """
    nodes = set(graph.nodes)
    neighbours = _neighbours(graph)
    result = Corrections(undone=undone_edits(edits))
    for edit in edits:
        if edit.action not in ACTIONS:
            raise EditError(f"edit {edit.edit_id}: unknown action {edit.action!r}")
        for face in edit.touched():
            if parse_face_id(face).key not in nodes:
                raise EditError(f"edit {edit.edit_id} ({edit.action}): no face {face} in the graph")
        if edit.action in ("undo", "redo") or edit.edit_id in result.undone:
            continue
        result.active.append(edit.edit_id)
        _apply(edit, result, neighbours)
    return result


def side_corrections(graph: ProbabilityGraph, edits: Sequence[Edit]) -> Corrections:
    """The corrections that the log ``edits`` makes to one side's ``graph``.

    A project's log covers both sides of the hoard and a side is clustered alone (a face never links
    across sides), so each side replays the edits about its own faces only. The command line
    (:func:`coindie.numismatics.sources.project_dies`) and the review app (:mod:`coindie.serve.cuts`) both
    call this, so they agree on every side.
    """
    on_side = set(graph.nodes)
    return replay(graph, [e for e in edits if {parse_face_id(f).key for f in e.touched()} <= on_side])


def _apply(edit: Edit, result: Corrections, neighbours: Mapping[str, set[str]]) -> None:
    def cut(p: Pair) -> None:
        result.forced.discard(p)
        result.cut.add(p)

    def force(p: Pair) -> None:
        result.cut.discard(p)
        result.forced.add(p)

    if edit.action == "cut":
        cut(pair(edit.a or "", edit.b or ""))
    elif edit.action in ("link", "merge"):
        force(pair(edit.a or "", edit.b or ""))
    elif edit.action == "move":
        face = parse_face_id(edit.a or "").key
        linked = neighbours.get(face, set()) | {x for p in result.forced if face in p for x in p}
        for other in linked - {face}:
            cut(pair(face, other))
        if edit.b:
            force(pair(face, edit.b))
    elif edit.action == "split":
        group, rest = edit.payload.get("group", ()), edit.payload.get("rest", ())
        for a in group:
            for b in rest:
                cut(pair(a, b))
    elif edit.action == "verify":
        result.verified.append(frozenset(parse_face_id(f).key for f in edit.payload.get("members", ())))
    elif edit.action == "register":
        result.probability[pair(edit.a or "", edit.b or "")] = float(edit.payload["probability"])


def _neighbours(graph: ProbabilityGraph) -> dict[str, set[str]]:
    out: dict[str, set[str]] = {}
    for a, b, _ in graph.edges():
        out.setdefault(a, set()).add(b)
        out.setdefault(b, set()).add(a)
    return out


def corrected_graph(graph: ProbabilityGraph, corrections: Corrections) -> ProbabilityGraph:
    """``graph`` with the expert probabilities, cut links at 0 and forced links at 1 (added if unscored)."""
    weights = {(a, b) if a <= b else (b, a): p for a, b, p in graph.edges()}
    weights.update(corrections.probability)
    for p in corrections.cut:
        weights[p] = 0.0
    for p in corrections.forced:
        weights[p] = 1.0
    return ProbabilityGraph.from_edges(((a, b, p) for (a, b), p in weights.items()), graph.nodes)


def kept_links(graph: ProbabilityGraph, corrections: Corrections, threshold: float) -> np.ndarray:
    """(m,) bool over ``corrected_graph``'s edges: the links the paper's components method keeps at τ
    (probability above τ, or forced; never cut)."""
    corrected = corrected_graph(graph, corrections)
    return _kept(corrected, corrections, threshold)


def _kept(corrected: ProbabilityGraph, corrections: Corrections, threshold: float) -> np.ndarray:
    names = corrected.nodes
    flags = [
        (pair(names[i], names[j]) in corrections.forced, pair(names[i], names[j]) in corrections.cut)
        for i, j in zip(corrected.i, corrected.j, strict=True)
    ]
    forced = np.array([f for f, _ in flags], dtype=bool)
    cut_ = np.array([c for _, c in flags], dtype=bool)
    return ((corrected.probability > threshold) | forced) & ~cut_


def corrected_tree_links(
    corrected: ProbabilityGraph, corrections: Corrections, algorithm: ClusteringAlgorithm
) -> MergeLinks:
    """The tree that ``algorithm`` (``average`` or ``consensus``) builds on the corrected graph
    (:func:`corrected_graph`), as links over its nodes (:func:`coindie.clustering.merges.merge_links`): no
    merge is carried by a pair the experts cut."""
    index = {face: k for k, face in enumerate(corrected.nodes)}
    excluded = [(index[a], index[b]) for a, b in corrections.cut if a in index and b in index]
    return merge_links(corrected, algorithm, excluded)


def corrected_clusters(
    graph: ProbabilityGraph,
    corrections: Corrections,
    threshold: float,
    method: str = "components",
    **params: Any,
) -> Clustering:
    """The die clusters at ``threshold`` once the corrections are applied; ``params``: the method's other
    parameters (the consensus's ``measure``).

    ``components`` keeps the forced links at any τ (even 1). ``average`` and ``consensus`` cut their tree
    of the corrected graph (forced links at probability 1, cut ones at 0) as links
    (:func:`corrected_tree_links`), then keep the forced links and drop the cut ones as ``components``
    does: a split or a move holds whatever the tree. Leiden clusters the corrected graph.
    """
    # the parameters checked by their declarations
    algorithm = get_algorithm(method, threshold=threshold, **params)
    corrected = corrected_graph(graph, corrections)
    n = corrected.n_nodes
    linkage = method in LINKAGE_METHODS and n >= 2
    if (method != ConnectedComponents.NAME and not linkage) or n == 0:
        return algorithm.fit(corrected).clustering_
    threshold = algorithm.threshold
    if linkage:
        links = corrected_tree_links(corrected, corrections, algorithm)
        kept = links.kept(threshold)
        index = {face: k for k, face in enumerate(corrected.nodes)}
        forced = [(index[a], index[b]) for a, b in corrections.forced if a in index and b in index]
        ends = np.array(forced, np.int64).reshape(-1, 2)
        i = np.concatenate([links.i[kept], ends[:, 0]])
        j = np.concatenate([links.j[kept], ends[:, 1]])
    else:
        kept = _kept(corrected, corrections, threshold)
        i, j = corrected.i[kept], corrected.j[kept]
    return link_components(corrected.nodes, i, j, method, threshold)
