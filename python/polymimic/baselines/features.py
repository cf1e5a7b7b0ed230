"""Features a cloned policy computes from the environment's observation.

An observation is ``[robot x mm, robot y mm, robot θ rad, ball x mm, ball y mm]`` in field
coordinates (``PenaltyKick-v0``'s, origin at the centre, +x toward the target goal). A feature
set adds quantities computed from it alone, never anything the observation does not hold:

- ``"raw"``: the observation as it is, θ as sin and cos (so that ±π meet);
- ``"ball_relative"``: ``"raw"`` and the ball seen from the robot: its distance (mm) and its
  bearing from the robot's heading (sin, cos), and its position in the robot's frame (mm);
- ``"goal_relative"``: ``"ball_relative"`` and the target goal: the ball's bearing to the goal
  centre from the robot's heading (sin, cos), the ball's distance to it (mm), the angle at the
  ball between the goal and the robot (cos: −1 when the robot is right behind the ball on the
  ball–goal line), and the robot's signed offset from that line (mm).

>>> import numpy as np
>>> observation = np.array([[-170.0, 0.0, 0.0, 170.0, 0.0]])
>>> features(observation, feature_set="ball_relative")[0, 4:7].round(3).tolist()   # distance, sin, cos
[340.0, 0.0, 1.0]
>>> features(observation, feature_set="goal_relative")[0, -2:].round(3).tolist()  # behind the ball, on the line
[-1.0, 0.0]
"""

from __future__ import annotations

import numpy as np

from polymimic.bodies import BodySpec, as_body

__all__ = ["FEATURE_NAMES", "FEATURE_SETS", "OBSERVATION_SIZE", "TARGET_GOAL_MM", "check_observations", "features",
           "target_goal_of"]

FEATURE_SETS = ("raw", "ball_relative", "goal_relative")
OBSERVATION_SIZE = 5
TARGET_GOAL_MM = (510.0, 0.0)
"""The target goal's centre on the imitator's field (1020 × 810 mm, goal at +x)."""

_RAW = ("robot_x_mm", "robot_y_mm", "sin_theta", "cos_theta", "ball_x_mm", "ball_y_mm")
_BALL = (*_RAW[:4], "ball_dist_mm", "sin_ball_bearing", "cos_ball_bearing", *_RAW[4:],
         "ball_ahead_mm", "ball_left_mm")
FEATURE_NAMES = {
    "raw": _RAW,
    "ball_relative": _BALL,
    "goal_relative": (*_BALL, "sin_goal_bearing", "cos_goal_bearing", "ball_goal_dist_mm", "cos_behind_ball",
                      "line_offset_mm"),
}
"""Each feature set's columns, in order (units in the names)."""


def check_observations(observations: object, *, name: str = "observations") -> np.ndarray:
    """``observations`` as a float ``(n, 5)`` array, or a ValueError naming its shape."""
    array = np.asarray(observations, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != OBSERVATION_SIZE:
        raise ValueError(f"{name} must be an (n, {OBSERVATION_SIZE}) batch of [robot x mm, robot y mm, "
                         f"robot θ rad, ball x mm, ball y mm], got shape {array.shape}")
    return array


def target_goal_of(body: BodySpec) -> tuple[float, float]:
    """The target goal's centre (mm) on the field ``body`` (a :class:`polymimic.Body`, a built-in
    body's name, or a described wheeled body) plays on.

    >>> target_goal_of("lego"), target_goal_of("tiny")
    ((510.0, 0.0), (280.0, 0.0))
    """
    return (as_body(body).field.length_mm / 2, 0.0)


def features(observations: np.ndarray, *, feature_set: str,
             target_goal_mm: tuple[float, float] = TARGET_GOAL_MM) -> np.ndarray:
    """The ``(n, k)`` features of feature set ``feature_set`` for an ``(n, 5)`` batch, on a
    field whose target goal's centre is ``target_goal_mm`` (the thesis's large field's by
    default)."""
    obs = check_observations(observations)
    if feature_set not in FEATURE_SETS:
        raise ValueError(f"unknown feature_set {feature_set!r}; expected one of {', '.join(FEATURE_SETS)}")
    robot_x, robot_y, theta, ball_x, ball_y = obs.T
    columns = [robot_x, robot_y, np.sin(theta), np.cos(theta), ball_x, ball_y]
    if feature_set == "raw":
        return np.column_stack(columns)
    dx, dy = ball_x - robot_x, ball_y - robot_y
    bearing = np.arctan2(dy, dx) - theta
    cos_t, sin_t = np.cos(theta), np.sin(theta)
    columns[4:4] = [np.hypot(dx, dy), np.sin(bearing), np.cos(bearing)]
    columns += [cos_t * dx + sin_t * dy, -sin_t * dx + cos_t * dy]
    if feature_set == "ball_relative":
        return np.column_stack(columns)
    gx, gy = target_goal_mm[0] - ball_x, target_goal_mm[1] - ball_y
    goal_bearing = np.arctan2(gy, gx) - theta
    goal_dist = np.hypot(gx, gy)
    rx, ry = -dx, -dy  # ball → robot
    robot_dist = np.hypot(rx, ry)
    behind = (gx * rx + gy * ry) / np.maximum(goal_dist * robot_dist, 1e-9)
    offset = (gx * ry - gy * rx) / np.maximum(goal_dist, 1e-9)
    columns += [np.sin(goal_bearing), np.cos(goal_bearing), goal_dist, behind, offset]
    return np.column_stack(columns)
