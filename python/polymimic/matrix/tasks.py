"""The work of a matrix, as tasks a process pool or Ray can run: one cell's trial and its
evaluation (polymimic), or that evaluation played again for its first attempt to be pictured,
one of polymimic's weightings of a cell's members on validation attempts, one cell's bco tuning,
one bco fit and its evaluation. Each depends on its arguments alone, so the same seeds give the
same bits on any worker."""

from __future__ import annotations

import dataclasses
import json
from typing import Any

from polymimic import baselines
from polymimic._native import PrimitiveRecognizer, SegmentedDemonstrations
from polymimic.baselines.evaluation import VALIDATION_SEED_BASE
from polymimic.baselines.hyperparameters import (
    DEFAULT,
    PLAIN_BOOSTING,
    TUNED_LABELS,
    Hyperparameters,
    candidates,
)
from polymimic.baselines.tuning import validation_attempts_apart
from polymimic.evaluation import Attempts
from polymimic.field import Demonstration, PrimitiveSequence, self_observation
from polymimic.learning import Evaluation, ImitatorPolicy, evaluate, run_trial, segmented
from polymimic.matrix.config import DemonstratorSet, MatrixConfig
from polymimic.matrix.draws import drawn

__all__ = ["Shared", "attempt_task", "bco_task", "dumps", "polymimic_task", "recognise_task", "tuning_task",
           "weighing_task"]


@dataclasses.dataclass(frozen=True)
class Shared:
    """What every task of a matrix shares: the config, each row's recogniser, each set's pool of
    demonstrations (:mod:`polymimic.matrix.draws`) and each (row, column)'s set."""

    config: MatrixConfig
    recognizers: dict[str, PrimitiveRecognizer]
    demonstrations: dict[str, list[Demonstration]]
    sets: dict[str, dict[str, DemonstratorSet]]

    def cell(self, row: str, column: str, draw: int) -> tuple[DemonstratorSet, list[Demonstration]]:
        """A cell's demonstrator set and the demonstrations of its draw ``draw`` (trial or fit
        ``draw`` learns from them)."""
        chosen = self.sets[row][column]
        return chosen, drawn(self.demonstrations[chosen.name], names=chosen.names, spec=chosen.spec, draw=draw,
                             per_configuration=self.config.matrix.sizes.demonstrations_per_configuration,
                             seed=self.config.seeds.demonstrations)

    def draw_of(self, seed: int) -> int:
        """The draw a trial's or a fit's seed learns from: its index among the trials."""
        return int(seed - self.config.seeds.first_trial)


def recognise_task(config: MatrixConfig, row: str) -> tuple[list[PrimitiveSequence], PrimitiveRecognizer]:
    """``row`` → its self-observation on its own body and field, over its own primitives or the
    wheeled five (``[matrix] primitives``), and the recogniser trained on it."""
    settings = config.run.recognizer
    own = config.matrix.primitives == "own"
    sequences = self_observation(settings.train_per_primitive, seed=config.seeds.self_observation_train,
                                 config=config.run.field, body=config.body(row),
                                 primitives="own" if own else "wheeled")
    return sequences, settings.train(sequences)


_segmented: dict[tuple[int, str, str, int], SegmentedDemonstrations] = {}
"""In each process, the latest draws of cells segmented by their row's recogniser (the first
trial's draw serves the weighing as well as its trial)."""
_SEGMENTED_KEPT = 8


def _cell_segments(shared: Shared, row: str, column: str, draw: int) -> SegmentedDemonstrations:
    key = (id(shared), row, column, draw)
    if key not in _segmented:
        _, demos = shared.cell(row, column, draw)
        while len(_segmented) >= _SEGMENTED_KEPT:
            del _segmented[next(iter(_segmented))]
        _segmented[key] = segmented(demos, shared.recognizers[row], **dataclasses.asdict(shared.config.run.segmenter))
    return _segmented[key]


def polymimic_task(shared: Shared, job: tuple[str, str, int, str]) -> dict[str, Any]:
    """``(row, column, trial seed, weighting)`` → polymimic's evaluation after that trial: the
    row's imitator, learning on its own setting and weighing the cell's members as chosen, driven
    by the improved control."""
    row, column, seed, weighting = job
    played = _played(shared, row, column, seed, weighting, attempts=shared.config.evaluation_attempts())
    return {**_evaluation(shared, row, column, "polymimic", seed, played), "weighting": weighting}


def attempt_task(shared: Shared, job: tuple[str, str, int, str]) -> dict[str, Any]:
    """``(row, column, trial seed, weighting)`` → that trial's evaluation played again, as
    :func:`polymimic_task` plays it: its first attempt (``"attempt"``, frames and all) and every
    attempt's outcome, for the caller to check against the saved evaluation."""
    row, column, seed, weighting = job
    played = _played(shared, row, column, seed, weighting, attempts=shared.config.evaluation_attempts())
    return {"row": row, "column": column, "seed": seed, "weighting": weighting, "attempt": played.attempts[0],
            "outcomes": [a.outcome for a in played.attempts]}


def weighing_task(shared: Shared, job: tuple[str, str, str]) -> dict[str, Any]:
    """``(row, column, weighting)`` → one trial under the first trial's seed with that weighting
    of the cell's members, played on the validation attempts bco's tuning plays (never the
    evaluation's): polymimic's tuning, with bco's effort."""
    row, column, weighting = job
    config, tuning = shared.config, shared.config.matrix.tuning
    attempts = validation_attempts_apart(tuning.validation_attempts_per_configuration,
                                         validation_seed=tuning.validation_seed,
                                         evaluation=config.evaluation_attempts())
    played = _played(shared, row, column, config.seeds.first_trial, weighting,
                     attempts=Attempts(per_configuration=tuning.validation_attempts_per_configuration,
                                       seed=VALIDATION_SEED_BASE + tuning.validation_seed))
    if [(a.configuration, a.seed) for a in played.attempts] != attempts:
        raise RuntimeError("the imitator's validation attempts are not bco's")  # the seed rule, guarded
    return {"row": row, "column": column, "weighting": weighting, "seed": config.seeds.first_trial,
            "validation_seed": tuning.validation_seed, "goals": played.goals, "own_goals": played.own_goals,
            "attempts": len(played.attempts)}


def _played(shared: Shared, row: str, column: str, seed: int, weighting: str, *, attempts: Attempts) -> Evaluation:
    """One trial of the cell under ``seed`` with the members weighed by ``weighting``, its
    improved-control policy played on ``attempts``."""
    config = shared.config
    learning = config.run.learning.replace(imitator_weighting=weighting)
    chosen = shared.sets[row][column]
    batch, body = _cell_segments(shared, row, column, shared.draw_of(seed)), config.body(row)
    trial = run_trial(batch, recognizer=shared.recognizers[row], ordering=list(chosen.names), config=learning,
                      phase_one="interleaved", seed=seed, body=body)
    policy = ImitatorPolicy(trial, recognizer=shared.recognizers[row], config=learning, control="improved",
                            demonstrations=batch, body=body)
    return evaluate(policy, attempts=attempts, field_config=config.run.field)


def _bco_inputs(shared: Shared, row: str) -> dict[str, Any]:
    return {"recognizer": shared.recognizers[row], "segmenter": dataclasses.asdict(shared.config.run.segmenter),
            "imitator": shared.config.body(row), "max_samples": shared.config.matrix.tuning.max_decision_samples}


def bco_candidates(budget: int) -> list[Hyperparameters]:
    """``budget`` candidates for bco in a cell: plain boosted trees (what made ``bc`` as strong as
    a plain scikit-learn cloner) with each labelling first, then the benchmark's other candidates,
    each with each labelling. Boosted trees fit a cell's crowd in seconds where the benchmark's
    first candidate, a network, takes a minute: twenty cells could not afford it."""
    drawn = [c for c in candidates(budget + 2) if c not in (PLAIN_BOOSTING, DEFAULT)]
    pool = [PLAIN_BOOSTING, *drawn]
    return [dataclasses.replace(h, labels=labels) for h in pool for labels in TUNED_LABELS][:budget]


def tuning_task(shared: Shared, job: tuple[str, str]) -> dict[str, Any]:
    """``(row, column)`` → bco's hyperparameters chosen on validation attempts (labelled by the
    row's recogniser, played by the row's body), every candidate's score, and (``"evaluation"``)
    the chosen fit's evaluation under the first fit seed: the fit the evaluation would make."""
    row, column = job
    config, settings = shared.config, shared.config.matrix.tuning
    _, demos = shared.cell(row, column, 0)
    tuning = baselines.tune("bco", demos, candidates=bco_candidates(settings.tuning_budget),
                            validation_seed=settings.validation_seed,
                            attempts_per_configuration=settings.validation_attempts_per_configuration,
                            evaluation=config.evaluation_attempts(), seed=config.seeds.first_trial,
                            field_config=config.run.field, **_bco_inputs(shared, row))
    return {"row": row, "column": column, "hyperparameters": tuning.hyperparameters.to_dict(), "scores": tuning.scores,
            "evaluation": _bco_evaluation(shared, row, column, config.seeds.first_trial, tuning.policy)}


def bco_task(shared: Shared, job: tuple[str, str, int, dict[str, Any]]) -> dict[str, Any]:
    """``(row, column, fit seed, the tuned hyperparameters)`` → that bco fit's evaluation."""
    row, column, seed, hyperparameters = job
    _, demos = shared.cell(row, column, shared.draw_of(seed))
    fitted = baselines.fit("bco", demos, hyperparameters=Hyperparameters.from_dict(hyperparameters),
                           seed=seed, **_bco_inputs(shared, row))
    return _bco_evaluation(shared, row, column, seed, fitted)


def _bco_evaluation(shared: Shared, row: str, column: str, seed: int, policy: Any) -> dict[str, Any]:
    played = baselines.evaluate_policy(policy, attempts=shared.config.evaluation_attempts(),
                                       field_config=shared.config.run.field)
    return _evaluation(shared, row, column, "bco", seed, played)


def _evaluation(shared: Shared, row: str, column: str, method: str, seed: int, played: Any) -> dict[str, Any]:
    outcomes = [a.outcome for a in played.attempts]
    return {"row": row, "column": column, "method": method, "seed": seed,
            "evaluation_seed": shared.config.seeds.evaluation, "goals": played.goals, "own_goals": played.own_goals,
            "attempts": len(outcomes), "outcomes": outcomes}


def dumps(data: dict[str, Any]) -> str:
    """``data`` as JSON with sorted keys and a final newline: the same data, the same bytes."""
    return json.dumps(data, sort_keys=True) + "\n"
