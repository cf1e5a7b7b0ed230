"""polymimic's tuning in a matrix, with bco's effort: how it weighs a cell's members
(``[learning] imitator_weighting``), chosen among ``[matrix] weightings`` on bco's validation
attempts in every cell of more than one demonstrator. One demonstrator weighs 1 however it is
weighed, so such a cell has no choice to make, nor has a matrix of one candidate: they take the
first candidate."""

from __future__ import annotations

from typing import Any

from polymimic.baselines.tuning import validation_rank
from polymimic.matrix.cell_files import load_cell_weighing
from polymimic.matrix.config import MatrixConfig, demonstrator_sets
from polymimic.matrix.rundir import MatrixDir

__all__ = ["chosen_weighting", "is_weighed"]


def is_weighed(config: MatrixConfig, row: str, column: str) -> bool:
    """Does polymimic choose its weighting in the computed cell ``(row, column)``?"""
    return len(config.matrix.weightings) > 1 and len(
        demonstrator_sets(row, config.run.demonstrators)[column].members) > 1


def chosen_weighting(run: MatrixDir, config: MatrixConfig, row: str, column: str) -> tuple[str, list[dict[str, Any]]]:
    """How polymimic weighs the members in the computed cell ``(row, column)``, and every
    candidate's validation score: the best by net goals, then goals (the first of equals), where
    the cell is weighed; else the first candidate, untried."""
    weightings = config.matrix.weightings
    if not is_weighed(config, row, column):
        return weightings[0], []
    scores = [load_cell_weighing(run.require(run.weighing_path(row, column, w), "matrix")) for w in weightings]
    best = max(range(len(scores)), key=lambda i: (validation_rank(scores[i]), -i))
    return weightings[best], [{"weighting": s["weighting"], "goals": s["goals"], "own_goals": s["own_goals"],
                               "attempts": s["attempts"]} for s in scores]
