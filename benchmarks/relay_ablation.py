"""What the relays and the second pass's veto question each bring to a scored project, with its labels.

    .venv/bin/python benchmarks/relay_ablation.py PROJECT LABELS_CSV [--name NAME]

Per side, the FMI of ``coindie cluster --auto``'s clusters (the consensus, two passes) four ways: with or
without the relays (:mod:`coindie.project.relay`), and with the scorer's veto asked again in the second
pass or only in the first (:func:`coindie.clustering.second_pass.cluster_twice`). "Without the relays" is
the project copied with each relayed pair's probability put back to its value before its first relay (the
``relays`` table keeps it): the clustering reads probabilities only, so this is the run with
``--relay-neighbours 0`` without registering the hoard again. Also the relays tried and kept, on pairs of
one die and of two, and the time the run spent on its pairs and on its relays. A measurement, no pass/fail
(BENCHMARK.md, "Relays, and the veto asked again").
"""

from __future__ import annotations

import argparse
import shutil
import sqlite3
import tempfile
from datetime import datetime
from pathlib import Path

from sklearn.metrics import fowlkes_mallows_score

from coindie.clustering.second_pass import cluster_twice
from coindie.io import read_labels
from coindie.project import Project, open_project


def without_relays(folder: Path, copy: Path) -> Path:
    """``folder``'s database copied to ``copy`` with each relayed pair's first probability put back."""
    copy.mkdir(parents=True, exist_ok=True)
    shutil.copy(folder / "project.sqlite", copy / "project.sqlite")
    with sqlite3.connect(copy / "project.sqlite") as db:
        rows = db.execute(
            "SELECT source, target, params_hash, before FROM relays ORDER BY at, rowid"
        ).fetchall()
        first: dict[tuple[str, str, str], float] = {}
        for source, target, params, before in rows:
            first.setdefault((source, target, params), before)
        db.executemany(
            "UPDATE pairs SET probability = ?, valid = CASE WHEN ? > 0 THEN 1 ELSE valid END "
            "WHERE source = ? AND target = ? AND params_hash = ?",
            [(b, b, s, t, h) for (s, t, h), b in first.items()],
        )
        db.execute("DELETE FROM relays")
    return copy


def side_fmi(project: Project, side: str, truth: dict[str, str], ask_again: bool) -> float:
    graph = project.probability_graph(side)
    first = project.calibration(side)

    def vetoed(across):  # noqa: ANN001, ANN202
        return project._vetoed_mixture(side, first, across) if ask_again or across is None else None

    result = cluster_twice(
        lambda across: graph if across is None else project.probability_graph(side, across=across),
        "consensus",
        vetoed,
    )
    faces = [face for face in graph.nodes if face in truth]
    return float(fowlkes_mallows_score([truth[f] for f in faces], [result.clusters.labels[f] for f in faces]))


def relay_counts(project: Project, truth: dict[str, str]) -> str:
    rows = project.db.execute("SELECT source, target, kept FROM relays").fetchall()
    same = [r for r in rows if truth.get(r["source"]) == truth.get(r["target"])]
    other = [r for r in rows if truth.get(r["source"]) != truth.get(r["target"])]
    return (
        f"relays tried / kept: one die {len(same)} / {sum(r['kept'] for r in same)}, "
        f"two dies {len(other)} / {sum(r['kept'] for r in other)}"
    )


def stage_seconds(project: Project) -> str:
    run = project.db.execute("SELECT * FROM runs ORDER BY run_id DESC LIMIT 1").fetchone()
    first = project.db.execute("SELECT MIN(at) AS at FROM relays").fetchone()["at"]
    if run is None or run["ended_at"] is None or first is None:
        return "no timed run with relays"
    query = "SELECT MAX(done_at) AS at FROM pairs WHERE done_at < ?"
    pairs_end = project.db.execute(query, (first,)).fetchone()
    t = lambda stamp: datetime.fromisoformat(stamp).timestamp()  # noqa: E731
    pairs = t(pairs_end["at"]) - t(run["started_at"])
    relays = t(run["ended_at"]) - t(pairs_end["at"])
    return f"last run: {pairs:.0f} s to its last pair, then {relays:.0f} s of relays (+{relays / pairs:.0%})"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("project", type=Path)
    parser.add_argument("labels", type=Path)
    parser.add_argument("--name", default=None)
    args = parser.parse_args()
    truth = {str(face): str(die) for face, die in read_labels(args.labels).items()}
    name = args.name or args.project.name
    project = open_project(args.project)
    print(f"{name}: {relay_counts(project, truth)}; {stage_seconds(project)}")
    with tempfile.TemporaryDirectory() as scratch:
        bare = open_project(without_relays(args.project, Path(scratch) / "bare"))
        for side in project.scored_sides(project.current_params()):
            cells = []
            for label, one in (("no relays", bare), ("relays", project)):
                for ask_again in (False, True):
                    fmi = side_fmi(one, side, truth, ask_again)
                    cells.append(f"{label}, veto asked {'twice' if ask_again else 'once'} {fmi:.3f}")
            print(f"{name} {side}: " + " | ".join(cells))


if __name__ == "__main__":
    main()
