"""The report's example in docs/numismatics.md and the README: a small synthetic study, its report and a
screenshot of it in headless Chromium.

    python benchmarks/numismatics_report_example.py            # OUT = build/numismatics_report

Generates the ``tiny`` hoard (16 faces), makes it a project, scores every pair, writes OUT/report.html
and OUT/report.pdf, and the screenshot docs/images/numismatics_report.png (the top of the page, 1200 x
2400 pixels: the study, the estimates, the die links and the first plates).
"""

from __future__ import annotations

import argparse
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--out", type=Path, default=REPO / "build" / "numismatics_report")
    parser.add_argument("--image", type=Path, default=REPO / "docs" / "images" / "numismatics_report.png")
    args = parser.parse_args(argv)

    from coindie.project import init_project
    from coindie.project.run import RunConfig, run_project
    from coindie.report import build_report, print_pdf, screenshot
    from coindie.synth.hoard import synthesize

    hoard = args.out / "hoard"
    synthesize(hoard, preset="tiny", seed=5, workers=2)
    project, _ = init_project(args.out / "project", hoard, hoard / "labels.csv")
    run_project(project, RunConfig(workers=2, mode="exhaustive"), echo=lambda _: None)
    coins = args.out / "coins.csv"
    coins.write_text(
        "coin_id,weight,findspot\nL1,3.10,Rennes\nL2,3.30,Rennes\nL3,2.90,Paris\nL4,3.05,Paris\n"
        "L5,3.00,Paris\nL6,3.20,Rennes\nL7,2.95,Rennes\nL8,3.15,Paris\n"
    )
    html = build_report(args.out / "project", args.out / "report.html", metadata=coins)
    print(print_pdf(html, args.out / "report.pdf"))
    print(screenshot(html, args.image, 1200, 2400))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
