"""Candidate search on a synthetic hoard: recall of same-die partners vs K, and the cost of the search.

    python benchmarks/bench_candidates.py OUT --project P            # a project already prepared
    python benchmarks/bench_candidates.py OUT --hoard H --workers 2  # a hoard: init + per-face work
    python benchmarks/bench_candidates.py OUT --synth-faces 10000 --spacing 0.1 --workers 16

With ``--synth-faces N`` the ``riedones`` preset is multiplied (every die group k times larger, k the
smallest with at least N faces) and generated first. The per-face work is a project run with
``--plan-only`` (descriptors of every face, candidate pairs planned). Figures per side and K (see
``coindie.candidates.recall``): pair recall, share of faces finding a same-die partner, share of dies
connected; plus the time of the exact (faiss flat) and approximate (HNSW) searches. Writes
``OUT/candidates.md``, ``.json`` and ``.png``.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from coindie.bench.machine import describe_machine

KS = (1, 2, 3, 5, 10, 20, 50)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("out", type=Path)
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("--project", type=Path)
    source.add_argument("--hoard", type=Path)
    source.add_argument("--synth-faces", type=int)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument(
        "--spacing", type=float, default=0.05, help="scanner spacing of a generated hoard (mm)"
    )
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--ks", default=",".join(map(str, KS)))
    args = parser.parse_args(argv)
    ks = sorted({int(k) for k in args.ks.split(",")})
    args.out.mkdir(parents=True, exist_ok=True)
    timings: dict[str, float] = {}
    project_dir = args.project
    hoard = args.hoard
    if args.synth_faces:
        hoard = args.out / "hoard"
        timings["generate hoard"] = _generate(hoard, args.synth_faces, args.seed, args.spacing, args.workers)
    if project_dir is None:
        project_dir = args.out / "project"
        timings["per-face work (read, grid, descriptor)"] = _prepare(
            project_dir, hoard, args.workers, max(ks)
        )
    results, search = _measure(project_dir, ks)
    timings |= search
    machine = describe_machine(args.workers)
    (args.out / "candidates.json").write_text(
        json.dumps({"machine": machine, "timings": timings, "results": results}, indent=2) + "\n"
    )
    (args.out / "candidates.md").write_text(_markdown(results, timings, machine))
    _plot(results, args.out / "candidates.png")
    print((args.out / "candidates.md").read_text())
    return 0


def _generate(out: Path, n_faces: int, seed: int, spacing: float, workers: int) -> float:
    from coindie.cli.progress import counting_progress
    from coindie.synth.hoard import PhysicsParams, generate
    from coindie.synth.plan import plan_hoard
    from coindie.synth.presets import get_preset
    from coindie.synth.scanner import ScanParams

    base = get_preset("riedones")
    factor = max(1, math.ceil(n_faces / 2070))
    groups = tuple(replace(g, n_dies=g.n_dies * factor, n_coins=g.n_coins * factor) for g in base.groups)
    preset = replace(base, name=f"riedones x{factor}", groups=groups, pair_targets=())
    start = time.perf_counter()
    with counting_progress("faces") as progress:
        generate(
            out,
            plan_hoard(preset, seed),
            PhysicsParams(scan=ScanParams(spacing_mm=spacing)),
            workers=workers,
            progress=progress,
        )
    return time.perf_counter() - start


def _prepare(project_dir: Path, hoard: Path, workers: int, k: int) -> float:
    from coindie.cli.progress import counting_progress
    from coindie.project import init_project
    from coindie.project.run import RunConfig, run_project

    project, _ = init_project(project_dir, hoard, hoard / "labels.csv")
    start = time.perf_counter()
    report = run_project(
        project,
        RunConfig(workers=workers, mode="candidates", k=k, plan_only=True),
        progress=counting_progress,
    )
    return report.stage_seconds.get("faces", time.perf_counter() - start)


def _measure(project_dir: Path, ks: list[int]) -> tuple[list[dict], dict[str, float]]:
    from coindie.candidates import candidate_recall, nearest_neighbours
    from coindie.project import open_project

    project = open_project(project_dir)
    labels = project.labels()
    rows = project.db.execute(
        "SELECT s.face_id, s.side, c.descriptor FROM scans s "
        "JOIN scan_cache c ON c.content_hash = s.content_hash "
        "WHERE s.status = 'ok' GROUP BY s.face_id ORDER BY s.face_id"
    ).fetchall()
    results, timings = [], {}
    for side in sorted({r["side"] for r in rows}):
        faces = [r for r in rows if r["side"] == side and r["face_id"] in labels]
        X = np.stack([np.frombuffer(r["descriptor"], np.float32) for r in faces])
        dies = [labels[r["face_id"]] for r in faces]
        for name, exact_below in (("exact", len(X)), ("hnsw", 0)):
            start = time.perf_counter()
            neighbours, _ = nearest_neighbours(X, max(ks), exact_below=exact_below)
            timings[f"search {name}, side {side} ({len(X)} faces, K = {max(ks)})"] = (
                time.perf_counter() - start
            )
            for k in ks:
                recall = candidate_recall(neighbours, dies, k)
                results.append({"side": side, "index": name, **recall.to_dict()})
    return results, timings


def _markdown(results: list[dict], timings: dict[str, float], machine: str) -> str:
    lines = [
        "| side | index | K | faces | dies | candidate pairs | all pairs | pair recall "
        "| faces with a partner found | dies connected |"
    ]
    lines.append("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for r in results:
        n = r["n_faces"]
        lines.append(
            f"| {r['side']} | {r['index']} | {r['k']} | {n} | {r['n_dies']} | {r['n_candidate_pairs']:,} "
            f"| {n * (n - 1) // 2:,} | "
            f"{r['pair_recall']:.1%} | {r['face_recall']:.2%} | {r['die_connected']:.2%} |"
        )
    lines += ["", "| step | seconds |", "| --- | ---: |"]
    lines += [f"| {name} | {seconds:.2f} |" for name, seconds in timings.items()]
    return "\n".join(lines) + f"\n\nMachine: {machine}.\n"


def _plot(results: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for side, style in (("D", "-"), ("R", "--")):
        mine = [r for r in results if r["side"] == side and r["index"] == "exact"]
        if not mine:
            continue
        ks = [r["k"] for r in mine]
        for key, label, color in (
            ("face_recall", "faces with a same-die partner found", "C0"),
            ("die_connected", "dies connected", "C1"),
            ("pair_recall", "same-die pairs kept", "C2"),
        ):
            ax.plot(
                ks, [100 * r[key] for r in mine], style, marker="o", color=color, label=f"{label} ({side})"
            )
    ax.axhline(99, color="grey", lw=0.8, ls=":")
    ax.set_xscale("log")
    ax.set_xlabel("K (candidates per face)")
    ax.set_ylabel("%")
    ax.set_title("Candidate search: what the K nearest faces keep")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
