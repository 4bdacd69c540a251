"""Documented parameters: each field of a parameter class carries its unit, its valid range and a doc line.

One table (the field metadata) both documents the parameters (``describe``) and validates them
(``check_ranges``), in the spirit of scikit-learn's parameter constraints.
"""

from __future__ import annotations

import math
from dataclasses import field, fields
from typing import Any

from coindie.errors import ParameterError


def param(
    default: Any, *, unit: str, lo: float, hi: float, doc: str, pair: bool = False, new: bool = False
) -> Any:
    """A dataclass field with its unit, range [lo, hi] and documentation.

    ``pair=True`` marks a ``(low, high)`` range drawn per coin or per die: both ends must lie in [lo, hi]
    and low <= high. ``new=True`` marks an axis added after hoards were first made: its default is today's
    behaviour and it is left out of the hoard's records while it holds it (see ``writer.to_jsonable``).
    """
    metadata = {"unit": unit, "range": (lo, hi), "doc": doc, "pair": pair, "omit_default": new}
    return field(default=default, metadata=metadata)


def new_field(default: Any) -> Any:
    """A field of a drawn spec added with the wide world's axes, left out of records at its default."""
    return field(default=default, metadata={"omit_default": True})


def check_ranges(obj: Any) -> None:
    """Raise ParameterError naming the first field of ``obj`` outside its documented range."""
    for f in fields(obj):
        if "range" not in f.metadata:
            continue
        value = getattr(obj, f.name)
        problem = _range_problem(value, f.metadata["range"], f.metadata["pair"])
        if problem is not None:
            lo, hi = f.metadata["range"]
            kind = "a (low, high) pair of numbers" if f.metadata["pair"] else "a number"
            raise ParameterError(
                f"The '{f.name}' parameter of {type(obj).__name__} must be {kind} in the range "
                f"[{lo}, {hi}] ({f.metadata['unit']}){problem}. Got {value!r}."
            )


def _range_problem(value: Any, bounds: tuple[float, float], pair: bool) -> str | None:
    values = value if pair else (value,)
    if pair and (not isinstance(value, tuple | list) or len(value) != 2):
        return ""
    for v in values:
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
            return ""
        if not bounds[0] <= v <= bounds[1]:
            return ""
    if pair and values[0] > values[1]:
        return " with low <= high"
    return None


def describe(cls: type) -> list[dict[str, Any]]:
    """The documentation table of a parameter class: one row per field (name, default, unit, range, doc)."""
    rows = []
    for f in fields(cls):
        if "range" in f.metadata:
            rows.append(
                {
                    "name": f.name,
                    "default": f.default,
                    "unit": f.metadata["unit"],
                    "range": f.metadata["range"],
                    "doc": f.metadata["doc"],
                }
            )
    return rows
