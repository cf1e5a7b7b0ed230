"""Readings at one rate resampled to another: linear in position, along the shorter arc in
heading, the command held from the reading that sent it.

>>> import numpy as np
>>> t_s = np.array([0.0, 1.0])
>>> float(np.degrees(heading(t_s, np.radians([170.0, -170.0]), np.array([0.5]))[0]))  # across ±180°
180.0
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["FRAME_RATE_HZ", "grid", "heading", "held", "linear", "wrap_angle"]

FRAME_RATE_HZ = 30.0
"""polymimic's tracker rate: frames at 0, 1/30, 2/30, … s."""
TIME_SLACK_S = 5e-4
"""A reading this close to a grid time is at it: half a millisecond, so that timestamps written
to the millisecond (0.0333 for 1/30 s) still reach their frame."""


def grid(duration_s: float, rate_hz: float = FRAME_RATE_HZ) -> np.ndarray:
    """Times ``0, 1/rate_hz, 2/rate_hz, …`` up to ``duration_s`` (inclusive, within
    :data:`TIME_SLACK_S`).

    >>> grid(0.1).round(4).tolist()
    [0.0, 0.0333, 0.0667, 0.1]
    """
    n = math.floor(duration_s * rate_hz + TIME_SLACK_S * rate_hz) + 1
    times: np.ndarray = np.arange(n) / rate_hz
    return times


def wrap_angle(theta_rad: np.ndarray) -> np.ndarray:
    """Angles wrapped to (−π, π].

    >>> wrap_angle(np.array([np.pi, -np.pi, 3 * np.pi / 2])).round(4).tolist()
    [3.1416, 3.1416, -1.5708]
    """
    wrapped: np.ndarray = np.pi - np.mod(np.pi - theta_rad, 2 * np.pi)
    return wrapped


def linear(t_s: np.ndarray, values: np.ndarray, at_s: np.ndarray) -> np.ndarray:
    """``values`` read at ``t_s`` (increasing), interpolated linearly at ``at_s``."""
    out: np.ndarray = np.interp(at_s, t_s, values)
    return out


def heading(t_s: np.ndarray, theta_rad: np.ndarray, at_s: np.ndarray) -> np.ndarray:
    """Headings interpolated along the shorter arc between consecutive readings, wrapped to
    (−π, π]."""
    return wrap_angle(linear(t_s, np.unwrap(theta_rad), at_s))


def held(t_s: np.ndarray, values: np.ndarray, at_s: np.ndarray) -> np.ndarray:
    """At each of ``at_s``, the value of the latest reading at or before it (a command stays in
    force until the next one is sent).

    >>> held(np.array([0.0, 1.0]), np.array([4, 2]), np.array([0.0, 0.5, 1.0])).tolist()
    [4, 4, 2]
    """
    index = np.searchsorted(t_s, at_s + TIME_SLACK_S, side="right") - 1
    out: np.ndarray = values[np.clip(index, 0, len(values) - 1)]
    return out
