"""The project folder and its database: scans, per-face cache, pairs, runs, labels, edits.

A project is ``FOLDER/project.sqlite`` plus ``FOLDER/cache/``. Everything a run needs to resume is in the
database; every write is a short transaction, so a killed process leaves the file consistent. Paths of
scans are stored absolute (a Dask worker on another machine needs the same mount).
"""

from __future__ import annotations

import json
import os
import sqlite3
import time
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from datetime import UTC, datetime
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from coindie.errors import CoinDieError
from coindie.ids import FaceId, parse_face_id
from coindie.project.schema import PRAGMAS, RELAYS_SCHEMA, SCHEMA, SCHEMA_VERSION
from coindie.similarity.calibration import (
    MAX_SAME_SHARE,
    MAX_SAME_SHARE_CANDIDATES,
    MIXTURE_THRESHOLD,
    HoardCalibration,
    calibrated_side,
)

if TYPE_CHECKING:
    from coindie.clustering import ProbabilityGraph
    from coindie.clustering.second_pass import TwoPassResult
    from coindie.clustering.threshold import ThresholdChoice

DB_NAME = "project.sqlite"
CACHE_DIR = "cache"


@dataclass(frozen=True)
class Overrule:
    """A split of a side's scores that the scorer vetoed and ``coindie cluster --auto`` keeps all the
    same (:meth:`Project.overrule`)."""

    silhouette: float  # mean silhouette of its clusters: how far they stand out
    after_pulls: bool  # the split once each face's pull is taken off (the second pass), not the side's own
    calibration: HoardCalibration  # that split


class ProjectError(CoinDieError):
    """A project folder is missing, not a project, of another version, or asked something impossible."""


def now() -> str:
    """UTC time stamp, ISO 8601 to the millisecond."""
    return datetime.now(UTC).isoformat(timespec="milliseconds")


@dataclass(frozen=True)
class ScanRow:
    """One face of the project."""

    face_id: str
    name: str
    side: str
    path: str
    content_hash: str | None
    status: str
    error: str | None
    n_points: int | None


@dataclass
class AddReport:
    """What adding a scan folder did: faces new, changed (their pairs dropped), unchanged, and files
    that could not be listed (duplicates of a face)."""

    added: list[str] = field(default_factory=list)
    changed: list[str] = field(default_factory=list)
    unchanged: int = 0
    skipped: list[str] = field(default_factory=list)


def side_of(face_id: FaceId) -> str:
    """The die study a face belongs to: ``D`` (obverses, with and without beard), ``R``, or ``?`` for ids
    that name no face (compared among themselves)."""
    return face_id.face.value


def init_project(
    folder: str | Path, scans_dir: str | Path, labels: str | Path | None = None, unit: str | None = None
) -> tuple[Project, AddReport]:
    """Create the project (or open it again) and add the scans of ``scans_dir``; ``labels`` (a CSV
    ``coin_id,die_id`` or ``name, die``) are stored for evaluation only. ``unit`` declares the scans' unit
    (:data:`coindie.io.units.DECLARED_UNITS`; None: each face's unit is told from its size)."""
    from coindie.io.labels import read_labels
    from coindie.io.units import checked_unit

    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise ProjectError(f"{folder}: exists and is not a folder")
    checked_labels = read_labels(labels) if labels is not None else None
    checked_unit(unit)
    folder.mkdir(parents=True, exist_ok=True)
    project = Project(folder)
    project.create()
    if unit is not None:
        project.declare_unit(unit)
    report = project.add_scans(scans_dir)
    if checked_labels is not None:
        project.set_labels({str(k): v for k, v in checked_labels.items()}, str(Path(labels).resolve()))
    return project, report


def open_project(folder: str | Path) -> Project:
    """An existing project; ``ProjectError`` naming the folder when there is none."""
    folder = Path(folder)
    if not (folder / DB_NAME).is_file():
        raise ProjectError(f"{folder}: not a coindie project (no {DB_NAME}; create one with coindie init)")
    project = Project(folder)
    project.check_version()
    return project


class Project:
    """A project folder. Connections are opened per process (SQLite connections do not cross forks)."""

    def __init__(self, folder: str | Path) -> None:
        self.folder = Path(folder).resolve()
        self.db_path = self.folder / DB_NAME
        self.cache_dir = self.folder / CACHE_DIR
        self._connection: sqlite3.Connection | None = None
        self._pid = os.getpid()

    def __repr__(self) -> str:
        return f"Project({str(self.folder)!r})"

    # ---------------------------------------------------------------------------------------- database

    @property
    def db(self) -> sqlite3.Connection:
        if self._connection is None or self._pid != os.getpid():
            self._connection = sqlite3.connect(self.db_path, timeout=30.0, isolation_level=None)
            self._connection.row_factory = sqlite3.Row
            for pragma in PRAGMAS:
                self._connection.execute(pragma)
            self._pid = os.getpid()
        return self._connection

    def close(self) -> None:
        if self._connection is not None:
            self._connection.close()
            self._connection = None

    @contextmanager
    def transaction(self) -> Iterator[sqlite3.Connection]:
        """One atomic write: everything inside is committed together or not at all."""
        db = self.db
        db.execute("BEGIN IMMEDIATE")
        try:
            yield db
        except BaseException:
            db.execute("ROLLBACK")
            raise
        db.execute("COMMIT")

    def create(self) -> None:
        self.cache_dir.mkdir(parents=True, exist_ok=True)
        self.db.executescript(f"BEGIN IMMEDIATE;{SCHEMA}COMMIT;")  # executescript runs its own statements
        with self.transaction() as db:
            db.execute("INSERT OR IGNORE INTO meta VALUES ('schema_version', ?)", (str(SCHEMA_VERSION),))
            db.execute("INSERT OR IGNORE INTO meta VALUES ('created_at', ?)", (now(),))
        self.check_version()

    def check_version(self) -> None:
        try:
            row = self.db.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
        except sqlite3.DatabaseError as error:
            raise ProjectError(f"{self.db_path}: not a readable project database ({error})") from None
        if row is None or int(row["value"]) != SCHEMA_VERSION:
            found = row["value"] if row else "none"
            raise ProjectError(
                f"{self.db_path}: project schema version {found}, this coindie reads {SCHEMA_VERSION}"
            )
        columns = {r["name"] for r in self.db.execute("PRAGMA table_info(pairs)")}
        if "features" not in columns:  # a project made before the relief scorer: its pairs lack features
            with self.transaction() as db:
                db.execute("ALTER TABLE pairs ADD COLUMN features BLOB")
        if not self.db.execute("SELECT name FROM sqlite_master WHERE name = 'relays'").fetchone():
            self.db.executescript(f"BEGIN IMMEDIATE;{RELAYS_SCHEMA}COMMIT;")  # a project made before relays

    def meta(self, key: str, default: str | None = None) -> str | None:
        row = self.db.execute("SELECT value FROM meta WHERE key = ?", (key,)).fetchone()
        return row["value"] if row else default

    def set_meta(self, key: str, value: str) -> None:
        self.set_metas({key: value})

    def set_metas(self, values: Mapping[str, str]) -> None:
        """Set several meta keys in one transaction."""
        with self.transaction() as db:
            db.executemany("INSERT OR REPLACE INTO meta VALUES (?, ?)", values.items())

    @property
    def unit(self) -> str | None:
        """The unit the project's scans were declared in (``coindie init --unit``); None when each face's
        unit is told from its size (:mod:`coindie.io.units`)."""
        return self.meta("unit")

    def declare_unit(self, unit: str) -> None:
        """Record the scans' unit. Every face of a project is read in one unit: once a face has been
        read, another unit is refused (``ProjectError``: make a new project)."""
        current = self.unit
        if unit == current:
            return
        read = self.db.execute("SELECT COUNT(*) FROM scans WHERE status != 'new'").fetchone()[0]
        if read:
            was = current if current is not None else "told from each face's size"
            raise ProjectError(
                f"{self.folder}: {read} faces were read with unit {was}; to read the scans in {unit}, "
                "make a new project"
            )
        self.set_meta("unit", unit)

    # ------------------------------------------------------------------------------------------- scans

    def scan_dirs(self) -> list[Path]:
        return [Path(p) for p in json.loads(self.meta("scan_dirs", "[]") or "[]")]

    def add_scans(self, scans_dir: str | Path) -> AddReport:
        """List ``scans_dir`` (files are not read here) and record new or changed faces. A face whose file
        changed (size or modification time) is prepared again and loses its pairs."""
        from coindie.ids import face_id_of
        from coindie.io import open_dataset

        scans_dir = Path(scans_dir).resolve()
        dataset = open_dataset(scans_dir)
        dirs = [str(p) for p in self.scan_dirs()]
        if str(scans_dir) not in dirs:
            self.set_meta("scan_dirs", json.dumps([*dirs, str(scans_dir)]))
        report = AddReport(skipped=[str(failure) for failure in dataset.duplicates])
        known = {row["face_id"]: row for row in self.db.execute("SELECT * FROM scans")}
        stamp = now()
        with self.transaction() as db:
            for path in dataset.paths:
                face_id = face_id_of(path)
                size, mtime = _stat(path)
                row = known.get(face_id.key)
                if row is None:
                    db.execute(
                        "INSERT INTO scans (face_id, name, side, path, size_bytes, mtime_ns, added_at) "
                        "VALUES (?, ?, ?, ?, ?, ?, ?)",
                        (face_id.key, face_id.name, side_of(face_id), str(path), size, mtime, stamp),
                    )
                    report.added.append(face_id.key)
                elif (row["path"], row["size_bytes"], row["mtime_ns"]) != (str(path), size, mtime):
                    db.execute(
                        "UPDATE scans SET path = ?, size_bytes = ?, mtime_ns = ?, status = 'new', "
                        "content_hash = NULL, error = NULL WHERE face_id = ?",
                        (str(path), size, mtime, face_id.key),
                    )
                    db.execute("DELETE FROM pairs WHERE source = ? OR target = ?", (face_id.key,) * 2)
                    report.changed.append(face_id.key)
                else:
                    report.unchanged += 1
        return report

    def refresh(self) -> AddReport:
        """Add the new and changed scans of every folder added so far."""
        total = AddReport()
        for folder in self.scan_dirs():
            if not folder.is_dir():
                continue
            report = self.add_scans(folder)
            total.added += report.added
            total.changed += report.changed
            total.unchanged += report.unchanged
            total.skipped += report.skipped
        return total

    def scans(self, status: str | None = None) -> list[ScanRow]:
        query = "SELECT * FROM scans" + (" WHERE status = ?" if status else "") + " ORDER BY face_id"
        rows = self.db.execute(query, (status,) if status else ())
        return [
            ScanRow(
                r["face_id"],
                r["name"],
                r["side"],
                r["path"],
                r["content_hash"],
                r["status"],
                r["error"],
                r["n_points"],
            )  # fmt: skip
            for r in rows
        ]

    def cached_file(self, content_hash: str, params_hash: str) -> Path | None:
        row = self.db.execute(
            "SELECT file FROM scan_cache WHERE content_hash = ? AND params_hash = ?",
            (content_hash, params_hash),
        ).fetchone()
        return self.cache_dir / row["file"] if row and (self.cache_dir / row["file"]).is_file() else None

    def record_face_error(self, face_id: str, error: str) -> None:
        """The face could not be prepared: it is left out of every plan, with its error."""
        with self.transaction() as db:
            db.execute(
                "UPDATE scans SET status = 'error', error = ?, prepared_at = ? WHERE face_id = ?",
                (error, now(), face_id),
            )

    def record_face(
        self,
        face_id: str,
        params_hash: str,
        *,
        content_hash: str,
        file: str,
        n_points: int,
        descriptor: bytes,
        seconds: float,
    ) -> None:
        """The face prepared: its cache file (under ``cache_dir``) and descriptor, for ``params_hash``."""
        with self.transaction() as db:
            db.execute(
                "INSERT OR REPLACE INTO scan_cache VALUES (?, ?, ?, ?, ?, ?, ?)",
                (content_hash, params_hash, file, n_points, descriptor, seconds, now()),
            )
            db.execute(
                "UPDATE scans SET status = 'ok', error = NULL, content_hash = ?, n_points = ?, "
                "prepared_at = ? WHERE face_id = ?",
                (content_hash, n_points, now(), face_id),
            )

    def prepared_faces(self, params_hash: str) -> list[sqlite3.Row]:
        """The usable faces prepared for ``params_hash``: ``face_id``, ``side``, ``descriptor`` (float32
        bytes) and ``file`` (relative to ``cache_dir``), by face id."""
        return self.db.execute(
            "SELECT s.face_id, s.side, c.descriptor, c.file FROM scans s JOIN scan_cache c "
            "ON c.content_hash = s.content_hash AND c.params_hash = ? WHERE s.status = 'ok' "
            "ORDER BY s.face_id",
            (params_hash,),
        ).fetchall()

    def face_status_counts(self) -> dict[str, int]:
        """Faces by status (``new``, ``ok``, ``error``)."""
        rows = self.db.execute("SELECT status, COUNT(*) AS n FROM scans GROUP BY status")
        return {r["status"]: r["n"] for r in rows}

    def face_errors(self) -> list[str]:
        """``face: error`` of every face that could not be prepared."""
        rows = self.db.execute("SELECT * FROM scans WHERE status = 'error'")
        return [f"{r['face_id']}: {r['error']}" for r in rows]

    # ------------------------------------------------------------------------------------------ labels

    def set_labels(self, labels: Mapping[str, str], source: str) -> None:
        with self.transaction() as db:
            db.execute("DELETE FROM labels")
            db.executemany(
                "INSERT INTO labels VALUES (?, ?, ?)",
                [(parse_face_id(k).key, str(v), source) for k, v in labels.items()],
            )

    def labels(self) -> dict[str, str]:
        """Face id -> die, as given at init (empty when none were)."""
        return {r["face_id"]: r["die"] for r in self.db.execute("SELECT face_id, die FROM labels")}

    # ------------------------------------------------------------------------------------------- edits

    def add_edit(
        self, author: str, action: str, a: str | None = None, b: str | None = None, **payload: Any
    ) -> int:
        """Append one expert edit to the log (never updated nor deleted); its id."""
        with self.transaction() as db:
            cursor = db.execute(
                "INSERT INTO edits (at, author, action, a, b, payload) VALUES (?, ?, ?, ?, ?, ?)",
                (now(), author, action, a, b, json.dumps(payload, sort_keys=True)),
            )
        return int(cursor.lastrowid or 0)

    def edits(self) -> list[dict[str, Any]]:
        rows = self.db.execute("SELECT * FROM edits ORDER BY edit_id")
        return [{**dict(r), "payload": json.loads(r["payload"])} for r in rows]

    # ------------------------------------------------------------------------------------------- pairs

    def current_params(self) -> str | None:
        """The parameter set of the latest run (the pairs ``probability_graph`` reads by default)."""
        row = self.db.execute(
            "SELECT params_hash FROM runs WHERE params_hash IS NOT NULL ORDER BY run_id DESC LIMIT 1"
        ).fetchone()
        return row["params_hash"] if row else None

    def scored_pairs(self, params_hash: str | None = None, side: str | None = None) -> list[dict[str, Any]]:
        """The done pairs of a parameter set (the latest run's by default), as dictionaries with the
        transform and histogram decoded; sorted by (source, target)."""
        params_hash = params_hash or self.current_params()
        if params_hash is None:
            return []
        query = "SELECT * FROM pairs WHERE params_hash = ? AND status = 'done'"
        args: tuple[str, ...] = (params_hash,)
        if side is not None:
            query, args = query + " AND side = ?", (*args, side)
        return [decode_pair(r) for r in self.db.execute(query + " ORDER BY source, target", args)]

    def plan_pairs(
        self, params_hash: str, side: str, origin: str, run_id: int, pairs: Iterable[tuple[str, str]]
    ) -> None:
        """Plan ``(source, target)`` pairs (status ``todo``); a pair already planned stays as it is."""
        with self.transaction() as db:
            db.executemany(
                "INSERT OR IGNORE INTO pairs (source, target, params_hash, side, origin, planned_run) "
                "VALUES (?, ?, ?, ?, ?, ?)",
                ((a, b, params_hash, side, origin, run_id) for a, b in pairs),
            )

    def count_pairs(self, params_hash: str, side: str) -> int:
        """Pairs of ``side`` planned for ``params_hash``, whatever their status."""
        row = self.db.execute(
            "SELECT COUNT(*) AS n FROM pairs WHERE params_hash = ? AND side = ?", (params_hash, side)
        ).fetchone()
        return int(row["n"])

    def pairs_with_status(self, params_hash: str, statuses: tuple[str, ...]) -> list[tuple[str, str]]:
        """``(source, target)`` of the pairs of ``params_hash`` whose status is one of ``statuses``."""
        marks = ",".join("?" * len(statuses))
        query = f"SELECT source, target FROM pairs WHERE params_hash = ? AND status IN ({marks})"
        return [(r["source"], r["target"]) for r in self.db.execute(query, (params_hash, *statuses))]

    def pair_status_counts(self, params_hash: str | None) -> dict[str, dict[str, int]]:
        """side -> status -> count of the pairs of ``params_hash``."""
        counts: dict[str, dict[str, int]] = {}
        for r in self.db.execute(
            "SELECT side, status, COUNT(*) AS n FROM pairs WHERE params_hash = ? GROUP BY side, status",
            (params_hash,),
        ):
            counts.setdefault(r["side"], {})[r["status"]] = r["n"]
        return counts

    def failed_pairs(self, params_hash: str | None, limit: int) -> list[str]:
        """``source-target: reason`` of at most ``limit`` failed pairs."""
        rows = self.db.execute(
            "SELECT source, target, reason FROM pairs WHERE params_hash = ? AND status = 'failed' LIMIT ?",
            (params_hash, limit),
        )
        return [f"{r['source']}-{r['target']}: {r['reason']}" for r in rows]

    def scored_sides(self, params_hash: str | None) -> list[str]:
        """The sides having done pairs for ``params_hash``, sorted."""
        rows = self.db.execute(
            "SELECT DISTINCT side FROM pairs WHERE params_hash = ? AND status = 'done' ORDER BY side",
            (params_hash,),
        )
        return [r["side"] for r in rows]

    def refusal_reasons(self, params_hash: str | None, side: str, limit: int = 3) -> list[tuple[str, int]]:
        """The most common reasons (and their counts) of the done pairs of ``side`` whose registration
        was refused."""
        rows = self.db.execute(
            "SELECT reason, COUNT(*) AS n FROM pairs WHERE params_hash = ? AND side = ? AND status = 'done' "
            "AND valid = 0 GROUP BY reason ORDER BY n DESC LIMIT ?",
            (params_hash, side, limit),
        )
        return [(r["reason"], r["n"]) for r in rows]

    def commit_pairs(self, params_hash: str, run_id: int, rows: list[dict[str, Any]], seconds: float) -> None:
        """One batch of pair results and the run's counters, atomically; a pair already done (by an earlier
        run) is never overwritten. ``rows``: the worker's dictionaries (``source``, ``target``, ``status``
        and, for a done pair, its figures)."""
        stamp = now()
        with self.transaction() as db:
            db.executemany(
                "UPDATE pairs SET status = ?, method = ?, valid = ?, reason = ?, probability = ?, "
                "residual = ?, T_target_source = ?, histogram = ?, features = ?, timings = ?, run_id = ?, "
                "done_at = ? "
                "WHERE source = ? AND target = ? AND params_hash = ? AND status != 'done'",
                [
                    (
                        r["status"],
                        r.get("method"),
                        r.get("valid"),
                        r.get("reason"),
                        r.get("probability"),
                        r.get("residual"),
                        r.get("T_target_source"),
                        r.get("histogram"),
                        r.get("features"),
                        r.get("timings"),
                        run_id,
                        stamp,
                        r["source"],
                        r["target"],
                        params_hash,
                    )  # fmt: skip
                    for r in rows
                ],
            )
            db.execute(
                "UPDATE runs SET pairs_done = pairs_done + ?, pairs_seconds = pairs_seconds + ?, "
                "updated_at = ? WHERE run_id = ?",
                (len(rows), seconds, stamp, run_id),
            )

    def tried_relays(self, params_hash: str) -> set[tuple[str, str, str]]:
        """``(source, target, via)`` of the relays tried for ``params_hash`` (coindie.project.relay)."""
        rows = self.db.execute("SELECT source, target, via FROM relays WHERE params_hash = ?", (params_hash,))
        return {(r["source"], r["target"], r["via"]) for r in rows}

    def relay_counts(self, params_hash: str | None) -> tuple[int, int]:
        """Relays tried for ``params_hash``, and how many of them a pair kept."""
        row = self.db.execute(
            "SELECT COUNT(*) AS n, COALESCE(SUM(kept), 0) AS kept FROM relays WHERE params_hash = ?",
            (params_hash,),
        ).fetchone()
        return int(row["n"]), int(row["kept"])

    def commit_relays(
        self, params_hash: str, run_id: int, rows: list[dict[str, Any]], min_gain: float = 0.0
    ) -> int:
        """One batch of relay results (:func:`coindie.project.workers.relay_batch`), atomically: each is
        recorded in ``relays``, and replaces its done pair's figures only where it raises the pair's
        log-odds by more than ``min_gain`` (:data:`coindie.project.relay.MIN_GAIN`). The number kept."""
        from coindie.project.relay import log_odds_gain

        stamp = now()
        kept = 0
        with self.transaction() as db:
            for r in rows:
                found = db.execute(
                    "SELECT probability FROM pairs WHERE source = ? AND target = ? AND params_hash = ? "
                    "AND status = 'done'",
                    (r["source"], r["target"], params_hash),
                ).fetchone()
                before = float(found["probability"] or 0.0) if found else None
                after = r.get("probability") if r["status"] == "done" else None
                keep = before is not None and after is not None and log_odds_gain(before, after) > min_gain
                # A relay measures the distance histogram (where the run measures histograms) only where
                # it beat its pair's probability of when it was planned, which a pair's probability now
                # can only have raised: a relay kept here has its histogram, or the run measures none.
                if keep:
                    db.execute(
                        "UPDATE pairs SET method = ?, valid = ?, reason = ?, probability = ?, residual = ?, "
                        "T_target_source = ?, histogram = ?, features = ?, timings = ?, run_id = ?, "
                        "done_at = ? WHERE source = ? AND target = ? AND params_hash = ?",
                        (
                            r["method"], r["valid"], r["reason"], after, r.get("residual"),
                            r["T_target_source"], r["histogram"], r["features"], r["timings"], run_id,
                            stamp, r["source"], r["target"], params_hash,
                        ),
                    )  # fmt: skip
                    kept += 1
                db.execute(
                    "INSERT OR REPLACE INTO relays VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                    (
                        r["source"], r["target"], params_hash, r["via"], before, after, int(keep),
                        r.get("reason"), run_id, stamp,
                    ),
                )  # fmt: skip
        return kept

    # -------------------------------------------------------------------------------------------- runs

    def start_run(self, params_hash: str, config: str, version: str, pid: int, host: str) -> int:
        """Record a run as ``running``; its id."""
        with self.transaction() as db:
            cursor = db.execute(
                "INSERT INTO runs (started_at, updated_at, status, version, params_hash, config, pid, host) "
                "VALUES (?, ?, 'running', ?, ?, ?, ?, ?)",
                (now(), now(), version, params_hash, config, pid, host),
            )
        return int(cursor.lastrowid or 0)

    def set_run_params(self, run_id: int, params_hash: str, config: dict[str, Any]) -> None:
        """The parameter set and configuration of a run, once known after its start (the coin scale
        follows from the faces it prepares)."""
        with self.transaction() as db:
            db.execute(
                "UPDATE runs SET params_hash = ?, config = ?, updated_at = ? WHERE run_id = ?",
                (params_hash, json.dumps(config, sort_keys=True), now(), run_id),
            )

    def running_runs(self) -> list[sqlite3.Row]:
        """``run_id``, ``pid``, ``host`` of the runs recorded as running (some may have died)."""
        return self.db.execute("SELECT run_id, pid, host FROM runs WHERE status = 'running'").fetchall()

    def mark_run_killed(self, run_id: int) -> None:
        """A run that died without closing (kill -9)."""
        with self.transaction() as db:
            db.execute("UPDATE runs SET status = 'killed' WHERE run_id = ?", (run_id,))

    def end_run(self, run_id: int, status: str, message: str) -> None:
        with self.transaction() as db:
            db.execute(
                "UPDATE runs SET status = ?, ended_at = ?, updated_at = ?, message = ? WHERE run_id = ?",
                (status, now(), now(), message, run_id),
            )

    def latest_run(self) -> dict[str, Any] | None:
        """The last run's row (``run_id``, ``status``, ``config``, ``pairs_done``, ...), None before any."""
        row = self.db.execute("SELECT * FROM runs ORDER BY run_id DESC LIMIT 1").fetchone()
        return dict(row) if row else None

    def probability_graph(
        self,
        side: str | None = None,
        params_hash: str | None = None,
        *,
        calibrated: bool = True,
        across: Mapping[str, object] | None = None,
        scorer_veto: bool = True,
    ) -> ProbabilityGraph:
        """The project's scored pairs as a :class:`coindie.clustering.ProbabilityGraph`: every usable face
        of ``side`` (``D`` or ``R``; both when None, with no link across sides) and an edge per done pair
        weighted by its same-die probability — calibrated on this hoard's own pairs, side by side
        (:meth:`calibration`), unless ``calibrated`` is False (the scorer's own probabilities).
        ``across``: a first clustering (face id -> label); each face's pull on its scores, fitted on the
        pairs across its clusters, is taken off before the calibration
        (:mod:`coindie.similarity.face_effects`). ``scorer_veto=False``: the hoard's mixture calibrates
        even where the scorer judges its upper population different-die
        (:func:`coindie.similarity.calibrate_hoard`)."""
        from coindie.clustering import ProbabilityGraph

        faces = [s.face_id for s in self.scans("ok") if side is None or s.side == side]
        known = set(faces)
        pairs = [
            p for p in self.scored_pairs(params_hash, side) if p["source"] in known and p["target"] in known
        ]
        weights = np.array([float(p["probability"] or 0.0) for p in pairs])
        if calibrated:
            valid = np.array([scored(p) for p in pairs], dtype=bool)
            for one_side in {p["side"] for p in pairs}:
                on = np.array([p["side"] == one_side for p in pairs])
                mine = [p for p, o in zip(pairs, on, strict=True) if o]
                prior, what = self._calibration_start(one_side, params_hash)
                weights[on], _ = calibrated_side(
                    weights[on], valid[on], [p["source"] for p in mine], [p["target"] for p in mine],
                    across=across, prior=prior, what=what, max_same_share=_max_same_share(mine),
                    scorer_veto=scorer_veto,
                )  # fmt: skip
        edges = [(p["source"], p["target"], float(w)) for p, w in zip(pairs, weights, strict=True)]
        return ProbabilityGraph.from_edges(edges, faces, where=str(self.folder))

    def mixture_threshold(self, side: str | None = None, params_hash: str | None = None) -> float | None:
        """τ from the hoard's own score populations (:data:`coindie.similarity.calibration.
        MIXTURE_THRESHOLD` on the calibrated probabilities) when the scores of ``side`` (every side when
        None) separate; None when some do not (then a threshold must come from elsewhere)."""
        params_hash = params_hash or self.current_params()
        sides = [one for one in self.scored_sides(params_hash) if side is None or one == side]
        if sides and all(self.calibration(one, params_hash).separates for one in sides):
            return MIXTURE_THRESHOLD
        return None

    def auto_threshold(
        self, side: str | None = None, method: str = "components", graph: ProbabilityGraph | None = None
    ) -> tuple[float, str]:
        """The threshold without labels, and how it was chosen: the hoard's own score populations, or,
        when they do not separate, the best silhouette of the calibrated graph's clusters. ``consensus``
        clustering cuts the consensus of the calibrated probabilities where the silhouette of its own
        clusters is best (:meth:`auto_graph` for the second pass). ``graph``: :meth:`probability_graph`
        of ``side`` when the caller holds it already."""
        from coindie.clustering import select_threshold_unsupervised
        from coindie.clustering.algorithms import ConsensusLinkage

        tau = self.mixture_threshold(side)
        if tau is not None and method != ConsensusLinkage.NAME:
            return tau, "from the hoard's two score populations"
        graph = self.probability_graph(side) if graph is None else graph
        choice = select_threshold_unsupervised(graph, method)
        if method == ConsensusLinkage.NAME:
            # the probabilities are calibrated on the hoard (when they separate): the cut is on their
            # consensus, where the hoard's own clusters say
            return choice.threshold, _consensus_how(choice, "", separates=tau is not None)
        return choice.threshold, f"chosen by silhouette {choice.score:.3f} (the scores do not separate)"

    def auto_graph(
        self, side: str, method: str = "components", calibration: HoardCalibration | None = None
    ) -> tuple[ProbabilityGraph, float, str, dict[str, Any]]:
        """``side``'s calibrated graph, its threshold without labels (:meth:`auto_threshold`), how it was
        chosen, and the method's parameters to cluster it with (``cluster(graph, method, threshold,
        **params)``). With ``consensus`` clustering, in two passes where the first clusters do not stand
        out (:mod:`coindie.clustering.second_pass`): each face's pull on its scores (a well-kept, finely
        scanned face scores higher with every face of its design than a worn one) fitted on the pairs
        across the first clusters and taken off (:mod:`coindie.similarity.face_effects`), the graph
        calibrated again and cut again, its consensus comparing faces by direction alone. Where the scorer
        vetoed the hoard's own calibration (:attr:`coindie.similarity.HoardCalibration.vetoed`), that
        calibration's clusters are kept if they stand out (:func:`cluster_twice`). ``calibration``:
        :meth:`calibration` of ``side``, where the caller holds it."""
        from coindie.clustering import PAPER_THRESHOLD
        from coindie.clustering.algorithms import ConsensusLinkage

        graph = self.probability_graph(side)
        if graph.n_nodes < 3:
            return graph, PAPER_THRESHOLD, "the paper's (too few faces to choose one)", {}
        if method != ConsensusLinkage.NAME:
            return graph, *self.auto_threshold(side, method, graph), {}
        calibration = self.calibration(side) if calibration is None else calibration
        result = self._cluster_twice(side, method, graph, calibration)
        note = ""
        if result.second_pass:
            note = f", each face's pull taken off (first clusters' silhouette {result.first_silhouette:.2f})"
        if result.overruled_scorer:
            note += (
                ", on the hoard's own score populations, which the scorer had judged different-die: their "
                f"clusters stand out (silhouette {result.overrule_silhouette:.2f})"
            )
        separates = calibration.separates or calibration.scorer_holds or result.overruled_scorer
        how = _consensus_how(result.choice, note, separates=separates)
        return result.graph, result.choice.threshold, how, result.params

    def overrule(
        self, side: str, method: str = "consensus", calibration: HoardCalibration | None = None
    ) -> Overrule | None:
        """Where ``side``'s scores do not separate and ``coindie cluster --auto`` keeps the clusters of a
        split the scorer vetoed (:attr:`coindie.similarity.HoardCalibration.vetoed`) all the same, because
        they stand out: how far, and which split (the side's own, or the one once each face's pull is
        taken off, :func:`coindie.clustering.second_pass.cluster_twice`). None otherwise: the scores
        separate, or nothing was overruled (the warning of :mod:`coindie.project.status` stands alone).

        The side's own split need not be vetoed: on the independent generator's hard hoards (seeds 22
        and 23) two sides' own splits were not clear (Ashman's D 1.67 and 1.77), the splits once the
        pulls were off were, and ``cluster --auto`` kept their clusters (silhouettes 0.69 and 0.76),
        while the run only warned. ``calibration``: :meth:`calibration` of ``side``, where the caller
        holds it (on a side of many pairs, its fit is most of the time)."""
        calibration = self.calibration(side) if calibration is None else calibration
        if calibration.separates or calibration.scorer_holds:
            return None
        graph = self.probability_graph(side)
        if graph.n_nodes < 3:
            return None
        tried: dict[bool, HoardCalibration] = {}
        result = self._cluster_twice(side, method, graph, calibration, tried)
        if not result.overruled_scorer:
            return None
        return Overrule(result.overrule_silhouette, result.second_pass, tried[result.second_pass])

    def _cluster_twice(
        self,
        side: str,
        method: str,
        graph: ProbabilityGraph,
        calibration: HoardCalibration,
        tried: dict[bool, HoardCalibration] | None = None,
    ) -> TwoPassResult:
        """:func:`coindie.clustering.second_pass.cluster_twice` on ``side`` (``graph``: its calibrated
        graph, ``calibration`` its calibration), the hoard's own mixture tried where the scorer vetoed
        it; ``tried``, when given, receives the calibrations asked of each pass (False: the first, True:
        once each face's pull is off)."""
        from coindie.clustering.second_pass import cluster_twice

        return cluster_twice(
            lambda across: graph if across is None else self.probability_graph(side, across=across),
            method,
            partial(self._vetoed_mixture, side, calibration, {} if tried is None else tried),
        )

    def _vetoed_mixture(
        self,
        side: str,
        first: HoardCalibration,
        tried: dict[bool, HoardCalibration],
        across: Mapping[str, object] | None,
    ) -> ProbabilityGraph | None:
        """``side``'s graph calibrated by the hoard's mixture where only the scorer's veto refused it
        (each face's pull taken off first across ``across``), None where the calibration stands or fails
        for another reason (:func:`coindie.clustering.second_pass.cluster_twice`). ``first``: the side's
        calibration without ``across``, which the caller holds already; ``tried[across is not None]``
        receives the calibration asked."""
        calibration = first if across is None else self.calibration(side, across=across)
        tried[across is not None] = calibration
        if not calibration.vetoed:
            return None
        return self.probability_graph(side, across=across, scorer_veto=False)

    def calibration(
        self, side: str, params_hash: str | None = None, *, across: Mapping[str, object] | None = None
    ) -> HoardCalibration:
        """The two populations of ``side``'s scored pairs (:func:`coindie.similarity.calibrate_hoard`),
        EM started from the run's scorer's training populations; with ``across`` (a first clustering),
        each face's pull fitted across its clusters taken off first."""
        params_hash = params_hash or self.current_params()
        pairs = self.scored_pairs(params_hash, side)
        probabilities = [float(p["probability"] or 0.0) for p in pairs]
        prior, what = self._calibration_start(side, params_hash)
        valid = [scored(p) for p in pairs]
        return calibrated_side(
            probabilities, valid, [p["source"] for p in pairs], [p["target"] for p in pairs],
            across=across, prior=prior, what=what, max_same_share=_max_same_share(pairs),
        )[1]  # fmt: skip

    def _calibration_start(
        self, side: str, params_hash: str | None
    ) -> tuple[dict[str, tuple[float, float]] | None, str]:
        prior_text = self.meta(f"populations:{params_hash or self.current_params()}")
        prior = json.loads(prior_text) if prior_text else {}
        return {k: (float(v[0]), float(v[1])) for k, v in prior.items()} or None, side_pairs(side)


def side_pairs(side: str) -> str:
    """The pairs of a side in words (``obverse pairs``), as the calibration's lines name them."""
    return f"{ {'D': 'obverse', 'R': 'reverse'}.get(side, side) } pairs"


def _consensus_how(choice: ThresholdChoice, note: str, *, separates: bool) -> str:
    """How a consensus cut was chosen, in words (``coindie cluster --auto``, the demo)."""
    how = f"consensus cut chosen by {choice.criterion} {choice.score:.3f}{note}"
    return how + ("" if separates else " (the scores do not separate)")


def _max_same_share(pairs: list[dict[str, Any]]) -> float:
    """Every pair of a side: most are of different dies; candidates: each face's nearest, mostly its own."""
    if any(p.get("origin") == "candidates" for p in pairs):
        return MAX_SAME_SHARE_CANDIDATES
    return MAX_SAME_SHARE


def scored(pair: Mapping[str, Any]) -> bool:
    """Whether a done pair was scored: its registration found a pose, and the scorer did not refuse it
    (a refusal leaves probability 0 with its reason)."""
    return bool(pair["valid"]) and not (pair.get("reason") and not pair.get("probability"))


def decode_pair(row: sqlite3.Row) -> dict[str, Any]:
    """A pairs row with its JSON and blob columns decoded."""
    pair = dict(row)
    if pair.get("T_target_source"):
        pair["T_target_source"] = np.asarray(json.loads(pair["T_target_source"]), dtype=np.float64)
    if pair.get("histogram") is not None:
        pair["histogram"] = np.frombuffer(pair["histogram"], dtype=np.float32).astype(np.float64)
    if pair.get("features") is not None:
        pair["features"] = np.frombuffer(pair["features"], dtype=np.float32).astype(np.float64)
    if pair.get("timings"):
        pair["timings"] = json.loads(pair["timings"])
    return pair


def _stat(path: Path) -> tuple[int, int]:
    try:
        info = path.stat()
    except OSError:  # a broken link: listed, and prepared into an error with its message
        return 0, 0
    return int(info.st_size), int(info.st_mtime_ns)


def elapsed_since(stamp: str) -> float:
    """Seconds since an ISO time stamp written by :func:`now`."""
    return time.time() - datetime.fromisoformat(stamp).timestamp()
