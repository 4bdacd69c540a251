"""The review app's HTTP API (FastAPI) and its guard: a per-start token and a Host check.

Every request needs the token (``?token=``, the ``X-Coindie-Token`` header, or the cookie the first page
sets) and a ``Host`` header naming this server (a page of another site that reaches 127.0.0.1 through DNS
rebinding carries its own host name): otherwise 403 or 400 with a JSON ``error``. Errors are JSON
``{"error": message}``: 404 unknown face, pair, file or export; 400 bad parameter or edit; 409 conflict.
"""

from __future__ import annotations

import hmac
import math
from pathlib import Path
from typing import Any

import numpy as np
from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, JSONResponse, Response
from pydantic import BaseModel, Field
from starlette.exceptions import HTTPException as StarletteHTTPException

from coindie.clustering.corrections import Corrections, EditError, corrected_clusters, corrected_graph, pair
from coindie.errors import CoinDieError, ParameterError
from coindie.project.edits import EditConflict
from coindie.serve import images
from coindie.serve.exports import EXPORTS, export
from coindie.serve.manual import register_by_points
from coindie.serve.queue import review_queue
from coindie.serve.source import ReviewSource
from coindie.similarity.histogram import HistogramSettings

STATIC = Path(__file__).parent / "static"
TOKEN_COOKIE = "coindie_token"
PAIR_IMAGES = ("target", "source", "difference", "heat")


class EditRequest(BaseModel):
    action: str
    a: str | None = None
    b: str | None = None
    payload: dict[str, Any] = Field(default_factory=dict)
    base_seq: int
    client: str = ""
    author: str = "expert"
    threshold: float | None = None


class RegisterRequest(BaseModel):
    target_pixels: list[tuple[float, float]]
    source_pixels: list[tuple[float, float]]
    reason: str = ""
    base_seq: int
    client: str = ""
    author: str = "expert"


def _error(status: int, message: str) -> JSONResponse:
    return JSONResponse({"error": message}, status_code=status)


def _threshold(value: str | None, default: float) -> float:
    if value is None or value == "":
        return default
    try:
        tau = float(value)
    except ValueError:
        raise ParameterError(f"threshold must be a number in [0, 1]; got {value!r}") from None
    if not (math.isfinite(tau) and 0.0 <= tau <= 1.0):
        raise ParameterError(f"threshold must be a number in [0, 1]; got {value!r}")
    return tau


def create_app(source: ReviewSource, token: str, hosts: set[str] | None = None) -> FastAPI:
    """The app for ``source``; requests must carry ``token`` and a Host among ``hosts`` (host names)."""
    allowed = {h.lower() for h in (hosts or set())} | {"127.0.0.1", "localhost", "[::1]"}
    app = FastAPI(title="coindie review", docs_url=None, redoc_url=None, openapi_url=None)

    @app.middleware("http")
    async def guard(request: Request, call_next):  # noqa: ANN001, ANN202
        host = request.headers.get("host", "")
        name = host.rsplit(":", 1)[0] if not host.endswith("]") else host
        if name.lower() not in allowed:
            return _error(400, f"refused: Host {host!r} is not this server (DNS rebinding guard)")
        given = (
            request.query_params.get("token")
            or request.headers.get("x-coindie-token")
            or request.cookies.get(TOKEN_COOKIE)
        )
        if not given:
            return _error(403, "refused: no access token (open the URL coindie serve printed, with ?token=)")
        if not hmac.compare_digest(given.encode(), token.encode()):
            return _error(403, "refused: wrong access token (each start of coindie serve makes a new one)")
        response = await call_next(request)
        if request.query_params.get("token"):
            response.set_cookie(TOKEN_COOKIE, token, httponly=True, samesite="strict")
        return response

    @app.exception_handler(KeyError)
    async def not_found(_: Request, error: KeyError) -> JSONResponse:
        return _error(404, str(error.args[0]) if error.args else "not found")

    @app.exception_handler(StarletteHTTPException)
    async def http_error(_: Request, error: StarletteHTTPException) -> JSONResponse:
        message = "no such page or file" if error.status_code == 404 else str(error.detail)
        return _error(error.status_code, message)

    @app.exception_handler(RequestValidationError)
    async def invalid(_: Request, error: RequestValidationError) -> JSONResponse:
        problems = "; ".join(f"{'.'.join(map(str, e['loc']))}: {e['msg']}" for e in error.errors())
        return _error(400, f"bad request: {problems}")

    @app.exception_handler(EditConflict)
    async def conflict(_: Request, error: EditConflict) -> JSONResponse:
        return JSONResponse({"error": str(error), "conflict_with": error.edit_id}, status_code=409)

    @app.exception_handler(CoinDieError)
    async def bad_request(_: Request, error: CoinDieError) -> JSONResponse:
        return _error(400, str(error))

    @app.exception_handler(ValueError)
    async def bad_value(_: Request, error: ValueError) -> JSONResponse:
        return _error(400, str(error))

    def state_of(corrections: Corrections) -> dict[str, Any]:
        corrected = corrected_graph(source.graph, corrections)
        index = {face: k for k, face in enumerate(source.graph.nodes)}
        edges = []
        for a, b, p in corrected.edges():
            key = pair(a, b)
            state = (
                "cut"
                if key in corrections.cut
                else "forced"
                if key in corrections.forced
                else "expert"
                if key in corrections.probability
                else "auto"
            )
            edges.append([index[a], index[b], round(p, 5), state])
        links = None
        if source.cuts:  # the sides' own cuts: the browser cuts their trees' links, not the probabilities
            found = source.links(corrections)
            links = [
                [index[a], index[b], float(v)] for (a, b), v in zip(found.pairs, found.value, strict=True)
            ]
        return {
            "name": source.name,
            "has_images": source.has_images,
            "threshold": source.threshold,
            "method": source.method,
            "how": source.how,
            "links": links,
            "seq": source.log.last_seq(),
            "nodes": [
                {
                    "id": f,
                    "x": source.layout[f][0],
                    "y": source.layout[f][1],
                    "side": source.sides.get(f, "?"),
                }
                for f in source.graph.nodes
            ],
            "edges": edges,
            "verified": [sorted(v) for v in corrections.verified],
            **undo_redo(corrections),
        }

    def undo_redo(corrections: Corrections) -> dict[str, int | None]:
        """The edit an Undo switches off (the latest in effect) and the one a Redo switches on again
        (the latest undone, while nothing newer was done)."""
        log = source.log.edits()
        undo = max(corrections.active, default=None)
        redo = None
        for edit in reversed(log):
            if edit.action == "undo" and int(edit.payload.get("target", 0)) in corrections.undone:
                redo = int(edit.payload["target"])
                break
            if edit.action not in ("undo", "redo"):
                break
        return {"undo_target": undo, "redo_target": redo}

    @app.get("/")
    def index() -> Response:
        return FileResponse(STATIC / "index.html", headers={"Cache-Control": "no-store"})

    @app.get("/static/{name:path}")
    def static(name: str) -> Response:
        path = (STATIC / name).resolve()
        if ".." in Path(name).parts or not path.is_relative_to(STATIC.resolve()) or not path.is_file():
            raise KeyError(f"no static file {name!r}")
        return FileResponse(path)

    @app.get("/api/state")
    def state() -> dict[str, Any]:
        return state_of(source.corrections())

    @app.get("/api/edits")
    def edits(since: str = "0") -> dict[str, Any]:
        if not since.isdigit():
            raise ParameterError(f"since must be a sequence number (0, 1, ...); got {since!r}")
        found = source.log.edits(int(since))
        return {"seq": source.log.last_seq(), "edits": [_edit_json(e) for e in found]}

    @app.post("/api/edits")
    def add_edit(request: EditRequest) -> dict[str, Any]:
        tau = _threshold(None if request.threshold is None else str(request.threshold), source.threshold)
        edit = source.log.append(
            source.graph,
            request.action,
            request.a,
            request.b,
            request.payload,
            base_seq=request.base_seq,
            author=request.author,
            client=request.client,
            threshold=tau,
        )
        return {"edit": _edit_json(edit), "seq": edit.edit_id}

    @app.get("/api/clusters")
    def clusters(threshold: str | None = None, method: str | None = None) -> dict[str, Any]:
        """The clusters the browser shows at slider value ``threshold``; with ``method``, that method's
        clusters of the graph at that threshold (the experts' edits applied)."""
        tau = _threshold(threshold, source.threshold)
        corrections = source.corrections()
        if method is None:
            result = source.clusters(tau, corrections)
        else:
            result = corrected_clusters(source.graph, corrections, tau, method)
        groups = result.clusters()
        return {
            "threshold": tau,
            "method": result.method,
            "seq": source.log.last_seq(),
            "n_clusters": len(groups),
            "n_singletons": sum(len(g) == 1 for g in groups),
            "clusters": [{"members": g, "verified": corrections.is_verified(g)} for g in groups],
        }

    @app.get("/api/faces/{face}")
    def face(face: str, threshold: str | None = None) -> dict[str, Any]:
        key = source.face(face)
        tau = _threshold(threshold, source.threshold)
        corrections = source.corrections()
        labels = source.clusters(tau, corrections).labels
        members = sorted(f for f, lab in labels.items() if lab == labels[key])
        return {
            "face": key,
            "side": source.sides.get(key, "?"),
            "has_image": key in source.scan_paths,
            "cluster": members,
            "verified": corrections.is_verified(members),
            "neighbours": source.neighbours(key, corrections),
        }

    def scan_path(face: str) -> Path:
        key = source.face(face)
        if key not in source.scan_paths:
            raise KeyError(f"{key}: no scan (a bare graph file has no images)")
        return source.scan_paths[key]

    @app.get("/api/faces/{face}/thumbnail.png")
    def thumbnail(face: str) -> Response:
        return Response(images.thumbnail(scan_path(face), unit=source.unit), media_type="image/png")

    @app.get("/api/faces/{face}/relief.png")
    def relief(face: str) -> Response:
        return Response(images.own_image(scan_path(face), unit=source.unit), media_type="image/png")

    @app.get("/api/faces/{face}/relief.json")
    def relief_grid(face: str) -> dict[str, Any]:
        grid, _, _ = images.own_frame(scan_path(face), unit=source.unit)
        return grid.to_dict()

    @app.get("/api/pairs/{a}/{b}")
    def pair_info(a: str, b: str) -> dict[str, Any]:
        record = source.pair_record(a, b)
        settings = HistogramSettings()
        histogram = None if record.histogram is None else np.asarray(record.histogram).tolist()
        if histogram is None and record.valid and record.T_target_source is not None and source.has_images:
            # the run did not measure it (coindie run --histograms): measured now, from the scans
            key = tuple(float(v) for v in np.asarray(record.T_target_source).ravel())
            histogram = list(
                images.pair_histogram(scan_path(record.target), scan_path(record.source), key, source.unit)
            )
        return {
            "target": record.target,
            "source": record.source,
            "probability": record.probability,
            "valid": record.valid,
            "reason": record.reason,
            "method": record.method,
            "origin": record.origin,
            "T_target_source": None if record.T_target_source is None else record.T_target_source.tolist(),
            "histogram": histogram,
            "max_distance_mm": settings.max_distance_mm,
            "has_images": source.has_images,
        }

    def aligned(a: str, b: str) -> images.AlignedPair:
        record = source.pair_record(a, b)
        target, moved = scan_path(record.target), scan_path(record.source)
        if record.T_target_source is None:
            raise KeyError(f"the pair {record.target}-{record.source} has no transform")
        key = tuple(float(v) for v in np.asarray(record.T_target_source).ravel())
        return images.aligned_pair(target, moved, key, 420, source.unit)

    @app.get("/api/pairs/{a}/{b}/{kind}.png")
    def pair_image(a: str, b: str, kind: str) -> Response:
        if kind not in PAIR_IMAGES:
            raise KeyError(f"no pair image {kind!r}: one of {', '.join(PAIR_IMAGES)}")
        return Response(images.pair_image(aligned(a, b), kind), media_type="image/png")

    @app.get("/api/pairs/{a}/{b}/clouds.json")
    def clouds(a: str, b: str) -> dict[str, Any]:
        record = source.pair_record(a, b)
        if record.T_target_source is None:
            raise KeyError(f"the pair {record.target}-{record.source} has no transform")
        return images.clouds(
            scan_path(record.target), scan_path(record.source), record.T_target_source, source.unit
        )

    @app.post("/api/pairs/{a}/{b}/register")
    def register(a: str, b: str, request: RegisterRequest) -> dict[str, Any]:
        target, moved = source.face(a), source.face(b)
        if len(request.target_pixels) != len(request.source_pixels) or len(request.target_pixels) < 3:
            raise ParameterError("pick the same number (>= 3) of corresponding points on both faces")
        target_points = images.picked_points(scan_path(target), request.target_pixels, unit=source.unit)
        source_points = images.picked_points(scan_path(moved), request.source_pixels, unit=source.unit)
        result = register_by_points(
            scan_path(target), scan_path(moved), target_points, source_points, source.unit
        )
        reason = request.reason.strip() or "expert re-registration"
        payload = {
            "source": moved,
            "target": target,
            "origin": "expert",
            "reason": reason,
            "note": result.reason,
            "T_target_source": result.T_target_source.tolist(),
            "probability": result.probability,
            "histogram": result.histogram.tolist(),
            "kabsch_rms_mm": result.kabsch_rms_mm,
            "icp_pairs": result.icp_pairs,
            "target_pixels": request.target_pixels,
            "source_pixels": request.source_pixels,
        }
        edit = source.log.append(
            source.graph,
            "register",
            target,
            moved,
            payload,
            base_seq=request.base_seq,
            author=request.author,
            client=request.client,
            threshold=source.threshold,
        )
        return {
            "edit": _edit_json(edit),
            "seq": edit.edit_id,
            "probability": result.probability,
            "note": result.reason,
        }

    @app.get("/api/queue")
    def queue(threshold: str | None = None, limit: int = 200) -> dict[str, Any]:
        tau = _threshold(threshold, source.threshold)
        corrections = source.corrections()
        items = review_queue(source.graph, source.links(corrections), corrections, tau, limit, source.apart)
        return {"threshold": tau, "items": [item.to_dict() for item in items]}

    @app.get("/api/export/{name}")
    def export_file(name: str, threshold: str | None = None) -> Response:
        if name not in EXPORTS:
            raise KeyError(f"no export {name!r}: one of {', '.join(EXPORTS)}")
        tau = _threshold(threshold, source.threshold)
        corrections = source.corrections()
        text = export(source, corrections, source.clusters(tau, corrections), name)
        return Response(
            text, media_type=EXPORTS[name], headers={"Content-Disposition": f'attachment; filename="{name}"'}
        )

    return app


def _edit_json(edit: Any) -> dict[str, Any]:
    return {
        "edit_id": edit.edit_id,
        "action": edit.action,
        "a": edit.a,
        "b": edit.b,
        "at": edit.at,
        "author": edit.author,
        "payload": dict(edit.payload),
    }


__all__ = ["EditError", "create_app"]
