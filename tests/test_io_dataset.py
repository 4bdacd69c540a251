"""Folders of scans: listed without reading, labels picked up, bad files recorded instead of raised."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from coindie.errors import ScanReadError
from coindie.ids import parse_face_id
from coindie.io import Labels, ScanFailure, open_dataset, write_labels, write_ply
from coindie.scan import Scan


def small_scan(seed: int, n: int = 30) -> Scan:
    rng = np.random.default_rng(seed)
    return Scan(rng.normal(size=(n, 3)), normals=rng.normal(size=(n, 3)))


def good_folder(folder: Path) -> Path:
    """Three good scans (two PLY, one STL) and a labels.csv, plus a file of another kind."""
    write_ply(folder / "L0002R.ply", small_scan(2, n=20))
    write_ply(folder / "L0001D.ply", small_scan(1, n=10))
    trimesh.creation.icosphere(subdivisions=1).export(folder / "L0003D.STL")
    write_labels(folder / "labels.csv", {"L1D": "a", "L3D": "a", "L2R": "b"})
    (folder / "notes.txt").write_text("not a scan")
    return folder


def test_lists_scans_sorted_without_reading_them(tmp_path):
    folder = good_folder(tmp_path)
    (tmp_path / "L0009D.ply").write_bytes(b"garbage")  # listed: it is only read on demand

    dataset = open_dataset(folder)

    names = ["L0001D.ply", "L0002R.ply", "L0003D.STL", "L0009D.ply"]
    assert [path.name for path in dataset.paths] == names
    assert dataset.ids == [parse_face_id(Path(name).stem) for name in names]
    assert len(dataset) == 4 and dataset.failures == []


def test_uses_the_folders_labels_and_reads_by_id(tmp_path):
    dataset = open_dataset(good_folder(tmp_path))
    assert dataset.labels == Labels({"L0001D": "a", "L0003D": "a", "L0002R": "b"})
    scan = dataset.read("L01D")
    assert scan.id == parse_face_id("L0001D") and scan.n_points == 10
    assert dataset.read(parse_face_id("L0002R")).n_points == 20
    with pytest.raises(ScanReadError, match="no scan of face L0004D in this folder"):
        dataset.read("L4D")


def test_labels_given_explicitly_override_the_folders(tmp_path):
    folder = good_folder(tmp_path)
    other = write_labels(tmp_path / "other.csv", {"L1D": "z"})
    assert dict(open_dataset(folder, other).labels) == {parse_face_id("L1D"): "z"}
    assert open_dataset(folder, {"L2R": "q"}).labels["L0002R"] == "q"
    (folder / "labels.csv").unlink()
    assert open_dataset(folder).labels is None


def test_load_all_reads_every_good_scan(tmp_path):
    scans, failures = open_dataset(good_folder(tmp_path)).load_all()
    assert [scan.id.key for scan in scans] == ["L0001D", "L0002R", "L0003D"]
    assert [scan.n_points for scan in scans[:2]] == [10, 20]
    assert failures == []


def test_not_recursive_unless_asked(tmp_path):
    good_folder(tmp_path)
    (tmp_path / "more").mkdir()
    write_ply(tmp_path / "more" / "L0005D.ply", small_scan(5))
    assert parse_face_id("L5D") not in open_dataset(tmp_path).ids
    assert parse_face_id("L5D") in open_dataset(tmp_path, recursive=True).ids


def test_two_files_of_one_face_make_a_failure_for_the_second(tmp_path):
    write_ply(tmp_path / "L0082D.ply", small_scan(1, n=11))
    write_ply(tmp_path / "L082D.ply", small_scan(2, n=12))

    dataset = open_dataset(tmp_path)
    scans, failures = dataset.load_all()

    assert [path.name for path in dataset.paths] == ["L0082D.ply"]
    assert [scan.n_points for scan in scans] == [11]
    assert [failure.path.name for failure in failures] == ["L082D.ply"]
    assert "same face (L0082D) as L0082D.ply" in failures[0].problem


def test_a_folder_with_bad_files_loads_the_good_ones_and_lists_the_bad(tmp_path):
    good_folder(tmp_path)
    (tmp_path / "L0010D.ply").symlink_to(tmp_path / "gone.ply")  # broken link
    (tmp_path / "L0011D.ply").mkdir()  # a directory named like a scan
    (tmp_path / "L0012D.ply").write_bytes(b"\x00\xffnot a ply at all")
    (tmp_path / "L0013D.obj").write_text("this is no mesh\n")
    (tmp_path / "L0014D.ply").touch()
    truncated = write_ply(tmp_path / "L0015D.ply", small_scan(15)).read_bytes()
    (tmp_path / "L0015D.ply").write_bytes(truncated[:-40])

    dataset = open_dataset(tmp_path)
    scans, failures = dataset.load_all()

    assert [scan.id.key for scan in scans] == ["L0001D", "L0002R", "L0003D"]
    problems = {failure.path.name: failure.problem for failure in failures}
    assert sorted(problems) == [f"L00{i}D.{'obj' if i == 13 else 'ply'}" for i in range(10, 16)]
    assert problems["L0010D.ply"].startswith("broken symbolic link")
    assert problems["L0011D.ply"] == "is a directory, not a scan file"
    assert problems["L0012D.ply"].startswith("not a PLY file")
    assert problems["L0014D.ply"] == "empty file (0 bytes)"
    assert problems["L0015D.ply"].startswith("truncated file")
    assert all(str(failure).startswith(str(failure.path)) for failure in failures)


def test_iterating_twice_does_not_repeat_failures(tmp_path):
    good_folder(tmp_path)
    (tmp_path / "L0012D.ply").write_bytes(b"garbage")
    dataset = open_dataset(tmp_path)
    assert len(list(dataset.iter_scans())) == 3
    assert len(list(dataset.iter_scans())) == 3
    assert dataset.failures == [ScanFailure(tmp_path / "L0012D.ply", dataset.failures[0].problem)]


def test_missing_folder_or_file_instead_of_folder(tmp_path):
    with pytest.raises(ScanReadError, match="no such folder"):
        open_dataset(tmp_path / "absent")
    (tmp_path / "file").touch()
    with pytest.raises(ScanReadError, match="not a folder"):
        open_dataset(tmp_path / "file")
