"""How close is a synthetic hoard to the real Riedones3D study (:mod:`coindie.synth.calibration`): die
sizes, die links, the c2c histograms and renders, printed as JSON with the plots written to ``--images``.

    python benchmarks/synth_calibration.py HOARD --real ../shared/data/riedones3d --images docs/images
    python benchmarks/synth_calibration.py x --parameters   # the parameter tables of docs/synthetic.md
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from coindie.synth.calibration import calibrate, parameter_tables


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("hoard", type=Path, help="a folder made by `coindie synth`")
    parser.add_argument("--real", type=Path, default=Path("../shared/data/riedones3d"), help="the real facts")
    parser.add_argument("--images", type=Path, default=Path("docs/images"), help="where the PNGs go")
    parser.add_argument("--pairs", type=int, default=120, help="same-die pairs in the mean histogram")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--parameters", action="store_true", help="print the parameter tables and stop")
    args = parser.parse_args(argv)
    if args.parameters:
        print(parameter_tables())
        return
    result = calibrate(args.hoard, args.real, args.images, args.pairs, args.seed)
    summary = {k: v for k, v in result["histogram"].items() if not k.endswith("_mean")}
    print(
        json.dumps(
            {"die_sizes": result["die_sizes"], "links": result["links"], "histogram": summary}, indent=1
        )
    )


if __name__ == "__main__":
    main()
