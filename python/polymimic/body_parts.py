"""What a body is made of beyond its constants: the slip of its wheels and the field it plays
on, as checked values. :mod:`polymimic.bodies` re-exports :class:`Slip` and :class:`Field`.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from typing import Any

__all__ = ["Field", "Slip", "number_in"]


def number_in(name: str, value: Any, low: float, high: float, *, open_low: bool = False) -> float:
    """``value`` as a float if it is a real number in ``[low, high]`` (above ``low`` where
    ``open_low``), else a ``ValueError`` naming ``name`` and what is allowed."""
    number = float(value) if isinstance(value, numbers.Real) and not isinstance(value, bool) else math.nan
    if not math.isfinite(number) or number > high or number < low or (open_low and number <= low):
        if open_low and low == 0:
            allowed = "a positive number" if high >= 1e6 else f"a positive number at most {high:g}"
        else:
            allowed = f"a number in [{low:g}, {high:g}]"
        raise ValueError(f"{name} must be {allowed}, got {value!r}")
    return number


@dataclasses.dataclass(frozen=True)
class Slip:
    """How far the wheels stray from what a command asks, drawn afresh whenever a command starts
    (and after each second it is held): a common factor, log-normal with mean 1 and sd
    ``common_sd``, scales both wheels (carpet, battery); a differential δ, normal with sd
    ``differential_sd``, slows the left wheel by (1 − δ) and speeds the right by (1 + δ)."""

    common_sd: float = 0.2
    differential_sd: float = 0.04

    def __post_init__(self) -> None:
        number_in("slip.common_sd", self.common_sd, 0.0, 10.0)
        number_in("slip.differential_sd", self.differential_sd, 0.0, 1.0)



@dataclasses.dataclass(frozen=True)
class Field:
    """A field of your own: its length (goal line to goal line) and width, the width of each goal
    mouth (centred on its line; half the field's width unless given) and the ball's diameter,
    mm. Checked when made: sizes positive, the ball narrower than the mouth, the mouth no wider
    than the field.

    >>> Field(1500, 1000).goal_mouth_mm
    500.0
    """

    length_mm: float
    width_mm: float
    goal_mouth_mm: float | None = None
    ball_diameter_mm: float = 100.0

    def __post_init__(self) -> None:
        length = number_in("field.length_mm", self.length_mm, 0.0, 1e6, open_low=True)
        width = number_in("field.width_mm", self.width_mm, 0.0, 1e6, open_low=True)
        mouth = width / 2 if self.goal_mouth_mm is None else number_in("field.goal_mouth_mm", self.goal_mouth_mm,
                                                                         0.0, width, open_low=True)
        ball = number_in("field.ball_diameter_mm", self.ball_diameter_mm, 0.0, mouth, open_low=True)
        if ball >= mouth:
            raise ValueError(f"field.ball_diameter_mm must be below the goal mouth ({mouth:g} mm), got {ball:g}")
        for name, value in (("length_mm", length), ("width_mm", width), ("goal_mouth_mm", mouth),
                            ("ball_diameter_mm", ball)):
            object.__setattr__(self, name, value)

    @property
    def half_length_mm(self) -> float:
        """Where the goal lines are: x = ± this."""
        return self.length_mm / 2

    @property
    def half_width_mm(self) -> float:
        """Where the side lines are: y = ± this."""
        return self.width_mm / 2

    @property
    def goal_half_mouth_mm(self) -> float:
        """How far from the centre line a goal mouth reaches."""
        return float(self.goal_mouth_mm or 0) / 2

    def sizes(self) -> dict[str, float]:
        """The four sizes by name."""
        return {"length_mm": self.length_mm, "width_mm": self.width_mm, "goal_mouth_mm": float(self.goal_mouth_mm or 0),
                "ball_diameter_mm": self.ball_diameter_mm}
