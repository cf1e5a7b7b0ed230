"""A field's configuration: the defaults (tracker noise, physics substeps, time limit, ball, the
humanoid's sizes) and one's own table laid over them, checked whole.

:mod:`polymimic.field` re-exports :func:`check_config` and :func:`default_config`.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from typing import Any

from polymimic import _native
from polymimic._tables import Path, merged

__all__ = ["check_config", "default_config", "native_field_config"]


def check_config(config: Mapping[str, Any] | str) -> dict[str, Any]:
    """A field configuration checked whole, with every key it leaves out filled in from
    :func:`default_config`: every key known (nested tables by their dotted name), every value of
    its default's type and in range.

    >>> check_config({"time_limit_s": 30.0})["time_limit_s"]
    30.0
    >>> check_config({"time_limt_s": 30.0})
    Traceback (most recent call last):
    ...
    ValueError: unknown key 'time_limt_s' in the field config; known keys: tracker, substeps_per_frame, ...
    """
    if isinstance(config, str):
        try:
            config = json.loads(config)
        except ValueError as error:
            raise ValueError(f"the field config is not valid JSON: {error}") from error
    if not isinstance(config, Mapping):
        raise TypeError(f"the field config must be a mapping, got {type(config).__name__}")
    full = merged(default_config(), config, unknown=_unknown_key, not_table=_not_a_table, leaf=_number)
    checked: dict[str, Any] = json.loads(_native.check_field_config(json.dumps(full)))
    return checked


def _unknown_key(path: Path, known: Sequence[str]) -> Exception:
    prefix = "".join(f"{k}." for k in path[:-1])
    return ValueError(f"unknown key {'.'.join(path)!r} in the field config; known keys: "
                      f"{', '.join(prefix + k for k in known)}")


def _not_a_table(path: Path, value: Any) -> Exception:
    return TypeError(f"field config {'.'.join(path)!r} must be a table, got {value!r}")


def _number(path: Path, value: Any, default: Any) -> Any:
    """A finite number, an integer where the default is one; as many numbers where the default
    is a list (the humanoid's windows and sizes)."""
    name = ".".join(path)
    if isinstance(default, list):
        if not isinstance(value, (list, tuple)) or len(value) != len(default):
            raise TypeError(f"field config {name!r} must be {len(default)} numbers, like the default {default!r}; "
                            f"got {value!r}")
        return [_number((*path[:-1], f"{path[-1]}[{i}]"), v, d) for i, (v, d) in enumerate(zip(value, default))]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or (
            isinstance(default, int) and not isinstance(value, int)):
        kind = "an integer" if isinstance(default, int) else "a number"
        raise TypeError(f"field config {name!r} must be {kind}, like the default {default!r}; got {value!r}")
    if not math.isfinite(value):
        raise ValueError(f"field config {name!r} must be a finite number, got {value!r}")
    return value


def native_field_config(config: Mapping[str, Any] | str | None) -> str | None:
    """The JSON the native field takes, checked; ``None`` for the default field."""
    return None if config is None else json.dumps(check_config(config))


def default_config() -> dict[str, Any]:
    """The field's configuration (tracker noise, physics substeps, time limit, ball)."""
    config: dict[str, Any] = json.loads(_native.default_field_config())
    return config
