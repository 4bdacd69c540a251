"""Projects whose pairs were scored at chosen log-odds, without scans: what the calibration, the run's
lines, ``cluster --auto`` and the review app make of a hoard's scores."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from coindie.project import Project, init_project


def scored_project(folder: Path, same: np.ndarray, log_odds: np.ndarray, n_faces: int) -> Project:
    """A project whose obverse pairs (every pair of ``n_faces`` faces, in ``np.triu_indices`` order)
    were scored at ``log_odds``; its scans are never read (empty files), only listed."""
    scans = folder / "scans"
    scans.mkdir(parents=True)
    names = [f"L{k + 1:04d}D" for k in range(n_faces)]
    for name in names:
        (scans / f"{name}.ply").write_bytes(b"")
    project, _ = init_project(folder / "project", scans)
    for name in names:
        project.record_face(name, "h", content_hash=name, file="", n_points=1, descriptor=b"", seconds=0.0)
    run = project.start_run("h", "{}", "test", 0, "here")
    i, j = np.triu_indices(n_faces, k=1)
    project.plan_pairs("h", "D", "exhaustive", run, [(names[a], names[b]) for a, b in zip(i, j, strict=True)])
    probabilities = 1.0 / (1.0 + np.exp(-log_odds))
    done = {"status": "done", "method": "relief", "valid": True, "reason": "", "T_target_source": "[]",
            "histogram": None, "features": b""}  # fmt: skip
    rows = [
        {**done, "source": names[a], "target": names[b], "probability": float(p)}
        for a, b, p in zip(i, j, probabilities, strict=True)
    ]
    project.commit_pairs("h", run, rows, 0.0)
    return project


def two_designs(
    folder: Path, n_linked: int, same: tuple[float, float], seed: int
) -> tuple[Project, np.ndarray, np.ndarray, np.ndarray]:
    """A project of 40 coins of two designs whose dies 0 to ``n_linked - 1`` struck two coins each and the
    others one: the pairs of one design scored at log-odds -15 +- 1.2, those of two at -19 +- 0.6, the
    same-die pairs around ``same`` (an independent generator's hoards of seed 19). The project, and the
    pairs' faces (``i``, ``j``) and whether they share a die."""
    die = np.concatenate([np.arange(n_linked), np.arange(40 - n_linked)])
    design = die % 2
    i, j = np.triu_indices(len(die), k=1)
    rng = np.random.default_rng(seed)
    log_odds = np.where(
        design[i] == design[j], rng.normal(-15.0, 1.2, len(i)), rng.normal(-19.0, 0.6, len(i))
    )
    same_die = die[i] == die[j]
    log_odds[same_die] = rng.normal(*same, int(same_die.sum()))
    return scored_project(folder, same_die, log_odds, len(die)), i, j, same_die


def unevenly_worn_scores(seed: int, pull: float = 2.5) -> tuple[np.ndarray, np.ndarray]:
    """The dies of 31 faces (9, 7, 6, 4, 3 and 2 coins) and their pairs' log-odds (``np.triu_indices``
    order) on scans unlike the scorer's (every pair below log-odds 0), worn unevenly: each face's pull, drawn
    with a spread of ``pull``, larger than the same-die gap of 6."""
    rng = np.random.default_rng(seed)
    die = np.repeat(np.arange(6), [9, 7, 6, 4, 3, 2])
    pulls = rng.normal(0.0, pull, len(die))
    i, j = np.triu_indices(len(die), k=1)
    same = die[i] == die[j]
    return die, -16.0 + pulls[i] + pulls[j] + 6.0 * same + rng.normal(0.0, 0.7, len(i))
