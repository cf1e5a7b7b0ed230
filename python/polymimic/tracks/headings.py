"""Whether a log's headings are angles in the unit declared for them, wrapped or unwrapped.

A tracker that integrates the robot's turning writes headings past ±180° (an unwrapped
heading: 370° is 10°); one that wraps them keeps to a turn. Both are read as the angle they
are. Degrees declared as radians give themselves away as soon as the robot turns or faces
away from the field's axis: a robot turning at 13° a second would read as turning more than
:data:`MAX_TURN_RAD_S` (two turns a second, faster than any robot on the field), and a
heading of 51° or more would read as more than :data:`MAX_UNWRAPPED_TURNS` turns. So headings
beyond a full turn are taken as unwrapped only if none lies beyond that many turns and, within
each episode, no two consecutive readings differ by more than that rate allows; otherwise the
error names the reading and the unit that would fit.

>>> import numpy as np
>>> t_s = np.array([0.0, 0.1, 0.2])
>>> bool(np.all(turn_rates_rad_s(np.radians([350.0, 365.0, 380.0]), t_s) <= MAX_TURN_RAD_S))  # integrated, in rad
True
>>> bool(np.all(turn_rates_rad_s(np.array([350.0, 365.0, 380.0]), t_s) <= MAX_TURN_RAD_S))    # degrees taken as rad
False
"""

from __future__ import annotations

import math

import numpy as np

from polymimic.tracks.episodes import Stretch
from polymimic.tracks.errors import TrackLogError
from polymimic.tracks.reading import Log
from polymimic.tracks.units import UNITS, Units, unit_hint

__all__ = ["MAX_TURN_RAD_S", "MAX_UNWRAPPED_TURNS", "check_headings", "turn_rates_rad_s"]

MAX_TURN_RAD_S = 4 * math.pi
"""No robot on the field turns faster than two turns a second; unwrapped headings never jump."""
MAX_UNWRAPPED_TURNS = 8
"""An unwrapped heading lies within this many turns of straight ahead (a penalty kick lasts at
most a minute)."""


def turn_rates_rad_s(theta_rad: np.ndarray, t_s: np.ndarray) -> np.ndarray:
    """How fast the heading changes from each reading to the next (times increasing), rad/s; 0
    where either reading is lost (NaN)."""
    turn_rad = np.abs(np.diff(theta_rad))
    rates: np.ndarray = np.where(np.isfinite(turn_rad), turn_rad, 0.0) / np.diff(t_s)
    return rates


def check_headings(log: Log, stretches: list[Stretch], units: Units) -> None:
    """A ``TrackLogError`` if the headings cannot be angles in the declared unit (see above)."""
    theta = log.measured["robot_theta"]
    turns = np.abs(theta) / (2 * math.pi)
    most_turns = float(np.nanmax(turns, initial=0.0))
    if most_turns <= 1 + 1e-9 / (2 * math.pi):  # within a full turn, as a wrapping tracker writes
        return
    angle = units["angle"]
    per_unit = UNITS["angle"][angle]
    # The hint stands only where degrees would pass the check that failed.
    degrees_per_rad = UNITS["angle"]["deg"]
    hint = f"; did you mean {unit_hint('angle', 'deg')}?" if angle == "rad" else ""
    if most_turns > MAX_UNWRAPPED_TURNS:
        row = int(np.nanargmax(turns))
        fits = most_turns * degrees_per_rad <= MAX_UNWRAPPED_TURNS
        raise TrackLogError(f"{log.where(row, 'robot_theta')}: heading {theta[row] / per_unit:g} {angle} is more "
                            f"than {MAX_UNWRAPPED_TURNS} full turns, too many even for an unwrapped heading"
                            f"{hint if fits else ''}")
    t_s = log.measured["t"]
    for stretch in stretches:
        rows = slice(stretch.start, stretch.stop)
        rate = turn_rates_rad_s(theta[rows], t_s[rows])
        fast = np.flatnonzero(rate > MAX_TURN_RAD_S)
        if fast.size:
            row = stretch.start + int(fast[0]) + 1
            raise TrackLogError(
                f"{log.where(row, 'robot_theta')}: heading {theta[row] / per_unit:g} {angle} after "
                f"{theta[row - 1] / per_unit:g} {angle} {t_s[row] - t_s[row - 1]:.3g} s before, a turn of "
                f"{rate[fast[0]] / (2 * math.pi):.3g} turns a second (at most {MAX_TURN_RAD_S / (2 * math.pi):g}); "
                f"headings beyond a full turn are read as unwrapped only where they change smoothly"
                f"{hint if rate[fast[0]] * degrees_per_rad <= MAX_TURN_RAD_S else ''}")
