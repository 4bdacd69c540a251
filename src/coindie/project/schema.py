"""The project database: tables, and the SQLite settings that make it safe to kill a run at any moment.

WAL journalling lets readers (``coindie status``, the clustering) read while a run writes, and makes each
committed batch durable; ``synchronous=NORMAL`` is the WAL setting that loses nothing committed on a
process crash (only an OS crash may lose the last transactions, never corrupt the file).
"""

from __future__ import annotations

#: Bumped when the tables change; a project of another version is refused with a clear message.
SCHEMA_VERSION = 1

SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (
    key TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
-- One row per face. status: new (listed, not prepared), ok (cached), error (unusable: see error).
CREATE TABLE IF NOT EXISTS scans (
    face_id TEXT PRIMARY KEY,
    name TEXT NOT NULL,
    side TEXT NOT NULL,
    path TEXT NOT NULL,
    size_bytes INTEGER NOT NULL,
    mtime_ns INTEGER NOT NULL,
    content_hash TEXT,
    status TEXT NOT NULL DEFAULT 'new',
    error TEXT,
    n_points INTEGER,
    added_at TEXT NOT NULL,
    prepared_at TEXT
);
-- Per-face work, keyed by the scan file's content and the parameters that made it.
CREATE TABLE IF NOT EXISTS scan_cache (
    content_hash TEXT NOT NULL,
    params_hash TEXT NOT NULL,
    file TEXT NOT NULL,
    n_points INTEGER NOT NULL,
    descriptor BLOB NOT NULL,
    seconds REAL NOT NULL,
    created_at TEXT NOT NULL,
    PRIMARY KEY (content_hash, params_hash)
);
-- One row per pair of faces and parameter set. status: todo, done, failed (see reason).
CREATE TABLE IF NOT EXISTS pairs (
    source TEXT NOT NULL,
    target TEXT NOT NULL,
    params_hash TEXT NOT NULL,
    side TEXT NOT NULL,
    origin TEXT NOT NULL,
    status TEXT NOT NULL DEFAULT 'todo',
    method TEXT,
    valid INTEGER,
    reason TEXT,
    probability REAL,
    residual REAL,
    T_target_source TEXT,
    histogram BLOB,
    features BLOB,
    timings TEXT,
    planned_run INTEGER,
    run_id INTEGER,
    done_at TEXT,
    PRIMARY KEY (source, target, params_hash)
);
CREATE INDEX IF NOT EXISTS pairs_by_status ON pairs (params_hash, status);
CREATE TABLE IF NOT EXISTS runs (
    run_id INTEGER PRIMARY KEY AUTOINCREMENT,
    started_at TEXT NOT NULL,
    ended_at TEXT,
    status TEXT NOT NULL,
    version TEXT NOT NULL,
    params_hash TEXT,
    config TEXT NOT NULL,
    pairs_done INTEGER NOT NULL DEFAULT 0,
    pairs_seconds REAL NOT NULL DEFAULT 0,
    updated_at TEXT,
    pid INTEGER,
    host TEXT,
    message TEXT
);
-- Die labels given at init (experts' or a hoard's truth): used by evaluation only, never to cluster.
CREATE TABLE IF NOT EXISTS labels (
    face_id TEXT PRIMARY KEY,
    die TEXT NOT NULL,
    source TEXT NOT NULL
);
"""

#: Every relay tried (:mod:`coindie.project.relay`): the pair registered again from a pose composed through
#: ``via``, its probability before and after, whether the pair kept the relay's result. A project made before
#: relays gets the table when it is opened.
RELAYS_SCHEMA = """
CREATE TABLE IF NOT EXISTS relays (
    source TEXT NOT NULL,
    target TEXT NOT NULL,
    params_hash TEXT NOT NULL,
    via TEXT NOT NULL,
    before REAL,
    after REAL,
    kept INTEGER NOT NULL,
    reason TEXT,
    run_id INTEGER,
    at TEXT NOT NULL,
    PRIMARY KEY (source, target, params_hash, via)
);
"""

SCHEMA += RELAYS_SCHEMA

#: The experts' edit log (also the whole schema of a bare graph.json's sidecar log, coindie serve).
EDITS_SCHEMA = """
-- The experts' edits (the web app): an append-only log, replayed in order.
CREATE TABLE IF NOT EXISTS edits (
    edit_id INTEGER PRIMARY KEY AUTOINCREMENT,
    at TEXT NOT NULL,
    author TEXT NOT NULL,
    action TEXT NOT NULL,
    a TEXT,
    b TEXT,
    payload TEXT NOT NULL DEFAULT '{}'
);
CREATE TRIGGER IF NOT EXISTS edits_no_update BEFORE UPDATE ON edits
BEGIN SELECT RAISE(ABORT, 'the edits log is append-only'); END;
CREATE TRIGGER IF NOT EXISTS edits_no_delete BEFORE DELETE ON edits
BEGIN SELECT RAISE(ABORT, 'the edits log is append-only'); END;
"""

SCHEMA += EDITS_SCHEMA

PRAGMAS = (
    "PRAGMA journal_mode=WAL",
    "PRAGMA synchronous=NORMAL",
    "PRAGMA foreign_keys=ON",
    "PRAGMA busy_timeout=30000",
)
