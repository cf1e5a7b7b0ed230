"""Scoring a trained policy: its attempts from the thesis's starts or one's own, played on the
field, counted as goals and own goals (thesis Tables 4.8, 4.11) and kept as demonstrations.

Which attempts are played is one value, :class:`Attempts` (how many per start, under which
seed, from which starts). :func:`evaluate` plays them with anything that plays as an
:class:`~polymimic.ImitatorPolicy` does (:class:`Plays`); :mod:`polymimic.learning` re-exports
it with :class:`Evaluation`, :func:`net_goals` and :func:`spare_attempts`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any, Protocol, Union

from polymimic import _native
from polymimic._arguments import integer
from polymimic.bodies import Body, BodySpec, as_body
from polymimic.field import Demonstration, as_frames
from polymimic.field_config import native_field_config

__all__ = ["Attempts", "Evaluation", "Plays", "attempts_as_demonstrations", "evaluate", "net_goals", "spare_attempts"]

Start = Union[int, Mapping[str, Any]]
"""A start: the thesis's field configuration ``1`` or ``2``, or ``{"robot": (x_mm, y_mm,
theta_rad), "ball": (x_mm, y_mm)}`` on the body's field."""


@dataclasses.dataclass(frozen=True)
class Attempts:
    """Which attempts a policy plays: ``per_configuration`` from each start, their starting
    positions' noise and episodes drawn under ``seed``; the same value plays the same attempts.

    Parameters
    ----------
    per_configuration : int, default 25
        Attempts from each start (at least 1; the thesis's 25).
    seed : int, default 0
        The evaluation's seed, in ``[0, 2**64)``.
    starts : sequence of 1, 2 or dict, optional
        Where attempts start: the thesis's field configurations ``1`` and ``2`` (the default),
        or starts of your own (see :func:`evaluate`).

    Examples
    --------
    >>> attempts = Attempts(per_configuration=5, seed=1000)
    >>> attempts.count, attempts.episodes()[0][0]
    (10, 1)
    >>> Attempts(per_configuration=0)
    Traceback (most recent call last):
    ...
    ValueError: per_configuration must be at least 1, got 0
    """

    per_configuration: int = 25
    seed: int = 0
    starts: Sequence[Start] | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "per_configuration", integer("per_configuration", self.per_configuration, 1))
        object.__setattr__(self, "seed", integer("seed", self.seed, 0, 2**64 - 1))
        if self.starts is not None:
            if isinstance(self.starts, (str, bytes, Mapping)) or not isinstance(self.starts, Sequence):
                raise TypeError(f"starts must be a sequence of starts (1, 2 or a dict), got {self.starts!r}")
            object.__setattr__(self, "starts", tuple(self.starts))

    @property
    def count(self) -> int:
        """How many attempts are played: ``per_configuration`` from each start."""
        return self.per_configuration * (2 if self.starts is None else len(self.starts))

    def episodes(self) -> list[tuple[int, int]]:
        """The (configuration, episode seed) of every attempt from the thesis's two starts,
        configuration 1's first: what a batched player (``polymimic.baselines.evaluation.play``) steps.

        Raises
        ------
        ValueError
            For attempts from starts of one's own (only :func:`evaluate` plays those).
        """
        if self.starts is not None:
            raise ValueError("episodes are the thesis's configurations' only; attempts from starts of your own are "
                             "played by polymimic.evaluate")
        return [(int(c), int(s)) for c, s in _native.attempt_seeds(self.per_configuration, seed=self.seed)]


def attempts_given(attempts: Attempts | None, *, attempts_per_configuration: int | None = None,
                   seed: int | None = None, starts: Sequence[Start] | None = None) -> Attempts:
    """The one :class:`Attempts` of a call that gives either ``attempts=`` or the keywords it
    stands for (``attempts_per_configuration``, 25 unless given; ``seed``, 0; ``starts``); a
    ``TypeError`` where it gives both."""
    if attempts is None:
        return Attempts(per_configuration=integer("attempts_per_configuration",
                                                  25 if attempts_per_configuration is None
                                                  else attempts_per_configuration, 1),
                        seed=integer("seed", 0 if seed is None else seed, 0, 2**64 - 1),
                        starts=None if starts is None else list(starts))
    if not isinstance(attempts, Attempts):
        raise TypeError(f"attempts must be a polymimic.Attempts, got {type(attempts).__name__}")
    both = [f"{name}=" for name, value in (("attempts_per_configuration", attempts_per_configuration),
                                           ("seed", seed), ("starts", starts)) if value is not None]
    if both:
        raise TypeError(f"give attempts= or {', '.join(both)}, not both")
    return attempts


def thesis_attempts(attempts: Any, *, name: str) -> Attempts:
    """``attempts``, the argument ``name``, checked to be :class:`Attempts` from the thesis's two
    configurations: what a call takes that knows its attempts by their episodes (practice and
    tuning keep their own attempts apart from them; a batched player steps them).

    Raises
    ------
    TypeError
        For anything but an :class:`Attempts`.
    ValueError
        For attempts from starts of one's own.

    Examples
    --------
    >>> thesis_attempts(Attempts(per_configuration=2), name="evaluation").count
    4
    >>> thesis_attempts(Attempts(starts=[1]), name="evaluation")
    Traceback (most recent call last):
    ...
    ValueError: evaluation must be attempts from the thesis's configurations, got starts=(1,): ...
    """
    if not isinstance(attempts, Attempts):
        raise TypeError(f"{name} must be a polymimic.Attempts, got {type(attempts).__name__}")
    if attempts.starts is not None:
        raise ValueError(f"{name} must be attempts from the thesis's configurations, got starts={attempts.starts!r}: "
                         f"attempts from starts of your own are played by polymimic.evaluate")
    return attempts


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


def evaluate(policy: Plays, *, attempts: Attempts | None = None, attempts_per_configuration: int | None = None,
             seed: int | None = None, field_config: dict[str, Any] | str | None = None,
             starts: Sequence[Start] | None = None) -> Evaluation:
    """The policy's ``attempts`` (an :class:`Attempts`; or given as ``attempts_per_configuration``
    attempts from each of ``starts`` under ``seed``), in parallel, on the field ``field_config``
    describes (as for :func:`polymimic.record`; default: the thesis's), with the policy's body;
    the attempts are recorded as that body's.

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
    attempts : Attempts, optional
        Which attempts to play; or give them as the next two and ``starts`` (not both).
    attempts_per_configuration : int, default 25
        Attempts from each start (at least 1).
    seed : int, default 0
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
    TypeError
        For ``attempts`` given beside the keywords it stands for.

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
    >>> played = evaluate(policy, attempts=Attempts(per_configuration=2, seed=1, starts=[near]))
    >>> [a.configuration for a in played.attempts], played.goals
    ([0, 0], 2)
    >>> evaluate(policy, attempts_per_configuration=2, starts=[near], seed=1).goals   # the same attempts
    2
    """
    chosen = attempts_given(attempts, attempts_per_configuration=attempts_per_configuration, seed=seed, starts=starts)
    raw = policy.evaluate(chosen.per_configuration, seed=chosen.seed, field_config=native_field_config(field_config),
                          starts=None if chosen.starts is None else list(chosen.starts))
    played = attempts_as_demonstrations(raw, "imitator", body=policy.body)
    return Evaluation(goals=sum(a.outcome == "goal" for a in played),
                      own_goals=sum(a.outcome == "own_goal" for a in played), attempts=played,
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
