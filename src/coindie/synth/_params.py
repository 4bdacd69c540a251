"""The synthetic hoard's physics parameters, declared through :mod:`coindie.params`.

Each field of a physics class (a :class:`~coindie.params.Configurable`) carries its unit, its valid range
and a doc line: one table both documents the parameters (``describe``) and validates them. A physics
parameter is any number (an int or a float, kept as given) or a ``(low, high)`` range of numbers.
"""

from __future__ import annotations

import numbers
from dataclasses import field, fields
from typing import Any

from coindie.params import param as declared_param


def param(
    default: Any, *, unit: str, lo: float, hi: float, doc: str, pair: bool = False, new: bool = False
) -> Any:
    """A dataclass field with its unit, range [lo, hi] and documentation.

    ``pair=True`` marks a ``(low, high)`` range drawn per coin or per die: both ends must lie in [lo, hi]
    and low <= high. ``new=True`` marks an axis added after hoards were first made: its default is today's
    behaviour and it is left out of the hoard's records while it holds it (see ``writer.to_jsonable``).
    """
    kind = dict(kind=tuple, item=numbers.Real, length=2, ordered=True) if pair else dict(kind=numbers.Real)
    return declared_param(
        default, doc=doc, unit=unit, low=lo, high=hi, metadata={"omit_default": new}, **kind
    )


def new_field(default: Any) -> Any:
    """A field of a drawn spec added with the wide world's axes, left out of records at its default."""
    return field(default=default, metadata={"omit_default": True})


def describe(cls: type) -> list[dict[str, Any]]:
    """The documentation table of a parameter class: one row per field (name, default, unit, range, doc)."""
    rows = []
    for f in fields(cls):
        declared = f.metadata.get("param")
        if declared is not None:
            rows.append(
                {
                    "name": f.name,
                    "default": f.default,
                    "unit": declared.unit,
                    "range": (declared.low, declared.high),
                    "doc": declared.doc,
                }
            )
    return rows
