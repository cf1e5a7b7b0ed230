"""The thesis's learning experiments (§4.4): their trials and the evaluation of their imitators.

Three experiments, each of many trials that differ only in their seed:

* ``heterogeneous_rcb``: Expert, Tiny, Humanoid, trained in that order in phase one (RCB);
* ``heterogeneous_bcr``: the same demonstrations, the reverse order (BCR);
* ``varying_skill``: Poor, Average, Expert, their demonstrations interleaved in phase one.

Trials and evaluations run as tasks on a :class:`~polymimic.reproduce.backends.TaskRunner`; every result
is written to the run directory, atomically, as it arrives, so an interrupted stage resumes
where it stopped and a finished one is never redone. Who takes part is in
:mod:`polymimic.reproduce.roster`.
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Sequence
from typing import Any

from polymimic._atomic import atomic_write_text
from polymimic._native import PrimitiveRecognizer
from polymimic.datasets import save_demonstrations
from polymimic.learning import (
    ImitatorPolicy,
    LearningConfig,
    SegmentedDemonstrations,
    TrialResult,
    evaluate,
    run_trial,
)
from polymimic.reproduce.backends import TaskRunner
from polymimic.reproduce.config import RunConfig
from polymimic.reproduce.progress import progress
from polymimic.reproduce.roster import CONTROLS, EXPERIMENTS, Experiment
from polymimic.reproduce.rundir import MissingInputError, RunDir
from polymimic.segments import load_segments

__all__ = ["evaluate_imitators", "evaluated_seeds", "imitator_policy", "learn", "trial_seeds"]


def trial_seeds(config: RunConfig) -> list[int]:
    """Every experiment's trial seeds: ``first_trial``, ``first_trial + 1``, …"""
    return [config.seeds.first_trial + i for i in range(config.experiments.trials)]


def evaluated_seeds(config: RunConfig) -> list[int]:
    """The seeds of the trials whose imitators are evaluated: the first ones."""
    return trial_seeds(config)[:config.experiments.evaluated_imitators]


def imitator_policy(trial: TrialResult, *, recognizer: PrimitiveRecognizer, config: LearningConfig,
                    control: str, demonstrations: SegmentedDemonstrations) -> ImitatorPolicy:
    """The trial's imitator driving the robot by ``control``; the improved control also learns
    from the (segmented) ``demonstrations`` the imitator watched."""
    if control not in CONTROLS:
        raise ValueError(f"control must be one of {', '.join(CONTROLS)}, got {control!r}")
    return ImitatorPolicy(trial, recognizer=recognizer, config=config, control=control,
                          demonstrations=demonstrations if control == "improved" else None)


# Tasks: module-level, so that process-pool and Ray workers can import them.

@dataclasses.dataclass(frozen=True)
class TrialInputs:
    """What every trial of an experiment shares."""

    items: SegmentedDemonstrations
    recognizer: PrimitiveRecognizer
    ordering: tuple[str, ...]
    phase_one: str
    learning: LearningConfig


def trial_task(inputs: TrialInputs, seed: int) -> str:
    """One trial, as the JSON :meth:`TrialResult.save` writes (it depends on ``seed`` alone)."""
    return run_trial(inputs.items, recognizer=inputs.recognizer, ordering=list(inputs.ordering),
                     config=inputs.learning, phase_one=inputs.phase_one, seed=seed).to_json()


@dataclasses.dataclass(frozen=True)
class EvaluationInputs:
    """What every evaluation of an experiment's imitators shares."""

    recognizer: PrimitiveRecognizer
    learning: LearningConfig
    attempts_per_configuration: int
    seed: int
    items: SegmentedDemonstrations
    """The experiment's segmented demonstrations: what its imitators watched."""
    field: dict[str, Any]
    """The field the imitators play on (the run's)."""


def evaluation_task(inputs: EvaluationInputs, job: tuple[int, str, str, bool]) -> dict[str, Any]:
    """Goals and own goals of one trial's imitator; ``job`` is ``(trial seed, trial JSON,
    control, keep the attempts)``."""
    trial_seed, trial_json, control, keep = job
    policy = imitator_policy(TrialResult.from_json(trial_json), recognizer=inputs.recognizer,
                             config=inputs.learning, control=control, demonstrations=inputs.items)
    evaluation = evaluate(policy, attempts_per_configuration=inputs.attempts_per_configuration, seed=inputs.seed,
                          field_config=inputs.field)
    return {"trial_seed": trial_seed, "control": control, "seed": inputs.seed,
            "goals": evaluation.goals, "own_goals": evaluation.own_goals, "attempts": len(evaluation.attempts),
            "outcomes": [a.outcome for a in evaluation.attempts],
            "attempt_list": evaluation.attempts if keep else None}


# Stages.

def experiment_items(run: RunDir, experiment: Experiment) -> SegmentedDemonstrations:
    """The experiment's segmented demonstrations, demonstrator by demonstrator."""
    return SegmentedDemonstrations.concat([load_segments(run.require(run.segments_path(who), "segment"))
                                           for who in experiment.demonstrators])


def _selected(names: Sequence[str] | None) -> list[Experiment]:
    if names is None:
        return list(EXPERIMENTS.values())
    unknown = [n for n in names if n not in EXPERIMENTS]
    if unknown:
        raise ValueError(f"unknown experiment {unknown[0]!r}; expected one of {', '.join(EXPERIMENTS)}")
    return [EXPERIMENTS[n] for n in names]


def learn(run: RunDir, config: RunConfig, runner: TaskRunner, *, experiments: Sequence[str] | None = None,
          limit: int | None = None, quiet: bool = False) -> dict[str, int]:
    """Run every experiment's trials that have no file yet (at most ``limit`` per experiment);
    return how many ran, by experiment."""
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    ran = {}
    for experiment in _selected(experiments):
        missing = [s for s in trial_seeds(config) if not run.trial_path(experiment.name, s).exists()]
        missing = missing[:limit] if limit is not None else missing
        ran[experiment.name] = len(missing)
        if not missing:
            continue
        run.experiment_dir(experiment.name).mkdir(parents=True, exist_ok=True)
        inputs = TrialInputs(items=experiment_items(run, experiment), recognizer=recognizer,
                             ordering=experiment.ordering, phase_one=experiment.phase_one, learning=config.learning)
        with progress(total=len(missing), desc=f"learn {experiment.name}", quiet=quiet) as bar:
            for seed, text in runner.map(trial_task, inputs, missing):
                atomic_write_text(run.trial_path(experiment.name, seed), text)
                bar.update(1)
    return ran


def _evaluation_done(path: Any, control: str, attempts: int) -> bool:
    if not path.exists():
        return False
    try:
        saved = json.loads(path.read_text(encoding="utf-8"))
    except ValueError:
        return False
    # A file that says another control drove its imitator (as builds that could not choose
    # wrote "control_used") is not this evaluation.
    driven_by = saved.get("control_used", saved.get("control"))
    return bool(driven_by == control and saved.get("attempts") == attempts)


def evaluate_imitators(run: RunDir, config: RunConfig, runner: TaskRunner, *,
                       experiments: Sequence[str] | None = None, quiet: bool = False) -> dict[str, int]:
    """Evaluate the imitators of every experiment's first ``evaluated_imitators`` trials, by each
    control, where not done yet; the first imitator's attempts are kept as a dataset. Returns how
    many evaluations ran, by experiment."""
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    attempts = 2 * config.experiments.attempts_per_configuration
    seeds = evaluated_seeds(config)
    ran = {}
    for experiment in _selected(experiments):
        jobs = []
        for seed in seeds:
            for control in CONTROLS:
                keep = seed == seeds[0]
                if _evaluation_done(run.evaluation_path(experiment.name, seed, control), control, attempts) and (
                        not keep or run.attempts_path(experiment.name, control).exists()):
                    continue
                trial_path = run.trial_path(experiment.name, seed)
                if not trial_path.exists():
                    raise MissingInputError(f"{trial_path} is missing: run `polymimic learn --run-dir {run.path}` "
                                            "first")
                jobs.append((seed, trial_path.read_text(encoding="utf-8"), control, keep))
        ran[experiment.name] = len(jobs)
        if not jobs:
            continue
        inputs = EvaluationInputs(recognizer=recognizer, learning=config.learning,
                                  attempts_per_configuration=config.experiments.attempts_per_configuration,
                                  seed=config.seeds.evaluation, items=experiment_items(run, experiment),
                                  field=config.field)
        with progress(total=len(jobs), desc=f"evaluate {experiment.name}", quiet=quiet) as bar:
            for _, result in runner.map(evaluation_task, inputs, jobs):
                kept = result.pop("attempt_list")
                if kept is not None:
                    save_demonstrations(kept, run.attempts_path(experiment.name, result["control"]))
                atomic_write_text(run.evaluation_path(experiment.name, result["trial_seed"], result["control"]),
                                  json.dumps(result) + "\n")
                bar.update(1)
    return ran
