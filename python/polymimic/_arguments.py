"""Arguments checked where they cross into the library: the errors name the argument, the value
and what is allowed (Python's own say only that an int was expected, and take True as 1)."""

from __future__ import annotations

import math
import numbers
from typing import Any

__all__ = ["finite", "in_range", "integer", "probability", "whole"]


def integer(name: str, value: Any, low: int, high: int | None = None) -> int:
    """``value`` as an int in ``low..high`` (inclusive); a ``TypeError`` for a bool or a
    non-integer, a ``ValueError`` naming ``name`` for one out of range.

    >>> integer("n", 3, 1)
    3
    >>> integer("n", True, 1)
    Traceback (most recent call last):
    ...
    TypeError: n must be an integer, got True
    """
    number = whole(name, value)
    if number < low or (high is not None and number > high):
        allowed = f"at least {low}" if high is None else f"in {low}..{high}"
        raise ValueError(f"{name} must be {allowed}, got {number}")
    return number


def whole(name: str, value: Any) -> int:
    """``value`` as an int; a ``TypeError`` naming ``name`` for a bool or a non-integer (its range
    is the caller's to check, in the caller's words)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer, got {value!r}")
    return int(value)


def in_range(name: str, value: float, low: float, high: float | None = None, *, exclusive_low: bool = False) -> None:
    """A ``ValueError`` naming ``name = value`` unless ``value`` is a finite number from ``low`` (or
    above it, ``exclusive_low``) to ``high``, worded as a config's key is (the config prefixes
    its section).

    >>> in_range("trials", 0, 1)
    Traceback (most recent call last):
    ...
    ValueError: trials = 0 must be at least 1
    """
    below = value <= low if exclusive_low else value < low
    if not math.isfinite(value) or below or (high is not None and value > high):
        bound = f"{'above' if exclusive_low else 'at least'} {low}"
        bound += f" and at most {high}" if high is not None else ""
        raise ValueError(f"{name} = {value!r} must be {bound}")


def finite(name: str, value: Any, *, low: float | None = None) -> float:
    """``value`` as a float if it is a finite real number (at least ``low`` where given); a
    ``ValueError`` naming ``name``, the value and what is allowed for anything else (a bool
    included).

    >>> finite("gap_margin", -1.0, low=0)
    Traceback (most recent call last):
    ...
    ValueError: gap_margin must be a finite number ≥ 0, got -1.0
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) or \
            (low is not None and value < low):
        raise ValueError(f"{name} must be a finite number{'' if low is None else f' ≥ {low:g}'}, got {value!r}")
    return float(value)


def probability(name: str, value: Any) -> float:
    """``value`` as a float in [0, 1]; a ``ValueError`` naming ``name``, the value and the range
    for anything else: out of range, NaN, a bool (``True`` is not a probability) or no number.

    >>> probability("lapse", 0.25)
    0.25
    >>> probability("lapse", 1.5)
    Traceback (most recent call last):
    ...
    ValueError: lapse must be a number in [0, 1], got 1.5
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0.0 <= float(value) <= 1.0:
        raise ValueError(f"{name} must be a number in [0, 1], got {value!r}")
    return float(value)
