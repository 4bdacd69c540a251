"""Declared, validated parameters: the one parameter mechanism of coindie.

Every configurable class (registration parts, clustering algorithms, histogram, classifier and training
settings, the synthetic hoard's physics, ...) is a dataclass deriving from :class:`Configurable` whose
fields are declared with :func:`param` (kind, default, range, unit, one line of documentation), and whose
constraints between fields are :class:`Rule` s. The declaration is the single source of truth: it validates
at construction with messages in scikit-learn's format ("The 'noise_bound' parameter of teaser must be a
float in the range (0, inf) mm. Got -1."), parses command-line text, and lists the parameters for
``coindie methods``. The tests generate invalid values from every declaration of every class.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Mapping
from dataclasses import MISSING, dataclass, field, fields
from typing import Any, ClassVar

import numpy as np

from coindie.errors import ParameterError

#: ``numbers.Real``: any int or float, kept as given (the synthetic hoard's physics).
_KIND_NAMES = {float: "a float", int: "an int", bool: "a bool", str: "a string", numbers.Real: "a number"}
_NUMBERS = (int, float, numbers.Real)
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
    choices: tuple[Any, ...] | None = None
    #: None is accepted too ("a float in the range (0, inf) mm or None").
    optional: bool = False
    #: For ``kind=tuple``: the kind of every item (each in the range), the item count (exact, or at least).
    item: type | None = None
    length: int | None = None
    min_length: int = 0
    #: For a ``(low, high)`` pair: low <= high.
    ordered: bool = False

    def describe(self) -> str:
        """The accepted values: "a float in the range (0, inf) mm", "one of 'a', 'b'"."""
        text = self._describe_value()
        return f"{text} or None" if self.optional else text

    def _describe_tuple(self) -> str:
        """ "a tuple of at least 1 ints in the range [1, inf)", "a (low, high) pair of numbers in ..." """
        count = f"{self.length}" if self.length is not None else f"at least {self.min_length}"
        if self.choices is not None:
            return f"a tuple of {count} items, each {self._item().describe()}"
        _article, kind, rest = self._item().describe().split(" ", 2)
        what = "a (low, high) pair of" if self.ordered else f"a tuple of {count}"
        return f"{what} {kind}s {rest}" + (" with low <= high" if self.ordered else "")

    def _describe_value(self) -> str:
        if self.kind is tuple:
            return self._describe_tuple()
        if self.choices is not None:
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.kind in (bool, str) or self.kind not in _NUMBERS:
            return _KIND_NAMES.get(self.kind, f"a {self.kind.__name__}")
        left, right = "(" if self.low_open else "[", ")" if self.high_open else "]"
        bounds = f"{left}{_number(self.low)}, {_number(self.high)}{right}".replace("[-inf", "(-inf")
        bounds = bounds.replace("inf]", "inf)")
        unit = f" {self.unit}" if self.unit else ""
        return f"{_KIND_NAMES[self.kind]} in the range {bounds}{unit}"

    def check(self, owner: str, name: str, value: Any) -> Any:
        """The value converted to the declared kind, or a ParameterError naming owner, name and range."""
        if value is None and self.optional:
            return None
        converted = self._converted(value)
        if converted is None or not self._in_range(converted):
            raise ParameterError(
                f"The {name!r} parameter of {owner} must be {self.describe()}. Got {value!r}."
            )
        return converted

    def _item(self) -> Param:
        """The declaration of one item of a tuple parameter."""
        kind = self.item or float
        return Param(
            kind, None, self.doc, self.unit, self.low, self.high, self.low_open, self.high_open, self.choices
        )

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
        if self.kind is tuple:
            return self._converted_items(value)
        if self.kind is bool:
            return bool(value) if isinstance(value, bool | np.bool_) else None
        if isinstance(value, bool | np.bool_) or (self.kind is str) != isinstance(value, str):
            return None
        if self.kind is int:
            return int(value) if isinstance(value, numbers.Integral) or _is_integral(value) else None
        if self.kind is float:
            return float(value) if isinstance(value, numbers.Real) and not math.isnan(value) else None
        if self.kind is numbers.Real:
            return value if isinstance(value, numbers.Real) and not math.isnan(value) else None
        return value if isinstance(value, self.kind) else None

    def _converted_items(self, value: Any) -> Any:
        """A tuple of checked items (of the declared count, a pair in order), or None."""
        if not isinstance(value, tuple | list):
            return None
        count_ok = len(value) == self.length if self.length is not None else len(value) >= self.min_length
        item = self._item()
        items = tuple(item._converted(v) for v in value)
        if not count_ok or any(v is None or not item._in_range(v) for v in items):
            return None
        if self.ordered and items[0] > items[1]:
            return None
        return items if isinstance(value, tuple) else list(items)

    def _in_range(self, value: Any) -> bool:
        if self.kind is tuple:  # its items were checked by _converted_items
            return True
        if self.choices is not None:
            return value in self.choices
        if self.kind not in _NUMBERS:
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
    default: Any = MISSING,
    kind: type | None = None,
    *,
    doc: str,
    unit: str = "",
    low: float = -math.inf,
    high: float = math.inf,
    low_open: bool = False,
    high_open: bool = False,
    choices: tuple[Any, ...] | None = None,
    optional: bool = False,
    item: type | None = None,
    length: int | None = None,
    min_length: int = 0,
    ordered: bool = False,
    default_factory: Callable[[], Any] | None = None,
    metadata: Mapping[str, Any] | None = None,
) -> Any:
    """A dataclass field carrying its :class:`Param` declaration.

    ``kind`` defaults to the default's type; ``default`` may be left out for a required field (then
    ``kind`` is needed) or given by ``default_factory``. ``metadata`` adds entries to the field's own.
    """
    if kind is None:
        kind = type(default_factory() if default_factory is not None else default)
    declared = Param(
        kind, default, doc, unit, low, high, low_open, high_open, choices, optional, item, length,
        min_length, ordered,
    )  # fmt: skip
    extra = {"param": declared} | dict(metadata or {})
    if default_factory is not None:
        return field(default_factory=default_factory, metadata=extra)
    return field(default=default, metadata=extra)


@dataclass(frozen=True)
class Rule:
    """A constraint between declared parameters (``wear_min <= wear_max``), checked after each one's own.

    ``holds`` gets the object; ``requirement`` says in words what must hold.
    """

    names: tuple[str, ...]
    holds: Callable[[Any], bool]
    requirement: str

    def check(self, owner: str, obj: Any) -> None:
        if not self.holds(obj):
            got = ", ".join(f"{name}={getattr(obj, name)!r}" for name in self.names)
            which = " and ".join(repr(name) for name in self.names)
            noun = "parameter" if len(self.names) == 1 else "parameters"
            raise ParameterError(f"The {which} {noun} of {owner} must satisfy {self.requirement}. Got {got}.")


class Configurable:
    """Base of the configurable classes: dataclasses whose declared fields are checked on creation.

    Subclasses may set ``NAME`` (used in messages and, for registration parts, as the parameter prefix,
    e.g. ``teaser.noise_bound``; the class name when not set, ``OWNER`` overrides it in messages) and
    ``RULES`` (constraints between fields).
    A subclass with its own ``__post_init__`` calls ``super().__post_init__()`` first and validates
    nothing by hand.
    """

    NAME: ClassVar[str] = ""
    #: The name in messages when ``NAME`` says something else (a scorer's name, say).
    OWNER: ClassVar[str] = ""
    RULES: ClassVar[tuple[Rule, ...]] = ()

    def __post_init__(self) -> None:
        owner = self.owner()
        for f in fields(self):  # type: ignore[arg-type]
            declared = f.metadata.get("param")
            if declared is not None:
                object.__setattr__(self, f.name, declared.check(owner, f.name, getattr(self, f.name)))
        for rule in self.RULES:
            rule.check(owner, self)

    @classmethod
    def owner(cls) -> str:
        """The name messages give the class: ``OWNER``, else ``NAME``, else the class name."""
        return cls.OWNER or cls.NAME or cls.__name__

    @classmethod
    def declared(cls) -> dict[str, Param]:
        """Name -> declaration of every parameter, in field order."""
        return {f.name: f.metadata["param"] for f in fields(cls) if "param" in f.metadata}  # type: ignore[arg-type]

    def values(self) -> dict[str, Any]:
        """Name -> current value of every declared parameter."""
        return {name: getattr(self, name) for name in self.declared()}
