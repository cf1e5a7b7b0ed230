"""Distil, then fine-tune (after PIRLNav, Ramrakhya et al. 2023): the trained imitator is
distilled into an RL actor by DAgger, the critic warms up with the actor frozen, then PPO
fine-tunes from the reward with the teacher's term annealed away.

1. DAgger (``dagger_rounds`` rounds of ``dagger_steps`` environment steps): the first round the
   teacher plays, later rounds the actor; every state visited is labelled with the teacher's
   decision there, and the actor clones all the labels so far (cross-entropy).
2. Critic warm-up (``warmup_steps``): PPO learns with the actor's parameters frozen, so its
   value function learns what the distilled actor's states are worth before it changes the
   actor (the forgetting that a cold critic causes is what the warm-up prevents).
3. Fine-tuning: PPO from the reward for the rest of the budget; after every rollout the actor
   also takes cloning steps on the teacher's labels, weighted from ``teacher_weight`` down to 0
   at the end of the budget.

The practised policy is the actor alone once it has earned it — a check on practice attempts
(:class:`~polymimic.practice.teacher.Gate`, counted against the budget) shows it no worse than
the teacher alone on the same attempts, with confidence
(:class:`~polymimic.practice.teacher.Curriculum`, one stage) — and the teacher until then:
practice never scores an actor its own play has not shown to hold.

The learner reads only the env's observation and the outcome's reward; every environment step
counts against the budget, DAgger's too. Needs the ``rl`` extra.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from polymimic.baselines.evaluation import ball_as_read
from polymimic.env import PenaltyKickEnv
from polymimic.evaluation import Attempts, thesis_attempts
from polymimic.learning import ImitatorPolicy
from polymimic.practice.curve import CurvePoint
from polymimic.practice.practised import PractisedPolicy
from polymimic.practice.teacher import (
    TEACHER_ALONE,
    Curriculum,
    Gate,
    TeacherPractice,
    _checkpoints,
    _Counter,
    _practised,
    _RollIn,
    _scored,
    _teacher_alone,
    check_confidence,
)

__all__ = ["distil"]


def distil(teacher: ImitatorPolicy, *, steps: int, seed: int = 0, checkpoints: Sequence[int] | None = None,
           evaluation: Attempts = Attempts(), dagger_rounds: int = 3,
           dagger_steps: int = 2000, warmup_steps: int = 4000, teacher_weight: float = 1.0,
           tolerance: float = 0.02, confidence_z: float = 2.0, gate: Gate | None = None,
           field_config: Any = None,
           **ppo_kwargs: Any) -> TeacherPractice:
    """Practise ``teacher`` by distilling it into a PPO actor and fine-tuning, for ``steps``
    environment steps under ``seed``, scored on the ``evaluation`` attempts (an
    :class:`~polymimic.Attempts` from the thesis's configurations; a ``ValueError`` for one with
    starts of its own) at each of ``checkpoints`` (default: every fifth of the budget); the
    actor replaces the teacher once a check (``gate``: by default every 10 000 steps, on 100
    practice attempts) shows it no worse than the teacher alone on the same attempts, to within
    ``tolerance`` net goals per attempt with confidence (less ``confidence_z`` standard errors),
    and a later actor replaces it when a check shows the same and nets more on the check's
    attempts."""
    from stable_baselines3.common.callbacks import BaseCallback  # type: ignore[import-not-found, unused-ignore]

    from polymimic.baselines import ppo
    from polymimic.baselines.ppo_bc import Pretraining, clone_into

    marks = _checkpoints(checkpoints, steps)
    scored_on = thesis_attempts(evaluation, name="evaluation")
    check_confidence(tolerance, confidence_z)  # before the teacher plays
    counter = _Counter()
    checks = gate if gate is not None else Gate()
    _, reference = _teacher_alone(teacher, seed, field_config, checks)
    earning = Curriculum(stages=(0,), reference=reference, tolerance=tolerance, confidence_z=confidence_z)
    ppo_kwargs = {"n_steps": 256, "batch_size": 64, **ppo_kwargs}
    model = ppo.new_model(seed=seed, field_config=field_config, imitator=teacher.body,
                          wrap=lambda env: _RollIn(env, teacher, lambda: 0, counter), **ppo_kwargs)
    cloning = Pretraining(learning_rate=3e-4, epochs=5, batch_size=64)
    features: list[np.ndarray] = []
    labels: list[int] = []
    rng = np.random.default_rng(seed)
    curve: list[CurvePoint] = []
    phase_ends = [min(steps, dagger_rounds * dagger_steps), min(steps, dagger_rounds * dagger_steps + warmup_steps)]

    def practised(handover: int) -> PractisedPolicy:
        return _practised(teacher, model, counter, "distil", handover)

    def score(mark: int) -> None:
        curve.append(_scored(checks.scored(practised(TEACHER_ALONE)), mark, counter, scored_on, field_config))

    class Budget(BaseCallback):  # type: ignore[misc, unused-ignore]
        def _on_step(self) -> bool:
            return counter.steps < counter.limit

        def _on_rollout_end(self) -> None:
            weight = teacher_weight * max(0.0, 1.0 - counter.steps / max(1, steps))
            if labels and weight > 0 and counter.steps >= phase_ends[1]:
                step = Pretraining(learning_rate=3e-4 * weight, epochs=1, batch_size=64)
                clone_into(model, np.array(features), np.array(labels), step, seed=counter.steps)
            if checks.due(counter):
                checks.check(practised(0), earning, counter, seed, field_config)

    dagger_end, warm_end = phase_ends
    for mark in marks:
        while counter.steps < mark:
            if counter.steps < dagger_end:
                round_index = counter.steps // dagger_steps
                round_end = min((round_index + 1) * dagger_steps, dagger_end)
                _dagger(teacher, model, counter, min(mark, round_end), round_index == 0, features, labels, rng,
                        field_config)
                if counter.steps >= round_end:
                    clone_into(model, np.array(features), np.array(labels), cloning, seed=seed + round_index)
                continue
            warming = counter.steps < warm_end
            counter.limit = min(mark, warm_end) if warming else mark
            _freeze_actor(model, frozen=warming)
            model.learn(total_timesteps=10 * steps + 1, callback=Budget(), reset_num_timesteps=False)
            _freeze_actor(model, frozen=False)
        score(mark)
    return TeacherPractice(policy=checks.scored(practised(TEACHER_ALONE)), curve=curve, steps=counter.steps)


def _dagger(teacher: ImitatorPolicy, model: Any, counter: _Counter, until: int, teacher_acts: bool,
            features: list[np.ndarray], labels: list[int], rng: np.random.Generator, field_config: Any) -> None:
    """Play until ``until`` steps, the teacher (or the actor) acting, every visited state
    labelled with the teacher's decision there."""
    from polymimic.baselines import ppo

    body = teacher.body
    length_mm = body.field.length_mm
    while counter.steps < until:
        configuration = 1 + int(rng.integers(2))
        env = PenaltyKickEnv(configuration=configuration, config=field_config, body=body)
        observation, info = env.reset(seed=int(rng.integers(2**62)))
        player = teacher.player()
        player.reset(start=configuration, seed=info["episode_seed"])
        last: np.ndarray | None = None
        done = False
        while not done and counter.steps < until:
            raw = np.asarray(observation, dtype=np.float64)
            read = raw.copy()
            read[3:5] = ball_as_read(read[3:5], last, robot_x_mm=float(read[0]), field_length_mm=length_mm)
            last = read
            seen = ppo.scaled(read[None, :], "goal_relative", body)[0]
            label = player.decide(*(float(v) for v in raw))
            features.append(seen)
            labels.append(label)
            action = label if teacher_acts else int(model.predict(seen, deterministic=True)[0])
            observation, _, terminated, truncated, info = env.step(action)
            counter.steps += 1
            done = terminated or truncated


def _freeze_actor(model: Any, *, frozen: bool) -> None:
    """The actor's layers (its share of the MLP and its action head) learn or not."""
    policy = model.policy
    for module in (policy.mlp_extractor.policy_net, policy.action_net):
        for parameter in module.parameters():
            parameter.requires_grad_(not frozen)
