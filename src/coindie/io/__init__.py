"""Scans in and out: PLY/STL/OBJ readers, the Riedones3D PLY writer, die-label CSVs, folders of scans.

``read_scan`` checks the file (exists, is a file, not empty, not over ``max_bytes``) before reading a
byte of it, and every problem is a typed error (``ScanReadError``/``InvalidScanError``, ``LabelsError``)
whose message starts with the file's path. trimesh (slow to import) is loaded only when a mesh is read.
"""

from coindie.io.dataset import ScanFailure, ScanFolder, open_dataset
from coindie.io.labels import Labels, read_labels, write_labels
from coindie.io.ply import read_ply, write_ply
from coindie.io.reader import MAX_SCAN_BYTES, SCAN_SUFFIXES, read_scan

__all__ = [
    "MAX_SCAN_BYTES",
    "SCAN_SUFFIXES",
    "Labels",
    "ScanFailure",
    "ScanFolder",
    "open_dataset",
    "read_labels",
    "read_ply",
    "read_scan",
    "write_labels",
    "write_ply",
]
