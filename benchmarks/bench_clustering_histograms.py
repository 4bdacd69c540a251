"""Histogram variants (symmetric, the authors' swapped grids) on pairs already registered.

    python benchmarks/bench_clustering_histograms.py BENCH_DIR --hoard H --train-pairs TRAIN.csv \
        --max-faces 60 [--groups R] [--out OUT]

The transforms found by ``coindie bench clustering`` (``BENCH_DIR/pairs.csv``) and by ``coindie train
similarity`` (``TRAIN.csv``) are reused: only the histograms are recomputed, for the pairs whose
registration was valid (the others score 0 in every variant). For each variant a classifier is fitted on
the training pairs, τ chosen on the validation split by FMI, and the test split scored with ``components``,
next to the pair AUC. Writes ``OUT/histogram_variants.md`` and ``.json`` (OUT defaults to BENCH_DIR).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from functools import lru_cache

import numpy as np

from coindie.bench.clustering import rerun_arguments

VARIANTS = {
    "paper's text (source 0.1, target 0.05 mm, one way)": {},
    "symmetric (mean of both directions)": {"symmetric": True},
    "authors' code grids (source 0.05, target 0.1 mm)": {"source_grid_mm": 0.05, "target_grid_mm": 0.1},
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    rerun_arguments(parser)
    parser.add_argument("--groups", default="R")
    args = parser.parse_args(argv)
    out = args.out or args.bench

    from coindie.bench.clustering import THRESHOLD_FROM, chosen_faces, pair_figures, probability_graph
    from coindie.cli.progress import counting_progress
    from coindie.clustering import cluster, evaluate, select_threshold
    from coindie.io.truth import load_truth
    from coindie.similarity import HistogramSettings, SameDieClassifier, c2c_histogram
    from coindie.similarity.batch import read_scores

    truth = load_truth(args.hoard)
    groups = [g.strip() for g in args.groups.split(",")]
    faces = {}
    for group in groups:
        faces[("cluster_test", group)] = chosen_faces(truth, "cluster_test", group, args.max_faces)
        val = THRESHOLD_FROM[group]
        faces[("cluster_val", val)] = chosen_faces(truth, "cluster_val", val, args.max_faces)
    wanted = {(a.face_id, b.face_id) for f in faces.values() for i, a in enumerate(f) for b in f[i + 1 :]}
    bench = {k: v for k, v in read_scores(args.bench / "pairs.csv").items() if k in wanted}
    train = read_scores(args.train_pairs)
    results = {}
    for name, changes in VARIANTS.items():
        settings = HistogramSettings(**changes)
        start = time.perf_counter()
        todo = [(k, s) for k, s in [*train.items(), *bench.items()] if s.valid]
        rescored = {}
        with counting_progress(name[:8]) as progress:
            progress(0, len(todo))
            for key, score in sorted(todo, key=lambda item: (item[0][1], item[0][0])):
                source, target = _scan(str(truth.faces[key[0]].path)), _scan(str(truth.faces[key[1]].path))
                histogram = c2c_histogram(source, target, score.T_target_source, settings)
                rescored[key] = replace(score, histogram=histogram)
                progress(1, 0)
        train_rows = [
            (rescored[k], truth.faces[k[0]].die == truth.faces[k[1]].die) for k in train if k in rescored
        ]
        train_rows = [(s, same) for s, same in train_rows if s.histogram.any()]
        model = SameDieClassifier(settings=settings).fit(
            np.stack([s.histogram for s, _ in train_rows]), np.array([same for _, same in train_rows])
        )
        scores = {**bench, **{k: v for k, v in rescored.items() if k in bench}}
        graphs = {key: probability_graph(f, scores, model) for key, f in faces.items()}
        dies = {key: {f.face_id: f.die for f in group} for key, group in faces.items()}
        entry = {"seconds": time.perf_counter() - start, "groups": {}}
        for group in groups:
            val_key, test_key = ("cluster_val", THRESHOLD_FROM[group]), ("cluster_test", group)
            tau = select_threshold(graphs[val_key], dies[val_key], "components").threshold
            r = evaluate(cluster(graphs[test_key], "components", tau).labels, dies[test_key])
            entry["groups"][group] = {
                "threshold": tau,
                **r.scores(),
                "pairs": pair_figures(graphs[test_key], dies[test_key]),
            }
        results[name] = entry
    (out / "histogram_variants.json").write_text(json.dumps(results, indent=2) + "\n")
    lines = ["| histogram | group | τ (val) | FMI | ARI | clusters / dies | pair AUC | max other p |"]
    lines.append("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for name, entry in results.items():
        for group, e in entry["groups"].items():
            p = e["pairs"]
            lines.append(
                f"| {name} | {group} | {e['threshold']:.3g} | {e['fmi']:.3f} | {e['ari']:.3f} | "
                f"{e['n_clusters']} / {e['n_dies']} | {p.get('auc', float('nan')):.4f} | "
                f"{p.get('max_other_probability', float('nan')):.3f} |"
            )
    (out / "histogram_variants.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


@lru_cache(maxsize=48)
def _scan(path: str):  # noqa: ANN202
    from coindie.io import read_scan

    return read_scan(path)


if __name__ == "__main__":
    sys.exit(main())
