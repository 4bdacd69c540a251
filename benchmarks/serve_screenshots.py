"""The README's screenshots of the review app (not a benchmark): each main view, taken in headless Chromium.

    python benchmarks/serve_screenshots.py PROJECT docs/images [--threshold 0.5]

PROJECT is a scored project (``coindie demo OUT`` makes one in OUT/project); it is copied first, so its
edit log is left as it is. It opens as ``coindie serve`` opens it: on ``coindie cluster --auto``'s clusters,
or with ``--threshold``, on the paper's components at τ.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("project", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--threshold", type=float, default=None)
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    from serve_support import copy_project, served
    from test_serve_e2e import CHROMIUM, CHROMIUM_ARGS, image_spread

    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as folder:
        project = copy_project(args.project, Path(folder) / "project")
        start = () if args.threshold is None else ("--threshold", str(args.threshold))
        with served(project, *start) as url, sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
            page = browser.new_page(viewport={"width": 1500, "height": 950})
            page.goto(url)
            page.wait_for_function("window.coindie && window.coindie.ready", timeout=120000)
            face = page.evaluate("window.coindie.state.nodes[0].id")
            page.fill("#search", face)
            page.press("#search", "Enter")
            page.wait_for_function(f"document.getElementById('face-id')?.textContent === '{face}'")
            image_spread(page, "#panel img.thumb")
            page.evaluate(  # the whole graph again, the face still selected
                "() => { const c = window.coindie; c.matches = null; "
                "c.renderer.getCamera().setState({x: 0.5, y: 0.5, ratio: 1, angle: 0}); "
                "c.renderer.refresh(); }"
            )
            page.wait_for_timeout(4000)
            page.screenshot(path=str(args.out / "review-graph.png"))
            page.click("#neighbours tr.neighbour >> nth=0")
            page.wait_for_selector("#pair:not([hidden])")
            for kind in ("target", "source", "difference", "heat"):
                image_spread(page, f"#img-{kind}")
            page.wait_for_selector("#three canvas", timeout=120000)
            page.wait_for_timeout(2000)
            page.screenshot(path=str(args.out / "review-pair.png"))
            page.click("#pair-fix")
            for role in ("target", "source"):
                image_spread(page, f"#pick-{role} img")
            page.locator("#fix").scroll_into_view_if_needed()
            page.screenshot(path=str(args.out / "review-registration.png"))
            page.click("#pair-close")
            page.click("#queue-button")
            page.wait_for_selector("#queue:not([hidden])")
            page.wait_for_timeout(500)
            page.screenshot(path=str(args.out / "review-queue.png"))
            browser.close()
    for name in ("graph", "pair", "registration", "queue"):
        print(args.out / f"review-{name}.png")


if __name__ == "__main__":
    main()
