"""coindie: find which ancient coins were struck by the same die, from 3D scans.

Units are millimetres everywhere. Transforms are 4x4 homogeneous matrices named after the frames
they map between: ``T_target_source`` maps points of the source frame into the target frame.
"""

from coindie.errors import CoinDieError, InvalidScanError, ParameterError, ScanReadError
from coindie.ids import Face, FaceId, parse_face_id
from coindie.scan import Scan

__version__ = "0.1.0"

__all__ = [
    "CoinDieError",
    "Face",
    "FaceId",
    "InvalidScanError",
    "ParameterError",
    "Scan",
    "ScanReadError",
    "__version__",
    "parse_face_id",
]
