"""The one parameter mechanism: every configurable class of coindie, found by walking its modules, refuses
values generated outside each declaration with a ParameterError naming the parameter; and no class in the
library validates its parameters by hand beside the mechanism."""

from __future__ import annotations

import ast
import dataclasses
import importlib
import math
import numbers
import pkgutil
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import coindie
from coindie.errors import ParameterError
from coindie.params import Configurable, Param

SRC = Path(coindie.__file__).parent


def configurable_classes() -> list[type[Configurable]]:
    """Every Configurable dataclass defined in a module of coindie, in module order."""
    found: dict[str, type[Configurable]] = {}
    for module_info in pkgutil.walk_packages(coindie.__path__, "coindie."):
        module = importlib.import_module(module_info.name)
        for value in vars(module).values():
            if (
                isinstance(value, type)
                and issubclass(value, Configurable)
                and value.__module__ == module.__name__
                and dataclasses.is_dataclass(value)
            ):
                found[f"{value.__module__}.{value.__qualname__}"] = value
    return list(found.values())


def _examples() -> dict[str, Callable[[], Any]]:
    """A valid instance of each class whose fields are not all defaulted (qualified name -> factory)."""
    from coindie.numismatics.estimators import DieCounts
    from coindie.synth.face import sample_face_spec
    from coindie.synth.presets import get_preset

    return {
        "coindie.numismatics.estimators.DieCounts": lambda: DieCounts((3, 1)),
        "coindie.synth.face.FaceSpec": lambda: sample_face_spec(np.random.default_rng(0), 0.5),
        "coindie.synth.presets.DieGroup": lambda: get_preset("tiny").groups[0],
        "coindie.synth.presets.Preset": lambda: get_preset("tiny"),
    }


CLASSES = configurable_classes()
EXAMPLES = _examples()


def _name(cls: type) -> str:
    return f"{cls.__module__}.{cls.__qualname__}"


def example(cls: type[Configurable]) -> Any:
    """A valid instance: the defaults, or the class's example."""
    return EXAMPLES[_name(cls)]() if _name(cls) in EXAMPLES else cls()


def outside_values(p: Param) -> list[object]:
    """Values the declaration must refuse: just outside each finite bound, NaN, the wrong kind, and for
    tuples a wrong count, a bad item and (for a pair) the ends swapped."""
    if p.kind is tuple:
        return _outside_tuples(p)
    if p.choices is not None:
        return ["no-such-choice", 1]
    if p.kind is bool:
        return ["yes", 1]
    if p.kind is str:  # any text is a string (a path, say): what is refused is another kind
        return [1, float("nan")]
    values: list[object] = ["text", float("nan"), True]
    step = 1 if p.kind is int else 1e-9
    if p.kind is int:
        values.append((p.low if math.isfinite(p.low) else 0) + 1.5)  # not integral
    if math.isfinite(p.low):
        values.append(p.low if p.low_open else p.low - step)
    if math.isfinite(p.high):
        values.append(p.high if p.high_open else p.high + step)
    else:
        values.append(float("inf"))
    return values


def _outside_tuples(p: Param) -> list[object]:
    item = p._item()
    good = _inside_value(item)
    count = p.length if p.length is not None else max(p.min_length, 1)
    values: list[object] = ["text", 1]
    values += [(bad,) * count for bad in outside_values(item)]
    if p.length is not None:
        values.append((good,) * (p.length + 1))
    if p.min_length > 0:
        values.append(())
    if p.ordered and math.isfinite(p.low) and math.isfinite(p.high) and p.low < p.high:
        values.append((p.high, p.low))
    return values


def _inside_value(p: Param) -> object:
    """One value the declaration accepts."""
    if p.choices is not None:
        return p.choices[0]
    if p.kind is bool:
        return False
    if p.kind is str:
        return "x"
    return p.low if math.isfinite(p.low) and not p.low_open else p.high if math.isfinite(p.high) else 1


CASES = [
    (cls, name, value)
    for cls in CLASSES
    for name, declared in cls.declared().items()
    for value in outside_values(declared)
]


def test_the_walk_finds_the_configurable_classes_of_every_layer() -> None:
    names = {_name(cls) for cls in CLASSES}
    for expected in (
        "coindie.registration.teaser.TeaserSolver",
        "coindie.preprocess.config.PreprocessConfig",
        "coindie.similarity.histogram.HistogramSettings",
        "coindie.similarity.classifier.SameDieClassifier",
        "coindie.clustering.algorithms.Leiden",
        "coindie.project.run.RunConfig",
        "coindie.registration.learned.train.TrainOptions",
        "coindie.synth.design.DieParams",
    ):
        assert expected in names
    assert len(CASES) > 500


@pytest.mark.parametrize("cls", CLASSES, ids=_name)
def test_each_class_builds_valid_with_documented_parameters(cls: type[Configurable]) -> None:
    instance = example(cls)
    declared = cls.declared()
    assert declared, "a Configurable declares at least one parameter"
    assert all(p.doc for p in declared.values())
    fields = {f.name for f in dataclasses.fields(cls)}
    for rule in cls.RULES:
        assert set(rule.names) <= fields and rule.requirement
    assert set(instance.values()) == set(declared)


@pytest.mark.parametrize(
    ("cls", "name", "value"), CASES, ids=[f"{c.__qualname__}-{n}-{v!r}" for c, n, v in CASES]
)
def test_every_declared_parameter_refuses_values_outside_its_declaration(
    cls: type[Configurable], name: str, value: object
) -> None:
    owner = re.escape(cls.owner())
    with pytest.raises(ParameterError, match=rf"^The '{name}' parameter of {owner} must be .* Got "):
        dataclasses.replace(example(cls), **{name: value})


def test_rules_name_their_parameters_and_values() -> None:
    from coindie.synth.circulation import CirculationParams

    with pytest.raises(
        ParameterError,
        match=r"The 'wear_min' and 'wear_max' parameters of CirculationParams must satisfy "
        r"wear_min <= wear_max\. Got wear_min=0\.5, wear_max=0\.2\.",
    ):
        CirculationParams(wear_min=0.5, wear_max=0.2)


def test_values_are_converted_to_the_declared_kind_and_numbers_kept_as_given() -> None:
    p = Param(float, 1.0, "x", low=0.0)
    assert p.check("o", "x", np.float32(0.5)) == 0.5 and isinstance(p.check("o", "x", 2), float)
    real = Param(numbers.Real, 1, "x", low=0, high=5)
    assert type(real.check("o", "x", 2)) is int
    pair = Param(tuple, (0, 1), "x", low=0, high=1, item=numbers.Real, length=2, ordered=True)
    assert pair.check("o", "x", [0.2, 0.4]) == [0.2, 0.4]
    assert Param(float, None, "x", optional=True).check("o", "x", None) is None


# ------------------------------------------------------------------------------ no validation by hand


def _raises_parameter_error(node: ast.AST) -> bool:
    for child in ast.walk(node):
        if isinstance(child, ast.Raise) and child.exc is not None:
            target = child.exc.func if isinstance(child.exc, ast.Call) else child.exc
            if isinstance(target, ast.Name) and target.id == "ParameterError":
                return True
    return False


def _hand_validation() -> list[str]:
    """``path:line Class`` for each ``__post_init__`` in src that raises ParameterError itself."""
    found = []
    for path in sorted(SRC.rglob("*.py")):
        if path == SRC / "params.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for cls in (n for n in ast.walk(tree) if isinstance(n, ast.ClassDef)):
            for method in cls.body:
                if isinstance(method, ast.FunctionDef) and method.name == "__post_init__":
                    if _raises_parameter_error(method):
                        found.append(f"{path.relative_to(SRC)}:{method.lineno} {cls.name}")
    return found


def test_no_class_validates_its_parameters_by_hand() -> None:
    assert _hand_validation() == [], "declare the parameters with coindie.params.param (or a Rule)"


def test_the_scan_finds_hand_validation() -> None:
    tree = ast.parse(
        "class A:\n"
        "    def __post_init__(self):\n"
        "        if self.x < 0:\n"
        "            raise ParameterError('x')\n"
    )
    method = tree.body[0].body[0]  # type: ignore[attr-defined]
    assert _raises_parameter_error(method)


@pytest.mark.parametrize("cls", CLASSES, ids=_name)
def test_an_own_post_init_calls_the_mechanism_first(cls: type[Configurable]) -> None:
    """A subclass's ``__post_init__`` that does not call ``super().__post_init__()`` skips the checks."""
    own = cls.__dict__.get("__post_init__")
    if own is None:
        return
    import inspect

    assert "super().__post_init__()" in inspect.getsource(own)


def test_pydantic_is_only_for_the_web_requests() -> None:
    users = [
        str(path.relative_to(SRC))
        for path in SRC.rglob("*.py")
        if re.search(r"^\s*(from|import) pydantic", path.read_text(encoding="utf-8"), re.M)
    ]
    assert all(user.startswith("serve/") for user in users), users
