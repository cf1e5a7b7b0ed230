"""write_tracks: demonstrations written as a tracker log, in other units and at another rate."""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic._atomic import atomic_path
from polymimic.field import UNKNOWN_COMMAND, Demonstration
from polymimic.tracks.episodes import EPISODE_GAP_S
from polymimic.tracks.reading import SUFFIXES
from polymimic.tracks.resampling import TIME_SLACK_S, grid, heading, held, linear, wrap_angle
from polymimic.tracks.units import OPTIONAL, REQUIRED, checked_columns, checked_units, default_name, factor

__all__ = ["BETWEEN_EPISODES_S", "write_tracks"]

BETWEEN_EPISODES_S = 2 * EPISODE_GAP_S
"""Without an episode column, each episode's clock starts this long after the previous one ended,
so that :func:`import_tracks` cuts the log where the episodes were."""


def write_tracks(demonstrations: Sequence[Demonstration], path: str | os.PathLike[str], *,
                 units: Mapping[str, str] | None = None, rate_hz: float = 30.0,
                 columns: Mapping[str, str] | None = None,
                 include: Sequence[str] = ("episode", "outcome", "command")) -> None:
    """Write demonstrations as a tracker log (CSV or Parquet, by ``path``'s extension), atomically.

    Parameters
    ----------
    demonstrations : list of Demonstration
        The episodes, in the order written.
    path : str or path-like
        A ``.csv`` or ``.parquet`` file (replaced if it exists; its directory must exist).
    units : dict, optional
        As for :func:`import_tracks`: ``{"length": "m", "angle": "deg", "time": "ms"}``.
    rate_hz : float
        Readings a second. Each episode is resampled from its frames at ``0, 1/rate_hz, …``
        (linear in position, the shorter arc in heading, headings wrapped to (−180°, 180°] or
        (−π, π]), and its final frame, how it ended, is always written as its last reading.
    columns : dict, optional
        polymimic's column names → the names to write; by default the names with their unit
        (``t_s``, ``robot_x_m``, ``robot_theta_deg``, …) and ``episode``, ``outcome``,
        ``command``, ``configuration``.
    include : list of str
        The optional columns to write, of ``episode`` (the index from 0), ``outcome``,
        ``command`` (the id in force) and ``configuration``. Without ``episode``, each episode's
        clock starts :data:`BETWEEN_EPISODES_S` after the previous one's end.

    Examples
    --------
    >>> import pathlib, tempfile, polymimic, pyarrow.csv
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "log.csv"
    >>> write_tracks(polymimic.record("poor", configuration=1, n=1, seed=0), path, units={"length": "m"})
    >>> pyarrow.csv.read_csv(path).column_names
    ['episode', 't_s', 'robot_x_m', 'robot_y_m', 'robot_theta_rad', 'ball_x_m', 'ball_y_m', 'outcome', 'command']
    """
    import pyarrow as pa
    import pyarrow.csv as pacsv
    import pyarrow.parquet as pq

    demos = _checked_demonstrations(demonstrations)
    checked = checked_units(units)
    names = checked_columns(columns)
    rate = _rate(rate_hz)
    if isinstance(include, str) or not all(name in OPTIONAL for name in include):
        raise ValueError(f"include must list some of {', '.join(OPTIONAL)}, got {include!r}")
    suffix = os.path.splitext(os.fspath(path))[1].lower()
    if suffix not in SUFFIXES:
        kind = suffix or "a file without an extension"
        raise ValueError(f"{os.fspath(path)}: write_tracks writes a .csv or a .parquet file, not {kind}")
    if "command" in include:
        for i, demo in enumerate(demos):
            if (demo.frames["command"] == UNKNOWN_COMMAND).any():
                raise ValueError(f"demonstration {i} has no recorded commands; leave 'command' out of include")
    parts: dict[str, list[np.ndarray]] = {name: [] for name in ("episode", *REQUIRED, "outcome", "command",
                                                               "configuration")}
    start_s = 0.0
    for i, demo in enumerate(demos):
        frames = demo.frames
        t_s = frames["t_s"] - frames["t_s"][0]
        at_s = grid(float(t_s[-1]), rate)
        if at_s[-1] < t_s[-1] - TIME_SLACK_S:
            at_s = np.append(at_s, t_s[-1])
        offset_s = 0.0 if "episode" in include else start_s
        parts["t"].append((at_s + offset_s) / factor("t", checked))
        for name in ("robot_x", "robot_y", "ball_x", "ball_y"):
            parts[name].append(linear(t_s, frames[f"{name}_mm"], at_s) / factor(name, checked))
        parts["robot_theta"].append(wrap_angle(heading(t_s, frames["robot_theta_rad"], at_s))
                                    / factor("robot_theta", checked))
        parts["episode"].append(np.full(len(at_s), i, dtype=np.int64))
        parts["outcome"].append(np.full(len(at_s), demo.outcome, dtype=object))
        parts["command"].append(held(t_s, frames["command"], at_s).astype(np.int64))
        parts["configuration"].append(np.full(len(at_s), demo.configuration, dtype=np.int64))
        start_s += float(t_s[-1]) + BETWEEN_EPISODES_S
    order = [n for n in ("episode",) if n in include] + list(REQUIRED) + [
        n for n in ("outcome", "command", "configuration") if n in include]
    arrays = [pa.array(np.concatenate(parts[n]) if parts[n] else np.empty(0)) for n in order]
    table = pa.table(dict(zip([names.get(n, default_name(n, checked)) for n in order], arrays)))
    with atomic_path(path) as temporary:
        if suffix == ".csv":
            pacsv.write_csv(table, temporary)
        else:
            pq.write_table(table, temporary)


def _checked_demonstrations(demonstrations: Any) -> list[Demonstration]:
    if isinstance(demonstrations, Demonstration):
        raise TypeError("expected a list of Demonstration, got a single Demonstration; wrap it in a list")
    if isinstance(demonstrations, (str, bytes)) or not isinstance(demonstrations, Sequence):
        raise TypeError(f"expected a list of Demonstration, got {type(demonstrations).__name__}")
    for i, demo in enumerate(demonstrations):
        if not isinstance(demo, Demonstration):
            raise TypeError(f"demonstrations item {i} is a {type(demo).__name__}, not a Demonstration")
        if len(demo.frames) == 0:
            raise ValueError(f"demonstration {i} has no frames")
    return list(demonstrations)


def _rate(rate_hz: Any) -> float:
    if isinstance(rate_hz, bool) or not isinstance(rate_hz, numbers.Real) or not (
            math.isfinite(float(rate_hz)) and float(rate_hz) > 0):
        raise ValueError(f"rate_hz must be a positive number of readings a second, got {rate_hz!r}")
    return float(rate_hz)
