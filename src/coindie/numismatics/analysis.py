"""The whole numismatic analysis of one study in one call: die links and estimates per side, written out.

Used by ``coindie dielinks``, ``coindie report`` and ``benchmarks/numismatics_riedones.py``.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from coindie.numismatics.accumulation import accumulation_curve, plot_accumulation
from coindie.numismatics.die_links import DieLinks, build_die_links, draw_die_links, write_exports
from coindie.numismatics.estimators import DieCounts, Estimates, estimate
from coindie.numismatics.sources import SIDES, SideDies

#: The estimator the accumulation plot extrapolates (the lower bound that needs no model of die outputs).
PLOTTED_ESTIMATOR = "Chao1 (bias-corrected)"


@dataclass
class Analysis:
    """Die links (when both sides are there), estimates per side, and the files written."""

    sides: dict[str, SideDies]
    estimates: dict[str, Estimates]
    links: DieLinks | None
    files: dict[str, Path] = field(default_factory=dict)

    def to_dict(self) -> dict[str, object]:
        return {
            "estimates": {SIDES.get(s, s): e.to_dict() for s, e in self.estimates.items()},
            "die_links": self.links.summary() if self.links else None,
            "files": {k: str(v) for k, v in self.files.items()},
        }


def side_estimates(sides: dict[str, SideDies], confidence: float = 0.95) -> dict[str, Estimates]:
    return {s: estimate(DieCounts.from_labels(d.dies), confidence) for s, d in sides.items() if d.dies}


def analyse(
    sides: dict[str, SideDies],
    out_dir: str | Path | None = None,
    *,
    confidence: float = 0.95,
    formats: tuple[str, ...] = ("svg", "png"),
    title: str = "",
) -> Analysis:
    """Estimates per side; die links when both sides are given; with ``out_dir``, the exports
    (``die_links.*``), the diagram and each side's accumulation curve (``accumulation_<side>.*``) and
    ``estimates.json``."""
    estimates = side_estimates(sides, confidence)
    links = build_die_links(sides["D"], sides["R"]) if "D" in sides and "R" in sides else None
    result = Analysis(sides, estimates, links)
    if out_dir is None:
        return result
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if links is not None:
        result.files.update(write_exports(links, out))
        for fmt in formats:
            result.files[f"diagram_{fmt}"] = draw_die_links(
                links, out / f"die_links.{fmt}", title=title or None
            )
    for side, est in estimates.items():
        curve = accumulation_curve(est.counts)
        name = SIDES.get(side, "faces")
        for fmt in formats:
            result.files[f"accumulation_{name}_{fmt}"] = plot_accumulation(
                est.counts,
                est.get(PLOTTED_ESTIMATOR),
                out / f"accumulation_{name}.{fmt}",
                curve=curve,
                title=f"Die accumulation: {name} dies, n = {est.counts.n} coins, d = {est.counts.d} dies",
            )
    path = out / "estimates.json"
    path.write_text(json.dumps(result.to_dict(), indent=2, default=str) + "\n")
    result.files["estimates_json"] = path
    return result
