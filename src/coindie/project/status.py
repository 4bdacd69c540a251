"""Where a project stands: faces by status, pairs by status and side, the last run's rate and ETA, errors."""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field
from typing import Any

from coindie.preprocess.coin_size import REFERENCE_DIAMETER_MM
from coindie.project.store import Project, elapsed_since, side_pairs
from coindie.similarity.calibration import HoardCalibration


@dataclass
class ProjectStatus:
    folder: str
    faces: dict[str, int]
    pairs: dict[str, dict[str, int]]  # side -> status -> count (the latest parameter set)
    last_run: dict[str, Any] | None
    pairs_per_second: float | None
    eta_seconds: float | None
    face_errors: list[str] = field(default_factory=list)
    pair_errors: list[str] = field(default_factory=list)
    separation: list[str] = field(default_factory=list)  # per side: do the scores separate (words, numbers)
    relays: tuple[int, int] = (0, 0)  # relays tried, and kept (coindie.project.relay)
    unit: str | None = None  # the scans' declared unit (coindie init --unit); None: told from each size
    coin_scale: float = 1.0  # the design's lengths against the 21.4 mm coins' (coindie.preprocess.coin_size)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    def text(self) -> str:
        lines = [f"project {self.folder}"]
        lines.append("faces: " + ", ".join(f"{n} {status}" for status, n in sorted(self.faces.items())))
        lines.append(
            f"scans read in {self.unit} (declared)"
            if self.unit
            else "scans read in mm (m or um where a face's size says so)"
        )
        for side, counts in sorted(self.pairs.items()):
            total = sum(counts.values())
            done = counts.get("done", 0)
            share = f" ({done / total:.1%})" if total else ""
            details = ", ".join(f"{n} {status}" for status, n in sorted(counts.items()))
            lines.append(f"pairs of side {side}: {total} planned, {done} done{share}: {details}")
        if self.last_run:
            run = self.last_run
            lines.append(
                f"last run {run['run_id']}: {run['status']}, started {run['started_at']}, "
                f"{run['pairs_done']} pairs committed"
            )
        if self.coin_scale != 1.0:
            lines.append(
                f"the design's lengths (registration and relief features) scaled by {self.coin_scale:.3g} "
                f"to the coins' size, from those set for {REFERENCE_DIAMETER_MM:g} mm coins"
            )
        if self.pairs_per_second:
            lines.append(f"rate {self.pairs_per_second:.2f} pairs/s")
        if self.eta_seconds is not None:
            lines.append(f"ETA {_duration(self.eta_seconds)} for the remaining pairs at that rate")
        if self.relays[0]:
            lines.append(
                f"relays: {self.relays[0]} registrations from a pose through a third face, "
                f"{self.relays[1]} scored their pair higher and were kept"
            )
        lines += self.separation
        lines += [f"bad scan: {error}" for error in self.face_errors]
        lines += [f"failed pair: {error}" for error in self.pair_errors]
        return "\n".join(lines)


def project_status(project: Project, max_errors: int = 50) -> ProjectStatus:
    faces = project.face_status_counts()
    params = project.current_params()
    pairs = project.pair_status_counts(params)
    run = project.latest_run()
    last_run = dict(run) if run else None
    if last_run and last_run["status"] == "running" and not _still_running(last_run):
        last_run["status"] = "stopped without closing (killed); coindie run resumes it"
    rate = eta = None
    if run and run["pairs_done"] and run["updated_at"]:
        seconds = elapsed_since(run["started_at"]) - elapsed_since(run["updated_at"])
        rate = run["pairs_done"] / seconds if seconds > 0 else None
        remaining = sum(counts.get("todo", 0) for counts in pairs.values())
        eta = remaining / rate if rate and remaining else None
    face_errors = project.face_errors()
    pair_errors = project.failed_pairs(params, max_errors)
    config = json.loads(last_run["config"]) if last_run and last_run.get("config") else {}
    return ProjectStatus(
        str(project.folder), faces, pairs, last_run, rate, eta, face_errors[:max_errors], pair_errors,
        separation_lines(project), project.relay_counts(params), project.unit,
        float(config.get("coin_scale", 1.0)),
    )  # fmt: skip


def separation_lines(project: Project) -> list[str]:
    """One line per side with scored pairs: how its scores split into same-die and different-die
    populations (the per-hoard calibration), or a WARNING in words and numbers when they do not, with
    the registrations' most common reasons for refusing pairs.

    A split that only the scorer's own scale refused (its typical upper pair below log-odds 0: scans
    unlike its training scans), whose clusters stand out so that ``coindie cluster --auto`` keeps them
    (:meth:`coindie.project.Project.overrule`), is told as such, with its numbers, not as a
    warning: the scores do separate. On the independent generator's coarse and two-scanner hoards of
    seed 17, the warning stood over die studies of FMI 1.000. Nor is a side whose pairs the scorer judges
    same-die stand apart above the hoard's upper population (:attr:`coindie.similarity.HoardCalibration.
    scorer_holds`): the scorer's own probabilities separate them. Where the side's own split is not clear
    but ``cluster --auto`` keeps the vetoed split found once each face's pull is taken off
    (:meth:`coindie.project.Project.overrule`), the warning stands and a second line tells that split
    and its clusters: the run no longer warns of murky scores and stops there while ``cluster --auto``
    goes on to the dies (the independent generator's hard hoards of seeds 22 and 23)."""
    params = project.current_params()
    lines = []
    for side in project.scored_sides(params):
        calibration = project.calibration(side, params)
        if calibration.separates or calibration.scorer_holds:
            lines.append(f"scores of side {side}: {calibration.message}")
            continue
        found = project.overrule(side, calibration=calibration)
        if found is not None and calibration.vetoed:
            told = _overruled(calibration, side, found.silhouette, project, after_pulls=found.after_pulls)
            lines.append(f"scores of side {side}: {told}")
            continue
        lines.append(f"WARNING, side {side}: {calibration.message}")
        if found is not None:  # the side's own split is not clear; the one once the pulls are off is
            told = _overruled(found.calibration, side, found.silhouette, project, after_pulls=False)
            lines.append(f"  once each face's pull is taken off, {told}")
        if calibration.apart is not None:
            n_top, low, high, _ = calibration.apart
            lines.append(
                f"  the {n_top} pairs standing apart above the rest (log-odds {low:.2f} to {high:.2f}) may "
                "be same-die pairs on scans that lower every score: the review app's queue offers them "
                f"first (coindie serve {project.folder})"
            )
        reasons = project.refusal_reasons(params, side)
        lines += [f"  refused {n} time(s): {reason}" for reason, n in reasons]
    return lines


def _overruled(
    calibration: HoardCalibration, side: str, silhouette: float, project: Project, *, after_pulls: bool
) -> str:
    """A vetoed split (``calibration``'s) whose clusters stand out (their mean ``silhouette``), in words and
    numbers, and where to look at it; ``after_pulls``: say that they stand out once each face's pull is
    off."""
    once = ", once each face's pull is taken off," if after_pulls else ""
    return (
        calibration.split(side_pairs(side), "an upper population")
        + f" that the scorer, trained on other scans, judges different-die; its clusters{once} stand out "
        f"(silhouette {silhouette:.2f}), so coindie cluster --auto takes them for the dies: check a "
        f"few of their pairs in the review app (coindie serve {project.folder})"
    )


def _still_running(run: dict[str, Any]) -> bool:
    import socket

    from coindie.project.run import pid_alive

    return run["host"] != socket.gethostname() or pid_alive(run["pid"])


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"
