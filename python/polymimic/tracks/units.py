"""A tracker log's columns and units: polymimic's names for them, the defaults, the conversions."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from polymimic.tracks.errors import TrackLogError

__all__ = ["OPTIONAL", "QUANTITY", "REQUIRED", "UNITS", "Units", "checked_columns", "checked_units", "default_name",
           "factor", "no_such_column", "unit_hint"]

REQUIRED = ("t", "robot_x", "robot_y", "robot_theta", "ball_x", "ball_y")
"""The columns every log needs: time, the robot's pose and the ball's position."""
OPTIONAL = ("episode", "outcome", "command", "configuration")
"""Columns a log may have: the episode id, its outcome, the command sent, its field configuration."""
QUANTITY = {"t": "time", "robot_x": "length", "robot_y": "length", "robot_theta": "angle",
            "ball_x": "length", "ball_y": "length"}

UNITS: dict[str, dict[str, float]] = {
    "length": {"mm": 1.0, "cm": 10.0, "m": 1000.0},
    "angle": {"rad": 1.0, "deg": math.pi / 180.0},
    "time": {"s": 1.0, "ms": 1e-3},
}
"""Each quantity's unit names and what one of them is in polymimic's own (mm, rad, s)."""
DEFAULT_UNITS = {"length": "mm", "angle": "rad", "time": "s"}

Units = dict[str, str]


def checked_units(units: Mapping[str, str] | None) -> Units:
    """``units`` with the defaults filled in; a ``ValueError`` for a quantity or unit not known.

    >>> checked_units({"length": "m"})
    {'length': 'm', 'angle': 'rad', 'time': 's'}
    >>> checked_units({"length": "inch"})
    Traceback (most recent call last):
    ...
    ValueError: units['length'] is 'inch'; expected one of mm, cm, m
    """
    if units is None:
        return dict(DEFAULT_UNITS)
    if not isinstance(units, Mapping):
        raise TypeError(f"units must be a mapping like {{'length': 'm', 'angle': 'deg'}}, got {type(units).__name__}")
    for quantity, unit in units.items():
        if quantity not in UNITS:
            raise ValueError(f"units has quantity {quantity!r}; expected some of {', '.join(UNITS)}")
        if unit not in UNITS[quantity]:
            raise ValueError(f"units[{quantity!r}] is {unit!r}; expected one of {', '.join(UNITS[quantity])}")
    return {**DEFAULT_UNITS, **units}


def factor(name: str, units: Units) -> float:
    """What one of the log's units of column ``name`` is in polymimic's (mm, rad or s)."""
    quantity = QUANTITY[name]
    return UNITS[quantity][units[quantity]]


def default_name(name: str, units: Units) -> str:
    """The column name polymimic gives ``name`` in a log of ``units``: its unit as a suffix
    (``t_s``, ``robot_x_m``, ``robot_theta_deg``); the bare name for the optional columns.

    >>> default_name("robot_theta", {"length": "mm", "angle": "deg", "time": "s"})
    'robot_theta_deg'
    """
    return f"{name}_{units[QUANTITY[name]]}" if name in QUANTITY else name


def checked_columns(columns: Mapping[str, str] | None) -> dict[str, str]:
    """``columns`` (polymimic's name → the file's), checked: known names, distinct file names."""
    if columns is None:
        return {}
    if not isinstance(columns, Mapping):
        raise TypeError(f"columns must map polymimic's names to the file's, got {type(columns).__name__}")
    known = REQUIRED + OPTIONAL
    for name, file_name in columns.items():
        if name not in known:
            raise ValueError(f"columns has {name!r}, which is none of polymimic's names; expected some of "
                             f"{', '.join(known)}")
        if not isinstance(file_name, str) or not file_name:
            raise TypeError(f"columns[{name!r}] must be a column name (a non-empty str), got {file_name!r}")
    taken: dict[str, Any] = {}
    for name, file_name in columns.items():
        if file_name in taken:
            raise ValueError(f"columns maps both {taken[file_name]!r} and {name!r} to {file_name!r}")
        taken[file_name] = name
    return dict(columns)


def unit_hint(quantity: str, unit: str) -> str:
    """The ``units=`` argument that says ``quantity`` is in ``unit``."""
    return f"units={{{quantity!r}: {unit!r}}}"


def no_such_column(path: str, missing: list[str], expected: dict[str, str], found: list[str],
                   units: Units) -> TrackLogError:
    """The error for required columns the file lacks, with the likeliest fix."""
    suffixed: dict[tuple[str, str], list[str]] = {}
    for name in missing:
        if name in QUANTITY:
            quantity = QUANTITY[name]
            for unit in UNITS[quantity]:
                if f"{name}_{unit}" in found:
                    suffixed.setdefault((quantity, unit), []).append(f"{name}_{unit}")
                    break
    hints = [f"The file has {', '.join(names)}: did you mean {unit_hint(quantity, unit)}?"
             for (quantity, unit), names in suffixed.items()]
    wanted = ", ".join(f"{name} (as {expected[name]!r})" for name in missing)
    hint = " " + " ".join(hints) if hints else (" Name the file's columns with columns={'robot_x': 'x', ...}.")
    return TrackLogError(f"{path}: no column for {wanted}; the file has {', '.join(map(repr, found)) or 'none'}."
                         f"{hint}")
