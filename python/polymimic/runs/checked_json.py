"""Reading a run's small JSON files, checked key by key: a damaged one is a
:class:`~polymimic.ModelFileError` naming the file and the key, so that a stage redoes it rather
than counts it.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "evaluation.json"
>>> _ = path.write_text('{"goals": -1}')
>>> integer_key(json_object(path, "evaluation"), "goals", str(path), 0)
Traceback (most recent call last):
...
polymimic.ModelFileError: .../evaluation.json: key 'goals' must be an integer at least 0, got -1
"""

from __future__ import annotations

import json
import os
import pathlib
from typing import Any

from polymimic._native import ModelFileError
from polymimic.field import OUTCOMES

__all__ = ["checked_checkpoints", "checked_outcomes", "checked_tuning", "integer_key", "json_object", "name_key"]


def json_object(path: str | os.PathLike[str], what: str) -> dict[str, Any]:
    """The JSON object in the file at ``path``, a saved ``what``."""
    where = os.fspath(path)
    try:
        data = json.loads(pathlib.Path(path).read_bytes().decode("utf-8"))
    except (OSError, ValueError) as error:
        raise ModelFileError(f"{where}: not a saved {what} ({error})") from error
    if not isinstance(data, dict):
        raise ModelFileError(f"{where}: not a saved {what} (a JSON object is expected)")
    return data


def integer_key(data: dict[str, Any], key: str, where: str, low: int, high: int | None = None) -> int:
    """``data[key]`` if it is an integer in ``low..high``, else a ``ModelFileError`` naming ``where``."""
    value = data.get(key)
    if type(value) is not int or value < low or (high is not None and value > high):
        span = f"{low}..{high}" if high is not None else f"at least {low}"
        raise ModelFileError(f"{where}: key {key!r} must be an integer {span}, got {value!r}")
    return value


def name_key(data: dict[str, Any], key: str, where: str, allowed: tuple[str, ...] | None = None) -> str:
    """``data[key]`` if it is a string (one of ``allowed``), else a ``ModelFileError`` naming ``where``."""
    value = data.get(key)
    if not isinstance(value, str) or (allowed is not None and value not in allowed):
        expected = f"one of {', '.join(allowed)}" if allowed else "a string"
        raise ModelFileError(f"{where}: key {key!r} must be {expected}, got {value!r}")
    return value


def checked_checkpoints(data: dict[str, Any], where: str, attempts: int) -> list[dict[str, Any]]:
    """A learning curve's checkpoints (a practice's, a ppo curve's): a list of objects, each with
    its goals and own goals within its ``attempts`` and its net goals their difference.

    >>> checked_checkpoints({"checkpoints": [{"goals": 3, "own_goals": 1, "net_goals": 2}]}, "curve.json", 5)
    [{'goals': 3, 'own_goals': 1, 'net_goals': 2}]
    >>> checked_checkpoints({"checkpoints": [{"goals": 3, "own_goals": 1, "net_goals": 4}]}, "curve.json", 5)
    Traceback (most recent call last):
    ...
    polymimic.ModelFileError: curve.json: checkpoint 0: its goals, own goals and net goals disagree ...
    """
    checkpoints = data.get("checkpoints")
    if not isinstance(checkpoints, list) or not checkpoints or not all(isinstance(c, dict) for c in checkpoints):
        raise ModelFileError(f"{where}: key 'checkpoints' must list objects, got {checkpoints!r}")
    for index, point in enumerate(checkpoints):
        at = f"{where}: checkpoint {index}"
        goals, own = integer_key(point, "goals", at, 0, attempts), integer_key(point, "own_goals", at, 0, attempts)
        net = point.get("net_goals")
        if goals + own > attempts or type(net) is not int or net != goals - own:
            raise ModelFileError(f"{at}: its goals, own goals and net goals disagree ({point!r})")
    return checkpoints


def checked_outcomes(data: dict[str, Any], where: str) -> tuple[int, list[str], int, int]:
    """An evaluation's attempts, outcomes, goals and own goals, the last two as its outcomes count
    them."""
    attempts, outcomes = integer_key(data, "attempts", where, 1), data.get("outcomes")
    if not isinstance(outcomes, list) or len(outcomes) != attempts or not all(o in OUTCOMES for o in outcomes):
        raise ModelFileError(f"{where}: key 'outcomes' must list {attempts} outcomes, each one of "
                             f"{', '.join(OUTCOMES)}")
    goals, own = integer_key(data, "goals", where, 0, attempts), integer_key(data, "own_goals", where, 0, attempts)
    for key, value, outcome in (("goals", goals, "goal"), ("own_goals", own, "own_goal")):
        if value != outcomes.count(outcome):
            raise ModelFileError(f"{where}: key {key!r} is {value} but its outcomes count {outcomes.count(outcome)}")
    return attempts, outcomes, goals, own


def checked_tuning(data: dict[str, Any], where: str) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """A baseline's tuning: the hyperparameters chosen (a whole choice: ``offline_rl``'s of its
    own kind) and every candidate's score (its goals and own goals on validation)."""
    from polymimic.baselines.hyperparameters import Hyperparameters
    from polymimic.baselines.offline_hyperparameters import OfflineHyperparameters

    chosen = data.get("hyperparameters")
    try:
        if data.get("method") == "offline_rl":
            OfflineHyperparameters.from_dict(chosen)  # type: ignore[arg-type]
        else:
            Hyperparameters.from_dict(chosen)  # type: ignore[arg-type]
    except (KeyError, TypeError, ValueError, AttributeError) as error:
        raise ModelFileError(f"{where}: key 'hyperparameters' is not a choice of hyperparameters "
                             f"({error!r})") from error
    scores = data.get("scores")
    if not isinstance(scores, list) or not scores or not all(isinstance(s, dict) for s in scores):
        raise ModelFileError(f"{where}: key 'scores' must list every candidate tried, got {scores!r}")
    for i, score in enumerate(scores):
        for key in ("goals", "own_goals"):
            integer_key(score, key, f"{where}: scores[{i}]", 0)
    return chosen, scores  # type: ignore[return-value]
