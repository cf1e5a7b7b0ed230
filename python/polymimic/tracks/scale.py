"""Whether a log's readings fit the field in the units declared for them.

Readings more than :data:`MARGIN_SHARE` of the field's size beyond its lines, or x readings that
never reach :data:`MIN_REACH_SHARE` of the half length from the centre (the robot and the ball
start a sixth of the length from it) mean a length unit declared wrong; the error says which
unit would fit, and how to give the log's own field if the log was read on another.
Headings are judged apart, episode by episode (:mod:`polymimic.tracks.headings`).
"""

from __future__ import annotations

import numpy as np

from polymimic.bodies import Field
from polymimic.tracks.errors import TrackLogError
from polymimic.tracks.reading import Log
from polymimic.tracks.units import UNITS, Units, unit_hint

__all__ = ["MARGIN_SHARE", "MIN_REACH_SHARE", "another_field", "check_scale"]

MARGIN_SHARE = 0.2
"""Readings may lie this share of the field's length (width) beyond its end (side) lines."""
MIN_REACH_SHARE = 0.2
"""Some x reading of the robot or the ball must be this share of the half length from the centre."""


def check_scale(log: Log, field: Field, units: Units, *, body: str = "lego") -> None:
    """A ``TrackLogError`` if the positions cannot be in the declared length unit on the field
    of ``body`` (its name, which the message gives)."""
    limit_x = field.half_length_mm + MARGIN_SHARE * field.length_mm
    limit_y = field.half_width_mm + MARGIN_SHARE * field.width_mm
    limits = {"robot_x": limit_x, "ball_x": limit_x, "robot_y": limit_y, "ball_y": limit_y}
    size = {name: float(np.nanmax(np.abs(log.measured[name]), initial=0.0)) for name in limits}
    excess = max(size[name] / limit for name, limit in limits.items())
    reach_mm = max(size["robot_x"], size["ball_x"])
    unit = units["length"]
    declared = UNITS["length"][unit]
    if excess > 1.0:
        name = max(limits, key=lambda n: size[n] / limits[n])
        row = int(np.nanargmax(np.abs(log.measured[name])))
        value = log.measured[name][row] / declared
        hint = _length_hint(excess, reach_mm, field, unit)
        raise TrackLogError(f"{log.where(row, name)}: {value:g} {unit} is far outside the "
                            f"{field.length_mm:g} × {field.width_mm:g} mm field of body {body!r} (more than "
                            f"{MARGIN_SHARE:.0%} of its size beyond the lines){hint}{another_field(hint)}")
    if 0.0 < reach_mm < MIN_REACH_SHARE * field.half_length_mm:
        hint = _length_hint(excess, reach_mm, field, unit)
        raise TrackLogError(f"{log.path}: the robot's and the ball's x readings reach only {reach_mm / declared:g} "
                            f"{unit} from the centre, too little for the {field.length_mm:g} × {field.width_mm:g} mm "
                            f"field of body {body!r}, on which they start {field.length_mm / 6:g} mm from it{hint}"
                            f"{another_field(hint)}")


def another_field(hint: str) -> str:
    """How to give the field a log was read on, after ``hint`` (a unit's, or none)."""
    return (f"{'; or, if' if hint else '; if'} the log is of another field, give a body that plays on it: "
            "body=WheeledBody(..., field=Field(length_mm, width_mm)) in Python, --body FILE.toml (a [bodies.<name>] "
            "table with field = { length_mm = ..., width_mm = ... }) to polymimic import-tracks, or a [bodies.<name>] "
            "table named by the demonstrator's body = in a run config")


def _length_hint(excess: float, reach_mm: float, field: Field, declared: str) -> str:
    """The length unit under which the readings would fit the field, as a question."""
    best = None
    for unit, size in UNITS["length"].items():
        scale = size / UNITS["length"][declared]
        if unit != declared and excess * scale <= 1.0 and reach_mm * scale >= MIN_REACH_SHARE * field.half_length_mm:
            if best is None or excess * scale > best[1]:
                best = (unit, excess * scale)
    return f"; did you mean {unit_hint('length', best[0])}?" if best else ""
