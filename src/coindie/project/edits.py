"""The experts' edit log on disk: append (checked, committed at once), read, and replay.

The log is the ``edits`` table of a project's database, or, for a bare ``graph.json``, of a sidecar SQLite
file next to it (``graph.json.edits.sqlite``). Rows are never updated nor deleted (triggers refuse it):
undo and redo are entries too. Each edit is committed before :meth:`EditLog.append` returns, so a browser
is told "saved" only for what is on disk.

Every edit carries the sequence number (``base_seq``: the latest edit id its client had seen). An edit
made against a stale sequence number that touches a face an edit since then touched is refused with an
:class:`EditConflict` naming that edit: two tabs never overwrite each other silently.
"""

from __future__ import annotations

import json
import sqlite3
import threading
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from coindie.clustering import Clustering, ProbabilityGraph
from coindie.clustering.corrections import (
    ACTIONS,
    Corrections,
    Edit,
    EditError,
    corrected_clusters,
    replay,
    undone_edits,
)
from coindie.errors import CoinDieError
from coindie.ids import parse_face_id
from coindie.project.schema import EDITS_SCHEMA, PRAGMAS
from coindie.project.store import DB_NAME, now

SIDECAR_SUFFIX = ".edits.sqlite"


class EditConflict(CoinDieError):
    """An edit made against an old state touches what a newer edit changed."""

    def __init__(self, message: str, edit_id: int) -> None:
        super().__init__(message)
        self.edit_id = edit_id


def sidecar_path(graph_path: str | Path) -> Path:
    """Where the edit log of a bare graph file lives: next to it, ``NAME.edits.sqlite``."""
    graph_path = Path(graph_path)
    return graph_path.with_name(graph_path.name + SIDECAR_SUFFIX)


class EditLog:
    """The append-only edit log of one SQLite file (a project's database or a sidecar)."""

    def __init__(self, db_path: str | Path) -> None:
        self.db_path = Path(db_path)
        self._lock = threading.Lock()  # one connection shared by the server's threads
        try:
            self._db = sqlite3.connect(
                self.db_path, timeout=30.0, isolation_level=None, check_same_thread=False
            )
            self._db.row_factory = sqlite3.Row
            for pragma in PRAGMAS:
                self._db.execute(pragma)
            self._db.executescript(f"BEGIN IMMEDIATE;{EDITS_SCHEMA}COMMIT;")
        except sqlite3.Error as error:
            raise CoinDieError(f"{self.db_path}: cannot open the edit log ({error})") from None

    @classmethod
    def of_project(cls, folder: str | Path) -> EditLog:
        return cls(Path(folder) / DB_NAME)

    def close(self) -> None:
        self._db.close()

    @contextmanager
    def _transaction(self) -> Iterator[sqlite3.Connection]:
        with self._lock:
            self._db.execute("BEGIN IMMEDIATE")
            try:
                yield self._db
            except BaseException:
                self._db.execute("ROLLBACK")
                raise
            self._db.execute("COMMIT")

    def edits(self, since: int = 0) -> list[Edit]:
        """The entries after sequence number ``since``, in order."""
        with self._lock:
            query = "SELECT * FROM edits WHERE edit_id > ? ORDER BY edit_id"
            rows = self._db.execute(query, (since,)).fetchall()
        return [_edit(r) for r in rows]

    def last_seq(self) -> int:
        with self._lock:
            row = self._db.execute("SELECT MAX(edit_id) AS m FROM edits").fetchone()
        return int(row["m"] or 0)

    def corrections(self, graph: ProbabilityGraph) -> Corrections:
        return replay(graph, self.edits())

    def clusters(self, graph: ProbabilityGraph, threshold: float, method: str = "components") -> Clustering:
        """The current clusters: the automatic graph with the whole log replayed, at ``threshold``."""
        return corrected_clusters(graph, self.corrections(graph), threshold, method)

    def append(
        self,
        graph: ProbabilityGraph,
        action: str,
        a: str | None = None,
        b: str | None = None,
        payload: Mapping[str, Any] | None = None,
        *,
        base_seq: int,
        author: str = "expert",
        client: str = "",
        threshold: float | None = None,
    ) -> Edit:
        """Check and append one edit, committed before returning; the stored edit.

        ``payload`` gets ``client``, ``base_seq`` and, when ``threshold`` is given, ``before`` and
        ``after``: the clusters (member lists) of the faces touched, at that threshold.

        Raises:
            EditError: unknown action or face, an undo of what is not in effect, a redo of what is.
            EditConflict: an edit after ``base_seq`` touched one of the same faces.
        """
        if action not in ACTIONS:
            raise EditError(f"unknown edit action {action!r}; one of {', '.join(ACTIONS)}")
        payload = dict(payload or {})
        a = parse_face_id(a).key if a else None
        b = parse_face_id(b).key if b else None
        nodes = set(graph.nodes)
        with self._transaction() as db:
            log = [_edit(r) for r in db.execute("SELECT * FROM edits ORDER BY edit_id")]
            last = log[-1].edit_id if log else 0
            if not 0 <= base_seq <= last:
                raise EditError(f"base_seq {base_seq} is not a sequence number of this log (latest {last})")
            draft = Edit(last + 1, action, a, b, payload)
            self._check(draft, log, nodes)
            touched = draft.touched() | _target_touched(draft, log)
            for later in log[base_seq:]:
                common = touched & (later.touched() | _target_touched(later, log))
                if common:
                    raise EditConflict(
                        f"refused: edit {later.edit_id} ({later.action} by {later.author or 'someone'}, "
                        f"{later.at}) changed {', '.join(sorted(common))} since you loaded state "
                        f"{base_seq}; reload and try again",
                        later.edit_id,
                    )
            payload["client"], payload["base_seq"] = client, base_seq
            if threshold is not None:
                before = corrected_clusters(graph, replay(graph, log), threshold)
                after = corrected_clusters(graph, replay(graph, [*log, draft]), threshold)
                payload["threshold"] = threshold
                payload["before"] = _members_of(before, touched)
                payload["after"] = _members_of(after, touched)
            stamp = now()
            cursor = db.execute(
                "INSERT INTO edits (at, author, action, a, b, payload) VALUES (?, ?, ?, ?, ?, ?)",
                (stamp, author, action, a, b, json.dumps(payload, sort_keys=True)),
            )
        return Edit(int(cursor.lastrowid or 0), action, a, b, payload, stamp, author)

    @staticmethod
    def _check(edit: Edit, log: Sequence[Edit], nodes: set[str]) -> None:
        for face in edit.touched():
            if parse_face_id(face).key not in nodes:
                raise EditError(f"{edit.action}: no face {face} in this graph")
        if edit.action in ("cut", "link", "merge", "register"):
            if not (edit.a and edit.b) or edit.a == edit.b:
                raise EditError(f"{edit.action} needs two different faces (a, b)")
        if edit.action == "move" and not edit.a:
            raise EditError("move needs the face to move (a) and a face of the cluster to join (b, or none)")
        if edit.action == "split" and not (edit.payload.get("group") and edit.payload.get("rest")):
            raise EditError("split needs the faces that leave (group) and those that stay (rest)")
        if edit.action == "verify" and not edit.payload.get("members"):
            raise EditError("verify needs the members of the cluster")
        if edit.action == "register":
            p = edit.payload.get("probability")
            if not isinstance(p, int | float) or not 0.0 <= p <= 1.0:
                raise EditError(f"register needs a probability in [0, 1]; got {p!r}")
        if edit.action in ("undo", "redo"):
            target = edit.payload.get("target")
            known = {e.edit_id: e for e in log}
            if not isinstance(target, int) or target not in known or known[target].action in ("undo", "redo"):
                raise EditError(f"{edit.action}: {target!r} is not an edit of this log that can be undone")
            undone = undone_edits(log)
            if edit.action == "undo" and target in undone:
                raise EditError(f"undo: edit {target} is already undone")
            if edit.action == "redo" and target not in undone:
                raise EditError(f"redo: edit {target} is in effect (nothing to redo)")


def _target_touched(edit: Edit, log: Sequence[Edit]) -> set[str]:
    if edit.action not in ("undo", "redo"):
        return set()
    target = edit.payload.get("target")
    return next((e.touched() for e in log if e.edit_id == target), set())


def _members_of(clustering: Clustering, faces: set[str]) -> list[list[str]]:
    labels = {clustering.labels[f] for f in faces if f in clustering.labels}
    return [sorted(f for f, lab in clustering.labels.items() if lab == label) for label in sorted(labels)]


def _edit(row: sqlite3.Row) -> Edit:
    return Edit.of({**dict(row), "payload": json.loads(row["payload"])})
