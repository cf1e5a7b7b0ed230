"""How an episode ended, from the field's geometry, and which configuration it started from.

An outcome missing from the log is read off the frames, as the simulated field decides it:

- the ball's centre crossing the target goal line (x = +L/2) inside the mouth (|y| at most
  half the mouth's width, at the point where it crosses; the thesis's mouths are half the field's
  width) is a ``goal``; the own goal line (x = −L/2) inside the mouth an
  ``own_goal``; either goal line outside the mouth, or a side line (|y| > W/2), ``ball_out``;
- the robot's centre leaving the field is ``robot_out``;
- a reading is beyond a line when it is more than the tolerance (:data:`LINE_TOLERANCE_MM`)
  past it: a ball pushed slowly over the line sits on it for several frames, and the tracker's
  jitter (σ 0.3 mm on the simulated field, which decides on the true position) would otherwise
  end the episode a few frames early;
- whichever left first between two frames wins (the ball on a tie); the episode ends on the
  first frame beyond the line, and frames after it are cut;
- a log that ends, with nothing beyond a line, with the ball's (or else the robot's) centre
  within the tolerance of a line ended because it crossed there: the final reading of a ball
  that just crossed can be jittered back inside;
- otherwise ``time_up``.

The configuration, when neither the caller nor the log gives it, is read from the first frame:
the robot behind the ball (smaller x) is configuration 1, otherwise 2 (configuration 1 puts the
robot at −L/6 and the ball at +L/6; configuration 2 mirrors it).
"""

from __future__ import annotations

import numpy as np

from polymimic.bodies import Field

__all__ = ["LINE_TOLERANCE_MM", "configuration_of", "outcome_of"]

LINE_TOLERANCE_MM = 1.0
"""A reading counts as beyond a line once more than this past it, and a log ending with the ball
or the robot this close to a line ended because it crossed it: about three times the simulated
tracker's jitter."""


def outcome_of(frames: np.ndarray, field: Field, *, tolerance_mm: float = LINE_TOLERANCE_MM) -> tuple[str, int]:
    """The outcome of ``frames`` (:data:`~polymimic.field.FRAME_DTYPE`) and how many frames to
    keep: up to and including the first frame beyond a line.

    >>> import numpy as np
    >>> from polymimic.field import FRAME_DTYPE
    >>> frames = np.zeros(4, dtype=FRAME_DTYPE)
    >>> frames["ball_x_mm"] = [480.0, 500.0, 520.0, 540.0]
    >>> outcome_of(frames, Field(1020.0, 810.0))
    ('goal', 3)
    """
    ball_x, ball_y = frames["ball_x_mm"], frames["ball_y_mm"]
    robot_x, robot_y = frames["robot_x_mm"], frames["robot_y_mm"]
    hl, hw = field.half_length_mm + tolerance_mm, field.half_width_mm + tolerance_mm
    ball_out = (np.abs(ball_x) > hl) | (np.abs(ball_y) > hw)
    robot_out = (np.abs(robot_x) > hl) | (np.abs(robot_y) > hw)
    if (ball_out | robot_out).any():
        i = int(np.argmax(ball_out | robot_out))
        j = max(i - 1, 0)
        ball_at = _leaving(ball_x[j], ball_y[j], ball_x[i], ball_y[i], field) if ball_out[i] else 2.0
        robot_at = _leaving(robot_x[j], robot_y[j], robot_x[i], robot_y[i], field) if robot_out[i] else 2.0
        if ball_at <= robot_at:
            return _ball_outcome(ball_x[j], ball_y[j], ball_x[i], ball_y[i], field), i + 1
        return "robot_out", i + 1
    return _at_the_end(frames, field, tolerance_mm), len(frames)


def configuration_of(frames: np.ndarray) -> int:
    """1 if the first frame has the robot behind the ball toward −x, else 2.

    >>> import numpy as np
    >>> from polymimic.field import FRAME_DTYPE
    >>> frames = np.zeros(1, dtype=FRAME_DTYPE)
    >>> frames["robot_x_mm"], frames["ball_x_mm"] = 170.0, -170.0
    >>> configuration_of(frames)
    2
    """
    return 1 if frames["robot_x_mm"][0] < frames["ball_x_mm"][0] else 2


def _leaving(x0: float, y0: float, x1: float, y1: float, field: Field) -> float:
    """The share of the step from (x0, y0) to (x1, y1) at which the point first leaves the field."""
    shares = []
    for a, b, half in ((x0, x1, field.half_length_mm), (y0, y1, field.half_width_mm)):
        if abs(b) > half:
            line = np.copysign(half, b)
            shares.append(float(np.clip((line - a) / (b - a), 0.0, 1.0)) if b != a else 0.0)
    return min(shares)


def _ball_outcome(x0: float, y0: float, x1: float, y1: float, field: Field) -> str:
    hl = field.half_length_mm
    if abs(x1) > hl:
        line = np.copysign(hl, x1)
        share = float(np.clip((line - x0) / (x1 - x0), 0.0, 1.0)) if x1 != x0 else 1.0
        y_cross = y0 + share * (y1 - y0)
        if abs(y_cross) <= field.goal_half_mouth_mm:
            return "goal" if x1 > 0 else "own_goal"
    return "ball_out"


def _at_the_end(frames: np.ndarray, field: Field, tolerance_mm: float) -> str:
    """``time_up``, unless the last frame has the ball or the robot on a line (within the
    tolerance)."""
    if len(frames) == 0:
        return "time_up"
    last = frames[-1]
    hl, hw = field.half_length_mm, field.half_width_mm
    ball_x, ball_y = float(last["ball_x_mm"]), float(last["ball_y_mm"])
    if hl - abs(ball_x) <= tolerance_mm:
        if abs(ball_y) <= field.goal_half_mouth_mm:
            return "goal" if ball_x > 0 else "own_goal"
        return "ball_out"
    if hw - abs(ball_y) <= tolerance_mm:
        return "ball_out"
    if min(hl - abs(float(last["robot_x_mm"])), hw - abs(float(last["robot_y_mm"]))) <= tolerance_mm:
        return "robot_out"
    return "time_up"
