"""Any baseline policy on the imitator's own attempts, every episode stepped together.

:func:`evaluate_policy` plays the attempts :func:`polymimic.evaluate` plays for the imitator:
the same configurations and episode seeds (``polymimic._native.attempt_seeds``), so the same
starts and the same noise. At every decision one batched ``predict`` goes over the
observations of every unfinished episode, and each runs its primitive for the policy's
``frames_per_action`` frames; a vector environment can replace the stepping without the
policies changing. During a tracking dropout the observation repeats the last good reading.

Seeds from :data:`VALIDATION_SEED_BASE` on are reserved for validation (tuning), so an
evaluation seed is below it.

>>> from polymimic import Attempts
>>> from polymimic.baselines.policy import RandomPolicy
>>> result = evaluate_policy(RandomPolicy(seed=0), attempts=Attempts(per_configuration=1, seed=0))
>>> len(result.attempts), [a.configuration for a in result.attempts]
(2, [1, 2])
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from threadpoolctl import threadpool_limits  # type: ignore[import-untyped, unused-ignore]

from polymimic import _native
from polymimic.baselines.policy import Policy
from polymimic.bodies import as_body
from polymimic.evaluation import Attempts, attempts_given
from polymimic.field import PRIMITIVE_SETS, PRIMITIVES, Demonstration, as_frames, primitive_command
from polymimic.field_config import native_field_config
from polymimic.learning import Evaluation

__all__ = ["VALIDATION_SEED_BASE", "attempts_of", "evaluate_policy", "play"]

VALIDATION_SEED_BASE = 2**62
"""Evaluation seeds lie in ``[0, 2**62)``, validation seeds in ``[2**62, 2**63)``: the two
never meet, and the episode seeds derived from them (a hash of the seed, the configuration and
the attempt) are disjoint but for a 64-bit collision, which :func:`polymimic.baselines.tune`
checks for."""

_LETTERS = ("F", "B", "L", "R", "S", "A", "D", "K")


def _check_seed(seed: Any, *, low: int, high: int, what: str) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not low <= seed < high:
        raise ValueError(f"seed must be an integer in [{low}, {high}) ({what}), got {seed!r}")
    return int(seed)


def _check_attempts(attempts_per_configuration: Any) -> int:
    n = attempts_per_configuration
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"attempts_per_configuration must be an integer ≥ 1, got {n!r}")
    return int(n)


def attempts_of(attempts_per_configuration: int, *, seed: int) -> list[tuple[int, int]]:
    """The (configuration, episode seed) of every attempt an evaluation under ``seed`` plays."""
    return [(int(c), int(s)) for c, s in _native.attempt_seeds(_check_attempts(attempts_per_configuration),
                                                                 seed=seed)]


def play(policy: Policy, attempts: list[tuple[int, int]], *,
         field_config: dict[str, Any] | str | None = None) -> Evaluation:
    """``policy`` on the given (configuration, episode seed) attempts, all stepped together,
    with the body the policy drives (its ``body``, a :class:`polymimic.Body` or a built-in
    body's name: the Lego robot if it has none)."""
    if not isinstance(policy, Policy):
        raise ValueError(f"policy must have frames_per_action, predict, reset and save; got {type(policy).__name__}")
    config = native_field_config(field_config)
    body = as_body(getattr(policy, "body", "lego"), what="policy.body")
    episodes = [_native.Episode(body, configuration=c, seed=s, config=config) for c, s in attempts]
    policy.reset()
    with threadpool_limits(limits=1):  # a batch of ≤ 50 rows gains nothing from threads, and loses on a busy node
        own = PRIMITIVE_SETS[body.primitive_set]
        executed = _step_together(policy, episodes, [primitive_command(p, body) for p in PRIMITIVES], own)
    demos = [Demonstration(frames=as_frames(e.frames), outcome=str(e.outcome), demonstrator=_name(policy),
                           configuration=c, seed=s, body=body) for e, (c, s) in zip(episodes, attempts)]
    return Evaluation(goals=sum(d.outcome == "goal" for d in demos),
                      own_goals=sum(d.outcome == "own_goal" for d in demos), attempts=demos, behaviours=executed)


def _step_together(policy: Policy, episodes: list[_native.Episode], commands: list[str],
                   own: Sequence[str] = PRIMITIVES) -> list[list[str]]:
    """Every episode to its end, one batched decision at a time, primitive i of the body's
    ``own`` set sent as ``commands[i]`` (one of the humanoid's own beyond the five as its
    body executes it now: a kick with the foot on the ball's side); the primitives each chose."""
    hold = int(policy.frames_per_action)
    last_seen = [_observation(e, None) for e in episodes]
    executed: list[list[str]] = [[] for _ in episodes]
    active = [i for i, e in enumerate(episodes) if not e.finished]
    while active:
        for i in active:
            last_seen[i] = _observation(episodes[i], last_seen[i])
        actions = np.asarray(policy.predict(np.array([last_seen[i] for i in active])))
        if actions.shape != (len(active),):
            raise ValueError(f"policy.predict returned shape {actions.shape} for {len(active)} observations")
        for i, action in zip(active, actions.tolist()):
            if not 0 <= action < len(own):
                raise ValueError(f"policy.predict returned {action!r}; actions are 0..{len(own) - 1} "
                                 f"({', '.join(own)})")
            executed[i].append(_LETTERS[action])
            command = commands[action] if action < len(commands) else episodes[i].command_for(own[action])
            episodes[i].run([command] * hold)
        active = [i for i in active if not episodes[i].finished]
    return executed


def evaluate_policy(policy: Policy, *, attempts: Attempts | None = None, attempts_per_configuration: int | None = None,
                    seed: int | None = None, field_config: dict[str, Any] | str | None = None) -> Evaluation:
    """Goals, own goals and every attempt of ``policy`` over ``attempts`` from the thesis's two
    configurations (or ``attempts_per_configuration``, default 25, from each under ``seed``,
    default 0): the imitator's own, :func:`polymimic.evaluate`'s for the same attempts.
    ``behaviours`` lists the primitives each attempt chose (``F B L R S``).

    Raises
    ------
    ValueError
        If the seed is outside ``[0, 2**62)`` (the validation seeds lie above), the attempts
        are not a positive integer or start where the imitator chose, or the policy returns the
        wrong number of actions.
    TypeError
        For ``attempts`` given beside the keywords it stands for.
    """
    if attempts is None:  # the keywords' own checks, worded as they were
        attempts_per_configuration = None if attempts_per_configuration is None else _check_attempts(
            attempts_per_configuration)
        seed = None if seed is None else _check_seed(seed, low=0, high=VALIDATION_SEED_BASE,
                                                     what="seeds from 2**62 are validation's")
    chosen = attempts_given(attempts, attempts_per_configuration=attempts_per_configuration, seed=seed)
    if attempts is not None:  # the keyword's seed was checked above
        _check_seed(chosen.seed, low=0, high=VALIDATION_SEED_BASE, what="seeds from 2**62 are validation's")
    return play(policy, chosen.episodes(), field_config=field_config)


def _observation(episode: _native.Episode, last: np.ndarray | None) -> np.ndarray:
    """What the robot sees now, ``[robot x, y, θ, ball x, y]``; the ball's last reading when
    it is out of sight (the robot's pose already repeats the last good one in a dropout)."""
    seen = episode.observation()
    robot = seen["robot"]
    ball = ball_as_read(seen["ball"], last, robot_x_mm=robot[0], field_length_mm=seen["field"][0])
    return np.array([*robot, *ball], dtype=np.float64)


def ball_as_read(ball: Any, last: np.ndarray | None, *, robot_x_mm: float,
                 field_length_mm: float) -> tuple[float, float]:
    """The ball as a policy reads it: where it is seen; out of sight (``None`` or NaN, as a
    humanoid's camera may leave it), the last observation's ball ``last[3:5]``; never seen yet,
    where the configuration puts it (a sixth of the field's length from the centre, on the
    other side from the robot)."""
    if ball is not None and all(math.isfinite(v) for v in ball):
        return float(ball[0]), float(ball[1])
    if last is not None:
        return float(last[3]), float(last[4])
    return math.copysign(field_length_mm / 6, robot_x_mm) * -1.0, 0.0


def _name(policy: Policy) -> str:
    return str(getattr(policy, "method", type(policy).__name__))
