"""The ways an imitator practises, by name, behind one call.

- ``distil`` (the default, chosen on validation attempts: docs/guides/practice.md): it is
  distilled into an RL actor by DAgger, whose critic warms up before PPO fine-tunes it with the
  teacher's term annealed (:func:`polymimic.practice.distil.distil`; needs the ``rl`` extra).
- ``explore``: it plays exploring around the ball (a random primitive at rate 0.3 when the ball
  is near) and learns from its attempts as physics only, the ball's response
  (:func:`polymimic.practice.practice`, :mod:`polymimic.practice.exploring`); it needs no extra.
- ``jsrl``: it guides an RL learner by jump-start RL (:func:`polymimic.practice.teacher.jsrl`;
  needs the ``rl`` extra).

Replaying its own policy and refining the world model's ball response and state values from it
(``practice(..., explore=0, refines=None)``, the first way practice was built) is no method of
its own: on the same validation attempts it gained a quarter of a goal of 100 where ``explore``,
needing nothing more either, gained 2.75.
"""

from __future__ import annotations

import importlib.util
from typing import Any

from polymimic.evaluation import Attempts
from polymimic.learning import ImitatorPolicy
from polymimic.practice.exploring import EXPLORE_RATE
from polymimic.practice.loop import Practice, practice

__all__ = ["DEFAULT_METHOD", "EXPLORE_RATE", "METHODS", "RETIRED_METHODS", "THROUGH_THE_TEACHER", "needs_rl_extra",
           "practise"]

METHODS = ("explore", "jsrl", "distil")
DEFAULT_METHOD = "distil"
"""The method that won on validation attempts: never below its teacher there (docs/guides/practice.md)."""
RETIRED_METHODS = ("refine",)
"""Methods practice no longer offers, whose files and runs still read: ``refine`` replayed its
own policy and refined the ball's response and the states' values (a practice file without a
``method`` key is one)."""
THROUGH_THE_TEACHER = ("jsrl", "distil")
"""The methods that train an RL learner (stable-baselines3: the ``rl`` extra)."""


def practise(policy: ImitatorPolicy, *, method: str = DEFAULT_METHOD, steps: int, seed: int = 0,
             evaluation: Attempts = Attempts(), field_config: Any = None,
             segmenter: dict[str, Any] | None = None) -> Practice:
    """``policy`` practised by ``method`` (one of :data:`METHODS`) for ``steps`` environment
    steps under ``seed``, scored at the default checkpoints on the ``evaluation`` attempts (an
    :class:`~polymimic.Attempts` from the thesis's configurations; a ``ValueError`` for one with
    starts of its own). A jump-start practice's ``policy`` is a
    :class:`~polymimic.practice.practised.PractisedPolicy` and learns from no attempts of its
    own (``attempts`` empty). A ``ModuleNotFoundError`` says how to install the ``rl`` extra a
    method through the teacher needs where stable-baselines3 is missing."""
    if method in RETIRED_METHODS:
        raise ValueError(f"practice method {method!r} is retired (it earned no place on validation: "
                         f"docs/guides/practice.md); practice(policy, ..., explore=0, refines=None) still plays it, "
                         f"or use one of {', '.join(METHODS)}")
    if method not in METHODS:
        raise ValueError(f"unknown practice method {method!r}; expected one of {', '.join(METHODS)}")
    needs_rl_extra(method)
    if method in THROUGH_THE_TEACHER:
        from polymimic.practice.curve import DEFAULT_CHECKPOINTS
        from polymimic.practice.distil import distil
        from polymimic.practice.teacher import jsrl

        marks = [c for c in DEFAULT_CHECKPOINTS if c < steps] + [steps]
        taught = (jsrl if method == "jsrl" else distil)(
            policy, steps=steps, seed=seed, checkpoints=marks, evaluation=evaluation, field_config=field_config)
        return Practice(policy=taught.policy, curve=taught.curve, steps=taught.steps, attempts=[], attempts_lost=0)
    return practice(policy, steps=steps, seed=seed, evaluation=evaluation, field_config=field_config,
                    segmenter=segmenter, explore=EXPLORE_RATE, refines=("ball_response",))


def needs_rl_extra(method: str) -> None:
    """A ``ModuleNotFoundError`` if ``method`` trains an RL learner and stable-baselines3 is missing."""
    if method in THROUGH_THE_TEACHER and importlib.util.find_spec("stable_baselines3") is None:
        raise ModuleNotFoundError(f"practice by {method} needs stable-baselines3 and torch: pip install "
                                  f"\"polymimic[rl]\" (explore needs neither)")
