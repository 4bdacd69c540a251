"""How close is a synthetic hoard to the real Riedones3D study? Measured, plotted, re-runnable.

- Die sizes: two-sample Kolmogorov-Smirnov statistic between the hoard's die sizes and the experts' (per
  family; beard obverses against the obverse list, the only real sizes there are).
- Die links: the network figures of the hoard (coins with both faces, obverse/reverse combinations, ...)
  next to the real ones (obverses without beard, as in the experts' files).
- The c2c histogram with the paper's settings (source grid 0.1 mm, target 0.05 mm, nearest neighbour
  source -> target, distances over 0.6 mm dropped, only points whose normal is within 1 rad of the
  source's main normal, 70 bins on [0, 0.6] mm with ``density=True``, mean of both directions) over pairs
  of faces aligned with their true transform: same die, and different dies of one type. The real mean in
  ``histogram_scaler.json`` is over the real training pairs of the logistic regression.
- Renders: faces of one die side by side, and faces of two dies of one type, all in the die's frame.

Run (from the repository): ``python benchmarks/synth_calibration.py HOARD_DIR --real
../shared/data/riedones3d --images docs/images``.
"""

from __future__ import annotations

import json
import re
from collections import Counter
from dataclasses import asdict, dataclass, is_dataclass
from pathlib import Path
from typing import Any

import numpy as np
from scipy.spatial import cKDTree
from scipy.stats import ks_2samp, wasserstein_distance

from coindie.arrays import FloatArray
from coindie.io import read_labels, read_ply
from coindie.scan import Scan
from coindie.synth.plan import HoardPlan, LinkStats, link_stats
from coindie.synth.presets import BEARD, OBVERSE, REVERSE
from coindie.synth.writer import read_truth, scan_from_die, to_jsonable

HIST_BINS = 70
HIST_RANGE_MM = (0.0, 0.6)
SOURCE_GRID_MM = 0.1
TARGET_GRID_MM = 0.05
MAX_NORMAL_ANGLE_RAD = 1.0
REAL_FILES = {OBVERSE: "experts_obverse_dies.csv", REVERSE: "experts_reverse_dies.csv"}
SCALER_FILE = "histogram_scaler.json"


# --- die sizes and die links ----------------------------------------------------------------------------


@dataclass(frozen=True)
class SizeComparison:
    """Die sizes of one family, synthetic vs real."""

    family: str
    dies: int
    real_dies: int
    largest: int
    real_largest: int
    single_coin_dies: int
    real_single_coin_dies: int
    ks_statistic: float
    ks_p_value: float


def real_die_sizes_of(real_dir: Path, family: str) -> list[int]:
    """Coins per die in the experts' file for ``family`` (beard: the obverse file)."""
    labels = read_labels(Path(real_dir) / REAL_FILES[REVERSE if family == REVERSE else OBVERSE])
    return sorted(Counter(labels.values()).values(), reverse=True)


def compare_die_sizes(plan: HoardPlan, real_dir: Path) -> list[SizeComparison]:
    rows = []
    for family in (BEARD, OBVERSE, REVERSE):
        sizes = [d.size for d in plan.dies if d.family == family]
        real = real_die_sizes_of(real_dir, family)
        test = ks_2samp(sizes, real)
        rows.append(
            SizeComparison(
                family, len(sizes), len(real), max(sizes), max(real), sizes.count(1), real.count(1),
                float(test.statistic), float(test.pvalue),
            )
        )  # fmt: skip
    return rows


def _coin_number(face_id: Any) -> int | None:
    if face_id.coin is not None:
        return face_id.coin
    match = re.match(r"L(\d+)", face_id.name)  # the experts' file has one odd id: "L773R et D"
    return int(match[1]) if match else None


def real_link_stats(real_dir: Path) -> LinkStats:
    """The real die-link network (obverses without beard and reverses)."""
    maps = []
    for family in (OBVERSE, REVERSE):
        labels = read_labels(Path(real_dir) / REAL_FILES[family])
        maps.append({n: die for face, die in labels.items() if (n := _coin_number(face)) is not None})
    return link_stats(*maps)


def plan_link_stats(plan: HoardPlan) -> LinkStats:
    """The hoard's network, beard obverses left out as in the experts' files."""
    obverse, reverse = plan.coin_dies()
    beard = {d.die_id for d in plan.dies if d.family == BEARD}
    return link_stats({c: d for c, d in obverse.items() if d not in beard}, reverse)


# --- c2c histograms --------------------------------------------------------------------------------------


def c2c_histogram(source: Scan, target: Scan) -> FloatArray:
    """One direction of the paper's histogram; ``source`` already in ``target``'s frame, both sampled."""
    main = source.normals.mean(axis=0)
    keep = source.normals @ (main / np.linalg.norm(main)) >= np.cos(MAX_NORMAL_ANGLE_RAD)
    distances, _ = cKDTree(target.points).query(source.points[keep], workers=1)
    distances = distances[distances <= HIST_RANGE_MM[1]]
    histogram, _ = np.histogram(distances, bins=HIST_BINS, range=HIST_RANGE_MM, density=True)
    return histogram


def pair_histogram(a: Scan, b: Scan, T_b_a: FloatArray) -> FloatArray:
    """Mean of both directions' histograms of faces ``a`` and ``b``, ``a`` mapped by ``T_b_a``."""
    from coindie.preprocess.sampling import grid_sample

    a_in_b = a.transformed(T_b_a)
    b_in_a = b.transformed(np.linalg.inv(T_b_a))
    forward = c2c_histogram(grid_sample(a_in_b, SOURCE_GRID_MM), grid_sample(b, TARGET_GRID_MM))
    backward = c2c_histogram(grid_sample(b_in_a, SOURCE_GRID_MM), grid_sample(a, TARGET_GRID_MM))
    return (forward + backward) / 2.0


def sample_pairs(
    truth: dict[str, Any], n_pairs: int, seed: int, *, same_die: bool, families: tuple[str, ...] = (OBVERSE,)
) -> list[tuple[str, str]]:
    """Random face pairs of the given families: of one die, or of two dies of one family (one type)."""
    faces = sorted(f for f, r in truth["faces"].items() if r["family"] in families)
    rng = np.random.default_rng(seed)
    die = {f: truth["faces"][f]["die_id"] for f in faces}
    family = {f: truth["faces"][f]["family"] for f in faces}
    candidates = [
        (a, b)
        for i, a in enumerate(faces)
        for b in faces[i + 1 :]
        if family[a] == family[b] and (die[a] == die[b]) == same_die
    ]
    chosen = rng.choice(len(candidates), min(n_pairs, len(candidates)), replace=False) if candidates else []
    return [candidates[i] for i in sorted(chosen)]


def mean_histogram(hoard_dir: Path, truth: dict[str, Any], pairs: list[tuple[str, str]]) -> FloatArray:
    """Mean histogram over pairs aligned with the true (die-frame) transform."""
    cache: dict[str, Scan] = {}

    def scan(face_id: str) -> Scan:
        if face_id not in cache:
            cache[face_id] = read_ply(Path(hoard_dir) / f"{face_id}.ply")
        return cache[face_id]

    histograms = [
        pair_histogram(scan(a), scan(b), scan_from_die(truth, b) @ np.linalg.inv(scan_from_die(truth, a)))
        for a, b in pairs
    ]
    return np.mean(histograms, axis=0)


def real_mean_histogram(real_dir: Path) -> FloatArray:
    """The real mean histogram as a density over mm (unit area).

    The stored mean sums to 70 (its area over 0-0.6 mm is 0.6): it is a density per unit of the range, as
    if the range were [0, 1]. Dividing by its area puts it on ``np.histogram(density=True)``'s scale.
    """
    stored = np.asarray(json.loads((Path(real_dir) / SCALER_FILE).read_text())["mean"], dtype=np.float64)
    return stored / (stored.sum() * _bin_width())


def _bin_width() -> float:
    return (HIST_RANGE_MM[1] - HIST_RANGE_MM[0]) / HIST_BINS


def bin_centres() -> FloatArray:
    edges = np.linspace(*HIST_RANGE_MM, HIST_BINS + 1)
    return (edges[:-1] + edges[1:]) / 2.0


def histogram_mode(histogram: FloatArray) -> float:
    """Centre (mm) of the fullest bin."""
    return float(bin_centres()[int(np.argmax(histogram))])


def histogram_distances(synthetic: FloatArray, real: FloatArray) -> dict[str, float]:
    """L1 distance between the two densities (0-2) and Wasserstein-1 distance (mm) between them."""
    centres = bin_centres()
    return {
        "l1": float(np.abs(synthetic - real).sum() * _bin_width()),
        "wasserstein_mm": float(wasserstein_distance(centres, centres, synthetic, real)),
    }


# --- figures ---------------------------------------------------------------------------------------------


def plot_histograms(curves: dict[str, FloatArray], path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axis = plt.subplots(figsize=(7, 4))
    for label, histogram in curves.items():
        style = "--" if "mix" in label else "-"
        axis.plot(bin_centres(), histogram, style, label=f"{label} (mode {histogram_mode(histogram):.3f} mm)")
    axis.set_xlabel("cloud-to-cloud distance (mm)")
    axis.set_ylabel("density")
    axis.set_title("Mean c2c histogram of aligned faces (70 bins, 0-0.6 mm)")
    axis.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path


def plot_die_sizes(plan: HoardPlan, real_dir: Path, path: Path) -> Path:
    """Rank-size plot of die sizes per family, synthetic vs real."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    for axis, family in zip(axes, (OBVERSE, REVERSE), strict=True):
        synthetic = sorted((d.size for d in plan.dies if d.family == family), reverse=True)
        real = real_die_sizes_of(real_dir, family)
        axis.step(range(1, len(real) + 1), real, where="post", label=f"experts ({len(real)} dies)")
        axis.step(
            range(1, len(synthetic) + 1), synthetic, where="post", label=f"synthetic ({len(synthetic)})"
        )
        axis.set_yscale("log")
        axis.set_xlabel("die rank")
        axis.set_ylabel("coins of the die")
        axis.set_title(f"{family} dies")
        axis.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path


def die_frame_render(scan: Scan, T_scan_die: FloatArray, width_px: int) -> Any:
    """The face rendered in its die's frame, so that faces of one die (or type) line up."""
    from coindie.preprocess.canonical import CanonicalFrame
    from coindie.render import render_relief

    frame = CanonicalFrame(np.linalg.inv(T_scan_die), np.zeros(6), "plane", scan.n_points, 0.0)
    return render_relief(scan, frame=frame, width_px=width_px, background=(255, 255, 255))


def render_strip(
    hoard_dir: Path, truth: dict[str, Any], faces: list[str], path: Path, width_px: int = 360
) -> Path:
    """Renders of ``faces`` side by side, each captioned with its face and die."""
    from PIL import Image, ImageDraw

    tiles = [
        die_frame_render(read_ply(Path(hoard_dir) / f"{f}.ply"), scan_from_die(truth, f), width_px)
        for f in faces
    ]
    height = max(t.height for t in tiles) + 24
    strip = Image.new("RGB", (sum(t.width for t in tiles), height), (255, 255, 255))
    x = 0
    for face, tile in zip(faces, tiles, strict=True):
        strip.paste(tile, (x, 24))
        record = truth["faces"][face]
        ImageDraw.Draw(strip).text((x + 6, 5), f"{face}  die {record['die_id']}", fill=(0, 0, 0))
        x += tile.width
    strip.quantize(colors=128).save(path, format="PNG", optimize=True)  # a palette keeps docs images small
    return path


def relief_points(hoard_dir: Path, truth: dict[str, Any], face_id: str) -> Scan:
    """The face's scan without the flan's side (the physics writes face vertices first)."""
    scan = read_ply(Path(hoard_dir) / f"{face_id}.ply")
    return scan.subset(np.arange(truth["faces"][face_id]["physics"]["n_face_points"]))


def example_faces(truth: dict[str, Any], family: str, per_die: int) -> tuple[list[str], list[str]]:
    """Faces of the largest die of ``family``, and ``per_die`` faces of each of its two largest dies."""
    by_die: dict[str, list[str]] = {}
    for face, record in sorted(truth["faces"].items()):
        if record["family"] == family:
            by_die.setdefault(record["die_id"], []).append(face)
    ranked = sorted(by_die.values(), key=len, reverse=True)
    one_die = ranked[0][: 2 * per_die]
    two_dies = [f for faces in ranked[:2] for f in faces[:per_die]]
    return one_die, two_dies


# --- the whole calibration -------------------------------------------------------------------------------


#: Share of same-die pairs among all pairs of the 200 registration-training obverses (2,132 of 19,900), if
#: the logistic regression was trained on every pair of them (the paper does not say more).
TRAINING_SAME_DIE_SHARE = 2132 / 19900


def calibrate(
    hoard_dir: Path, real_dir: Path, images: Path, n_pairs: int = 120, seed: int = 0
) -> dict[str, Any]:
    """Every measure and figure; returns the numbers (also written to ``HOARD_DIR/calibration.json``)."""
    truth = read_truth(hoard_dir)
    images.mkdir(parents=True, exist_ok=True)
    result = {
        "hoard": str(hoard_dir),
        **structure_comparison(json.loads((Path(hoard_dir) / "hoard.json").read_text()), real_dir, images),
        "histogram": histogram_comparison(hoard_dir, truth, real_dir, images, n_pairs, seed),
    }
    one_die, two_dies = example_faces(truth, OBVERSE, per_die=2)
    render_strip(hoard_dir, truth, one_die, images / "synth_one_die.png")
    render_strip(hoard_dir, truth, two_dies, images / "synth_two_dies.png")
    (Path(hoard_dir) / "calibration.json").write_text(json.dumps(to_jsonable(result), indent=1) + "\n")
    return result


def structure_comparison(hoard: dict[str, Any], real_dir: Path, images: Path) -> dict[str, Any]:
    """Die sizes and die links of the hoard's plan and of the full-size plan of the same preset and seed."""
    from coindie.synth.plan import plan_hoard
    from coindie.synth.presets import get_preset

    plan = plan_hoard(get_preset(hoard["preset"], hoard["scale"]), hoard["seed"])
    full = plan_hoard(get_preset(hoard["preset"]), hoard["seed"])
    plot_die_sizes(full, real_dir, images / "synth_die_sizes.png")
    return {
        "die_sizes": [asdict(row) for row in compare_die_sizes(plan, real_dir)],
        "die_sizes_full_preset": [asdict(row) for row in compare_die_sizes(full, real_dir)],
        "links": {"synthetic": asdict(plan_link_stats(plan)), "real": asdict(real_link_stats(real_dir))},
        "links_full_preset": asdict(plan_link_stats(full)),
    }


def histogram_comparison(
    hoard_dir: Path, truth: dict[str, Any], real_dir: Path, images: Path, n_pairs: int, seed: int
) -> dict[str, Any]:
    """Mean histograms of same-die and other-die obverse pairs (true alignment) vs the real mean."""
    same = mean_histogram(hoard_dir, truth, sample_pairs(truth, n_pairs, seed, same_die=True))
    other = mean_histogram(hoard_dir, truth, sample_pairs(truth, n_pairs, seed, same_die=False))
    mix = TRAINING_SAME_DIE_SHARE * same + (1.0 - TRAINING_SAME_DIE_SHARE) * other
    real = real_mean_histogram(real_dir)
    curves = {"real mean (training pairs)": real, "synthetic, same die": same, "synthetic, other die": other}
    plot_histograms({**curves, "synthetic, training mix": mix}, images / "synth_histogram.png")
    return {
        "pairs_each": n_pairs,
        "mode_real_mm": histogram_mode(real),
        "mode_same_die_mm": histogram_mode(same),
        "mode_other_die_mm": histogram_mode(other),
        "same_die_vs_real": histogram_distances(same, real),
        "other_die_vs_real": histogram_distances(other, real),
        "training_mix_vs_real": histogram_distances(mix, real),
        "same_die_mean": same,
        "other_die_mean": other,
        "real_mean": real,
    }


def parameter_tables() -> str:
    """Markdown tables of every physics parameter (name, default, unit, range, meaning) and of LinkParams."""
    from coindie.synth._params import describe
    from coindie.synth.hoard import PhysicsParams

    lines = []
    for name, value in vars(PhysicsParams()).items():
        if not is_dataclass(value):  # ``scanners``: more ScanParams
            continue
        lines += [
            f"**{type(value).__name__}** (`PhysicsParams.{name}`)",
            "",
            "| name | default | unit | range | meaning |",
        ]
        lines.append("| --- | --- | --- | --- | --- |")
        for row in describe(type(value)):
            low, high = row["range"]
            lines.append(
                f"| {row['name']} | {row['default']} | {row['unit']} | {low}-{high} | {row['doc']} |"
            )
        lines.append("")
    return "\n".join(lines)
