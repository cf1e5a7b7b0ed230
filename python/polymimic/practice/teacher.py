"""Practice through the teacher: the trained imitator guides an RL learner (stable-baselines3's
PPO) that reads only what the tracker shows and the outcome's reward.

``jsrl`` (jump-start RL, Uchendu et al. 2022, its gated curriculum): each practice episode, the
imitator plays the first ``h`` decisions and the learner the rest, so the learner starts where
the imitator's play leads and learns to finish. ``h`` steps down through a few stages, from the
imitator's typical attempt length to 0, and a stage is left only once the practised policy at
it — the imitator for ``h`` decisions, then the learner deciding as it will be scored,
deterministically — nets on practice attempts at least what the imitator nets alone on the
same attempts: the learner earns each earlier handover. Its own training episodes cannot tell:
PPO samples its actions while it learns, and from where the imitator leaves the ball a barely
trained learner's random pushes score far more often than its first choices do (on one crowd,
0.81 a training episode at a handover of 18 decisions, where the same policy deciding scored
0.46 an attempt). The checks' attempts are practice attempts, counted against the budget. The
policy scored at a checkpoint hands over at the last stage earned (before any, the imitator
plays alone), so practice never scores a handover its own play has not shown to hold
(:class:`~polymimic.practice.practised.PractisedPolicy`).

Every environment step counts against the budget, the imitator's roll-in steps too; learning
stops at each checkpoint with the steps to it spent (PPO updates every 512 steps, two
environments of 256, so few steps are left unlearned at a checkpoint).
stable-baselines3 and torch are needed (``pip install "polymimic[rl]"``).
"""

from __future__ import annotations

import dataclasses
import math
import pickle
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from polymimic._arguments import finite
from polymimic.evaluation import Attempts, thesis_attempts
from polymimic.field import OUTCOME_REWARDS
from polymimic.learning import ImitatorPolicy, evaluate
from polymimic.practice.curve import CurvePoint
from polymimic.practice.practised import PractisedPolicy

try:
    import gymnasium
except ImportError:  # the `gym` extra is absent: the module imports, practice through the teacher does not run
    gymnasium = None  # type: ignore[assignment]

__all__ = ["TEACHER_ALONE", "Curriculum", "Gate", "TeacherPractice", "jsrl"]

_Wrapper: Any = gymnasium.Wrapper if gymnasium is not None else object

TEACHER_ALONE = 3600
"""A handover later than any episode's last decision (an hour of one-second decisions): the
teacher plays every decision."""


@dataclasses.dataclass
class Curriculum:
    """The gated curriculum: ``stages`` are the handovers ``h`` in the order they are trained
    (decreasing, the last 0). A check plays the practised policy on the attempts the teacher
    alone netted ``reference`` on (its return on each, in order) and *passes* when, attempt by
    attempt, the policy is no worse than the teacher with confidence: the mean paired difference
    less ``confidence_z`` standard errors is at least ``-tolerance`` per attempt. A pass earns
    the stage (training moves to the next); ``earned`` is the handover of the last earned stage,
    :data:`TEACHER_ALONE` before any. Once the last stage is earned, checks go on, and a later
    policy passes only if it also nets more on the check's attempts than the one passed before.

    Why a confidence bound: a check repeated every few thousand steps on the same attempts
    passes by luck now and then if it only asks for the teacher's mean; an actor that passed so
    could then net several goals less than the teacher on other attempts.

    >>> curriculum = Curriculum(stages=(8, 0), reference=(1, 0, 1, 0), tolerance=0.0)
    >>> curriculum.checked([1, 0, 0, 0]), curriculum.earned
    (False, 3600)
    >>> curriculum.checked([1, 0, 1, 0]), curriculum.earned, curriculum.handover
    (True, 8, 0)
    """

    stages: tuple[int, ...]
    reference: Sequence[float]
    tolerance: float = 0.02
    confidence_z: float = 2.0
    earned: int = TEACHER_ALONE
    stage: int = 0
    best: float = -math.inf
    """The mean return of the policy last passed at the last stage (-inf before)."""

    def __post_init__(self) -> None:
        if not self.stages or any(h < 0 for h in self.stages) or list(self.stages) != sorted(self.stages, reverse=True):
            raise ValueError(f"stages must be decreasing handovers ≥ 0, got {self.stages}")
        if not self.reference:
            raise ValueError("reference must hold the teacher's return on at least one attempt")
        check_confidence(self.tolerance, self.confidence_z)
        self.reference = tuple(float(r) for r in self.reference)

    @classmethod
    def stepping_down(cls, start: int, count: int, **gate: Any) -> Curriculum:
        """``count`` stages evenly from below ``start`` decisions down to 0.

        >>> Curriculum.stepping_down(20, 4, reference=(0.5,)).stages
        (15, 10, 5, 0)
        """
        if count < 1:
            raise ValueError(f"a curriculum has at least one stage, got {count}")
        return cls(stages=tuple(math.ceil(start * (count - k) / count) for k in range(1, count + 1)), **gate)

    @property
    def handover(self) -> int:
        """The handover practice episodes are played at now, and the next check checks."""
        return self.stages[self.stage]

    @property
    def finished(self) -> bool:
        """Every stage earned: the learner plays alone."""
        return self.earned == self.stages[-1]

    def lower_bound(self, returns: Sequence[float]) -> float:
        """The mean of ``returns`` less the teacher's, attempt by attempt, less ``confidence_z``
        standard errors of that mean (none for a single attempt).

        >>> round(Curriculum(stages=(0,), reference=(0, 0)).lower_bound([1, 0]), 6)  # 0.5 - 2 * 0.7071 / 1.4142
        -0.5
        """
        if len(returns) != len(self.reference):
            raise ValueError(f"a check plays the reference's {len(self.reference)} attempts, "
                             f"got {len(returns)} returns")
        differences = np.asarray(returns, dtype=np.float64) - np.asarray(self.reference)
        spread = float(differences.std(ddof=1)) if len(differences) > 1 else 0.0
        return float(differences.mean()) - self.confidence_z * spread / math.sqrt(len(differences))

    def checked(self, returns: Sequence[float]) -> bool:
        """One check of :attr:`handover` from the returns of its attempts: passes at the gate
        (earning the stage and moving on)."""
        if self.lower_bound(returns) < -self.tolerance:
            return False
        mean = float(np.mean(returns))
        last = self.stage == len(self.stages) - 1
        if last and self.finished and mean <= self.best:
            return False
        if last:
            self.best = mean
        self.earned = self.stages[self.stage]
        self.stage = min(self.stage + 1, len(self.stages) - 1)
        return True


def check_confidence(tolerance: Any, confidence_z: Any) -> None:
    """A ``ValueError`` naming the argument unless ``tolerance`` is a finite number (below 0 the
    practised policy must beat the teacher by that much) and ``confidence_z`` a finite number
    ≥ 0."""
    finite("tolerance", tolerance)
    finite("confidence_z", confidence_z, low=0)


@dataclasses.dataclass
class Gate:
    """When and how the practised policy is checked: every ``every`` environment steps of
    learning, on ``attempts`` practice attempts per configuration played as it will be scored —
    always the same ones, those the teacher's reference was measured on, so that a check
    compares the two attempt by attempt rather than on attempts of other difficulty."""

    every: int = 10_000
    attempts: int = 50
    checks: int = 0
    last_step: int = 0
    passed: PractisedPolicy | None = None
    """A copy of the last policy a check passed (None before any): what practice scores, so that
    learning on after a check cannot move the policy scored."""

    def due(self, counter: _Counter) -> bool:
        """A check is due, and fits in the steps left to the checkpoint (a minute per attempt)."""
        return (counter.steps - self.last_step >= self.every
                and counter.limit - counter.steps >= 2 * self.attempts * _ATTEMPT_STEPS)

    def play(self, policy: Any, seed: int, field_config: Any) -> tuple[int, list[float]]:
        """``policy`` on the gate's practice attempts under ``seed``: the environment steps it
        took and its return on each attempt (1 a goal, -1 an own goal, else 0)."""
        from polymimic.practice.seeds import round_seed

        played = evaluate(policy, attempts_per_configuration=self.attempts, seed=round_seed(seed, 10_000),
                          field_config=field_config)
        steps = sum(math.ceil(len(a.frames) / _FRAMES_PER_STEP) for a in played.attempts)
        return steps, [OUTCOME_REWARDS.get(a.outcome, 0.0) for a in played.attempts]

    def check(self, policy: PractisedPolicy, curriculum: Curriculum, counter: _Counter, seed: int,
              field_config: Any) -> None:
        """Plays ``policy`` on the gate's practice attempts, counts their steps and lets
        ``curriculum`` judge their returns; a policy that passes is kept, copied."""
        self.checks += 1
        steps, returns = self.play(policy, seed, field_config)
        counter.steps += steps
        self.last_step = counter.steps
        if curriculum.checked(returns):  # the actor copied (its network learns on), the teacher shared
            self.passed = PractisedPolicy(policy.guide, pickle.loads(pickle.dumps(policy.actor)),
                                          handover=policy.handover, method=policy.method, steps=policy.steps)

    def scored(self, teacher_alone: PractisedPolicy) -> PractisedPolicy:
        """The policy a checkpoint scores: the last one passed, else ``teacher_alone``."""
        return teacher_alone if self.passed is None else self.passed


_FRAMES_PER_STEP = 30
"""Tracker frames per environment step (one decision a second)."""
_ATTEMPT_STEPS = 60
"""The most environment steps an attempt takes (the field's minute)."""


@dataclasses.dataclass
class _Counter:
    """Environment steps played, and the most that may be (the next checkpoint)."""

    steps: int = 0
    limit: int = 0


class _RollIn(_Wrapper):  # type: ignore[misc]
    """``PenaltyKick-v0`` whose episodes the teacher starts: on reset it plays ``handover()``
    decisions (an episode that ends in them is counted and replaced) and hands over."""

    def __init__(self, env: Any, teacher: ImitatorPolicy, handover: Callable[[], int], counter: _Counter) -> None:
        super().__init__(env)
        self._handover, self._counter = handover, counter
        self._player = teacher.player()
        self._last: Any = None
        self._info: dict[str, Any] = {}

    def reset(self, **kwargs: Any) -> Any:
        while True:
            observation, info = self.env.reset(**kwargs)
            kwargs.pop("seed", None)  # seeded once; later episodes follow the env's generator
            self._player.reset(start=self.env.unwrapped.configuration, seed=info["episode_seed"])
            ended = False
            for _ in range(min(self._handover(), self._counter.limit - self._counter.steps)):
                action = self._player.decide(*(float(v) for v in observation))
                observation, _, terminated, truncated, info = self.env.step(action)
                self._counter.steps += 1
                if terminated or truncated:
                    ended = True
                    break
            if not ended:
                self._last, self._info = observation, info
                return observation, info

    def step(self, action: Any) -> Any:
        if self._counter.steps >= self._counter.limit:
            # The budget to the checkpoint is spent: the episode is cut, no step is played.
            return self._last, 0.0, False, True, {**self._info, "budget_spent": True}
        self._counter.steps += 1
        self._last, reward, terminated, truncated, self._info = self.env.step(action)
        return self._last, reward, terminated, truncated, self._info


@dataclasses.dataclass(frozen=True)
class TeacherPractice:
    """What practice through the teacher returns: the practised ``policy``, its ``curve`` (one
    point per checkpoint) and the environment ``steps`` it played."""

    policy: PractisedPolicy
    curve: list[CurvePoint]
    steps: int


def jsrl(teacher: ImitatorPolicy, *, steps: int, seed: int = 0, checkpoints: Sequence[int] | None = None,
         evaluation: Attempts = Attempts(), stages: int = 8,
         handover_start: int | None = None, tolerance: float = 0.02, confidence_z: float = 2.0,
         gate: Gate | None = None, field_config: Any = None,
         on_checkpoint: Callable[[list[CurvePoint]], None] | None = None, **ppo_kwargs: Any) -> TeacherPractice:
    """Practise ``teacher`` by jump-start RL for ``steps`` environment steps under ``seed`` (the
    learner's network, its environments' episodes and the practice attempts), scored on the
    ``evaluation`` attempts (an :class:`~polymimic.Attempts` from the thesis's configurations; a
    ``ValueError`` for one with starts of its own) at each of ``checkpoints`` (default: every
    fifth of the budget). The curriculum (:class:`Curriculum`) has ``stages`` handovers from below
    ``handover_start`` decisions (default: the teacher's median scoring attempt) down to 0, each
    earned when a check (:class:`Gate`: by default every 10 000 steps, on 100 practice attempts)
    shows the practised policy no worse than the teacher alone on the same attempts, to within
    ``tolerance`` net goals per attempt with confidence (:meth:`Curriculum.lower_bound`, less
    ``confidence_z`` standard errors). ``ppo_kwargs`` go to stable-baselines3's PPO.
    """
    from polymimic.baselines import ppo

    marks = _checkpoints(checkpoints, steps)
    scored_on = thesis_attempts(evaluation, name="evaluation")
    check_confidence(tolerance, confidence_z)  # before the teacher plays
    checks = gate if gate is not None else Gate()
    typical, reference = _teacher_alone(teacher, seed, field_config, checks)
    schedule = Curriculum.stepping_down(handover_start if handover_start is not None else typical, stages,
                                        reference=reference, tolerance=tolerance, confidence_z=confidence_z)
    counter = _Counter()
    ppo_kwargs = {"n_steps": 256, "batch_size": 64, **ppo_kwargs}
    model = ppo.new_model(seed=seed, field_config=field_config, imitator=teacher.body,
                          wrap=lambda env: _RollIn(env, teacher, lambda: schedule.handover, counter), **ppo_kwargs)
    curve: list[CurvePoint] = []

    def practised(handover: int) -> PractisedPolicy:
        return _practised(teacher, model, counter, "jsrl", handover)

    def score(mark: int) -> None:
        curve.append(_scored(checks.scored(practised(TEACHER_ALONE)), mark, counter, scored_on, field_config))
        if on_checkpoint is not None:
            on_checkpoint(curve)

    from stable_baselines3.common.callbacks import BaseCallback  # type: ignore[import-not-found, unused-ignore]

    class Budget(BaseCallback):  # type: ignore[misc, unused-ignore]
        """Stops learning when the steps to the checkpoint are spent (a part-played rollout
        teaches nothing: PPO learns from whole rollouts)."""

        def _on_step(self) -> bool:
            return counter.steps < counter.limit

        def _on_rollout_end(self) -> None:
            if checks.due(counter):
                checks.check(practised(schedule.handover), schedule, counter, seed, field_config)

    for mark in marks:
        counter.limit = mark
        if counter.steps < mark:
            model.learn(total_timesteps=10 * steps + 1, callback=Budget(), reset_num_timesteps=False)
        score(mark)
    return TeacherPractice(policy=checks.scored(practised(TEACHER_ALONE)), curve=curve, steps=counter.steps)


def _checkpoints(checkpoints: Sequence[int] | None, steps: int) -> list[int]:
    """The checkpoints a practice of ``steps`` is scored at (default: every fifth of the budget);
    a ``ValueError`` for one outside ``0..steps``."""
    marks = sorted(set(checkpoints if checkpoints is not None else np.linspace(0, steps, 6).astype(int).tolist()))
    if not marks or marks[0] < 0 or marks[-1] > steps:
        raise ValueError(f"checkpoints must lie in 0..{steps}, got {marks}")
    return marks


def _practised(teacher: ImitatorPolicy, model: Any, counter: _Counter, method: str, handover: int) -> PractisedPolicy:
    """The teacher for ``handover`` decisions, then the PPO ``model`` deciding from the tracker's view."""
    from polymimic.baselines import ppo

    actor = ppo.PPOPolicy(model, feature_set="goal_relative", frames_per_action=30,
                          total_timesteps=counter.steps, method=method, body=teacher.body)
    return PractisedPolicy(teacher, actor, handover=handover, method=method, steps=counter.steps)


def _scored(policy: PractisedPolicy, mark: int, counter: _Counter, evaluation: Attempts,
            field_config: Any) -> CurvePoint:
    """``policy`` scored at checkpoint ``mark`` on the ``evaluation`` attempts."""
    result = evaluate(policy, attempts=evaluation, field_config=field_config)
    return CurvePoint(mark, counter.steps, result.goals - result.own_goals, result.goals, result.own_goals, 0, 0)


def _teacher_alone(teacher: ImitatorPolicy, seed: int, field_config: Any, gate: Gate) -> tuple[int, list[float]]:
    """On the gate's practice attempts (one-second decisions): the decisions of the teacher's
    median scoring attempt (of its median attempt when none scores), and its return on each."""
    from polymimic.practice.seeds import round_seed

    played = evaluate(teacher, attempts_per_configuration=gate.attempts, seed=round_seed(seed, 10_000),
                      field_config=field_config)
    attempts = played.attempts
    scoring = [len(a.frames) for a in attempts if a.outcome == "goal"] or [len(a.frames) for a in attempts]
    return max(1, math.ceil(float(np.median(scoring)) / 30)), [OUTCOME_REWARDS.get(a.outcome, 0.0) for a in attempts]
