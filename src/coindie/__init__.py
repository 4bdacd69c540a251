"""coindie: find which ancient coins were struck by the same die, from 3D scans.

Units are millimetres everywhere. Transforms are 4x4 homogeneous matrices named after the frames
they map between: ``T_target_source`` maps points of the source frame into the target frame.
"""

import os

# coindie parallelises over processes (one pair or one scan each); BLAS thread pools inside each process
# only fight over the cores and make small (N, 3) @ (3, 3) products ~50x slower under load. Set before
# numpy is first imported; an explicit setting in the environment wins.
for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")

from coindie.errors import CoinDieError, InvalidScanError, ParameterError, ScanReadError  # noqa: E402
from coindie.ids import Face, FaceId, parse_face_id  # noqa: E402
from coindie.scan import Scan  # noqa: E402

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
