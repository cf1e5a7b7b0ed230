"""Practice through the teacher: the trained imitator guides an RL learner (stable-baselines3's
PPO) that reads only what the tracker shows and the outcome's reward.

``jsrl`` (jump-start RL, Uchendu et al. 2022): each practice episode, the imitator plays the
first ``h`` decisions and the learner the rest, so the learner starts where the imitator's play
leads and learns to finish; ``h`` is drawn from ``0 … h_max``, and ``h_max`` shrinks from the
imitator's typical attempt length to 0 over the first ``curriculum`` share of the budget, until
the learner plays whole episodes. The policy scored at a checkpoint is the imitator for the
current ``h_max`` decisions, then the learner (:class:`~polymimic.practice.practised.PractisedPolicy`).

Every environment step counts against the budget, the imitator's roll-in steps too; learning
stops at each checkpoint with the steps to it spent (PPO updates every 512 steps, two
environments of 256, so few steps are left unlearned at a checkpoint).
stable-baselines3 and torch are needed (``pip install "polymimic[rl]"``).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from polymimic.learning import ImitatorPolicy, evaluate
from polymimic.practice.curve import CurvePoint
from polymimic.practice.practised import PractisedPolicy

try:
    import gymnasium
except ImportError:  # the `gym` extra is absent: the module imports, practice through the teacher does not run
    gymnasium = None  # type: ignore[assignment]

__all__ = ["Curriculum", "TeacherPractice", "jsrl"]

_Wrapper: Any = gymnasium.Wrapper if gymnasium is not None else object


@dataclasses.dataclass
class Curriculum:
    """How many decisions the teacher plays before the learner: at most ``start`` at step 0,
    shrinking linearly to 0 at step ``until``; each episode draws its ``h`` uniformly from
    ``0 … h_max``."""

    start: int
    until: int

    def h_max(self, steps: int) -> int:
        """The most decisions the teacher plays after ``steps`` environment steps.

        >>> Curriculum(start=20, until=1000).h_max(0), Curriculum(start=20, until=1000).h_max(500)
        (20, 10)
        """
        if self.until <= 0:
            return 0
        return max(0, math.ceil(self.start * (1.0 - steps / self.until)))


@dataclasses.dataclass
class _Counter:
    """Environment steps played, and the most that may be (the next checkpoint)."""

    steps: int = 0
    limit: int = 0


class _RollIn(_Wrapper):  # type: ignore[misc]
    """``PenaltyKick-v0`` whose episodes the teacher starts: on reset it plays ``h`` decisions
    (an episode that ends in them is counted and replaced) and hands over."""

    def __init__(self, env: Any, teacher: ImitatorPolicy, curriculum: Curriculum, counter: _Counter,
                 rng: np.random.Generator) -> None:
        super().__init__(env)
        self._curriculum, self._counter, self._rng = curriculum, counter, rng
        self._player = teacher.player()
        self._last: Any = None
        self._info: dict[str, Any] = {}

    def reset(self, **kwargs: Any) -> Any:
        while True:
            observation, info = self.env.reset(**kwargs)
            kwargs.pop("seed", None)  # seeded once; later episodes follow the env's generator
            h = int(self._rng.integers(0, self._curriculum.h_max(self._counter.steps) + 1))
            self._player.reset(start=self.env.unwrapped.configuration, seed=info["episode_seed"])
            ended = False
            for _ in range(min(h, self._counter.limit - self._counter.steps)):
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
         evaluation_seed: int = 0, evaluation_attempts: int = 25, curriculum: float = 0.5,
         handover_start: int | None = None, field_config: Any = None,
         on_checkpoint: Callable[[list[CurvePoint]], None] | None = None, **ppo_kwargs: Any) -> TeacherPractice:
    """Practise ``teacher`` by jump-start RL for ``steps`` environment steps under ``seed`` (the
    learner's network, its environments' episodes and the roll-ins' draws), scored on the
    evaluation attempts of ``evaluation_seed`` at each of ``checkpoints`` (default: every fifth
    of the budget). ``handover_start`` is ``h_max`` at the start (default: the decisions of the
    teacher's median scoring attempt), ``curriculum`` the share of the budget over which it
    shrinks to 0. ``ppo_kwargs`` go to stable-baselines3's PPO.
    """
    from polymimic.baselines import ppo

    marks = sorted(set(checkpoints if checkpoints is not None else np.linspace(0, steps, 6).astype(int).tolist()))
    if not marks or marks[0] < 0 or marks[-1] > steps:
        raise ValueError(f"checkpoints must lie in 0..{steps}, got {marks}")
    start = handover_start if handover_start is not None else _typical_length(teacher, seed, field_config)
    schedule = Curriculum(start=start, until=int(curriculum * steps))
    counter, rng = _Counter(), np.random.default_rng(seed)
    ppo_kwargs = {"n_steps": 256, "batch_size": 64, **ppo_kwargs}
    model = ppo.new_model(seed=seed, field_config=field_config, imitator=teacher.body,
                          wrap=lambda env: _RollIn(env, teacher, schedule, counter, rng), **ppo_kwargs)
    curve: list[CurvePoint] = []

    def practised(h: int) -> PractisedPolicy:
        actor = ppo.PPOPolicy(model, feature_set="goal_relative", frames_per_action=30,
                              total_timesteps=counter.steps, method="jsrl", body=teacher.body)
        return PractisedPolicy(teacher, actor, handover=h, method="jsrl", steps=counter.steps)

    def score(mark: int) -> None:
        h = schedule.h_max(mark)
        result = evaluate(practised(h), attempts_per_configuration=evaluation_attempts, seed=evaluation_seed,
                          field_config=field_config)
        curve.append(CurvePoint(mark, counter.steps, result.goals - result.own_goals, result.goals,
                                result.own_goals, 0, 0))
        if on_checkpoint is not None:
            on_checkpoint(curve)

    from stable_baselines3.common.callbacks import BaseCallback  # type: ignore[import-not-found, unused-ignore]

    class Budget(BaseCallback):  # type: ignore[misc, unused-ignore]
        """Stops learning when the steps to the checkpoint are spent (a part-played rollout
        teaches nothing: PPO learns from whole rollouts)."""

        def _on_step(self) -> bool:
            return counter.steps < counter.limit

    for mark in marks:
        counter.limit = mark
        if counter.steps < mark:
            model.learn(total_timesteps=10 * steps + 1, callback=Budget(), reset_num_timesteps=False)
        score(mark)
    return TeacherPractice(policy=practised(schedule.h_max(counter.steps)), curve=curve, steps=counter.steps)


def _typical_length(teacher: ImitatorPolicy, seed: int, field_config: Any) -> int:
    """Decisions in the teacher's median scoring attempt over a few practice attempts (one
    second each), or its median attempt when none scores."""
    from polymimic.practice.seeds import round_seed

    attempts = evaluate(teacher, attempts_per_configuration=5, seed=round_seed(seed, 10_000),
                        field_config=field_config).attempts
    scoring = [len(a.frames) for a in attempts if a.outcome == "goal"] or [len(a.frames) for a in attempts]
    return max(1, math.ceil(float(np.median(scoring)) / 30))
