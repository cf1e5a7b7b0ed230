"""The benchmark's own files, each checked whole on reading, so that a damaged one is redone
rather than counted (see :meth:`~polymimic.reproduce.rundir.RunHouse.finished`)."""

from __future__ import annotations

import json
import os
import pathlib
from typing import Any, TypedDict

from polymimic._native import ModelFileError
from polymimic.baselines import Hyperparameters
from polymimic.benchmark.config import METHODS
from polymimic.field import OUTCOMES

__all__ = ["SavedMethodEvaluation", "SavedPPOCurve", "SavedTuning", "load_method_evaluation", "load_ppo_curve",
           "load_tuning"]


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


def _object(path: str | os.PathLike[str], what: str) -> dict[str, Any]:
    where = os.fspath(path)
    try:
        data = json.loads(pathlib.Path(path).read_bytes().decode("utf-8"))
    except (OSError, ValueError) as error:
        raise ModelFileError(f"{where}: not a saved {what} ({error})") from error
    if not isinstance(data, dict):
        raise ModelFileError(f"{where}: not a saved {what} (a JSON object is expected)")
    return data


def _integer(data: dict[str, Any], key: str, where: str, low: int, high: int | None = None) -> int:
    value = data.get(key)
    if type(value) is not int or value < low or (high is not None and value > high):
        span = f"{low}..{high}" if high is not None else f"at least {low}"
        raise ModelFileError(f"{where}: key {key!r} must be an integer {span}, got {value!r}")
    return value


def _name(data: dict[str, Any], key: str, where: str, allowed: tuple[str, ...] | None = None) -> str:
    value = data.get(key)
    if not isinstance(value, str) or (allowed is not None and value not in allowed):
        expected = f"one of {', '.join(allowed)}" if allowed else "a string"
        raise ModelFileError(f"{where}: key {key!r} must be {expected}, got {value!r}")
    return value


def load_method_evaluation(path: str | os.PathLike[str]) -> SavedMethodEvaluation:
    """An evaluation file, checked: every key of its type and range, goals and own goals as its
    outcomes count them."""
    where, data = os.fspath(path), _object(path, "evaluation")
    attempts, outcomes = _integer(data, "attempts", where, 1), data.get("outcomes")
    if not isinstance(outcomes, list) or len(outcomes) != attempts or not all(o in OUTCOMES for o in outcomes):
        raise ModelFileError(f"{where}: key 'outcomes' must list {attempts} outcomes, each one of "
                             f"{', '.join(OUTCOMES)}")
    saved = SavedMethodEvaluation(profile=_name(data, "profile", where), method=_name(data, "method", where, METHODS),
                                  trial_seed=_integer(data, "trial_seed", where, 0),
                                  seed=_integer(data, "seed", where, 0),
                                  goals=_integer(data, "goals", where, 0, attempts),
                                  own_goals=_integer(data, "own_goals", where, 0, attempts),
                                  attempts=attempts, outcomes=outcomes)
    for key, value, outcome in (("goals", saved["goals"], "goal"), ("own_goals", saved["own_goals"], "own_goal")):
        if value != outcomes.count(outcome):
            raise ModelFileError(f"{where}: key {key!r} is {value} but its outcomes count {outcomes.count(outcome)}")
    return saved


def load_tuning(path: str | os.PathLike[str]) -> SavedTuning:
    """A tuning file, checked: its choice is a whole set of hyperparameters."""
    where, data = os.fspath(path), _object(path, "tuning")
    for key in ("chosen", "hyperparameters"):
        if not isinstance(data.get(key), dict):
            raise ModelFileError(f"{where}: key {key!r} must be an object, got {data.get(key)!r}")
    try:
        Hyperparameters.from_dict(data["hyperparameters"])
    except (KeyError, TypeError, ValueError) as error:
        raise ModelFileError(f"{where}: key 'hyperparameters' is not a choice of hyperparameters "
                             f"({error!r})") from error
    scores = data.get("scores")
    if not isinstance(scores, list) or not scores:
        raise ModelFileError(f"{where}: key 'scores' must list every candidate tried, got {scores!r}")
    for i, score in enumerate(scores):
        if not isinstance(score, dict):
            raise ModelFileError(f"{where}: scores[{i}] must be an object, got {score!r}")
        for key in ("goals", "own_goals"):
            _integer(score, key, f"{where}: scores[{i}]", 0)
    return SavedTuning(profile=_name(data, "profile", where), method=_name(data, "method", where, METHODS),
                       chosen=data["chosen"], hyperparameters=data["hyperparameters"], scores=scores,
                       validation_attempts=_integer(data, "validation_attempts", where, 1))


def load_ppo_curve(path: str | os.PathLike[str]) -> SavedPPOCurve:
    """A ppo curve file, checked: checkpoints in order of steps, from 0 to the budget or past it,
    each one's goals and own goals within its attempts and its net goals their difference."""
    where, data = os.fspath(path), _object(path, "ppo curve")
    attempts, total = _integer(data, "attempts", where, 1), _integer(data, "total_timesteps", where, 1)
    checkpoints = data.get("checkpoints")
    if not isinstance(checkpoints, list) or not checkpoints or not all(isinstance(c, dict) for c in checkpoints):
        raise ModelFileError(f"{where}: key 'checkpoints' must list objects, got {checkpoints!r}")
    steps = []
    for index, point in enumerate(checkpoints):
        at = f"{where}: checkpoint {index}"
        steps.append(_integer(point, "env_steps", at, 0))
        goals, own = _integer(point, "goals", at, 0, attempts), _integer(point, "own_goals", at, 0, attempts)
        if point.get("attempts") != attempts or point.get("net_goals") != goals - own or goals + own > attempts:
            raise ModelFileError(f"{at}: its attempts, goals, own goals and net goals disagree ({point!r})")
    if steps[0] != 0 or steps != sorted(set(steps)) or steps[-1] < total:
        raise ModelFileError(f"{where}: the checkpoints' env_steps must rise from 0 to at least {total}, got {steps}")
    return SavedPPOCurve(seed=_integer(data, "seed", where, 0),
                         evaluation_seed=_integer(data, "evaluation_seed", where, 0), attempts=attempts,
                         total_timesteps=total, eval_every=_integer(data, "eval_every", where, 1),
                         checkpoints=checkpoints)
