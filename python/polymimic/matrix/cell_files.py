"""The files the matrix's cells leave (evaluations, weighings, tunings), each checked whole on
reading, so that a damaged one is redone rather than counted."""

from __future__ import annotations

import os
from typing import Any, TypedDict

from polymimic._native import ModelFileError
from polymimic.matrix.config import WEIGHTINGS
from polymimic.runs.checked_json import checked_outcomes, checked_tuning, integer_key, json_object, name_key

__all__ = ["SavedCellEvaluation", "SavedCellTuning", "SavedCellWeighing", "load_cell_evaluation", "load_cell_tuning",
           "load_cell_weighing"]

METHODS = ("polymimic", "bco")


class SavedCellEvaluation(TypedDict):
    """One method's evaluation in one cell, after one trial (polymimic) or fit (bco)."""

    row: str
    column: str
    method: str
    seed: int
    evaluation_seed: int
    goals: int
    own_goals: int
    attempts: int
    outcomes: list[str]
    #: How polymimic weighed the cell's members (None for bco).
    weighting: str | None


class SavedCellWeighing(TypedDict):
    """One of polymimic's weightings tried in one cell: its trial's goals on the validation attempts."""

    row: str
    column: str
    weighting: str
    seed: int
    validation_seed: int
    goals: int
    own_goals: int
    attempts: int


class SavedCellTuning(TypedDict):
    """bco's tuning in one cell: the choice and every candidate's validation score."""

    row: str
    column: str
    hyperparameters: dict[str, Any]
    scores: list[dict[str, Any]]


def load_cell_evaluation(path: str | os.PathLike[str]) -> SavedCellEvaluation:
    """An evaluation file, checked: every key of its type and range, goals and own goals as its
    outcomes count them."""
    where, data = os.fspath(path), json_object(path, "evaluation")
    attempts, outcomes, goals, own_goals = checked_outcomes(data, where)
    method = name_key(data, "method", where, METHODS)
    return SavedCellEvaluation(row=name_key(data, "row", where), column=name_key(data, "column", where),
                               method=method, seed=integer_key(data, "seed", where, 0),
                               evaluation_seed=integer_key(data, "evaluation_seed", where, 0), goals=goals,
                               own_goals=own_goals, attempts=attempts, outcomes=outcomes,
                               weighting=name_key(data, "weighting", where, WEIGHTINGS)
                               if method == "polymimic" else None)


def load_cell_weighing(path: str | os.PathLike[str]) -> SavedCellWeighing:
    """A weighing file, checked: its weighting is one polymimic knows, its goals and own goals
    whole numbers within its attempts."""
    where, data = os.fspath(path), json_object(path, "weighing")
    attempts = integer_key(data, "attempts", where, 1)
    goals = integer_key(data, "goals", where, 0, attempts)
    own_goals = integer_key(data, "own_goals", where, 0, attempts)
    if goals + own_goals > attempts:
        raise ModelFileError(f"{where}: {goals} goals and {own_goals} own goals in {attempts} attempts")
    return SavedCellWeighing(row=name_key(data, "row", where), column=name_key(data, "column", where),
                             weighting=name_key(data, "weighting", where, WEIGHTINGS),
                             seed=integer_key(data, "seed", where, 0),
                             validation_seed=integer_key(data, "validation_seed", where, 0), goals=goals,
                             own_goals=own_goals, attempts=attempts)


def load_cell_tuning(path: str | os.PathLike[str]) -> SavedCellTuning:
    """A tuning file, checked: its choice is a whole set of hyperparameters and every candidate
    has a score."""
    where, data = os.fspath(path), json_object(path, "tuning")
    hyperparameters, scores = checked_tuning(data, where)
    return SavedCellTuning(row=name_key(data, "row", where), column=name_key(data, "column", where),
                           hyperparameters=hyperparameters, scores=scores)
