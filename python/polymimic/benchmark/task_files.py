"""The files the benchmark's tasks leave (evaluations, tunings, ppo curves, weighings, the
controllers' skill), each checked whole on reading, so that a damaged one is redone
rather than counted (see :meth:`~polymimic.reproduce.rundir.RunHouse.finished`)."""

from __future__ import annotations

import os
from typing import Any, TypedDict

from polymimic._native import ModelFileError
from polymimic.benchmark.config import METHODS, TRIAL_INDEPENDENT, WORLD_WEIGHTINGS
from polymimic.runs.checked_json import (
    checked_checkpoints,
    checked_outcomes,
    checked_tuning,
    integer_key,
    json_object,
    name_key,
)

__all__ = ["SavedMethodEvaluation", "SavedPPOCurve", "SavedTuning", "load_controller_skill", "load_method_evaluation",
           "load_ppo_bc_curve", "load_ppo_bc_tuning", "load_ppo_curve", "load_tuning", "load_weighing"]


class SavedMethodEvaluation(TypedDict):
    """One method's attempts after one trial of one profile."""

    profile: str
    method: str
    trial_seed: int
    seed: int
    goals: int
    own_goals: int
    attempts: int
    outcomes: list[str]


class SavedTuning(TypedDict):
    """A baseline's tuning on one profile: what it chose and every candidate's validation score."""

    profile: str
    method: str
    chosen: dict[str, Any]
    hyperparameters: dict[str, Any]
    scores: list[dict[str, Any]]
    validation_attempts: int


class SavedPPOCurve(TypedDict):
    """A ppo run: its training seed, budget and every checkpoint on the evaluation attempts."""

    seed: int
    evaluation_seed: int
    attempts: int
    total_timesteps: int
    eval_every: int
    checkpoints: list[dict[str, Any]]


EVALUATED = tuple(dict.fromkeys(METHODS + ("polymimic_practice",) + TRIAL_INDEPENDENT))
"""The methods whose evaluations and tunings the run directory keeps in files of their own (the
defaults, and polymimic_practice and offline_rl where named)."""


def load_method_evaluation(path: str | os.PathLike[str]) -> SavedMethodEvaluation:
    """An evaluation file, checked: every key of its type and range, goals and own goals as its
    outcomes count them."""
    where, data = os.fspath(path), json_object(path, "evaluation")
    attempts, outcomes, goals, own_goals = checked_outcomes(data, where)
    saved = SavedMethodEvaluation(profile=name_key(data, "profile", where),
                                  method=name_key(data, "method", where, EVALUATED),
                                  trial_seed=integer_key(data, "trial_seed", where, 0),
                                  seed=integer_key(data, "seed", where, 0), goals=goals, own_goals=own_goals,
                                  attempts=attempts, outcomes=outcomes)
    return saved


def load_tuning(path: str | os.PathLike[str]) -> SavedTuning:
    """A tuning file, checked: its choice is a whole set of hyperparameters."""
    where, data = os.fspath(path), json_object(path, "tuning")
    for key in ("chosen", "hyperparameters"):
        if not isinstance(data.get(key), dict):
            raise ModelFileError(f"{where}: key {key!r} must be an object, got {data.get(key)!r}")
    hyperparameters, scores = checked_tuning(data, where)
    return SavedTuning(profile=name_key(data, "profile", where), method=name_key(data, "method", where, EVALUATED),
                       chosen=data["chosen"], hyperparameters=hyperparameters, scores=scores,
                       validation_attempts=integer_key(data, "validation_attempts", where, 1))


def load_ppo_curve(path: str | os.PathLike[str]) -> SavedPPOCurve:
    """A ppo curve file, checked: checkpoints in order of steps, from 0 to the budget or past it,
    each one's goals and own goals within its attempts and its net goals their difference."""
    where, data = os.fspath(path), json_object(path, "ppo curve")
    attempts, total = integer_key(data, "attempts", where, 1), integer_key(data, "total_timesteps", where, 1)
    checkpoints = checked_checkpoints(data, where, attempts)
    steps = []
    for index, point in enumerate(checkpoints):
        at = f"{where}: checkpoint {index}"
        steps.append(integer_key(point, "env_steps", at, 0))
        if point.get("attempts") != attempts:
            raise ModelFileError(f"{at}: key 'attempts' must be the curve's {attempts}, got {point.get('attempts')!r}")
    if steps[0] != 0 or steps != sorted(set(steps)) or steps[-1] < total:
        raise ModelFileError(f"{where}: the checkpoints' env_steps must rise from 0 to at least {total}, got {steps}")
    return SavedPPOCurve(seed=integer_key(data, "seed", where, 0),
                         evaluation_seed=integer_key(data, "evaluation_seed", where, 0), attempts=attempts,
                         total_timesteps=total, eval_every=integer_key(data, "eval_every", where, 1),
                         checkpoints=checkpoints)


def load_ppo_bc_tuning(path: str | os.PathLike[str]) -> dict[str, Any]:
    """ppo_bc's cloning tuning, checked: a chosen cloning among its scored candidates."""
    where, data = os.fspath(path), json_object(path, "ppo_bc tuning")
    chosen, scores = data.get("chosen"), data.get("scores")
    if not isinstance(chosen, dict) or set(chosen) != {"epochs", "learning_rate", "batch_size"}:
        raise ModelFileError(f"{where}: key 'chosen' must be a cloning (epochs, learning_rate, batch_size), "
                             f"got {chosen!r}")
    if not isinstance(scores, list) or not any(isinstance(s, dict) and {**s, **chosen} == s for s in scores):
        raise ModelFileError(f"{where}: key 'scores' must list the candidates, the chosen one among them")
    name_key(data, "profile", where)
    integer_key(data, "validation_attempts", where, 1)
    return data


def load_ppo_bc_curve(path: str | os.PathLike[str]) -> dict[str, Any]:
    """A ppo_bc run's curve, checked as a ppo curve is, with its profile and the cloning it ran."""
    where, data = os.fspath(path), json_object(path, "ppo_bc curve")
    pretraining = data.get("pretraining")
    if not isinstance(pretraining, dict) or set(pretraining) != {"epochs", "learning_rate", "batch_size"}:
        raise ModelFileError(f"{where}: key 'pretraining' must be a cloning (epochs, learning_rate, batch_size), "
                             f"got {pretraining!r}")
    return {**load_ppo_curve(path), "profile": name_key(data, "profile", where), "pretraining": pretraining}


def load_weighing(path: str | os.PathLike[str]) -> dict[str, Any]:
    """A weighing file, checked: polymimic under one world weighting on the validation attempts."""
    where, data = os.fspath(path), json_object(path, "weighing")
    attempts = integer_key(data, "attempts", where, 1)
    goals, own = integer_key(data, "goals", where, 0, attempts), integer_key(data, "own_goals", where, 0, attempts)
    if goals + own > attempts:
        raise ModelFileError(f"{where}: {goals} goals and {own} own goals in {attempts} attempts")
    name_key(data, "profile", where)
    name_key(data, "weighting", where, WORLD_WEIGHTINGS)
    integer_key(data, "seed", where, 0)
    integer_key(data, "validation_seed", where, 0)
    return data


def load_controller_skill(path: str | os.PathLike[str]) -> dict[str, float]:
    """Each controller's net goals per attempt without lapses, checked: numbers in [−1, 1]."""
    where, data = os.fspath(path), json_object(path, "controller skill")
    for name, value in data.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not -1.0 <= value <= 1.0:
            raise ModelFileError(f"{where}: controller {name!r} has skill {value!r}; expected a number in [-1, 1]")
    return {name: float(value) for name, value in data.items()}
