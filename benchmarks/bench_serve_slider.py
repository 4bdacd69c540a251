"""The review app's threshold slider: time from the slider's input event to the redrawn graph, in Chromium.

    python benchmarks/bench_serve_slider.py OUT [--faces 2070] [--links 30000] [--moves 60]

A graph of the real hoard's size (2,070 faces, ~30,000 scored links; dies of very unbalanced sizes, as the
experts' labels) is written as node-link JSON, served by ``coindie serve`` and loaded in headless Chromium
(Debian's, software WebGL). The slider is moved ``--moves`` times over [0.3, 0.99]; the page records, per
move, the time from the input event to the next animation frame after sigma.js rendered (clusters
recomputed, nodes recoloured, links above τ shown). Writes ``OUT/slider.json`` and prints a table.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from coindie.bench.machine import describe_machine  # noqa: E402


def synthetic_graph(n_faces: int, n_links: int, seed: int = 0) -> dict:
    """Node-link JSON: dies of geometric sizes; same-die links mostly high, candidate links mostly low."""
    rng = np.random.default_rng(seed)
    dies = []
    while sum(dies) < n_faces:
        dies.append(int(min(rng.geometric(0.08), n_faces - sum(dies))))
    die_of = np.repeat(np.arange(len(dies)), dies)
    nodes = [f"L{k + 1:04d}D" for k in range(n_faces)]
    pairs: set[tuple[int, int]] = set()
    while len(pairs) < n_links:
        a = int(rng.integers(n_faces))
        members = np.flatnonzero(die_of == die_of[a])
        b = (
            int(rng.choice(members))
            if rng.random() < 0.5 and len(members) > 1
            else int(rng.integers(n_faces))
        )
        if a != b:
            pairs.add((min(a, b), max(a, b)))
    links = []
    for a, b in pairs:
        same = die_of[a] == die_of[b]
        p = rng.beta(8, 1.2) if same else rng.beta(1.2, 8)
        links.append({"source": nodes[a], "target": nodes[b], "weight": float(p)})
    return {
        "directed": False,
        "multigraph": False,
        "graph": {},
        "nodes": [{"id": n} for n in nodes],
        "links": links,
    }


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("out", type=Path)
    parser.add_argument("--faces", type=int, default=2070)
    parser.add_argument("--links", type=int, default=30000)
    parser.add_argument("--moves", type=int, default=60)
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    from serve_support import served
    from test_serve_e2e import CHROMIUM, CHROMIUM_ARGS, set_threshold

    args.out.mkdir(parents=True, exist_ok=True)
    graph = args.out / "graph.json"
    graph.write_text(json.dumps(synthetic_graph(args.faces, args.links)))
    sidecar = args.out / "graph.json.edits.sqlite"
    sidecar.unlink(missing_ok=True)
    with served(graph) as url, sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        page = browser.new_page(viewport={"width": 1400, "height": 900})
        start = time.perf_counter()
        page.goto(url)
        page.wait_for_function("window.coindie && window.coindie.ready", timeout=120000)
        load_s = time.perf_counter() - start
        page.evaluate("window.coindie.timings = []")
        for tau in np.linspace(0.3, 0.99, args.moves):
            set_threshold(page, round(float(tau), 2))
            page.wait_for_timeout(150)
        recorded = page.evaluate("window.coindie.timings")
        computed = np.asarray([t["computed"] for t in recorded], dtype=np.float64)
        timings = np.asarray([t["frame"] for t in recorded], dtype=np.float64)
        counts = page.text_content("#counts")
        browser.close()
    result = {
        "faces": args.faces,
        "links": args.links,
        "moves": len(timings),
        "load_s": load_s,
        "computed_median_ms": float(np.median(computed)),
        "computed_p95_ms": float(np.percentile(computed, 95)),
        "median_ms": float(np.median(timings)),
        "p95_ms": float(np.percentile(timings, 95)),
        "max_ms": float(timings.max()),
        "last_counts": counts,
        "machine": describe_machine(1),
    }
    (args.out / "slider.json").write_text(json.dumps(result, indent=2) + "\n")
    print(
        "| faces | links | moves | page load (s) | clusters + sigma refresh, median / p95 (ms) "
        "| input -> next frame, median / p95 / max (ms) |"
    )
    print("| ---: | ---: | ---: | ---: | ---: | ---: |")
    print(
        f"| {args.faces} | {args.links} | {len(timings)} | {load_s:.1f} | "
        f"{result['computed_median_ms']:.0f} / "
        f"{result['computed_p95_ms']:.0f} | {result['median_ms']:.0f} / {result['p95_ms']:.0f} / "
        f"{result['max_ms']:.0f} |"
    )


if __name__ == "__main__":
    main()
