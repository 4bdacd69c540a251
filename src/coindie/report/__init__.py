"""The die catalogue: a self-contained HTML report of a project (plates of aligned reliefs per die, die links,
estimates), printed to PDF by headless Chromium, and the aligned PLY models per die.

>>> from coindie.report import build_report, print_pdf
>>> build_report("study", "report.html", metadata="coins.csv")   # doctest: +SKIP
>>> print_pdf("report.html", "report.pdf")                        # doctest: +SKIP
"""

from coindie.report.alignment import align_die, export_aligned_dies, project_alignments
from coindie.report.chromium import ChromiumError, chromium_binary, print_pdf, screenshot
from coindie.report.html import build_report

__all__ = [
    "ChromiumError",
    "align_die",
    "build_report",
    "chromium_binary",
    "export_aligned_dies",
    "print_pdf",
    "project_alignments",
    "screenshot",
]
