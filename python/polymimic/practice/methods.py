"""The ways an imitator practises, by name, behind one call.

- ``refine``: it replays its own policy and refines its world model's ball response and state
  values from its attempts (:func:`polymimic.practice.practice`).
- ``explore``: it plays exploring around the ball (a random primitive at rate 0.3 when the ball
  is near) and learns from its attempts as physics only, the ball's response
  (:mod:`polymimic.practice.exploring`).
- ``jsrl``: it guides an RL learner by jump-start RL (:func:`polymimic.practice.teacher.jsrl`;
  needs the ``rl`` extra).
"""

from __future__ import annotations

from typing import Any

from polymimic.learning import ImitatorPolicy
from polymimic.practice.loop import Practice, practice

__all__ = ["EXPLORE_RATE", "METHODS", "practise"]

METHODS = ("refine", "explore", "jsrl")
EXPLORE_RATE = 0.3
"""``explore``'s rate of random primitives with the ball near."""


def practise(policy: ImitatorPolicy, *, method: str = "refine", steps: int, seed: int = 0,
             evaluation_seed: int = 0, evaluation_attempts: int = 25, field_config: Any = None,
             segmenter: dict[str, Any] | None = None) -> Practice:
    """``policy`` practised by ``method`` (one of :data:`METHODS`) for ``steps`` environment
    steps under ``seed``, scored at the default checkpoints on the evaluation attempts of
    ``evaluation_seed``. A jump-start practice's ``policy`` is a
    :class:`~polymimic.practice.practised.PractisedPolicy` and learns from no attempts of its
    own (``attempts`` empty)."""
    if method not in METHODS:
        raise ValueError(f"unknown practice method {method!r}; expected one of {', '.join(METHODS)}")
    if method == "jsrl":
        from polymimic.practice.curve import DEFAULT_CHECKPOINTS
        from polymimic.practice.teacher import jsrl

        marks = [c for c in DEFAULT_CHECKPOINTS if c < steps] + [steps]
        taught = jsrl(policy, steps=steps, seed=seed, checkpoints=marks, evaluation_seed=evaluation_seed,
                      evaluation_attempts=evaluation_attempts, field_config=field_config)
        return Practice(policy=taught.policy, curve=taught.curve, steps=taught.steps, attempts=[], attempts_lost=0)
    explore = EXPLORE_RATE if method == "explore" else 0.0
    return practice(policy, steps=steps, seed=seed, evaluation_seed=evaluation_seed,
                    evaluation_attempts=evaluation_attempts, field_config=field_config, segmenter=segmenter,
                    explore=explore, refines=["ball_response"] if method == "explore" else None)
