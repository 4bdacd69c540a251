"""Time and accuracy of every registered method on synthetic pairs (a quick check, not the benchmark).

    .venv/bin/python benchmarks/bench_registration_methods.py --pairs 10 --radius 10
    .venv/bin/python benchmarks/bench_registration_methods.py --pairs 40 --hoard HOARD  # from `coindie synth`

Without ``--hoard``, pairs come from the tests' ``synthetic_pairs.make_coin_pair`` (a 20 mm coin at 0.1 mm:
~31k target and ~27k source points) under the paper's random poses (x/y within ±25°, z within ±180°).
With ``--hoard``, each pair is two faces of one die (one pair per die, dies drawn at random), grid-sampled at
0.1 mm, with the truth of the hoard (:func:`coindie.io.truth.load_truth`: ``T_true``). A pair counts as
recovered by the registration benchmark's success thresholds (:mod:`coindie.bench.registration`: rotation
within 2°, translation within 0.3 mm). Local methods (``icp``) start from the identity, so they only show
what a local method does on such poses.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np

from coindie.bench.registration import GRID_MM, SUCCESS_ROTATION_DEG, SUCCESS_TRANSLATION_MM
from coindie.io import read_scan
from coindie.io.truth import load_truth
from coindie.preprocess.sampling import grid_sample
from coindie.registration import (
    get_method,
    list_methods,
    rotation_error_deg,
    scaled_registration_error,
    translation_error_mm,
)
from coindie.registration.clouds import FloatArray
from coindie.scan import Scan

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from synthetic_pairs import make_coin_pair  # noqa: E402  (a test helper: tests/synthetic_pairs.py)

Pair = tuple[Scan, Scan, FloatArray]


def synthetic_pairs(n_pairs: int, radius: float) -> Iterator[Pair]:
    for seed in range(n_pairs):
        pair = make_coin_pair(seed=seed, radius=radius)
        yield pair.source, pair.target, pair.T_target_source


def hoard_pairs(folder: Path, n_pairs: int, seed: int = 0) -> list[Pair]:
    """One random pair of faces for each of ``n_pairs`` random dies of a synthetic hoard."""
    truth = load_truth(folder)
    faces_of: dict[str, list[str]] = {}
    for face in truth.faces.values():  # in the order of labels.csv
        faces_of.setdefault(face.die, []).append(face.face_id)
    rng = np.random.default_rng(seed)
    dies = [die for die, faces in faces_of.items() if len(faces) >= 2]
    rng.shuffle(dies)
    pairs = []
    for die in dies[:n_pairs]:
        a, b = rng.choice(faces_of[die], 2, replace=False)
        scans = [grid_sample(read_scan(truth.faces[face].path), GRID_MM) for face in (a, b)]
        pairs.append((scans[0], scans[1], truth.T_true(a, b)))
    return pairs


def evaluate(method: str, pairs: list[Pair]) -> dict[str, float]:
    """Share recovered, share valid, share valid but wrong, median seconds and median SRE (x1000)."""
    registrar = get_method(method)
    recovered, valid, seconds, sre = [], [], [], []
    for source, target, truth in pairs:
        start = time.perf_counter()
        result = registrar.register(source, target)
        seconds.append(time.perf_counter() - start)
        T = result.T_target_source
        recovered.append(
            rotation_error_deg(truth, T) < SUCCESS_ROTATION_DEG
            and translation_error_mm(truth, T) < SUCCESS_TRANSLATION_MM
        )
        valid.append(result.valid)
        sre.append(1000 * scaled_registration_error(source.points, truth, T))
    ok, accepted = np.array(recovered), np.array(valid)
    return {
        "recovered": float(ok.mean()),
        "valid": float(accepted.mean()),
        "valid_but_wrong": float((accepted & ~ok).mean()),
        "seconds": float(np.median(seconds)),
        "sre_x1000": float(np.median(sre)),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--pairs", type=int, default=10)
    parser.add_argument("--radius", type=float, default=10.0, help="coin radius (mm) of the synthetic pairs")
    parser.add_argument("--hoard", type=Path, default=None, help="a folder written by `coindie synth`")
    parser.add_argument("--methods", nargs="*", default=None, help="default: every registered method")
    args = parser.parse_args()
    if args.hoard:
        pairs = hoard_pairs(args.hoard, args.pairs)
    else:
        pairs = list(synthetic_pairs(args.pairs, args.radius))
    sizes = [s.n_points for s, _, _ in pairs]
    print(f"{len(pairs)} pairs, median {int(np.median(sizes))} source points")
    print(
        f"{'method':<18} {'recovered':>9} {'valid':>6} {'valid&wrong':>11} {'median s':>9} {'SRE x1000':>10}"
    )
    for method in args.methods or list_methods():
        row = evaluate(method, pairs)
        print(
            f"{method:<18} {row['recovered']:>9.0%} {row['valid']:>6.0%} {row['valid_but_wrong']:>11.0%} "
            f"{row['seconds']:>9.2f} {row['sre_x1000']:>10.1f}"
        )


if __name__ == "__main__":
    main()
