"""Scoring a trained policy: its attempts from the thesis's starts or one's own, played on the
field, counted as goals and own goals (thesis Tables 4.8, 4.11) and kept as demonstrations.

:func:`evaluate` plays anything that plays as an :class:`~polymimic.ImitatorPolicy` does
(:class:`Plays`); :mod:`polymimic.learning` re-exports it with :class:`Evaluation`,
:func:`net_goals` and :func:`spare_attempts`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any, Protocol

from polymimic import _native
from polymimic._arguments import integer
from polymimic.bodies import Body, BodySpec, as_body
from polymimic.field import Demonstration, as_frames
from polymimic.field_config import native_field_config

__all__ = ["Evaluation", "Plays", "attempts_as_demonstrations", "evaluate", "net_goals", "spare_attempts"]


@dataclasses.dataclass(frozen=True)
class Evaluation:
    """Goals and own goals of a policy over its attempts (thesis Tables 4.8, 4.11), and every
    attempt, recorded like a demonstration.

    Attributes
    ----------
    goals : int
        Attempts that ended in the target goal.
    own_goals : int
        Attempts that ended in the imitator's own goal.
    attempts : list of Demonstration
        Every attempt, configuration 1's first, recorded as the policy's body's (demonstrator
        ``"imitator"``).
    behaviours : list of list of str
        The behaviours each attempt ran, in order.
    """

    goals: int
    own_goals: int
    attempts: list[Demonstration]
    behaviours: list[list[str]]


class Plays(Protocol):
    """Anything :func:`evaluate` scores: an :class:`ImitatorPolicy`, or a policy that plays
    the same attempts as it does (a practised imitator,
    :class:`polymimic.practice.practised.PractisedPolicy`)."""

    @property
    def body(self) -> Body:
        """The body it drives."""

    def evaluate(self, attempts_per_configuration: int, *, seed: int = 0, field_config: str | None = None,
                 starts: Sequence[int | Mapping[str, Any]] | None = None) -> list[dict[str, Any]]:
        """Its attempts as dicts (``frames``, ``outcome``, ``configuration``, ``seed``,
        ``behaviours``), as :meth:`ImitatorPolicy.evaluate` plays them."""


def evaluate(policy: Plays, *, attempts_per_configuration: int = 25, seed: int = 0,
             field_config: dict[str, Any] | str | None = None,
             starts: Sequence[int | Mapping[str, Any]] | None = None) -> Evaluation:
    """``attempts_per_configuration`` attempts from each start, in parallel, on the field
    ``field_config`` describes (as for :func:`polymimic.record`; default: the thesis's), with the
    policy's body; the attempts are recorded as that body's.

    ``starts`` are the thesis's field configurations ``1`` and ``2`` by default; a start of your
    own is ``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}`` on the body's field
    (a ``ValueError`` names one off the field or with the ball on the robot). A configuration
    plays the same episodes whatever else is listed; the k-th chosen start's attempts have
    episode seeds of their own, and are recorded with configuration ``0``. Each attempt is the
    policy's :meth:`~polymimic.ImitatorPolicy.player` stepped through the field one tracker
    reading at a time.

    Parameters
    ----------
    policy : ImitatorPolicy or PractisedPolicy
        The trained imitator to play (or anything that plays as it does: :class:`Plays`).
    attempts_per_configuration : int
        Attempts from each start (at least 1).
    seed : int
        The evaluation's seed, in ``[0, 2**64)``: the same seed plays the same starts and noise.
    field_config : dict or str, optional
        Field parameters laid over the default world (see :func:`polymimic.field.default_config`).
    starts : sequence of 1, 2 or dict, optional
        Where attempts start (default ``[1, 2]``).

    Returns
    -------
    Evaluation
        ``goals``, ``own_goals``, every attempt as a :class:`Demonstration`, and the behaviours
        each attempt ran.

    Raises
    ------
    ValueError
        For attempts below 1, a seed out of range, or a start off the body's field or with the
        ball on the robot.

    Examples
    --------
    >>> import polymimic
    >>> from polymimic import recognition
    >>> recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)
    >>> demos = polymimic.record("expert", configuration=1, n=2, seed=0)
    >>> from polymimic.learning import ImitatorPolicy, run_trial
    >>> policy = ImitatorPolicy(run_trial(demos, recognizer=recognizer, ordering=["expert"]), recognizer=recognizer,
    ...                         control="improved", demonstrations=demos)
    >>> near = {"robot": (150.0, 0.0, 0.0), "ball": (300.0, 0.0)}   # close in front of the goal
    >>> played = evaluate(policy, attempts_per_configuration=2, starts=[near], seed=1)
    >>> [a.configuration for a in played.attempts], played.goals
    ([0, 0], 2)
    """
    attempts_per_configuration = integer("attempts_per_configuration", attempts_per_configuration, 1)
    seed = integer("seed", seed, 0, 2**64 - 1)
    given = None if starts is None else list(starts)
    raw = policy.evaluate(attempts_per_configuration, seed=seed, field_config=native_field_config(field_config),
                          starts=given)
    attempts = attempts_as_demonstrations(raw, "imitator", body=policy.body)
    return Evaluation(goals=sum(a.outcome == "goal" for a in attempts),
                      own_goals=sum(a.outcome == "own_goal" for a in attempts), attempts=attempts,
                      behaviours=[a["behaviours"] for a in raw])


def attempts_as_demonstrations(raw: list[dict[str, Any]], demonstrator: str, *,
                               body: BodySpec = "lego") -> list[Demonstration]:
    """Native attempts (as :meth:`ImitatorPolicy.evaluate` returns them) as ``demonstrator``'s
    demonstrations on ``body``; an attempt from a chosen start has configuration 0."""
    body = as_body(body)
    return [Demonstration(frames=as_frames(a["frames"]), outcome=a["outcome"], demonstrator=demonstrator,
                          configuration=a["configuration"] or 0, seed=a["seed"], body=body) for a in raw]


def spare_attempts(n: int) -> int:
    """Attempts made beyond ``n``, to stand in for any whose tracking is lost.

    >>> spare_attempts(10), spare_attempts(100)
    (5, 20)
    """
    return _native.spare_attempts(n)


def net_goals(demonstrations: Sequence[Demonstration]) -> int:
    """Goals less own goals.

    >>> import polymimic
    >>> net_goals(polymimic.record("expert", configuration=1, n=2, seed=0))
    2
    """
    return _native.net_goals([d.outcome for d in demonstrations])
