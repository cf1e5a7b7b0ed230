"""Python demonstrators (docs/guides/own-data.md): what :func:`polymimic.record` accepts as a policy.

A policy is a callable ``policy(reading) -> command`` or an object with ``act(reading) ->
command`` and, optionally, ``reset(episode)`` (called before every episode with a dict of its
``attempt``, ``configuration``, ``seed`` and ``body``). ``reading`` is a
:class:`polymimic.Reading`: the tracker's latest reading (``t_s``, ``robot_x_mm``,
``robot_y_mm``, ``robot_theta_rad``, ``ball_x_mm``, ``ball_y_mm`` (NaN when the robot cannot see
the ball), ``ball_seen``, ``frame``, ``field_length_mm``, ``field_width_mm``). A command is a
primitive's name (``"forward"``, ``"backward"``, ``"left"``, ``"right"``, ``"stop"``), a command
of the body's language by name or id (on the Lego body the Expert's named wheel-speed pairs,
such as ``"arc_left_tight_fast"``; on the humanoid ``"Walk Forward"``, ``"Kick Left"``, …; see
:func:`polymimic.command_table`), or on a wheeled body a ``(left_mm_s, right_mm_s)`` pair of
wheel speeds within its top speed (kept to the micrometre per second; the frames record it by
the primitive it resembles, ``wheels_forward`` … ``wheels_stop``).

The policy decides ``decision_hz`` times a second (an argument of ``record``, else the policy's
own ``decision_hz`` attribute, else 30: every tracker frame), and each command is held until
its next decision.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from typing import Any

__all__ = ["DECISION_RATES_HZ", "PolicyParts", "policy_parts"]

DECISION_RATES_HZ = (30, 15, 10, 6, 5, 3, 2, 1)
"""The rates a policy may decide at: divisors of the tracker's 30 frames a second, so decisions
fall on frames."""


class PolicyParts:
    """A policy taken apart: its ``act`` and ``reset`` callables, rate and name.

    Attributes
    ----------
    act : callable
        Called with each :class:`polymimic.Reading`; returns the command to hold until the next
        decision.
    reset : callable or None
        Called before every episode with its details.
    decision_hz : float
        Decisions a second (one of :data:`DECISION_RATES_HZ`).
    name : str
        The name the demonstrations are recorded under.
    """

    __slots__ = ("act", "decision_hz", "name", "reset")

    def __init__(self, act: Callable[[Any], Any], reset: Callable[[Any], Any] | None, decision_hz: float,
                 name: str) -> None:
        self.act, self.reset, self.decision_hz, self.name = act, reset, decision_hz, name


def policy_parts(policy: Any, *, decision_hz: Any, name: Any, reserved: tuple[str, ...]) -> PolicyParts:
    """``policy``'s parts, checked: a ``TypeError`` for something that is neither callable nor
    has ``act``, a ``ValueError`` for a rate that does not divide 30 or a missing or reserved
    ``name`` (a built-in demonstrator's, in ``reserved``).

    >>> parts = policy_parts(lambda reading: "forward", decision_hz=10, name="mine", reserved=("expert",))
    >>> parts.decision_hz, parts.name, parts.reset is None
    (10.0, 'mine', True)
    >>> policy_parts(lambda reading: "forward", decision_hz=7, name="mine", reserved=())
    Traceback (most recent call last):
    ...
    ValueError: decision_hz must divide the tracker's 30 frames a second (one of 30, 15, 10, 6, 5, 3, 2, 1), got 7
    """
    act = getattr(policy, "act", None)
    if act is not None:
        if not callable(act):
            raise TypeError(f"the policy's act must be callable, got {act!r}")
        reset = getattr(policy, "reset", None)
        if reset is not None and not callable(reset):
            raise TypeError(f"the policy's reset must be callable, got {reset!r}")
    elif callable(policy):
        act, reset = policy, None
    else:
        raise TypeError(f"a demonstrator is a built-in's name, a callable policy(reading) -> command or an object "
                        f"with act(reading); got {policy!r}")
    rate = decision_hz if decision_hz is not None else getattr(policy, "decision_hz", 30)
    return PolicyParts(act, reset, _rate(rate), _name(name if name is not None else getattr(policy, "name", None),
                                                      reserved))


def _rate(value: Any) -> float:
    rates = ", ".join(map(str, DECISION_RATES_HZ))
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) or \
            value not in DECISION_RATES_HZ:
        raise ValueError(f"decision_hz must divide the tracker's 30 frames a second (one of {rates}), got {value!r}")
    return float(value)


def _name(value: Any, reserved: tuple[str, ...]) -> str:
    if value is None:
        raise ValueError("a Python demonstrator needs a name: record(policy, name=...) or a name attribute on the "
                         "policy")
    if not isinstance(value, str) or not value.isidentifier():
        raise ValueError(f"a demonstrator's name must be a word of letters, digits and _, got {value!r}")
    if value in reserved:
        raise ValueError(f"name {value!r} is a built-in demonstrator's; give your policy a name of its own")
    return value
