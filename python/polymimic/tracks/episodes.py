"""A log's rows cut into episodes, its clock checked, and what makes an episode invalid.

Without an episode column a new episode starts where the log shows the experimenter's hand
between two attempts: a gap of more than :data:`EPISODE_GAP_S` between readings, or the robot or
the ball moving more than :data:`RESET_SHARE` of the field's length from one reading to the next
(a reset: at 30 readings a second that would be over 7 m/s on the large field). Inside an
episode, a stretch of NaN readings, or no reading for more than :data:`LOST_PERIODS` nominal
periods, is lost tracking: the episode is invalid (SPEC §3.2.1).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from polymimic.tracks.errors import TrackLogError
from polymimic.tracks.reading import Log
from polymimic.tracks.units import REQUIRED, UNITS, unit_hint

__all__ = ["EPISODE_GAP_S", "LOST_PERIODS", "RESET_SHARE", "Stretch", "lost_tracking", "nominal_period_s",
           "split_episodes"]

EPISODE_GAP_S = 0.5
"""Without an episode column, a longer pause between two readings starts a new episode."""
RESET_SHARE = 0.25
"""Without an episode column, the robot or the ball moving more than this share of the field's
length between two readings (put back by hand) starts a new episode."""
LOST_PERIODS = 3.0
"""Inside an episode, no reading for more than this many nominal periods is lost tracking."""
RATE_TOLERANCE = 0.1
"""A declared ``rate_hz`` must match the median interval between readings to within 10 %."""
PERIOD_RANGE_S = (1e-3, EPISODE_GAP_S)
"""Trackers read between 2 and 1000 times a second: a median interval outside this range is a
time unit declared wrong."""


@dataclasses.dataclass(frozen=True)
class Stretch:
    """One episode's rows, ``start`` to ``stop`` (indices into the log), and its id: the log's
    episode id, or its index in the log when the log has none."""

    episode: Any
    start: int
    stop: int


def split_episodes(log: Log, *, field_length_mm: float) -> list[Stretch]:
    """The log's episodes in file order, each with times increasing (checked)."""
    t_s = log.measured["t"]
    _check_times_known(log)
    if "episode" in log.labels:
        stretches = _by_column(log)
    else:
        _check_increasing(log, 0, len(t_s), hint=True)
        cuts = _resets(log, field_length_mm)
        bounds = [0, *cuts.tolist(), len(t_s)]
        stretches = [Stretch(i, a, b) for i, (a, b) in enumerate(zip(bounds[:-1], bounds[1:]))]
    for s in stretches:
        _check_increasing(log, s.start, s.stop, hint=False)
    return stretches


def nominal_period_s(log: Log, stretches: list[Stretch], rate_hz: float | None, time_unit: str) -> float:
    """The interval between readings: ``1 / rate_hz`` if given (checked against the log's median
    interval), else that median; a time unit that cannot be right is refused."""
    t_s = log.measured["t"]
    # The unit is judged on every step forward, across episodes too: in a log whose seconds were
    # declared as milliseconds every reading is an episode of its own.
    forward = np.diff(t_s)
    forward = forward[forward > 0]
    if forward.size == 0:
        return 1.0 / rate_hz if rate_hz is not None else 1.0 / 30.0
    low, high = PERIOD_RANGE_S
    overall_s = float(np.median(forward))
    if not low <= overall_s <= high:
        raw = overall_s / UNITS["time"][time_unit]
        raise TrackLogError(f"{log.path}, column {log.file_names['t']!r}: readings are {raw:g} {time_unit} apart "
                            f"(the median interval), outside a tracker's {low:g}–{high:g} s"
                            f"{_time_hint(overall_s, time_unit)}")
    steps = np.concatenate([np.diff(t_s[s.start:s.stop]) for s in stretches])
    median_s = float(np.median(steps)) if steps.size else overall_s
    if not low <= median_s <= high:
        raw = median_s / UNITS["time"][time_unit]
        raise TrackLogError(f"{log.path}, column {log.file_names['t']!r}: readings are {raw:g} {time_unit} apart "
                            f"(the median interval), outside a tracker's {low:g}–{high:g} s"
                            f"{_time_hint(median_s, time_unit)}")
    if rate_hz is None:
        return median_s
    period_s = 1.0 / rate_hz
    if abs(median_s - period_s) > RATE_TOLERANCE * period_s:
        raise TrackLogError(f"{log.path}, column {log.file_names['t']!r}: rate_hz={rate_hz:g} means a reading every "
                            f"{period_s * 1e3:.1f} ms, but the readings are {median_s * 1e3:.1f} ms apart (median, "
                            f"{1.0 / median_s:.1f} Hz)")
    return period_s


def lost_tracking(log: Log, stretch: Stretch, period_s: float) -> str | None:
    """Why ``stretch`` is invalid (the first NaN reading, or the first gap of more than
    :data:`LOST_PERIODS` periods), or ``None`` if it was tracked throughout."""
    rows = slice(stretch.start, stretch.stop)
    t_s = log.measured["t"][rows]
    unseen = np.zeros(len(t_s), dtype=bool)
    for name in REQUIRED[1:]:
        unseen |= np.isnan(log.measured[name][rows])
    gaps = np.flatnonzero(np.diff(t_s) > LOST_PERIODS * period_s)
    first_unseen = int(np.argmax(unseen)) if unseen.any() else len(t_s)
    first_gap = int(gaps[0]) if gaps.size else len(t_s)
    if first_unseen == len(t_s) and first_gap == len(t_s):
        return None
    if first_unseen <= first_gap:
        columns = [log.file_names[n] for n in REQUIRED[1:] if np.isnan(log.measured[n][stretch.start + first_unseen])]
        return (f"lost tracking at {t_s[first_unseen] - t_s[0]:.2f} s (data row {stretch.start + first_unseen + 1}: "
                f"no {', '.join(columns)})")
    return (f"lost tracking at {t_s[first_gap] - t_s[0]:.2f} s (no reading for "
            f"{t_s[first_gap + 1] - t_s[first_gap]:.2f} s after data row {stretch.start + first_gap + 1})")


def _check_times_known(log: Log) -> None:
    unknown = np.flatnonzero(np.isnan(log.measured["t"]))
    if unknown.size:
        raise TrackLogError(f"{log.where(int(unknown[0]), 't')}: no time; every reading needs one")


def _by_column(log: Log) -> list[Stretch]:
    ids = log.labels["episode"]
    stretches: list[Stretch] = []
    seen: dict[Any, int] = {}
    start = 0
    for row, episode in enumerate(ids):
        if episode is None or (isinstance(episode, float) and math.isnan(episode)):
            raise TrackLogError(f"{log.where(row, 'episode')}: no episode id")
        if row > 0 and episode != ids[row - 1]:
            stretches.append(Stretch(ids[row - 1], start, row))
            start = row
        if episode in seen and row == start:
            raise TrackLogError(f"{log.where(row, 'episode')}: episode {episode!r} again, after other episodes "
                                f"(it began at data row {seen[episode] + 1}); the rows of an episode must be together")
        seen.setdefault(episode, row)
    stretches.append(Stretch(ids[-1], start, len(ids)))
    return stretches


def _check_increasing(log: Log, start: int, stop: int, *, hint: bool) -> None:
    t_s = log.measured["t"][start:stop]
    steps = np.diff(t_s)
    bad = np.flatnonzero(steps <= 0)
    if not bad.size:
        return
    row = start + int(bad[0]) + 1
    before, now = log.measured["t"][row - 1], log.measured["t"][row]
    if now == before:
        raise TrackLogError(f"{log.where(row, 't')}: time {now:g} s again (as in data row {row}); duplicated "
                            "timestamps")
    restart = (" If the log restarts its clock for every episode, name its episode column "
               "(columns={'episode': ...})." if hint else "")
    raise TrackLogError(f"{log.where(row, 't')}: time goes back from {before:g} s to {now:g} s; time must increase "
                        f"within an episode.{restart}")


def _resets(log: Log, field_length_mm: float) -> np.ndarray:
    """Rows that start a new episode, when the log has no episode column."""
    m = log.measured
    new = np.diff(m["t"]) > EPISODE_GAP_S
    for x, y in (("robot_x", "robot_y"), ("ball_x", "ball_y")):
        jump_mm = np.hypot(np.diff(m[x]), np.diff(m[y]))
        new |= np.nan_to_num(jump_mm, nan=0.0) > RESET_SHARE * field_length_mm
    cuts: np.ndarray = np.flatnonzero(new) + 1
    return cuts


def _time_hint(median_s: float, declared: str) -> str:
    """The time unit under which the log's readings would be a tracker's distance apart."""
    raw = median_s / UNITS["time"][declared]
    low, high = PERIOD_RANGE_S
    for unit, size in UNITS["time"].items():
        if unit != declared and low <= raw * size <= high:
            return f"; did you mean {unit_hint('time', unit)}?"
    return ""
