"""Die-label CSVs: both headers, round trips, the experts' real files, and every malformed case."""

from __future__ import annotations

from pathlib import Path

import pytest

from coindie.errors import LabelsError, ParameterError
from coindie.ids import parse_face_id
from coindie.io import Labels, read_labels, write_labels
from real_data import RIEDONES3D


def write_text(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_round_trip_writes_canonical_sorted_ids(tmp_path):
    labels = {"L0145R": "die 3", "L082D": "7", "L0001D": "7", "free-scan": "0"}
    path = write_labels(tmp_path / "labels.csv", labels)

    lines = path.read_text().splitlines()
    read = read_labels(path)

    assert lines[0] == "coin_id,die_id"
    assert lines[1:] == ["L0001D,7", "L0082D,7", "L0145R,die 3", "free-scan,0"]
    assert dict(read) == {parse_face_id(key): die for key, die in labels.items()}
    assert read.path == path


def test_experts_header_is_read_and_written(tmp_path):
    path = write_text(tmp_path / "experts.csv", "name, die\nL082D, 0\nL083D,1\nL084D,1\n")
    labels = read_labels(path)
    assert labels["L0082D"] == "0" and labels["L084D"] == "1"
    assert labels.dies() == {
        "0": [parse_face_id("L82D")],
        "1": [parse_face_id("L83D"), parse_face_id("L84D")],
    }

    again = write_labels(tmp_path / "again.csv", labels, header=("name", " die"))
    assert again.read_text().splitlines()[0] == "name, die"
    assert read_labels(again) == labels


def test_extra_columns_and_blank_lines_are_ignored(tmp_path):
    path = write_text(tmp_path / "l.csv", "\ufeffnote,die_id,coin_id\n\nx,4,L0002R\n,5,L0003R\n\n")
    assert dict(read_labels(path)) == {parse_face_id("L2R"): "4", parse_face_id("L3R"): "5"}


def test_same_die_twice_is_fine_but_two_dies_are_refused(tmp_path):
    fine = write_text(tmp_path / "fine.csv", "coin_id,die_id\nL082D,3\nL0082D,3\n")
    assert len(read_labels(fine)) == 1

    clash = write_text(tmp_path / "clash.csv", "coin_id,die_id\nL082D,3\nL1D,1\nL0082D,4\n")
    with pytest.raises(LabelsError) as error:
        read_labels(clash)
    message = str(error.value)
    assert message.startswith(str(clash))
    assert "L082D on line 2" in message and "L0082D on line 4" in message and "'3'" in message


@pytest.mark.parametrize(
    "text, problem",
    [
        ("", "empty file"),
        ("\n\n", "empty file"),
        ("coin_id,die_id\n", "no labels"),
        ("L082D,0\nL083D,1\n", "no header"),
        ("coin,die_number\nL082D,0\n", "unknown header"),
        ("coin_id,die_id\nL082D\n", "line 2: expected at least 2 columns"),
        ("coin_id,die_id\nL082D,\n", "line 2: empty die id"),
        ("coin_id,die_id\n,3\n", "line 2: empty face id"),
    ],
)
def test_malformed_files_raise_labels_error_naming_the_file(tmp_path, text, problem):
    path = write_text(tmp_path / "labels.csv", text)
    with pytest.raises(LabelsError, match=problem) as error:
        read_labels(path)
    assert str(error.value).startswith(f"{path}: ")
    assert "\n" not in str(error.value)


def test_missing_directory_and_binary_files(tmp_path):
    for path, problem in [
        (tmp_path / "absent.csv", "no such file"),
        (tmp_path, "is a directory"),
        (tmp_path / "blob.csv", "not a UTF-8 text file"),
    ]:
        if path.name == "blob.csv":
            path.write_bytes(b"\xff\xfe\x00\x81garbage")
        with pytest.raises(LabelsError, match=problem):
            read_labels(path)


def test_labels_mapping_behaviour():
    labels = Labels({"L082D": "1", parse_face_id("L0083D"): "1", "L0001R": "2"})
    assert len(labels) == 3 and labels.n_dies == 2
    assert "L0082D" in labels and parse_face_id("L83D") in labels
    assert "L0099D" not in labels and "" not in labels and 5 not in labels
    with pytest.raises(KeyError):
        labels["L0099D"]
    with pytest.raises(LabelsError, match="same face with different dies"):
        Labels({"L082D": "1", "L0082D": "2"})


def test_write_labels_refuses_an_unreadable_header(tmp_path):
    with pytest.raises(ParameterError, match="header"):
        write_labels(tmp_path / "l.csv", {"L1D": "0"}, header=("id", "cluster"))


@pytest.mark.parametrize(
    "name, rows, dies, largest, singles, first",
    [
        ("experts_obverse_dies.csv", 887, 74, 97, 23, "L0082D"),
        ("experts_reverse_dies.csv", 1102, 213, 35, 99, "L0001R"),
    ],
)
def test_the_experts_files_load_with_the_published_counts(name, rows, dies, largest, singles, first):
    path = RIEDONES3D / name
    if not path.exists():
        pytest.skip(f"the Riedones3D experts' file is not here: {path}")
    labels = read_labels(path)
    sizes = [len(faces) for faces in labels.dies().values()]
    assert (len(labels), labels.n_dies) == (rows, dies)
    assert (max(sizes), sizes.count(1)) == (largest, singles)
    assert first in labels  # the file writes it with 3 digits
    # every coin id is of the file's face ("L1084d" included); the obverse file also has one free id,
    # "L773R et D", kept as written
    assert {face_id.face for face_id in labels if face_id.coin is not None} == {parse_face_id(first).face}
