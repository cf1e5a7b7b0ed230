"""The matrix's own files, each checked whole on reading, so that a damaged one is redone rather
than counted."""

from __future__ import annotations

import os
from typing import Any, TypedDict

from polymimic.runs.files import checked_outcomes, checked_tuning, integer_key, json_object, name_key

__all__ = ["SavedCellEvaluation", "SavedCellTuning", "load_cell_evaluation", "load_cell_tuning"]

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
    return SavedCellEvaluation(row=name_key(data, "row", where), column=name_key(data, "column", where),
                               method=name_key(data, "method", where, METHODS),
                               seed=integer_key(data, "seed", where, 0),
                               evaluation_seed=integer_key(data, "evaluation_seed", where, 0), goals=goals,
                               own_goals=own_goals, attempts=attempts, outcomes=outcomes)


def load_cell_tuning(path: str | os.PathLike[str]) -> SavedCellTuning:
    """A tuning file, checked: its choice is a whole set of hyperparameters and every candidate
    has a score."""
    where, data = os.fspath(path), json_object(path, "tuning")
    hyperparameters, scores = checked_tuning(data, where)
    return SavedCellTuning(row=name_key(data, "row", where), column=name_key(data, "column", where),
                           hyperparameters=hyperparameters, scores=scores)
