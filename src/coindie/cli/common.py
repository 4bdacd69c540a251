"""What every command module of the CLI shares: the clean exit on coindie's own errors, which also names the
command-line flag of each library parameter an error message names."""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import wraps
from typing import Annotated, ParamSpec, TypeVar, get_type_hints

import typer
from typer.models import ArgumentInfo, ParameterInfo

from coindie.errors import CoinDieError

P = ParamSpec("P")
R = TypeVar("R")

#: Where a long job's tasks run instead of local worker processes (coindie.project.backends).
Dask = Annotated[
    str | None,
    typer.Option(help="Dask scheduler address (tcp://host:8786), or 'local' for a LocalCluster."),
]

#: The unit scan files are written in (coindie.io.units); none: millimetres, or metres or micrometres where
#: a face's size says so.
Unit = Annotated[
    str | None,
    typer.Option(
        help="Unit the scans are written in: mm, cm, m, um or in (default: mm, or m or um where a face's "
        "size says so)."
    ),
]

#: A registration method's parameters, each as key=value (coindie.registration.MethodInfo.parse checks them).
MethodParams = Annotated[
    list[str] | None,
    typer.Option(
        "--param",
        "-p",
        help="A parameter of the registration method as key=value (repeatable; see coindie methods), e.g. "
        "relief.angle_step=4.",
    ),
]


def method_params(method: str, items: list[str] | None) -> dict[str, object]:
    """``--param key=value`` items as the method's full parameter names and parsed values; a
    ``ParameterError`` names an item not written key=value, an unknown key or a bad value."""
    from coindie.registration import method_info

    def written(item: str) -> str:
        return f"--param must be written key=value (e.g. relief.angle_step=4). Got {item!r}."

    return method_info(method).parse_items(items or [], written)


#: Library parameters set by a flag of another name: parameter -> the option's Python name in the command.
FLAG_OF_PARAMETER = {"k": "candidates", "coin_diameter_mm": "coin_diameter"}

# Where the library names a parameter: "The 'k' parameter of RunConfig must be ...", "'workers' must be ...".
_NAMED_PARAMETER = re.compile(r"'(?P<name>[a-z_][a-z0-9_]*)'(?P<rest> parameter\b| must\b)")


def exits_cleanly(command: Callable[P, R]) -> Callable[P, R]:
    """Turn a ``CoinDieError`` into a one-line message on stderr and exit code 2."""

    @wraps(command)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        try:
            return command(*args, **kwargs)
        except CoinDieError as error:
            typer.echo(f"coindie: error: {with_flags(str(error), command_flags(command))}", err=True)
            raise typer.Exit(code=2) from None

    return wrapper


def with_flags(message: str, flags: dict[str, str]) -> str:
    """``message`` with the flag that sets each parameter it names after the name: "The 'k' parameter
    (--candidates) of RunConfig must be ...". ``flags`` maps an option's Python name to its flag."""

    def named(match: re.Match[str]) -> str:
        name = match["name"]
        flag = flags.get(FLAG_OF_PARAMETER.get(name, name))
        if flag is None:
            return match[0]
        if match["rest"] == " parameter":
            return f"'{name}' parameter ({flag})"
        return f"'{name}' ({flag}){match['rest']}"

    return _NAMED_PARAMETER.sub(named, message)


def command_flags(command: Callable[..., object]) -> dict[str, str]:
    """A command function's options: Python name -> its long flag (``--max-faces``, or the one declared)."""
    try:
        hints = get_type_hints(command, include_extras=True)
    except NameError:  # an annotation named only for type checkers: no flags, the message stays
        return {}
    flags = {}
    for name, hint in hints.items():
        declared = next((m for m in getattr(hint, "__metadata__", ()) if isinstance(m, ParameterInfo)), None)
        if isinstance(declared, ArgumentInfo):
            continue
        decls = getattr(declared, "param_decls", None) or ()
        flags[name] = next((d for d in decls if d.startswith("--")), "--" + name.replace("_", "-"))
    flags.pop("return", None)
    return flags
