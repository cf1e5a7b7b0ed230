"""import_tracks: a tracker log read, checked, cut into episodes and resampled into
demonstrations."""

from __future__ import annotations

import dataclasses
import math
import numbers
import os
import warnings
from collections.abc import Collection, Mapping
from typing import Any

import numpy as np

from polymimic.bodies import BodySpec, as_body
from polymimic.field import FRAME_DTYPE, OUTCOMES, UNKNOWN_COMMAND, Demonstration, command_table
from polymimic.tracks.episodes import (
    Stretch,
    bridged_gaps,
    dropped_readings,
    lost_tracking,
    nominal_period_s,
    split_episodes,
)
from polymimic.tracks.errors import LostTrackingWarning, TrackLogError
from polymimic.tracks.headings import check_headings
from polymimic.tracks.outcomes import LINE_TOLERANCE_MM, configuration_of, outcome_of
from polymimic.tracks.reading import Log, read_log
from polymimic.tracks.resampling import grid, heading, held, linear
from polymimic.tracks.scale import check_scale
from polymimic.tracks.units import checked_units

__all__ = ["ImportedTracks", "import_tracks"]

_SHOWN_INVALID = 3


@dataclasses.dataclass(frozen=True, repr=False)
class ImportedTracks:
    """What :func:`import_tracks` made of a log.

    ``demonstrations`` are the valid episodes in log order; ``invalid`` lists ``(episode,
    reason)`` for each episode left out (lost tracking); ``episodes`` counts them all. An
    episode is named by the log's episode id, or by its index in the log (from 0) when the log
    has no episode column; a demonstration's ``seed`` is that index. For each demonstration in
    turn, ``episode_ids`` names its episode, ``dropped_readings`` counts the single readings the
    tracker dropped (pauses of two or three periods, filled in by the resampling; see
    :data:`polymimic.tracks.episodes.DROPPED_PERIODS`) and ``gaps_bridged`` the gaps the
    interpolation bridged under ``max_gap_s`` (all 0 without it).
    """

    demonstrations: list[Demonstration]
    invalid: list[tuple[Any, str]]
    episodes: int
    path: str = ""
    gaps_bridged: list[int] = dataclasses.field(default_factory=list)
    dropped_readings: list[int] = dataclasses.field(default_factory=list)
    episode_ids: list[Any] = dataclasses.field(default_factory=list)

    def summary(self) -> str:
        """One line: how many episodes, how many became demonstrations (and the readings filled
        in and gaps bridged in them, if any), which were invalid and why."""
        source = f" from {os.path.basename(self.path)}" if self.path else ""
        repairs = _repairs(sum(self.dropped_readings), sum(self.gaps_bridged))
        gaps = f" ({repairs})" if repairs else ""
        line = (f"{self.episodes} episode{'s' * (self.episodes != 1)}{source}: {len(self.demonstrations)} "
                f"demonstration{'s' * (len(self.demonstrations) != 1)}{gaps}, {len(self.invalid)} invalid")
        if self.invalid:
            shown = "; ".join(f"episode {e}: {why}" for e, why in self.invalid[:_SHOWN_INVALID])
            more = f"; {len(self.invalid) - _SHOWN_INVALID} more" if len(self.invalid) > _SHOWN_INVALID else ""
            line += f" ({shown}{more})"
        return line

    def repaired(self) -> list[str]:
        """A line per demonstration whose readings were filled in or bridged: its episode and
        how many of each (none for a log read whole)."""
        return [f"episode {episode}: {_repairs(dropped, bridged)}"
                for episode, dropped, bridged in zip(self.episode_ids, self.dropped_readings, self.gaps_bridged)
                if dropped or bridged]

    def __repr__(self) -> str:
        return self.summary()


def _repairs(dropped: int, bridged: int) -> str:
    """``"2 dropped readings filled in, 1 gap bridged"``, each part only where it is not 0."""
    parts = ([f"{dropped} dropped reading{'s' * (dropped != 1)} filled in"] if dropped else []) + (
        [f"{bridged} gap{'s' * (bridged != 1)} bridged"] if bridged else [])
    return ", ".join(parts)


MIN_READINGS = 2
"""An episode of fewer readings shows no motion: it is left out, and counted, as invalid."""


def import_tracks(path: str | os.PathLike[str], *, demonstrator: str, columns: Mapping[str, str] | None = None,
                  units: Mapping[str, str] | None = None, rate_hz: float | None = None,
                  body: BodySpec = "lego",
                  configuration: int | None = None, ignore: Collection[str] = (),
                  line_tolerance_mm: float = LINE_TOLERANCE_MM, max_gap_s: float | None = None) -> ImportedTracks:
    """Demonstrations from a tracker log: a CSV or Parquet table of timed readings.

    Parameters
    ----------
    path : str or path-like
        A ``.csv`` (with a header row) or ``.parquet`` file, one row per reading.
    demonstrator : str
        The name the demonstrations are recorded under.
    columns : dict, optional
        polymimic's column names (``t``, ``robot_x``, ``robot_y``, ``robot_theta``, ``ball_x``,
        ``ball_y``; optional ``episode``, ``outcome``, ``command``, ``configuration``) → the file's.
        A column not named here is looked for under its name with its unit as a suffix
        (``t_s``, ``robot_x_mm``, ``robot_theta_deg``, as :func:`write_tracks` writes them), then
        under its bare name.
    units : dict, optional
        ``{"length": "mm" | "cm" | "m", "angle": "rad" | "deg", "time": "s" | "ms"}``; mm, rad and
        s where left out. Headings may be wrapped or unwrapped (past ±180°, as a tracker that
        integrates the turning writes them); degrees declared as radians are refused by the
        turn rate or the number of turns they would mean (:mod:`polymimic.tracks.headings`).
    rate_hz : float, optional
        The log's nominal rate, checked against its timestamps (the median interval within 10 %);
        without it the median interval is the nominal period.
    body : polymimic.Body, {"lego", "tiny", "humanoid"} or polymimic.bodies.WheeledBody
        The demonstrator's body; its field (size, goals) is the one the outcomes are read on.
    configuration : {1, 2}, optional
        Every episode's field configuration; else the log's configuration column, else read
        from each episode's first reading (the robot behind the ball toward −x is 1, else 2).
    ignore : list of str
        File columns to skip; any other column polymimic does not know is refused.
    line_tolerance_mm : float
        How far past a line a reading must be to count as beyond it, and how close to a line a
        log must end to have ended there, for outcomes derived from the geometry: the tracker's
        jitter (:data:`polymimic.tracks.outcomes.LINE_TOLERANCE_MM`, 1 mm); 0 for the lines as they are.
    max_gap_s : float, optional
        The longest gap in an episode's tracking that is bridged, in seconds (at least 0): no
        reading, or readings with a NaN (the robot's values or the ball's alike), from one
        reading with every value to the next. A gap up to this long is interpolated as any two
        readings are (each value from the readings that have it) and counted in
        ``gaps_bridged`` if the default would call it lost tracking; a longer one is lost
        tracking, however few periods it lasts. NaN readings at an episode's start or end are
        never bridged. Without an episode column a pause of over 0.5 s still starts a new
        episode, and NaN readings lasting that long, or across which the robot or the ball moves
        as far as a reset, are not bridged: there no gap over 0.5 s is bridged, whatever
        ``max_gap_s``. By default a pause of up to three periods is bridged, a NaN reading never.

    Notes
    -----
    Episodes are the log's episode ids in order, or, without an episode column, cut where the
    log pauses for more than 0.5 s or the robot or ball jumps more than a quarter of the field's
    length between two readings (:mod:`polymimic.tracks.episodes`). Each episode is resampled to
    30 frames a second from its first reading (``t_s`` from 0 up to its last reading): linear in
    position, along the shorter arc in heading (wrapped to (−π, π]), the command held from the
    reading that sent it. Commands are ids or names of :func:`polymimic.command_table`; without
    a command column every frame has :data:`polymimic.field.UNKNOWN_COMMAND`. A logged outcome
    (one of goal, own_goal, ball_out, robot_out, time_up, on any of the episode's rows) is
    taken as it is; otherwise it is derived from the field's geometry and the frames after it
    are cut (:mod:`polymimic.tracks.outcomes`). An episode with lost tracking (a NaN reading,
    or no reading for over three periods, unless ``max_gap_s`` bridges it) is not returned: it
    is listed in ``invalid``, and a :class:`LostTrackingWarning` says so.

    Raises
    ------
    TrackLogError
        (a ``ValueError``) for a log that does not read as declared: the message names the
        file, the data row (from 1; a CSV's line beside it) or episode, and the column.
    FileNotFoundError
        If there is no file at ``path``.
    ValueError, TypeError
        For arguments out of range or of the wrong type.

    Examples
    --------
    >>> import pathlib, tempfile, polymimic
    >>> from polymimic.tracks import write_tracks
    >>> log = pathlib.Path(tempfile.mkdtemp()) / "log.csv"
    >>> demos = polymimic.record("expert", configuration=1, n=3, seed=1)
    >>> write_tracks(demos, log, units={"length": "m", "angle": "deg"}, rate_hz=60, include=("episode",))
    >>> imported = import_tracks(log, demonstrator="alice", units={"length": "m", "angle": "deg"}, rate_hz=60)
    >>> imported
    3 episodes from log.csv: 3 demonstrations, 0 invalid
    >>> [d.outcome for d in imported.demonstrations] == [d.outcome for d in demos]
    True

    A tracker that dropped ten readings (0.18 s at 60 Hz) in the first episode:

    >>> lines = log.read_text().splitlines()
    >>> _ = log.write_text("\\n".join(lines[:21] + lines[31:]) + "\\n")
    >>> bridged = import_tracks(log, demonstrator="alice", units={"length": "m", "angle": "deg"}, rate_hz=60,
    ...                         max_gap_s=0.2)
    >>> bridged, bridged.gaps_bridged
    (3 episodes from log.csv: 3 demonstrations (1 gap bridged), 0 invalid, [1, 0, 0])
    """
    max_gap_s = _max_gap_s(max_gap_s)
    checked = checked_units(units)
    body = as_body(body)
    field = body.field
    if not isinstance(demonstrator, str) or not demonstrator:
        raise ValueError(f"demonstrator must be a non-empty name, got {demonstrator!r}")
    rate_hz = _rate(rate_hz)
    if isinstance(line_tolerance_mm, bool) or not isinstance(line_tolerance_mm, numbers.Real) or not (
            0.0 <= line_tolerance_mm < math.inf):
        raise ValueError(f"line_tolerance_mm must be a number of mm, at least 0; got {line_tolerance_mm!r}")
    if configuration is not None and (isinstance(configuration, bool) or configuration not in (1, 2)):
        raise ValueError(f"configuration must be 1, 2 or None, got {configuration!r}")
    log = read_log(path, columns=columns, units=checked, ignore=ignore)
    check_scale(log, field, checked, body=body.name)
    stretches = split_episodes(log, field_length_mm=field.length_mm)
    check_headings(log, stretches, checked)
    period_s = nominal_period_s(log, stretches, rate_hz, checked["time"])
    commands = _commands(log) if "command" in log.labels else None
    _check_outcomes(log)
    demos: list[Demonstration] = []
    invalid: list[tuple[Any, str]] = []
    gaps_bridged: list[int] = []
    dropped: list[int] = []
    episode_ids: list[Any] = []
    for index, stretch in enumerate(stretches):
        logged_outcome = _per_episode(log, stretch, "outcome")
        logged_configuration = _configuration(log, stretch, configuration)
        if max_gap_s is None:
            bridged, reason = 0, lost_tracking(log, stretch, period_s)
        else:
            bridged, reason = bridged_gaps(log, stretch, period_s, max_gap_s, field_length_mm=field.length_mm)
        if reason is None and stretch.stop - stretch.start < MIN_READINGS:
            reason = f"{stretch.stop - stretch.start} reading: too short to be an attempt"
        if reason is not None:
            invalid.append((stretch.episode, reason))
            continue
        frames = _resampled(log, stretch, commands)
        if logged_outcome is None:
            outcome, kept = outcome_of(frames, field, tolerance_mm=float(line_tolerance_mm))
            frames = frames[:kept].copy()
        else:
            outcome = str(logged_outcome)
        demos.append(Demonstration(frames=frames, outcome=outcome, demonstrator=demonstrator,
                                   configuration=logged_configuration or configuration_of(frames), seed=index,
                                   body=body))
        gaps_bridged.append(bridged)
        dropped.append(dropped_readings(log, stretch, period_s))
        episode_ids.append(stretch.episode)
    result = ImportedTracks(demonstrations=demos, invalid=invalid, episodes=len(stretches), path=log.path,
                            gaps_bridged=gaps_bridged, dropped_readings=dropped,
                            episode_ids=episode_ids)
    if invalid:
        warnings.warn(result.summary(), LostTrackingWarning, stacklevel=2)
    return result


def _rate(rate_hz: Any) -> float | None:
    if rate_hz is None:
        return None
    if isinstance(rate_hz, bool) or not isinstance(rate_hz, numbers.Real) or not (
            math.isfinite(float(rate_hz)) and float(rate_hz) > 0):
        raise ValueError(f"rate_hz must be a positive number of readings a second, got {rate_hz!r}")
    return float(rate_hz)


def _max_gap_s(max_gap_s: Any) -> float | None:
    if max_gap_s is None:
        return None
    try:  # an int too large for a float is as good as infinite
        seconds = float(max_gap_s) if isinstance(max_gap_s, numbers.Real) and not isinstance(max_gap_s, bool) else None
    except OverflowError:
        seconds = math.inf
    if seconds is None or not 0.0 <= seconds < math.inf:
        raise ValueError(f"max_gap_s must be a finite number of seconds, at least 0 (or None: a pause of three "
                         f"reading periods at most, no NaN reading), got {max_gap_s!r}")
    return seconds


def _resampled(log: Log, stretch: Stretch, commands: np.ndarray | None) -> np.ndarray:
    rows = slice(stretch.start, stretch.stop)
    m = log.measured
    t_s = m["t"][rows] - m["t"][stretch.start]
    at_s = grid(float(t_s[-1]))
    frames = np.empty(len(at_s), dtype=FRAME_DTYPE)
    frames["t_s"] = at_s
    for name in ("robot_x", "robot_y", "ball_x", "ball_y"):
        frames[f"{name}_mm"] = linear(*_read(t_s, m[name][rows]), at_s)
    frames["robot_theta_rad"] = heading(*_read(t_s, m["robot_theta"][rows]), at_s)
    frames["command"] = UNKNOWN_COMMAND if commands is None else held(t_s, commands[rows], at_s)
    return frames


def _read(t_s: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A column's readings without its NaN ones, so that the frames between are interpolated
    from the readings either side (only an episode imported under ``max_gap_s`` has any)."""
    known = ~np.isnan(values)
    return t_s[known], values[known]


def _check_outcomes(log: Log) -> None:
    for row, value in enumerate(log.labels.get("outcome", ())):
        if value is not None and value not in OUTCOMES:
            raise TrackLogError(f"{log.where(row, 'outcome')}: outcome {value!r} is not one of "
                                f"{', '.join(OUTCOMES)} (leave the column out to derive outcomes from the field)")


def _per_episode(log: Log, stretch: Stretch, name: str) -> Any:
    """The one value of column ``name`` on the episode's rows that have one (``None`` if none)."""
    if name not in log.labels:
        return None
    found, first_row = None, 0
    for row in range(stretch.start, stretch.stop):
        value = log.labels[name][row]
        if value is None:
            continue
        if found is None:
            found, first_row = value, row
        elif value != found:
            raise TrackLogError(f"{log.where(row, name)}: episode {stretch.episode!r} has {name} {value!r} here but "
                                f"{found!r} at data row {first_row + 1}; an episode has one")
    return found


def _configuration(log: Log, stretch: Stretch, given: int | None) -> int | None:
    logged = _per_episode(log, stretch, "configuration")
    if logged is None:
        return given
    try:
        number = int(logged) if float(logged) == int(float(logged)) else None
    except (TypeError, ValueError, OverflowError):  # not a number, or an infinite one
        number = None
    if number not in (1, 2):
        row = log.labels["configuration"].index(logged, stretch.start)
        raise TrackLogError(f"{log.where(row, 'configuration')}: configuration {logged!r}; expected 1 or 2")
    if given is not None and number != given:
        raise TrackLogError(f"{log.path}: episode {stretch.episode!r} has configuration {number} in column "
                            f"{log.file_names['configuration']!r}, but configuration={given} was given")
    return number


def _commands(log: Log) -> np.ndarray:
    """Each row's command id, from an id or a name of :func:`polymimic.command_table`."""
    table = command_table()
    ids = {int(row["id"]) for row in table}
    by_name = {str(row["name"]): int(row["id"]) for row in table}
    out = np.empty(log.n_rows, dtype=np.uint16)
    for row, value in enumerate(log.labels["command"]):
        command = _command_id(value, ids, by_name)
        if command is None:
            raise TrackLogError(f"{log.where(row, 'command')}: {value!r} is no command polymimic knows; expected an "
                                "id or a name of polymimic.command_table() (e.g. 0 or 'forward')")
        out[row] = command
    return out


def _command_id(value: Any, ids: set[int], by_name: dict[str, int]) -> int | None:
    if value is None or isinstance(value, bool):
        return None
    if isinstance(value, str):
        text = value.strip()
        if text in by_name:
            return by_name[text]
        try:
            value = float(text)
        except ValueError:
            return None
    if isinstance(value, numbers.Real) and math.isfinite(float(value)) and float(value).is_integer():
        number = int(float(value))
        return number if number in ids else None
    return None
