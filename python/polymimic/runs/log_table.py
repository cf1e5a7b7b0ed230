"""A tracker log as a config's demonstrator: ``[demonstrators.<name>] log = "FILE"`` with every
option :func:`polymimic.import_tracks` takes, by the same names, checked when the config is read.

>>> values = {"log": "ssl.csv", "rate_hz": 30, "max_gap_s": 0.35, "ignore": ["camera"]}
>>> check_log_table("[demonstrators.ssl]", values)
>>> values["ignore"], values["max_gap_s"]
(('camera',), 0.35)
>>> check_log_table("[demonstrators.ssl]", {"log": "ssl.csv", "max_gap_s": -1})
Traceback (most recent call last):
...
ValueError: [demonstrators.ssl]: max_gap_s must be a number of seconds, at least 0, got -1
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from polymimic.tracks.units import UNITS

__all__ = ["LOG_OPTIONS", "check_log_table"]

LOG_OPTIONS = ("rate_hz", "units", "columns", "configuration", "ignore", "line_tolerance_mm", "max_gap_s")
"""The options of :func:`polymimic.import_tracks` a log demonstrator's table may give, beside its
``log`` (the function's ``path``) and ``body``."""


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def check_log_table(where: str, values: dict[str, Any]) -> None:
    """A ``ValueError`` naming ``where`` and the key for a log table's value that
    :func:`polymimic.import_tracks` would refuse; numbers become floats and ``ignore`` a tuple,
    in place."""
    if not isinstance(values.get("log"), str) or not values["log"]:
        raise ValueError(f"{where}: log must be a non-empty string (the log's path), got {values.get('log')!r}")
    for key in ("units", "columns"):
        if not isinstance(values.get(key, {}), Mapping):
            raise ValueError(f"{where}: {key} must be a table, got {values[key]!r}")
    for quantity, unit in values.get("units", {}).items():
        if quantity not in UNITS or unit not in UNITS[quantity]:
            allowed = "; ".join(f"{q}: {', '.join(u)}" for q, u in UNITS.items())
            raise ValueError(f"{where}: units.{quantity} = {unit!r} is not a unit polymimic reads ({allowed})")
    rate_hz = values.get("rate_hz")
    if rate_hz is not None and not (_number(rate_hz) and 0 < rate_hz < 1e6):
        raise ValueError(f"{where}: rate_hz must be a positive number of readings a second, got {rate_hz!r}")
    for key, what in (("max_gap_s", "a number of seconds"), ("line_tolerance_mm", "a number of mm")):
        value = values.get(key)
        if value is not None and not (_number(value) and value >= 0):
            raise ValueError(f"{where}: {key} must be {what}, at least 0, got {value!r}")
        if value is not None:
            values[key] = float(value)
    configuration = values.get("configuration")
    if configuration is not None and (isinstance(configuration, bool) or configuration not in (1, 2)):
        raise ValueError(f"{where}: configuration must be 1 or 2 (every episode's field configuration), got "
                         f"{configuration!r}")
    ignore = values.get("ignore", ())
    if not isinstance(ignore, (list, tuple)) or not all(isinstance(c, str) and c for c in ignore):
        raise ValueError(f"{where}: ignore must be a list of the log's column names to skip, got {ignore!r}")
    values["ignore"] = tuple(ignore)
