"""Pictures of one registered pair's fine relief band, unclipped and clipped, and its local correlations.

    .venv/bin/python benchmarks/pair_bands.py PROJECT HOARD SOURCE TARGET -o pair.png

PROJECT is a project whose latest run scored the pair (its stored ``T_target_source`` is used, as the run
left it); HOARD the folder of its scans. The figure shows the target with the moved source's outline, the
two faces' fine bands on their overlap (``coindie.similarity.relief_features``, steps 1-3), and the local
correlations in Gaussian windows, with the bands as they are and clipped at ``clip_sd`` robust standard
deviations. Written for BENCHMARK.md, "One element cannot carry a correlation": a wrong pose that lays one
pellet of each of two dies on the other, over a lens of their flans. A diagnostic, no pass/fail.
"""

from __future__ import annotations

import argparse
from dataclasses import replace
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from coindie.io import read_scan
from coindie.preprocess import grid_sample
from coindie.project import open_project
from coindie.registration.clouds import with_normals
from coindie.similarity import relief_features as rf


def _scan_path(hoard: Path, face_id: str) -> Path:
    found = [p for p in hoard.glob(f"{face_id}.*") if p.suffix.lower() in (".ply", ".stl", ".obj")]
    if not found:
        raise SystemExit(f"{hoard}: no scan of {face_id}")
    return found[0]


def _bands(source, target, T_target_source, settings):  # noqa: ANN001, ANN202 (a diagnostic's plumbing)
    """Steps 1-3 of the features with the module's own helpers: overlap mask, fine bands, local map."""
    prepared = rf._prepared_target(target, settings)
    moved = source.transformed(T_target_source)
    heights = rf._grid_heights(moved, prepared.frame, settings)
    both = rf._eroded(np.isfinite(heights), settings) & prepared.inner
    window = rf._crop(both)
    mask = both[window]
    weights = rf._MaskWeights(mask)
    a = np.where(mask, heights[window], 0.0).astype(np.float32)
    b = np.where(mask, prepared.heights[window], 0.0).astype(np.float32)
    a = a - np.where(mask, weights.blur(a - b, settings.shape_sigma_mm / settings.pixel_mm), 0.0)
    fine_a = rf._clipped(rf._bands(a, weights, settings), mask, settings.clip_sd)[0]
    fine_b = rf._clipped(rf._bands(b, weights, settings), mask, settings.clip_sd)[0]
    sigma = settings.window_mm / settings.pixel_mm
    ab, aa, bb = (rf._gaussian(p, sigma) for p in (fine_a * fine_b, fine_a * fine_a, fine_b * fine_b))
    local = np.where(mask, ab / np.sqrt(np.maximum(aa * bb, 1e-12)), np.nan)
    return prepared, np.isfinite(heights), mask, fine_a, fine_b, local


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("project", type=Path)
    parser.add_argument("hoard", type=Path)
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("-o", "--out", type=Path, default=Path("pair_bands.png"))
    parser.add_argument("--clip-sd", type=float, default=rf.ReliefFeatureSettings().clip_sd)
    args = parser.parse_args()

    project = open_project(args.project)
    pair = next(
        (p for p in project.scored_pairs() if (p["source"], p["target"]) == (args.source, args.target)), None
    )
    if pair is None:
        raise SystemExit(f"{args.project}: no scored pair {args.source} -> {args.target} in its latest run")
    T = np.asarray(pair["T_target_source"], dtype=np.float64)
    # as a run reads them: grid-sampled on its per-face cache's grid (the histogram's finest, 0.05 mm)
    source, target = (
        grid_sample(with_normals(read_scan(_scan_path(args.hoard, face))), 0.05)
        for face in (args.source, args.target)
    )

    fig = plt.figure(figsize=(17, 7.5))
    grid = fig.add_gridspec(2, 4)
    overview = fig.add_subplot(grid[:, 0])
    for row, clip_sd in enumerate((0.0, args.clip_sd)):
        settings = replace(rf.ReliefFeatureSettings(), clip_sd=clip_sd)
        prepared, source_mask, mask, fine_a, fine_b, local = _bands(source, target, T, settings)
        features = dict(zip(rf.FEATURE_NAMES, rf.relief_features(source, target, T, settings), strict=True))
        if row == 0:
            overview.imshow(np.where(prepared.mask, prepared.heights, np.nan), cmap="cividis")
            overview.contour(source_mask, [0.5], colors="red", linewidths=1)
            overview.set_title(f"{args.target} (heights), {args.source}'s outline in red")
        label = f"clipped at {clip_sd:.0f} robust sd" if clip_sd else "unclipped"
        limit = float(np.max(np.abs(fine_b[mask]))) or 1.0
        panels = [fig.add_subplot(grid[row, column]) for column in (1, 2, 3)]
        for panel, band, name in ((panels[0], fine_b, args.target), (panels[1], fine_a, args.source)):
            panel.imshow(np.where(mask, band, np.nan), cmap="RdBu_r", vmin=-limit, vmax=limit)
            panel.set_title(f"{name}: fine band, {label}")
        image = panels[2].imshow(local, cmap="PiYG", vmin=-1, vmax=1)
        panels[2].set_title("local correlations")
        fig.colorbar(image, ax=panels[2], shrink=0.7)
        panels[1].set_xlabel(
            f"ncc_fine {features['ncc_fine']:.2f}, local median {features['local_median']:.2f}, "
            f"p90 {features['local_p90']:.2f}, overlap {features['overlap']:.2f}"
        )
        for axis in (overview, *panels):
            axis.set_xticks([])
            axis.set_yticks([])
    fig.suptitle(f"{args.source} on {args.target}, as registered (probability {pair['probability']:.3f})")
    fig.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out, dpi=80)
    print(args.out)


if __name__ == "__main__":
    main()
