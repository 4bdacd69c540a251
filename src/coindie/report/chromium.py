"""Headless Chromium for the report: print to PDF, and screenshots.

Chromium is Debian's (``apt-get install chromium``, ``/usr/bin/chromium``); ``COINDIE_CHROMIUM`` names
another binary. It runs with ``--no-sandbox`` (as root in containers the sandbox cannot start) on a
throw-away profile folder.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from coindie.errors import CoinDieError

CANDIDATES = ("/usr/bin/chromium", "/usr/bin/chromium-browser", "chromium", "google-chrome")
#: Seconds before a Chromium run is given up.
TIMEOUT_S = 180


class ChromiumError(CoinDieError):
    """No Chromium, or Chromium failed to print or shoot the page."""


def chromium_binary() -> str | None:
    """The Chromium to use, or None when there is none."""
    wanted = os.environ.get("COINDIE_CHROMIUM")
    for name in ((wanted,) if wanted else ()) + CANDIDATES:
        found = shutil.which(name) if name else None
        if found:
            return found
    return None


def _run(arguments: list[str], page: Path, output: Path) -> Path:
    binary = chromium_binary()
    if binary is None:
        raise ChromiumError(
            "headless Chromium is needed (apt-get update && apt-get install -y chromium), "
            "or set COINDIE_CHROMIUM to its path"
        )
    output.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="coindie-chromium-") as profile:
        command = [
            binary, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
            "--hide-scrollbars", f"--user-data-dir={profile}", *arguments, page.resolve().as_uri(),
        ]  # fmt: skip
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT_S, check=False)
        except subprocess.TimeoutExpired:
            raise ChromiumError(f"{page}: Chromium did not finish within {TIMEOUT_S} s") from None
    if done.returncode != 0 or not output.is_file() or output.stat().st_size == 0:
        tail = (done.stderr or done.stdout).strip().splitlines()[-3:]
        raise ChromiumError(f"{page}: Chromium failed (exit {done.returncode}): {' | '.join(tail)}")
    return output


def print_pdf(page: str | Path, pdf: str | Path) -> Path:
    """Print an HTML file to PDF (Chromium's print, no header or footer)."""
    pdf = Path(pdf)
    return _run([f"--print-to-pdf={pdf.resolve()}", "--no-pdf-header-footer"], Path(page), pdf)


def screenshot(page: str | Path, png: str | Path, width: int = 1280, height: int = 1600) -> Path:
    """A PNG of the top ``width`` x ``height`` pixels of the page."""
    png = Path(png)
    return _run([f"--screenshot={png.resolve()}", f"--window-size={width},{height}"], Path(page), png)
