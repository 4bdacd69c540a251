"""What workers run: the per-face work (once per face) and the scoring of a batch of pairs.

Both are pure functions of their task (file paths and parameters, all picklable) and of files in the
project's cache: they never touch the database, so they run the same in a local process or on a Dask
worker, and the results depend on neither. The scheduler (:mod:`coindie.project.run`) commits what they
return.

Per face (``prepare_face``): the scan file's content hash, the cloud grid-sampled at the finest grid the
pair function needs (the histogram's target grid, 0.05 mm in the paper's text), and the candidate-search
descriptor; saved as one ``.npz`` (float32) named by content hash and parameters.

Per pair (``score_batch``): :func:`coindie.similarity.score_pair` on two cached faces, with the registrar
fed the faces grid-sampled at the paper's 0.1 mm. A worker keeps recently loaded faces (and the
registration's and histogram's per-face work, cached by content in those modules) across the pairs of a
batch: batches are tiles of the pair matrix, so each face is loaded once per batch, not once per pair.
"""

from __future__ import annotations

import hashlib
import json
import os
import time
import traceback
import weakref
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from coindie.errors import CoinDieError
from coindie.scan import Scan

if TYPE_CHECKING:
    from coindie.similarity.histogram import FaceCache

#: Version of the pair function's own code (bump when a change alters results: the pairs are redone).
PAIR_FUNCTION_VERSION = 2
#: Version of the per-face work (bump when a change alters the cache: faces are prepared again).
#: 2: normals whose signs disagree are turned out of the coin on reading; 3: scans in metres or micrometres
#: are read in millimetres; 4: agreeing normals that the wall alone says point into the coin are turned.
FACE_WORK_VERSION = 4


@dataclass(frozen=True)
class FaceTask:
    face_id: str
    path: str
    cache_dir: str
    params_hash: str
    grid_mm: float
    registration_grid_mm: float
    #: The project's declared scan unit (None: told from the face's size). Not part of ``params_hash``:
    #: a project's unit cannot change once a face is read (``Project.declare_unit``).
    unit: str | None = None


@dataclass(frozen=True)
class PairBatch:
    """Pairs to score, ``(source, target)`` face ids; ``files`` maps each face to its cached ``.npz``."""

    pairs: tuple[tuple[str, str], ...]
    files: tuple[tuple[str, str], ...]
    config: str  # JSON: method, method_params, registration_grid_mm, classifier (dict)
    cache_faces: int


def face_params_hash(grid_mm: float, registration_grid_mm: float) -> str:
    """The key of the per-face cache: what the per-face work depends on."""
    from coindie.candidates import DescriptorSettings

    text = json.dumps(
        {
            "version": FACE_WORK_VERSION,
            "grid_mm": grid_mm,
            "registration_grid_mm": registration_grid_mm,
            "descriptor": DescriptorSettings().digest(),
        },
        sort_keys=True,
    )
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def file_hash(path: str | Path) -> str:
    """SHA-256 of a file's bytes (the key of its cached work: a renamed file keeps its cache)."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def prepare_face(task: FaceTask) -> dict[str, Any]:
    """Hash, read, grid-sample and describe one face; write its cache file. A bad scan returns its
    error (one line) instead of raising: a batch never dies because of one file."""
    start = time.perf_counter()
    try:
        return _prepare(task, start)
    except CoinDieError as error:
        return {"face_id": task.face_id, "error": str(error)}
    except Exception as error:  # an unforeseen failure of one file is recorded, not raised
        return {"face_id": task.face_id, "error": f"{task.path}: unexpected {type(error).__name__}: {error}"}


def _prepare(task: FaceTask, start: float) -> dict[str, Any]:
    from coindie.candidates.descriptor import face_descriptor
    from coindie.io import read_scan
    from coindie.preprocess import grid_sample
    from coindie.registration.clouds import MIN_POINTS, with_normals

    content_hash = file_hash(task.path)
    scan = read_scan(task.path, unit=task.unit)
    fine = grid_sample(with_normals(scan), task.grid_mm)
    if fine.n_points < MIN_POINTS:
        raise CoinDieError(f"{task.path}: {fine.n_points} points after grid sampling, too few to register")
    assert fine.normals is not None
    points, normals = fine.points.astype(np.float32), fine.normals.astype(np.float32)
    stored = Scan(points=points.astype(np.float64), normals=normals.astype(np.float64), id=task.face_id)
    descriptor = face_descriptor(grid_sample(stored, task.registration_grid_mm))
    name = f"{content_hash[:2]}/{content_hash}-{task.params_hash}.npz"
    target = Path(task.cache_dir) / name
    target.parent.mkdir(parents=True, exist_ok=True)
    partial = target.with_name(f".{target.stem}.{os.getpid()}.tmp.npz")
    np.savez(partial, points=points, normals=normals, descriptor=descriptor)
    os.replace(partial, target)  # atomic: a killed worker leaves no half-written cache file
    return {
        "face_id": task.face_id,
        "content_hash": content_hash,
        "file": name,
        "n_points": int(fine.n_points),
        "descriptor": descriptor.tobytes(),
        "seconds": time.perf_counter() - start,
    }


def load_descriptor(path: str | Path) -> np.ndarray:
    with np.load(path) as data:
        return np.asarray(data["descriptor"], dtype=np.float32)


# ------------------------------------------------------------------------------------------------- pairs


class SampledRegistrar:
    """A registrar that registers the faces grid-sampled at ``grid_mm`` (the paper registers 0.1 mm
    clouds) while the histogram reads the finer clouds it is given. The transform is the same frame either
    way: grid sampling moves no point. Coarse versions are kept per face object."""

    def __init__(self, inner: Any, grid_mm: float) -> None:
        self.inner = inner
        self.name = inner.name
        self.grid_mm = grid_mm
        self._coarse: weakref.WeakKeyDictionary[Scan, Scan] = weakref.WeakKeyDictionary()

    def register(self, source: Scan, target: Scan, *, T_init: Any = None) -> Any:
        if T_init is None:
            return self.inner.register(self.coarse(source), self.coarse(target))
        return self.inner.register(self.coarse(source), self.coarse(target), T_init=T_init)

    @property
    def refines_from_pose(self) -> bool:
        return bool(getattr(self.inner, "refines_from_pose", False))

    def coarse(self, scan: Scan) -> Scan:
        from coindie.preprocess import grid_sample
        from coindie.registration.clouds import freeze

        if scan not in self._coarse:
            self._coarse[scan] = freeze(grid_sample(scan, self.grid_mm))
        return self._coarse[scan]


class _Worker:
    """Per-process state: the scorer of one configuration and the faces loaded last."""

    def __init__(self) -> None:
        self.config_text = ""
        self.faces: OrderedDict[str, Scan] = OrderedDict()
        self.registrar: SampledRegistrar | None = None
        self.classifier: Any = None
        self.sampled_faces: FaceCache | None = None
        self.histograms = True  # every pair's distance histogram measured (RunConfig.histograms)

    def configure(self, config_text: str, cache_faces: int) -> None:
        if config_text == self.config_text:
            return
        from coindie.caches import LRUCache
        from coindie.registration import get_method
        from coindie.registration.base import CLOUD_CACHE_SIZE
        from coindie.similarity.histogram import FACE_CACHE_SIZE
        from coindie.similarity.scorers import scorer_from_dict

        config = json.loads(config_text)
        # The registrar and the histogram keep a few faces' work (search trees, relief images, sampled
        # clouds) keyed by content; a batch touches up to ``cache_faces`` faces, which must all stay cached
        # for each to be prepared once per batch.
        method = get_method(
            config["method"],
            cloud_cache_size=max(CLOUD_CACHE_SIZE, cache_faces + 2),
            **config["method_params"],
        )
        self.registrar = SampledRegistrar(method, config["registration_grid_mm"])
        self.sampled_faces = LRUCache(max(FACE_CACHE_SIZE, 2 * cache_faces + 4))
        self.classifier = scorer_from_dict(config["classifier"], "the run's classifier")
        # a config that does not say (one written by hand, or before the option) measures them, as before
        self.histograms = bool(config.get("histograms", True))
        self.config_text = config_text
        self.cache_faces = cache_faces

    def face(self, face_id: str, path: str) -> Scan:
        from coindie.registration.clouds import freeze

        # Keyed by the cache file, whose name holds the face's content hash: a process that runs several
        # projects in turn (one worker runs in the caller's process) must not take one hoard's L0001D
        # for another's.
        if path in self.faces:
            self.faces.move_to_end(path)
            return self.faces[path]
        with np.load(path) as data:
            points, normals = data["points"].astype(np.float64), data["normals"].astype(np.float64)
        scan = freeze(Scan(points=points, normals=normals, id=face_id))
        self.faces[path] = scan
        while len(self.faces) > self.cache_faces:
            self.faces.popitem(last=False)
        return scan


_WORKER = _Worker()


def score_batch(batch: PairBatch) -> list[dict[str, Any]]:
    """Score every pair of the batch; a pair that fails returns its reason instead of raising."""
    _WORKER.configure(batch.config, batch.cache_faces)
    files = dict(batch.files)
    return [_score_row(source_id, target_id, files) for source_id, target_id in batch.pairs]


@dataclass(frozen=True)
class RelayBatch:
    """Pairs to register again from a given pose (:mod:`coindie.project.relay`): ``(source, target, via,
    T_target_source as JSON, the pair's probability now)``; ``min_gain`` the log-odds a relay must add to
    its pair to be kept (:data:`coindie.project.relay.MIN_GAIN`); the rest as :class:`PairBatch`."""

    relays: tuple[tuple[str, str, str, str, float], ...]
    files: tuple[tuple[str, str], ...]
    config: str
    cache_faces: int
    min_gain: float


def relay_batch(batch: RelayBatch) -> list[dict[str, Any]]:
    """Score every pair of the batch from its given pose; each row as :func:`score_batch`'s, with ``via``.
    The paper's distance histogram (a fifth of a relay's time), where the run measures histograms, is
    measured only for the relays the project can keep, those that raise their pair's log-odds by more than
    ``min_gain``; the others have none."""
    from coindie.project.relay import log_odds_gain

    _WORKER.configure(batch.config, batch.cache_faces)
    files = dict(batch.files)
    rows = []
    for source_id, target_id, via, T_json, before in batch.relays:

        def kept(probability: float, before: float = before) -> bool:
            return log_odds_gain(before, probability) > batch.min_gain

        T_init = np.asarray(json.loads(T_json))
        rows.append({**_score_row(source_id, target_id, files, T_init, histogram_if=kept), "via": via})
    return rows


def _score_row(
    source_id: str,
    target_id: str,
    files: dict[str, str],
    T_init: np.ndarray | None = None,
    histogram_if: Callable[[float], bool] | None = None,
) -> dict[str, Any]:
    """One pair scored, as a row of the project's ``pairs`` (``histogram`` None where the distance
    histogram was not measured); ``histogram_if``: where the run measures histograms, measured only where
    it holds of the probability."""
    from coindie.similarity import add_histogram, score_pair

    cpu = time.process_time()
    # The paper scorer reads the histogram: measured with the pair whatever ``histogram_if`` says. For the
    # relief scorer it is a fifth of a pair's time, read by nobody but the review app (which measures it
    # when a pair is opened): measured only when the run asks for every pair's (RunConfig.histograms).
    wanted = _WORKER.histograms
    measured = (wanted and histogram_if is None) or _WORKER.classifier.INPUT == "histogram"
    try:
        source = _WORKER.face(source_id, files[source_id])
        target = _WORKER.face(target_id, files[target_id])
        score = score_pair(
            source,
            target,
            _WORKER.registrar,
            _WORKER.classifier.settings,
            _WORKER.classifier,
            _WORKER.sampled_faces,
            T_init=T_init,
            with_histogram=measured,
        )
        if (
            wanted
            and histogram_if is not None
            and not measured
            and score.valid
            and histogram_if(score.probability)
        ):
            score = add_histogram(score, source, target, _WORKER.classifier.settings, _WORKER.sampled_faces)
            measured = True
    except Exception as error:  # one bad pair is recorded with its reason; the batch goes on
        last = traceback.extract_tb(error.__traceback__)[-1] if error.__traceback__ else None
        where = f" ({Path(last.filename).name}:{last.lineno})" if last else ""
        return {
            "source": source_id,
            "target": target_id,
            "status": "failed",
            "reason": f"{type(error).__name__}: {error}{where}",
        }
    return {
        "source": source_id,
        "target": target_id,
        "status": "done",
        "method": score.method,
        "valid": bool(score.valid),
        "reason": score.reason,
        "probability": float(score.probability),
        "residual": float(score.residual) if np.isfinite(score.residual) else None,
        "T_target_source": json.dumps(np.asarray(score.T_target_source).tolist()),
        "histogram": np.asarray(score.histogram, dtype=np.float32).tobytes() if measured else None,
        "features": np.asarray(score.features, dtype=np.float32).tobytes(),
        # wall seconds per stage, and the CPU seconds of the whole pair (face loading included), which do
        # not depend on how loaded the machine is
        "timings": json.dumps({**score.timings, "cpu": time.process_time() - cpu}),
    }
