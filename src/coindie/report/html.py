"""``coindie report``: the die catalogue of a project as one self-contained HTML file.

Sections: the study (project, coindie version, date, clustering parameters, the latest run's
configuration); the estimates of the original number of dies per side; the die-link diagram and chains;
the accumulation curves; per die a **plate** (its coins' reliefs aligned to the die's reference coin, see
:mod:`coindie.report.alignment`; coin count; verified flag; the die's links to dies of the other side; the
coin metadata summarised); the singletons (dies of one coin). Every image is embedded as a data URI, so
the file can be mailed or archived alone, and printed to PDF by :func:`coindie.report.chromium.print_pdf`.

**Verified** comes from the project's edit log: a die is verified when an edit of action ``verify`` (or
``verify_die``, ``confirm``) names one of its faces (``a``, ``b`` or ``payload["faces"]``); without such
an edit it is ``unverified``.
"""

from __future__ import annotations

import base64
import io
import json
import tempfile
from collections.abc import Callable
from datetime import UTC, datetime
from html import escape
from pathlib import Path

from coindie import __version__
from coindie.numismatics.analysis import analyse
from coindie.numismatics.die_links import OBVERSE, REVERSE, DieLinks, node_name
from coindie.numismatics.metadata import CoinMetadata, read_metadata
from coindie.numismatics.sources import SIDES, SideDies, project_dies
from coindie.report.alignment import DieAlignment, project_alignments, scan_paths

Progress = Callable[[int, int], None]
VERIFY_ACTIONS = ("verify", "verify_die", "confirm")

CSS = """
body { font-family: Georgia, 'DejaVu Serif', serif; margin: 2em auto; max-width: 1100px; color: #222; }
h1 { font-size: 1.7em; } h2 { border-bottom: 1px solid #bbb; margin-top: 2em; }
table { border-collapse: collapse; font-size: 0.9em; margin: 0.5em 0 1em; }
td, th { border: 1px solid #ccc; padding: 2px 8px; text-align: left; } th { background: #f3efe9; }
.plate { border: 1px solid #cfc6b8; border-radius: 4px; padding: 0.6em 1em; margin: 1em 0;
         page-break-inside: avoid; break-inside: avoid; }
.plate h3 { margin: 0.2em 0; } .plate .meta { font-size: 0.85em; color: #555; }
.coins { display: flex; flex-wrap: wrap; gap: 10px; }
figure { margin: 0; text-align: center; font-size: 0.75em; }
figure img { display: block; background: #fff; }
.verified { color: #1d6b2a; font-weight: bold; } .unverified { color: #8a5a00; }
.singletons { display: flex; flex-wrap: wrap; gap: 10px; }
.singletons .plate { margin: 0; padding: 0.3em 0.6em; }
img.wide { max-width: 100%; }
.curves { display: flex; gap: 1%; } .curves img { width: 49.5%; }
@media print { body { margin: 0.5cm; max-width: none; } h2 { page-break-before: auto; } }
"""


def data_uri(payload: bytes, mime: str) -> str:
    return f"data:{mime};base64,{base64.b64encode(payload).decode('ascii')}"


def file_uri(path: Path) -> str:
    mime = {".svg": "image/svg+xml", ".png": "image/png"}[path.suffix]
    return data_uri(path.read_bytes(), mime)


def verified_faces(edits: list[dict]) -> set[str]:
    """Faces named by a verification edit (module docstring)."""
    from coindie.ids import parse_face_id

    faces: set[str] = set()
    for edit in edits:
        if edit.get("action") not in VERIFY_ACTIONS:
            continue
        names = [edit.get("a"), edit.get("b"), *(edit.get("payload") or {}).get("faces", [])]
        faces.update(parse_face_id(str(n)).key for n in names if n)
    return faces


def _render_plate_images(
    alignment: DieAlignment,
    paths: dict[str, Path],
    width_px: int,
    progress: Progress | None,
    unit: str | None = None,
) -> dict[str, str]:
    """Face -> PNG data URI of its relief in the reference's canonical frame; a face that cannot be read or
    rendered is left out (the plate says so)."""
    from coindie.errors import CoinDieError
    from coindie.io import read_scan
    from coindie.preprocess.canonical import canonical_frame
    from coindie.render import render_relief

    images: dict[str, str] = {}
    try:
        reference = read_scan(paths[alignment.reference], unit=unit)
        frame = canonical_frame(reference)
    except (CoinDieError, KeyError, OSError):
        frame = None
    for face in alignment.faces:
        try:
            scan = read_scan(paths[face], unit=unit)
            T = alignment.T_reference_face.get(face)
            if T is not None and frame is not None:
                image = render_relief(
                    scan.transformed(T), width_px=width_px, frame=frame, background=(255, 255, 255)
                )
            else:  # not aligned: its own canonical frame
                image = render_relief(scan, width_px=width_px, background=(255, 255, 255))
            buffer = io.BytesIO()
            # JPEG: a fifth of the PNG's size on these shaded reliefs, so a catalogue of thousands of coins
            # stays a file one can mail; quality 88 keeps the die's fine details.
            image.convert("RGB").save(buffer, format="JPEG", quality=88)
            images[face] = data_uri(buffer.getvalue(), "image/jpeg")
        except (CoinDieError, KeyError, OSError, ValueError):
            pass
        if progress:
            progress(1, 0)
    return images


def _die_links_text(links: DieLinks | None, side: str, die: str) -> str:
    if links is None:
        return ""
    node = node_name(OBVERSE if side == "D" else REVERSE, die)
    if node not in links.graph:
        return "no linked coin"
    g = links.graph
    parts = sorted(((g.nodes[o]["die"], w) for o, w in ((o, g[node][o]["weight"]) for o in g[node])),
                   key=lambda item: -item[1])  # fmt: skip
    other = "reverse" if side == "D" else "obverse"
    chain = g.nodes[node].get("chain")
    if not parts:
        return f"no {other} die linked (chain {chain})"
    return f"chain {chain}; {other} dies: " + ", ".join(
        f"{escape(d)} ({w} coin{'s' * (w > 1)})" for d, w in parts
    )


def _metadata_text(meta: CoinMetadata | None, faces: list[str]) -> str:
    if meta is None:
        return ""
    parts = []
    for column, value in meta.summary(faces).items():
        if isinstance(value, dict) and "mean" in value:
            parts.append(f"mean {escape(column)} {value['mean']:.3g} (n = {value['n']})")
        elif isinstance(value, dict):
            parts.append(f"{escape(column)}: " + ", ".join(f"{escape(str(k))} {v}" for k, v in value.items()))
    return "; ".join(parts)


def _coin_caption(meta: CoinMetadata | None, face: str) -> str:
    if meta is None:
        return ""
    row = meta.for_coin(face)
    return "<br>".join(f"{escape(k)}: {escape(v)}" for k, v in row.items() if v)


def _plate(
    alignment: DieAlignment,
    images: dict[str, str],
    verified: bool,
    links: DieLinks | None,
    meta: CoinMetadata | None,
    width_px: int,
    singleton: bool = False,
) -> str:
    side = SIDES.get(alignment.side, alignment.side)
    flag = (
        '<span class="verified">verified</span>' if verified else '<span class="unverified">unverified</span>'
    )
    n = len(alignment.faces)
    tree = {b: w for a, b, w in alignment.tree if a == alignment.reference}
    tree.update({a: w for a, b, w in alignment.tree if b == alignment.reference})
    figures = []
    for face in alignment.faces:
        missing = f'<div style="width:{width_px}px">(scan not readable)</div>'
        img = (
            f'<img src="{images[face]}" width="{width_px}" alt="{escape(face)}">'
            if face in images
            else missing
        )
        role = (
            "reference"
            if face == alignment.reference
            else ("not aligned" if face in alignment.unaligned else "")
        )
        caption = escape(face) + (f" <i>{role}</i>" if role else "")
        extra = _coin_caption(meta, face)
        figures.append(
            f"<figure>{img}<figcaption>{caption}{'<br>' + extra if extra else ''}</figcaption></figure>"
        )
    meta_line = _metadata_text(meta, alignment.faces)
    return (
        f'<section class="plate{" singleton" if singleton else ""}" data-side="{alignment.side}" '
        f'data-die="{escape(alignment.die)}">'
        f"<h3>{side} die {escape(alignment.die)}</h3>"
        f'<div class="meta">{n} coin{"s" * (n > 1)} · {flag}'
        + (f" · {_die_links_text(links, alignment.side, alignment.die)}" if links else "")
        + (f" · {meta_line}" if meta_line else "")
        + (
            f" · reference {escape(alignment.reference)}, aligned along {len(alignment.tree)} links"
            if n > 1
            else ""
        )  # fmt: skip
        + "</div>"
        f'<div class="coins">{"".join(figures)}</div></section>'
    )


def _estimates_table(analysis) -> str:  # noqa: ANN001 (Analysis)
    rows = []
    for side, est in analysis.estimates.items():
        c, cov = est.counts, est.coverage
        rows.append(
            f"<h3>{SIDES.get(side, side)} dies</h3><p>n = {c.n} coins, d = {c.d} dies, "
            f"d<sub>1</sub> = {c.d1} "
            f"singletons, d<sub>2</sub> = {c.d2} doubletons; coverage C = {cov.value:.3f} "
            f"({cov.low:.3f}–{cov.high:.3f}).</p><table><tr><th>estimator</th><th>dies</th>"
            f"<th>{est.confidence:.0%} interval</th><th>source / note</th></tr>"
        )
        for e in est.estimators:
            value = "–" if e.value is None else f"{e.value:.1f}"
            interval = "–" if e.low is None else f"{e.low:.1f} – {e.high:.1f}"
            rows.append(f"<tr><td>{escape(e.name)}</td><td>{value}</td><td>{interval}</td>"
                        f"<td>{escape(e.note or e.source)}</td></tr>")  # fmt: skip
        rows.append("</table>")
    return "".join(rows)


def _parameters(project_folder: Path, sides: dict[str, SideDies]) -> str:
    from coindie.project import open_project

    project = open_project(project_folder)
    row = project.latest_run()
    items = [
        ("project", str(project.folder)),
        ("coindie", __version__),
        ("date", datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")),
        *((f"{SIDES.get(side, side)} clusters", d.source) for side, d in sides.items()),
        ("faces", str(len(project.scans("ok")))),
        ("edits in the log", str(len(project.edits()))),
    ]
    if row is not None:
        items += [
            (
                "latest run",
                f"{row['run_id']} ({row['status']}, coindie {row['version']}, {row['started_at']})",
            ),
            ("parameter hash", str(row["params_hash"])),
        ]
    table = "".join(f"<tr><th>{escape(k)}</th><td>{escape(v)}</td></tr>" for k, v in items)
    config = ""
    if row is not None:
        pretty = json.dumps(json.loads(row["config"]), indent=1, sort_keys=True)
        config = f"<details><summary>run configuration</summary><pre>{escape(pretty)}</pre></details>"
    return f"<table>{table}</table>{config}"


def build_report(
    project_folder: str | Path,
    out: str | Path,
    *,
    metadata: str | Path | None = None,
    threshold: float | None = None,
    method: str = "components",
    auto: bool = False,
    width_px: int = 240,
    progress: Progress | None = None,
) -> Path:
    """Write the report (module docstring) to ``out`` and return its path."""
    from coindie.project import open_project

    project_folder = Path(project_folder)
    out = Path(out)
    meta = read_metadata(metadata) if metadata is not None else None
    sides: dict[str, SideDies] = project_dies(project_folder, method, threshold, auto)
    with tempfile.TemporaryDirectory(prefix="coindie-report-") as scratch:
        analysis = analyse(sides, scratch, formats=("svg",), title="Die links")
        figures = {key: file_uri(path) for key, path in analysis.files.items() if path.suffix == ".svg"}
    alignments = project_alignments(project_folder, sides)
    paths = scan_paths(project_folder)
    project = open_project(project_folder)
    verified, unit = verified_faces(project.edits()), project.unit
    project.close()
    if progress:
        progress(0, sum(len(a.faces) for dies in alignments.values() for a in dies))
    body = [
        f"<h1>Die study of {escape(project_folder.resolve().name)}</h1>",
        "<h2>The study</h2>", _parameters(project_folder, sides),
        "<h2>How many dies: estimates</h2>", _estimates_table(analysis),
    ]  # fmt: skip
    curves = [
        f'<img src="{uri}" alt="{escape(key)}">' for key, uri in figures.items() if key.startswith("accum")
    ]
    body.append(f'<div class="curves">{"".join(curves)}</div>')
    if analysis.links is not None:
        s = analysis.links.summary()
        body += [
            "<h2>Die links</h2>",
            f"<p>{s['obverse_dies']} obverse and {s['reverse_dies']} reverse dies, {s['combinations']} "
            f"combinations on {s['coins_with_both_faces']} coins with both faces, {s['chains']} "
            f"chain{'s' * (s['chains'] != 1)}. Dies "
            "within a chain are in spectral seriation order (Fiedler vector of the weighted link graph).</p>",
            f'<p><img class="wide" src="{figures["diagram_svg"]}" alt="die-link diagram"></p>',
        ]
    for side, dies in alignments.items():
        plates, singles = [], []
        for alignment in dies:
            images = _render_plate_images(
                alignment, paths, width_px if len(alignment.faces) > 1 else 160, progress, unit
            )
            is_verified = any(f in verified for f in alignment.faces)
            if len(alignment.faces) > 1:
                plates.append(_plate(alignment, images, is_verified, analysis.links, meta, width_px))
            else:
                singles.append(
                    _plate(alignment, images, is_verified, analysis.links, meta, 160, singleton=True)
                )
        name = SIDES.get(side, side)
        body.append(f"<h2>Plates: {name} dies</h2>" + "".join(plates))
        body.append(f'<h2>Singletons: {name} dies of one coin ({len(singles)})</h2><div class="singletons">'
                    + "".join(singles) + "</div>")  # fmt: skip
    html = (
        '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
        f"<title>Die study of {escape(project_folder.resolve().name)}</title><style>{CSS}</style></head>"
        f"<body>{''.join(body)}<footer><p>Made by coindie {__version__} on "
        f"{datetime.now(UTC).strftime('%Y-%m-%d')}.</p></footer></body></html>"
    )
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(html, encoding="utf-8")
    return out
