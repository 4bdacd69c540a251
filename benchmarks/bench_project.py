"""Die-study throughput: faces and pairs per second, total time vs number of faces, exhaustive vs candidates.

    python benchmarks/bench_project.py OUT --hoard /tmp/full --faces 100,300 --modes exhaustive,candidates \
        --workers 2 --max-minutes 10

For each size N, N faces of the hoard (both faces of N/2 coins drawn at random, seeded; links in
``OUT/subsets``) become a project, run on local processes in each mode, with at most ``--max-minutes`` of
pair scoring per run (a stopped run is measured on the pairs it committed: the rate is what counts, and
the run is resumable). When every planned pair is done, each side is clustered with the unsupervised
threshold and evaluated against the hoard's labels. Writes ``OUT/throughput.md``, ``.json``, and
``OUT/cost.png`` (measured points and the cost model: T(N) = N t_face + P(N) t_pair, where P(N) is
N^2/4 pairs for two equal sides exhaustive, and the measured candidate pairs per face times N with
candidates).
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import time
from pathlib import Path

import numpy as np

from coindie.bench.machine import describe_machine

PROJECTED_SIZES = (100, 300, 1_000, 2_070, 10_000, 100_000)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("out", type=Path)
    parser.add_argument("--hoard", type=Path, required=True)
    parser.add_argument("--faces", default="100,300")
    parser.add_argument("--modes", default="exhaustive,candidates")
    parser.add_argument("--k", type=int, default=20)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--max-minutes", type=float, default=10.0)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--runs-json", type=Path, action="append", default=[], help="runs measured before")
    parser.add_argument(
        "--cpu-sample", type=Path, help="a prepared project: CPU seconds per face and per pair"
    )
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    rows = [row for path in args.runs_json for row in json.loads(path.read_text())["runs"]]
    for n in [int(v) for v in args.faces.split(",") if v]:
        subset = _subset(args.hoard, n, args.seed, args.out / "subsets" / str(n))
        for mode in args.modes.split(","):
            rows.append(_measure(subset, args.out / "projects" / f"{mode}-{n}", mode, args))
            (args.out / "throughput.json").write_text(json.dumps(rows, indent=2) + "\n")
    model = _cost_model(rows, args.k)
    if args.cpu_sample:
        model["cpu"] = cpu_costs(args.cpu_sample)
        per_face = model["candidate_pairs_per_face"]
        for n, p in model["projected"].items():
            face_cpu = int(n) * model["cpu"]["face_cpu_s"]
            p["exhaustive_idle_seconds"] = (
                face_cpu + p["exhaustive_pairs"] * model["cpu"]["pair_cpu_s"]
            ) / args.workers
            p["candidate_idle_seconds"] = (
                face_cpu + per_face * int(n) * model["cpu"]["pair_cpu_s"]
            ) / args.workers
    machine = describe_machine(args.workers)
    document = {"machine": machine, "runs": rows, "model": model}
    (args.out / "throughput.json").write_text(json.dumps(document, indent=2) + "\n")
    (args.out / "throughput.md").write_text(_markdown(rows, model, machine, args))
    _plot(rows, model, args.out / "cost.png")
    print((args.out / "throughput.md").read_text())
    return 0


def _subset(hoard: Path, n: int, seed: int, folder: Path) -> Path:
    """Both faces of n/2 coins drawn at random (obverse-only coins count once), as links, with labels."""
    from coindie.io.labels import read_labels, write_labels

    faces = sorted(p for p in hoard.glob("*.ply"))
    coins = sorted({p.stem[:-1] for p in faces})
    rng = np.random.default_rng(seed)
    chosen: list[Path] = []
    for coin in rng.permutation(coins):
        chosen += [p for p in faces if p.stem[:-1] == coin]
        if len(chosen) >= n:
            break
    folder.mkdir(parents=True, exist_ok=True)
    for path in chosen[:n]:
        link = folder / path.name
        if not link.exists():
            link.symlink_to(path.resolve())
    labels = read_labels(hoard / "labels.csv")
    write_labels(
        folder / "labels.csv", {k: v for k, v in labels.items() if k.key in {p.stem for p in chosen[:n]}}
    )
    return folder


def _measure(subset: Path, folder: Path, mode: str, args: argparse.Namespace) -> dict:
    from coindie.cli.demo import cluster_and_evaluate
    from coindie.cli.progress import counting_progress
    from coindie.project import init_project
    from coindie.project.run import RunConfig, run_project

    project, _ = init_project(folder, subset, subset / "labels.csv")
    config = RunConfig(workers=args.workers, mode=mode, k=args.k, max_seconds=60.0 * args.max_minutes)
    start = time.perf_counter()
    report = run_project(project, config, progress=counting_progress)
    planned = sum(p.n_pairs for p in report.plans)
    done = project.db.execute(
        "SELECT COUNT(*) AS n FROM pairs WHERE params_hash = ? AND status = 'done'",
        (project.current_params(),),
    ).fetchone()["n"]
    row = {
        "faces": len(project.scans("ok")),
        "mode": mode,
        "k": args.k if mode == "candidates" else None,
        "pairs_planned": planned,
        "pairs_done_total": done,
        "pairs_this_run": report.pairs_done,
        "faces_seconds": report.stage_seconds.get("faces", 0.0),
        "plan_seconds": report.stage_seconds.get("plan", 0.0),
        "pairs_seconds": report.stage_seconds.get("pairs", 0.0),
        "run_seconds": time.perf_counter() - start,
        "finished": done == planned,
        "peak_rss_main_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
        "peak_rss_worker_mb": resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024,
    }
    row["pairs_per_second"] = report.pairs_done / row["pairs_seconds"] if row["pairs_seconds"] else None
    if row["finished"]:
        mark = time.perf_counter()
        row["clusters"] = cluster_and_evaluate(project, folder, "components")
        row["cluster_seconds"] = time.perf_counter() - mark
    return row


def cpu_costs(project_dir: Path, n_faces: int = 16, batch_faces: int = 12) -> dict:
    """CPU seconds (``time.process_time``, independent of how loaded the machine is) of the per-face work
    on ``n_faces`` faces and of one tile of pairs, both in this process, on a project already prepared."""
    import tempfile

    from coindie.project import open_project
    from coindie.project.run import RunConfig, _cache_files, _scorer, tile_batches
    from coindie.project.workers import FaceTask, PairBatch, face_params_hash, prepare_face, score_batch

    project = open_project(project_dir)
    scans = project.scans("ok")[:n_faces]
    with tempfile.TemporaryDirectory() as cache:
        params = face_params_hash(0.05, 0.1)
        start = time.process_time()
        for scan in scans:
            prepare_face(FaceTask(scan.face_id, scan.path, cache, params, 0.05, 0.1))
        face_cpu = (time.process_time() - start) / len(scans)
    scorer = _scorer(RunConfig())
    pairs = [
        (r["source"], r["target"]) for r in project.db.execute("SELECT source, target FROM pairs LIMIT 20000")
    ]
    tile = max(tile_batches(pairs, batch_faces), key=len)
    files = _cache_files(project, RunConfig())
    faces = sorted({f for pair in tile for f in pair})
    batch = PairBatch(tuple(tile), tuple((f, files[f]) for f in faces), scorer.config_text, 2 * batch_faces)
    results = score_batch(batch)
    cpu = [json.loads(r["timings"])["cpu"] for r in results if r.get("timings")]
    return {
        "face_cpu_s": face_cpu,
        "pair_cpu_s": float(np.mean(cpu)),
        "pairs_sampled": len(cpu),
        "faces_in_tile": len(faces),
        "faces_sampled": len(scans),
    }


def _cost_model(rows: list[dict], k: int) -> dict:
    """Seconds per face (per-face stage) and per pair (pair stage), pooled over the runs, wall clock."""
    face_rows = [r for r in rows if r["faces_seconds"] > 0]
    pair_rows = [r for r in rows if r["pairs_this_run"]]
    t_face = sum(r["faces_seconds"] for r in face_rows) / max(1, sum(r["faces"] for r in face_rows))
    t_pair = sum(r["pairs_seconds"] for r in pair_rows) / max(1, sum(r["pairs_this_run"] for r in pair_rows))
    candidates = [r for r in rows if r["mode"] == "candidates"]
    per_face = (
        sum(r["pairs_planned"] for r in candidates) / sum(r["faces"] for r in candidates)
        if candidates
        else 0.65 * k
    )
    projected = {}
    for n in PROJECTED_SIZES:
        exhaustive_pairs = 2 * (n // 2) * (n // 2 - 1) // 2
        projected[n] = {
            "exhaustive_pairs": exhaustive_pairs,
            "exhaustive_seconds": n * t_face + exhaustive_pairs * t_pair,
            "candidate_pairs": int(per_face * n),
            "candidate_seconds": n * t_face + per_face * n * t_pair,
        }
    return {
        "t_face_s": t_face,
        "t_pair_s": t_pair,
        "candidate_pairs_per_face": per_face,
        "projected": projected,
    }


def _markdown(rows: list[dict], model: dict, machine: str, args: argparse.Namespace) -> str:
    head = (
        "| faces | mode | pairs planned | pairs done | per-face stage (s) | plan (s) | pairs (s) | pairs/s "
    )
    head += "| peak RSS main / worker (MB) | all pairs done | clusters |"
    lines = [head, "| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | --- |"]
    for r in rows:
        mode = r["mode"] + (f" (K = {r['k']})" if r["k"] else "")
        rate = f"{r['pairs_per_second']:.2f}" if r["pairs_per_second"] else "–"
        clusters = "<br>".join(line.split(" (")[0] for line in r.get("clusters", [])) or "–"
        lines.append(
            f"| {r['faces']} | {mode} | {r['pairs_planned']:,} | {r['pairs_done_total']:,} | "
            f"{r['faces_seconds']:.1f} | "
            f"{r['plan_seconds']:.2f} | {r['pairs_seconds']:.1f} | {rate} | {r['peak_rss_main_mb']:.0f} / "
            f"{r['peak_rss_worker_mb']:.0f} | {'yes' if r['finished'] else 'no (time limit)'} | {clusters} |"
        )
    lines += [
        "",
        f"Cost model ({args.workers} workers): {model['t_face_s']:.3f} s per face, "
        f"{model['t_pair_s']:.4f} s per pair (wall clock), "
        f"{model['candidate_pairs_per_face']:.1f} candidate pairs per face at K = {args.k}.",
        "",
    ]
    lines += [
        "| faces | exhaustive pairs | exhaustive, at the measured rate | candidate pairs "
        "| candidates, at the measured rate |"
    ]
    lines += ["| ---: | ---: | ---: | ---: | ---: |"]
    idle = "cpu" in model
    if idle:
        c = model["cpu"]
        lines[-3:-3] = [
            "",
            f"CPU per face {c['face_cpu_s']:.3f} s ({c['faces_sampled']} faces), "
            f"per pair {c['pair_cpu_s']:.4f} s "
            f"({c['pairs_sampled']} pairs of one tile of {c['faces_in_tile']} faces, face loading included); "
            f"'idle cores' columns: that CPU time over {args.workers} otherwise idle cores.",
        ]
        lines[-2] = lines[-2] + " exhaustive, idle cores | candidates, idle cores |"
        lines[-1] = lines[-1] + " ---: | ---: |"
    for n, p in model["projected"].items():
        line = (
            f"| {int(n):,} | {p['exhaustive_pairs']:,} | {_duration(p['exhaustive_seconds'])} | "
            f"{p['candidate_pairs']:,} | {_duration(p['candidate_seconds'])} |"
        )
        if idle:
            line += f" {_duration(p['exhaustive_idle_seconds'])} | {_duration(p['candidate_idle_seconds'])} |"
        lines.append(line)
    return "\n".join(lines) + f"\n\nMachine: {machine}.\n"


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 2 * 3600:
        return f"{seconds / 60:.0f} min"
    if seconds < 3 * 86400:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 86400:.0f} days"


def _plot(rows: list[dict], model: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sizes = np.array([int(n) for n in model["projected"]])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for key, label, color in (
        ("exhaustive_seconds", "exhaustive", "C3"),
        ("candidate_seconds", "candidates", "C0"),
    ):
        ax.plot(
            sizes,
            [model["projected"][n][key] / 3600 for n in model["projected"]],
            color=color,
            label=f"{label} (model)",
        )
        measured = [r for r in rows if r["mode"] == label and r["pairs_this_run"]]
        ax.scatter(
            [r["faces"] for r in measured],
            [(r["faces_seconds"] + r["pairs_planned"] / r["pairs_per_second"]) / 3600 for r in measured],
            color=color, marker="o", label=f"{label} (measured rate)",
        )  # fmt: skip
    if "cpu" in model:
        for key, label, color in (
            ("exhaustive_idle_seconds", "exhaustive", "C3"),
            ("candidate_idle_seconds", "candidates", "C0"),
        ):
            values = [model["projected"][n][key] / 3600 for n in model["projected"]]
            ax.plot(sizes, values, color=color, ls="--", label=f"{label} (CPU time, idle cores)")
    ax.axhline(0.5, color="grey", ls=":", lw=0.8)
    ax.text(sizes[0], 0.55, "30 min", color="grey", fontsize=8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("faces")
    ax.set_ylabel("hours, scans to scored pairs")
    ax.set_title("Cost of a die study: exhaustive grows as N², candidates as N")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
