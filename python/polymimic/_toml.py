"""TOML in and out, in one place: every config of polymimic is read and written here.

Reading goes through the standard library's ``tomllib`` (``tomli`` before Python 3.11);
writing knows the plain tables of ``key = value`` lines the configs use, each value written so
that it reads back exactly (a float's ``repr`` is valid TOML).

>>> lines = []
>>> write_table(lines, "learning", {"lp_bounds": "soft", "decay_step": 0.007}, {"decay_step": "per step"})
>>> print("\\n".join(lines))
[learning]
lp_bounds = "soft"
decay_step = 0.007                       # per step
<BLANKLINE>
>>> loads("\\n".join(lines))
{'learning': {'lp_bounds': 'soft', 'decay_step': 0.007}}
"""

from __future__ import annotations

import dataclasses
import json
import sys
from collections.abc import Mapping
from typing import Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - exercised on Python 3.9 and 3.10 only
    import tomli as tomllib

__all__ = ["documented", "dumps", "loads", "write_table", "write_value"]


def loads(text: str) -> dict[str, Any]:
    """The tables of a TOML text; ``ValueError`` naming the line where it is not TOML."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"not valid TOML: {error}") from error


def dumps(values: Mapping[str, Any]) -> str:
    """One ``key = value`` line per value: a TOML document of plain values, no tables."""
    return "".join(f"{key} = {write_value(value)}\n" for key, value in values.items())


def documented(text: str, default: Any) -> Any:
    """A dataclass field of a config's section with its ``default`` and the doc ``text`` that
    :func:`write_table` writes beside its value (``field.metadata["doc"]``)."""
    return dataclasses.field(default=default, metadata={"doc": text})


def write_table(lines: list[str], name: str, values: Mapping[str, Any], docs: Mapping[str, str]) -> None:
    """Append ``[name]`` and one ``key = value`` line per value (its doc beside it), then its
    nested tables as ``[name.key]``."""
    lines.append(f"[{name}]")
    nested = {k: v for k, v in values.items() if isinstance(v, Mapping)}
    for key, value in values.items():
        if key not in nested:
            line = f"{key} = {write_value(value)}"
            lines.append(f"{line:<40} # {docs[key]}" if docs.get(key) else line)
    lines.append("")
    for key, value in nested.items():
        write_table(lines, f"{name}.{key}", value, {})


def write_value(value: Any) -> str:
    """One value as TOML that reads back equal."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(write_value(v) for v in value) + "]"
    raise TypeError(f"cannot write {value!r} as TOML")
