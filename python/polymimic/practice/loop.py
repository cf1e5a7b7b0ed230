"""Practice (docs/guides/practice.md): after watching, the imitator plays attempts on its own field and learns
from what the tracker showed of them.

Each round the policy plays ``attempts_per_round`` attempts from each field configuration, from
practice seeds (:mod:`polymimic.practice.seeds`), watched by the same tracker as any
demonstrator; by default it explores around the ball as it plays
(:mod:`polymimic.practice.exploring`). An attempt the tracker lost the robot or the ball in is left out and counted, as
§3.2.1 leaves out a demonstration; every other is cut where the tracker shows the ball or the
robot leaving the field, its outcome read off its frames (:func:`polymimic.tracks.outcomes.outcome_of`,
never the simulator's), and segmented by the imitator's own recogniser. The policy is then made
again with all its own attempts so far beside the demonstrations
(:meth:`polymimic.ImitatorPolicy.practised`): how the ball answered each of its own body's
primitives now also comes from its own play (and, with ``refines=None``, how the states it passed
through ended). Where the demonstrators pushed from stays theirs: the imitator's own pushes, many
of them corrections, widen that region and cost goals.

One environment step is one second of play (an attempt of 35.2 s costs 36 steps). The attempts
of a round are played together; at a checkpoint only the round's leading attempts that fit within
it count and refine the policy, and the policy is scored on the evaluation attempts (the 50 every
method plays), which never feed back into learning.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
import sys
from collections.abc import Sequence
from typing import Any

from polymimic import _native
from polymimic._arguments import probability
from polymimic._native import SegmentedDemonstrations
from polymimic.bodies import Body
from polymimic.evaluation import Attempts, thesis_attempts
from polymimic.field import Demonstration
from polymimic.field_config import native_field_config
from polymimic.learning import ImitatorPolicy, evaluate
from polymimic.practice.curve import DEFAULT_CHECKPOINTS, CurvePoint
from polymimic.practice.exploring import EXPLORE_RATE, explored_attempts
from polymimic.practice.practised import PractisedPolicy
from polymimic.practice.seeds import MAX_ROUNDS, check_apart, round_seed
from polymimic.tracks.outcomes import outcome_of

__all__ = ["Practice", "practice", "steps_of"]

FRAMES_PER_STEP = 30


@dataclasses.dataclass(frozen=True)
class Practice:
    """What :func:`practice` returns: the refined ``policy``, its ``curve`` (one point per
    checkpoint), the environment ``steps`` it played, and its own ``attempts`` (the ones it
    learned from, each with the outcome read off its frames)."""

    policy: ImitatorPolicy | PractisedPolicy
    curve: list[CurvePoint]
    steps: int
    attempts: list[Demonstration]
    attempts_lost: int


def steps_of(attempt: Demonstration) -> int:
    """Environment steps an attempt played: its seconds, a started second counting whole.

    >>> import numpy as np
    >>> from polymimic.field import FRAME_DTYPE
    >>> steps_of(Demonstration(frames=np.zeros(31, FRAME_DTYPE), outcome="goal", demonstrator="me",
    ...                        configuration=1, seed=0, body="lego"))
    2
    """
    return math.ceil(len(attempt.frames) / FRAMES_PER_STEP)


def practice(policy: ImitatorPolicy, *, steps: int = 25_000, seed: int = 0,
             checkpoints: Sequence[int] | None = None, attempts_per_round: int = 10,
             evaluation: Attempts = Attempts(), field_config: Any = None,
             segmenter: dict[str, Any] | None = None, weight: float = 1.0, quiet: bool = True,
             explore: float = EXPLORE_RATE, refines: Sequence[str] | None = ("ball_response",)) -> Practice:
    """Practise ``policy`` (an improved-control :class:`~polymimic.ImitatorPolicy` made with its
    constructor) for a budget of ``steps`` environment steps under practice ``seed``.

    ``checkpoints`` (default :data:`~polymimic.practice.curve.DEFAULT_CHECKPOINTS` up to the
    budget, and the budget) are the steps at which the policy is scored on the ``evaluation``
    attempts (an :class:`~polymimic.Attempts` from the thesis's configurations, which practice
    never plays; a ``ValueError`` for one with starts of its own) on the field ``field_config``
    describes (as :func:`polymimic.evaluate`); they must rise from 0 to at most ``steps``.
    ``segmenter`` passes the segmenter's settings, ``weight`` is what every sample of its own
    attempts weighs beside the demonstrations' (1: as much as the best demonstrator's under LP
    weighting); ``quiet=False`` shows a progress bar of steps. Zero steps return the policy as it
    was, bit for bit.

    ``explore`` plays each round's attempts exploring around the ball at that rate
    (:func:`~polymimic.practice.exploring.explored_attempts`; 0: as the policy chooses);
    ``refines`` names the parts of the world model its own attempts refine (default: the ball's
    response alone, physics; None: the ball's response and the states' values). The defaults are
    the ``explore`` method; ``explore=0, refines=None`` replays its own policy and refines both,
    which did not earn a method of its own on validation attempts (docs/guides/practice.md).

    >>> import polymimic
    >>> from polymimic import learning, recognition
    >>> recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1), codebook_size=32)
    >>> demos = polymimic.record("expert", configuration=1, n=3, seed=0)
    >>> trial = learning.run_trial(demos, recognizer=recognizer, ordering=["expert"])
    >>> policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demos)
    >>> result = practice(policy, steps=200, checkpoints=[0, 200], attempts_per_round=2,
    ...                   evaluation=polymimic.Attempts(per_configuration=2))
    >>> [p.checkpoint for p in result.curve], result.steps <= 200
    ([0, 200], True)
    """
    budget = _whole("steps", steps, 0)
    seed = _whole("seed", seed, 0, 2**62 - 1)
    per_round = _whole("attempts_per_round", attempts_per_round, 1)
    explore = probability("explore", explore)
    marks = _checkpoints(checkpoints, budget)
    scored_on = thesis_attempts(evaluation, name="evaluation")
    made_from = _trained(policy)
    body = made_from.body
    field = body.field
    learned: list[Demonstration] = []
    own: SegmentedDemonstrations | None = None
    lost = played_steps = round_index = 0
    refined = policy
    curve: list[CurvePoint] = []

    def score(mark: int) -> None:
        result = evaluate(refined, attempts=scored_on, field_config=field_config)
        curve.append(CurvePoint(mark, played_steps, result.goals - result.own_goals, result.goals, result.own_goals,
                                len(learned), lost))

    with _bar(budget, quiet) as bar:
        for mark in marks:
            full = mark == 0
            while not full and played_steps < mark:
                if round_index >= MAX_ROUNDS:
                    raise ValueError(f"practice ran out of rounds before {mark} steps")
                round_at = round_seed(seed, round_index)
                check_apart(_native.attempt_seeds(per_round, seed=round_at), evaluation=scored_on)
                round_index += 1
                if explore > 0.0:
                    attempts = explored_attempts(refined, attempts_per_configuration=per_round, seed=round_at,
                                                 epsilon=explore, field_config=native_field_config(field_config))
                else:
                    attempts = evaluate(refined, attempts_per_configuration=per_round, seed=round_at,
                                        field_config=field_config).attempts
                new = []
                for attempt in attempts:
                    cost = steps_of(attempt)
                    if played_steps + cost > mark:
                        full = True
                        break
                    played_steps += cost
                    bar.update(cost)
                    if not attempt.tracked_throughout:
                        lost += 1
                        continue
                    new.append(_as_tracked(attempt, field, body))
                if new:
                    learned += new
                    batch = SegmentedDemonstrations(_segmented(new, made_from.recognizer, body, segmenter))
                    own = batch if own is None else own + batch
                    refined = policy.practised(own, weight=weight, refines=refines)
            score(mark)
    return Practice(policy=refined, curve=curve, steps=played_steps, attempts=learned, attempts_lost=lost)


def _bar(total: int, quiet: bool) -> Any:
    """A tqdm bar of practice steps on stderr, unless ``quiet`` or stderr is no terminal."""
    from tqdm import tqdm

    return tqdm(total=total, desc="practice", unit="step", file=sys.stderr, leave=False, dynamic_ncols=True,
                disable=quiet or not sys.stderr.isatty())


def _as_tracked(attempt: Demonstration, field: Any, body: Body) -> Demonstration:
    """The attempt as the tracker showed it: cut where it shows the ball or robot leaving the
    field, with the outcome read off the frames."""
    outcome, keep = outcome_of(attempt.frames, field)
    return Demonstration(frames=attempt.frames[:keep], outcome=outcome, demonstrator="imitator",
                         configuration=attempt.configuration, seed=attempt.seed, body=body)


def _segmented(attempts: list[Demonstration], recognizer: Any, body: Body,
               segmenter: dict[str, Any] | None) -> list[dict[str, Any]]:
    """Its own attempts as the world model learns them: segmented by its own recogniser, played on
    its own field with its own reach as an imitator."""
    found = recognizer.segment_many([a.frames for a in attempts], **(segmenter or {}))
    return [{"demonstrator": "imitator", "outcome": a.outcome, "segments": s, "body": body, "imitating": True}
            for a, s in zip(attempts, found)]


def _trained(policy: Any) -> Any:
    """What ``policy`` is made from, refusing what practice cannot refine."""
    if not isinstance(policy, ImitatorPolicy) or not hasattr(policy, "_made_from"):
        raise ValueError(f"practice needs a trained polymimic.ImitatorPolicy made with its constructor (a policy "
                         f"for_trial makes keeps no demonstrations to learn again from), got {policy!r}")
    if policy.control != "improved":
        raise ValueError("practice refines the improved control's world model: make the policy with "
                         "control='improved'")
    if len(policy) == 0:
        raise ValueError("the policy was never trained: its imitator holds no behaviours")
    return policy.made_from


def _whole(name: str, value: Any, low: int, high: int | None = None) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or int(value) < low or \
            (high is not None and int(value) > high):
        allowed = f"an integer of at least {low}" + (f" and at most {high}" if high is not None else "")
        raise ValueError(f"{name} must be {allowed}, got {value!r}")
    return int(value)


def _checkpoints(checkpoints: Sequence[int] | None, budget: int) -> list[int]:
    if checkpoints is None:
        marks = [c for c in DEFAULT_CHECKPOINTS if c <= budget]
        return marks if marks[-1] == budget else [*marks, budget]
    marks = [_whole("checkpoint", c, 0) for c in checkpoints]
    if not marks or marks[0] != 0:
        raise ValueError(f"checkpoints must start at 0 (the policy before practice), got {list(checkpoints)!r}")
    if any(b <= a for a, b in zip(marks, marks[1:])):
        raise ValueError(f"checkpoints must rise, got {list(checkpoints)!r}")
    if marks[-1] > budget:
        raise ValueError(f"checkpoint {marks[-1]} lies beyond the budget of {budget} steps")
    return marks

