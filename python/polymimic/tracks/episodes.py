"""A log's rows cut into episodes, its clock checked, and what makes an episode invalid.

Without an episode column a new episode starts where the log shows the experimenter's hand
between two attempts: a gap of more than :data:`EPISODE_GAP_S` between readings, or the robot or
the ball moving more than :data:`RESET_SHARE` of the field's length from one reading to the next
(a reset: at 30 readings a second that would be over 7 m/s on the large field). Inside an
episode, a stretch of NaN readings, or no reading for more than :data:`LOST_PERIODS` nominal
periods, is lost tracking: the episode is invalid (thesis §3.2.1).

Real trackers drop frames, so a longest gap may be given instead (``max_gap_s``,
:func:`bridged_gaps`): a gap (a pause, or a run of readings with a NaN, the robot's or the
ball's alike) lasting at most that long is bridged by the resampling's interpolation, and a
longer one is lost tracking. Gaps do not change how a log is cut into episodes: without an
episode column a pause of more than :data:`EPISODE_GAP_S` still starts a new episode, and a run
of NaN readings that long, or one across which the robot or the ball moved as far as a reset,
is never bridged (it may hide the experimenter's hand).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from polymimic.tracks.errors import TrackLogError
from polymimic.tracks.reading import Log
from polymimic.tracks.units import REQUIRED, UNITS, unit_hint

__all__ = ["DROPPED_PERIODS", "EPISODE_GAP_S", "LOST_PERIODS", "RESET_SHARE", "Stretch", "bridged_gaps",
           "dropped_readings", "lost_tracking", "nominal_period_s", "split_episodes"]

EPISODE_GAP_S = 0.5
"""Without an episode column, a longer pause between two readings starts a new episode."""
RESET_SHARE = 0.25
"""Without an episode column, the robot or the ball moving more than this share of the field's
length between two readings (put back by hand) starts a new episode."""
LOST_PERIODS = 3.0
"""Inside an episode, no reading for more than this many nominal periods is lost tracking."""
DROPPED_PERIODS = 1.5
"""Two readings further apart than this many nominal periods (and no more than
:data:`LOST_PERIODS`) have readings dropped between them: as many as the periods they span, less
one (the tracker missed them; the resampling fills them in)."""
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
    unseen = _unseen(log, rows)
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


def dropped_readings(log: Log, stretch: Stretch, period_s: float) -> int:
    """How many readings the tracker dropped inside ``stretch`` where no gap is: pauses of more
    than :data:`DROPPED_PERIODS` and at most :data:`LOST_PERIODS` periods between two readings
    with every value, each counted as the periods it spans, rounded, less one. Gaps (NaN
    readings, longer pauses) are counted apart, by :func:`bridged_gaps`."""
    rows = slice(stretch.start, stretch.stop)
    seen = ~_unseen(log, rows)
    periods = np.diff(log.measured["t"][rows]) / period_s
    dropped = seen[:-1] & seen[1:] & (periods > DROPPED_PERIODS) & (periods <= LOST_PERIODS)
    return int((np.rint(periods[dropped]) - 1).sum())


def bridged_gaps(log: Log, stretch: Stretch, period_s: float, max_gap_s: float, *,
                 field_length_mm: float) -> tuple[int, str | None]:
    """How many gaps inside ``stretch`` interpolation bridges when gaps of up to ``max_gap_s``
    are allowed, and why the stretch is invalid (its first gap that is not bridged) or ``None``.

    A gap is what :func:`lost_tracking` calls lost tracking: a run of readings with a NaN, or
    no reading for more than :data:`LOST_PERIODS` periods. It lasts from the last reading with
    every value before it to the first one after. It is bridged if it lasts at most
    ``max_gap_s`` and, in a log without an episode column, at most :data:`EPISODE_GAP_S` with
    neither the robot nor the ball moving more than :data:`RESET_SHARE` of ``field_length_mm``
    across it (either would cut an episode there, were it a pause). NaN readings at the start or
    the end of the episode have no reading beyond them to interpolate from: never bridged. A
    pause longer than ``max_gap_s`` is lost tracking, gap or not.
    """
    rows = slice(stretch.start, stretch.stop)
    t_s = log.measured["t"][rows]
    known = np.flatnonzero(~_unseen(log, rows))
    if known.size == 0 or known[0] > 0:
        last = len(t_s) if known.size == 0 else int(known[0])
        return 0, _unseen_reason(log, stretch, 0, last, "at the episode's start, no reading before to interpolate from")
    spans_s = np.diff(t_s[known])
    gaps = (np.diff(known) > 1) | (spans_s > LOST_PERIODS * period_s)
    reset_mm = RESET_SHARE * field_length_mm if "episode" not in log.labels else None
    for i in np.flatnonzero(gaps | (spans_s > max_gap_s)):
        before, after = stretch.start + int(known[i]), stretch.start + int(known[i + 1])
        why = _not_bridged(log, before, after, max_gap_s, reset_mm)
        if why is not None:
            return 0, _gap_reason(log, stretch, before, after, why)
    if known[-1] < len(t_s) - 1:
        return 0, _unseen_reason(log, stretch, int(known[-1]) + 1, len(t_s),
                                 "at the episode's end, no reading after to interpolate from")
    return int(gaps.sum()), None


def _unseen(log: Log, rows: slice) -> np.ndarray:
    """Which of ``rows`` lack a value (NaN) in any measured column."""
    unseen = np.zeros(len(log.measured["t"][rows]), dtype=bool)
    for name in REQUIRED[1:]:
        unseen |= np.isnan(log.measured[name][rows])
    return unseen


def _not_bridged(log: Log, before: int, after: int, max_gap_s: float, reset_mm: float | None) -> str | None:
    """Why the gap between rows ``before`` and ``after`` (readings with every value) is not
    bridged, or ``None``; ``reset_mm`` for a log cut into episodes by pauses and resets."""
    m = log.measured
    span_s = m["t"][after] - m["t"][before]
    if span_s > max_gap_s:
        return f"longer than max_gap_s={max_gap_s:g}"
    if reset_mm is None:
        return None
    if span_s > EPISODE_GAP_S:
        return f"longer than the {EPISODE_GAP_S:g} s pause that starts an episode in a log without an episode column"
    moved_mm = max(math.hypot(m[x][after] - m[x][before], m[y][after] - m[y][before])
                   for x, y in (("robot_x", "robot_y"), ("ball_x", "ball_y")))
    if moved_mm > reset_mm:
        return (f"the robot or the ball moved {moved_mm:.0f} mm across it, as far as a reset by hand (over "
                f"{RESET_SHARE:.0%} of the field's length)")
    return None


def _gap_reason(log: Log, stretch: Stretch, before: int, after: int, why: str) -> str:
    """Lost tracking between rows ``before`` and ``after``, worded as :func:`lost_tracking` does."""
    t_s = log.measured["t"]
    span_s = t_s[after] - t_s[before]
    if after == before + 1:
        return (f"lost tracking at {t_s[before] - t_s[stretch.start]:.2f} s (no reading for {span_s:.2f} s after data "
                f"row {before + 1}, {why})")
    return _unseen_reason(log, stretch, before + 1 - stretch.start, after - stretch.start,
                          f"{span_s:.2f} s between readings, {why}")


def _unseen_reason(log: Log, stretch: Stretch, first: int, stop: int, why: str) -> str:
    """Lost tracking over the stretch's readings ``first`` to ``stop`` (indices within it), each
    with a NaN: the rows and the columns without values."""
    rows = slice(stretch.start + first, stretch.start + stop)
    columns = [log.file_names[n] for n in REQUIRED[1:] if np.isnan(log.measured[n][rows]).any()]
    named = (f"data row {rows.start + 1}" if stop - first == 1 else f"data rows {rows.start + 1}–{rows.stop}")
    t_s = log.measured["t"]
    return (f"lost tracking at {t_s[rows.start] - t_s[stretch.start]:.2f} s ({named}: no {', '.join(columns)}; "
            f"{why})")


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
