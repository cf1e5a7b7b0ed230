"""A table of given values merged over its defaults, in one place: the field's config
(:func:`polymimic.field.check_config`) and a run config's ``[field]`` section both go through
:func:`merged`, each with its own wording of the errors.

A key is named by its path from the top table, e.g. ``("tracker", "sigma_mm")``; a nested
table of the defaults is merged key by key, so a value left out keeps its default.

>>> defaults = {"time_limit_s": 30.0, "tracker": {"sigma_mm": 1.0, "lag_frames": 2}}
>>> def unknown(path, known):
...     return ValueError(f"unknown key {'.'.join(path)}; known: {', '.join(known)}")
>>> def not_table(path, value):
...     return TypeError(f"{'.'.join(path)} must be a table")
>>> def leaf(path, value, default):
...     return float(value) if isinstance(default, float) else value
>>> merged(defaults, {"tracker": {"sigma_mm": 2}}, unknown=unknown, not_table=not_table, leaf=leaf)
{'time_limit_s': 30.0, 'tracker': {'sigma_mm': 2.0, 'lag_frames': 2}}
>>> merged(defaults, {"tracker": {"sigma": 2}}, unknown=unknown, not_table=not_table, leaf=leaf)
Traceback (most recent call last):
...
ValueError: unknown key tracker.sigma; known: sigma_mm, lag_frames
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

__all__ = ["Path", "merged"]

Path = tuple[str, ...]
"""Where a key stands: the keys from the top table down to it."""


def merged(defaults: Mapping[str, Any], values: Mapping[str, Any], *,
           unknown: Callable[[Path, Sequence[str]], Exception],
           not_table: Callable[[Path, Any], Exception],
           leaf: Callable[[Path, Any, Any], Any],
           path: Path = ()) -> dict[str, Any]:
    """``defaults`` with ``values`` over them, nested tables merged key by key.

    Parameters
    ----------
    defaults, values
        The defaults and the given values; ``values`` may leave out any key.
    unknown
        ``unknown(path, known)``: the error for a key the defaults do not have; ``known`` are
        the keys of its table.
    not_table
        ``not_table(path, value)``: the error for a value that is not a table where the
        default is one.
    leaf
        ``leaf(path, value, default)``: checks any other value against its default and
        returns what to keep, or raises.
    path
        Where ``defaults`` stands (empty for the top table).
    """
    out = dict(defaults)
    for key, value in values.items():
        where = (*path, key)
        if key not in defaults:
            raise unknown(where, list(defaults))
        default = defaults[key]
        if isinstance(default, Mapping):
            if not isinstance(value, Mapping):
                raise not_table(where, value)
            out[key] = merged(default, value, unknown=unknown, not_table=not_table, leaf=leaf, path=where)
        else:
            out[key] = leaf(where, value, default)
    return out
