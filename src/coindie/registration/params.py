"""Declared, validated parameters of the registration parts.

Each part is a frozen keyword-only dataclass whose fields are declared with :func:`param` (kind, default,
range, unit, one line of documentation). The declaration is the single source of truth: it validates at
construction with messages like "The 'noise_bound' parameter of teaser must be a float in the range
(0, inf) mm. Got -1.", parses command-line text, and lists the parameters for ``coindie methods``.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import asdict, dataclass, field, fields
from typing import Any, ClassVar

import numpy as np

from coindie.errors import ParameterError

_KIND_NAMES = {float: "a float", int: "an int", bool: "a bool", str: "a string"}
_TRUE = {"true", "yes", "1", "on"}
_FALSE = {"false", "no", "0", "off"}


@dataclass(frozen=True)
class Param:
    """The declaration of one parameter."""

    kind: type
    default: Any
    doc: str
    unit: str = ""
    low: float = -math.inf
    high: float = math.inf
    low_open: bool = False
    high_open: bool = False
    choices: tuple[str, ...] | None = None

    def describe(self) -> str:
        """The accepted values: "a float in the range (0, inf) mm", "one of 'a', 'b'"."""
        if self.choices is not None:
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.kind in (bool, str):
            return _KIND_NAMES[self.kind]
        left, right = "(" if self.low_open else "[", ")" if self.high_open else "]"
        bounds = f"{left}{_number(self.low)}, {_number(self.high)}{right}".replace("[-inf", "(-inf")
        bounds = bounds.replace("inf]", "inf)")
        unit = f" {self.unit}" if self.unit else ""
        return f"{_KIND_NAMES[self.kind]} in the range {bounds}{unit}"

    def check(self, owner: str, name: str, value: Any) -> Any:
        """The value converted to the declared kind, or a ParameterError naming owner, name and range."""
        converted = self._converted(value)
        if converted is None or not self._in_range(converted):
            raise ParameterError(
                f"The {name!r} parameter of {owner} must be {self.describe()}. Got {value!r}."
            )
        return converted

    def parse(self, owner: str, name: str, text: str) -> Any:
        """A value from command-line text (``"0.5"``, ``"true"``, ``"identity"``), then checked."""
        value: Any = text
        if self.kind is bool:
            value = True if text.lower() in _TRUE else False if text.lower() in _FALSE else text
        elif self.kind in (int, float):
            value = _number_from(text, self.kind)
        return self.check(owner, name, value)

    def _converted(self, value: Any) -> Any:
        """The value as the declared kind (NumPy scalars included), or None when it is of another kind."""
        if self.kind is bool:
            return bool(value) if isinstance(value, bool | np.bool_) else None
        if isinstance(value, bool | np.bool_) or (self.kind is str) != isinstance(value, str):
            return None
        if self.kind is int:
            return int(value) if isinstance(value, numbers.Integral) or _is_integral(value) else None
        if self.kind is float:
            return float(value) if isinstance(value, numbers.Real) and not math.isnan(value) else None
        return value

    def _in_range(self, value: Any) -> bool:
        if self.choices is not None:
            return value in self.choices
        if self.kind not in (int, float):
            return True
        # Infinite bounds are always open: "(0, inf)" refuses inf.
        above = value > self.low if self.low_open or math.isinf(self.low) else value >= self.low
        below = value < self.high if self.high_open or math.isinf(self.high) else value <= self.high
        return above and below


def _number(x: float) -> str:
    return "inf" if x == math.inf else "-inf" if x == -math.inf else f"{x:g}"


def _is_integral(value: Any) -> bool:
    return isinstance(value, numbers.Real) and math.isfinite(value) and float(value).is_integer()


def _number_from(text: str, kind: type) -> Any:
    try:
        return kind(text)
    except ValueError:
        try:
            return float(text)  # "1e3" for an int: accepted if integral, refused by check otherwise
        except ValueError:
            return text


def param(
    default: Any,
    kind: type | None = None,
    *,
    doc: str,
    unit: str = "",
    low: float = -math.inf,
    high: float = math.inf,
    low_open: bool = False,
    high_open: bool = False,
    choices: tuple[str, ...] | None = None,
) -> Any:
    """A dataclass field carrying its :class:`Param` declaration (kind defaults to the default's type)."""
    declared = Param(kind or type(default), default, doc, unit, low, high, low_open, high_open, choices)
    return field(default=default, metadata={"param": declared})


class Configurable:
    """Base of the parts: frozen keyword-only dataclasses whose declared fields are checked on creation.

    Subclasses set ``NAME`` (used in messages and as the parameter prefix, e.g. ``teaser.noise_bound``).
    """

    NAME: ClassVar[str] = "part"

    def __post_init__(self) -> None:
        for f in fields(self):  # type: ignore[arg-type]
            declared = f.metadata.get("param")
            if declared is not None:
                object.__setattr__(self, f.name, declared.check(self.NAME, f.name, getattr(self, f.name)))

    @classmethod
    def declared(cls) -> dict[str, Param]:
        """Name -> declaration of every parameter, in field order."""
        return {f.name: f.metadata["param"] for f in fields(cls) if "param" in f.metadata}  # type: ignore[arg-type]

    def values(self) -> dict[str, Any]:
        """Name -> current value of every declared parameter."""
        return {name: value for name, value in asdict(self).items() if name in self.declared()}  # type: ignore[call-overload]
