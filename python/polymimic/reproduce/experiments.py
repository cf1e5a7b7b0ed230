"""The thesis's learning experiments (§4.4): their trials and the evaluation of their imitators.

Three experiments, each of many trials that differ only in their seed:

* ``heterogeneous_rcb``: Expert, Tiny, Humanoid, trained in that order in phase one (RCB);
* ``heterogeneous_bcr``: the same demonstrations, the reverse order (BCR);
* ``varying_skill``: Poor, Average, Expert, their demonstrations interleaved in phase one.

Trials and evaluations run as tasks on a :class:`~polymimic.runs.backends.TaskRunner`; every result
is written to the run directory, atomically, as it arrives, so an interrupted stage resumes
where it stopped and a finished one is never redone. Who takes part is in
:mod:`polymimic.runs.roster`.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import os
import pathlib
from collections.abc import Sequence
from typing import Any, TypedDict

from polymimic._atomic import atomic_write_text
from polymimic._native import ImitatorPolicy as CompiledPolicy
from polymimic._native import ModelFileError, PrimitiveRecognizer
from polymimic.bodies import Body, BodySpec
from polymimic.datasets import load_demonstrations, save_demonstrations
from polymimic.evaluation import Attempts
from polymimic.field import OUTCOMES
from polymimic.learning import (
    ImitatorPolicy,
    LearningConfig,
    SegmentedDemonstrations,
    TrialResult,
    evaluate,
    run_trial,
)
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError, RunConfig
from polymimic.runs.progress import progress
from polymimic.runs.roster import CONTROLS, Experiment
from polymimic.runs.rundir import MissingInputError
from polymimic.segments import load_segments

__all__ = ["SavedEvaluation", "evaluate_imitators", "evaluated_seeds", "imitator_policy", "learn", "load_evaluation",
           "trial_seeds"]


def trial_seeds(config: RunConfig) -> list[int]:
    """Every experiment's trial seeds: ``first_trial``, ``first_trial + 1``, …"""
    return [config.seeds.first_trial + i for i in range(config.experiments.sizes.trials)]


def evaluated_seeds(config: RunConfig) -> list[int]:
    """The seeds of the trials whose imitators are evaluated: the first ones."""
    return trial_seeds(config)[:config.experiments.evaluated_imitators]


def imitator_policy(trial: TrialResult, *, recognizer: PrimitiveRecognizer, config: LearningConfig,
                    control: str, demonstrations: SegmentedDemonstrations,
                    body: BodySpec = "lego") -> ImitatorPolicy:
    """The trial's imitator driving ``body`` by ``control``; the improved control also learns
    from the (segmented) ``demonstrations`` the imitator watched."""
    if control not in CONTROLS:
        raise ValueError(f"control must be one of {', '.join(CONTROLS)}, got {control!r}")
    return ImitatorPolicy(trial, recognizer=recognizer, config=config, control=control,
                          demonstrations=demonstrations if control == "improved" else None, body=body)


# Tasks: module-level, so that process-pool and Ray workers can import them.

@dataclasses.dataclass(frozen=True)
class TrialInputs:
    """What every trial of an experiment shares."""

    items: SegmentedDemonstrations
    recognizer: PrimitiveRecognizer
    ordering: tuple[str, ...]
    phase_one: str
    learning: LearningConfig
    body: Body = Body("lego")
    """The imitator's body, on whose setting the trial learns."""


def trial_task(inputs: TrialInputs, seed: int) -> str:
    """One trial, as the JSON :meth:`TrialResult.save` writes (it depends on ``seed`` alone)."""
    return run_trial(inputs.items, recognizer=inputs.recognizer, ordering=list(inputs.ordering),
                     config=inputs.learning, phase_one=inputs.phase_one, seed=seed, body=inputs.body).to_json()


@dataclasses.dataclass(frozen=True)
class EvaluationInputs:
    """What every evaluation of an experiment's imitators shares."""

    recognizer: PrimitiveRecognizer
    learning: LearningConfig
    attempts: Attempts
    """The attempts every imitator plays (the run's evaluation attempts)."""
    items: SegmentedDemonstrations
    """The experiment's segmented demonstrations: what its imitators watched."""
    field: dict[str, Any]
    """The field the imitators play on (the run's)."""
    body: Body = Body("lego")
    """The imitators' body."""


_first_policies: dict[str, tuple[EvaluationInputs, ImitatorPolicy]] = {}
"""In each process, by control: the first policy made for the inputs it was made from, whose
learning from the demonstrations the policies of every other trial share."""


def _policy(inputs: EvaluationInputs, trial: TrialResult, control: str) -> CompiledPolicy:
    """The trial's imitator driven by ``control``; what the improved control learns from the
    demonstrations is learned once per process and experiment where it does not depend on the
    trial (under ``"even"`` weighting)."""
    first = _first_policies.get(control)
    if first is not None and first[0] is inputs and inputs.learning.imitator_weighting == "even":
        return first[1].for_trial(trial)
    policy = imitator_policy(trial, recognizer=inputs.recognizer, config=inputs.learning, control=control,
                             demonstrations=inputs.items, body=inputs.body)
    _first_policies[control] = (inputs, policy)
    return policy


def evaluation_task(inputs: EvaluationInputs, job: tuple[int, str, str, bool]) -> dict[str, Any]:
    """Goals and own goals of one trial's imitator; ``job`` is ``(trial seed, trial JSON,
    control, keep the attempts)``."""
    trial_seed, trial_json, control, keep = job
    policy = _policy(inputs, TrialResult.from_json(trial_json), control)
    evaluation = evaluate(policy, attempts=inputs.attempts, field_config=inputs.field)
    return {"trial_seed": trial_seed, "control": control, "seed": inputs.attempts.seed,
            "goals": evaluation.goals, "own_goals": evaluation.own_goals, "attempts": len(evaluation.attempts),
            "outcomes": [a.outcome for a in evaluation.attempts],
            "attempt_list": evaluation.attempts if keep else None}


# Stages.

def experiment_items(run: RunDir, experiment: Experiment) -> SegmentedDemonstrations:
    """The experiment's segmented demonstrations, demonstrator by demonstrator."""
    return SegmentedDemonstrations.concat([load_segments(run.require(run.segments_path(who), "segment"))
                                           for who in experiment.demonstrators])


def _selected(config: RunConfig, names: Sequence[str] | None) -> list[Experiment]:
    """The experiments ``names`` asks for (all of them for None): the thesis's and the config's."""
    known = config.all_experiments()
    if names is None:
        return list(known.values())
    unknown = [n for n in names if n not in known]
    if unknown:
        raise ConfigError(f"unknown experiment {unknown[0]!r}; expected one of {', '.join(known)}")
    return [known[n] for n in names]


def learn(run: RunDir, config: RunConfig, runner: TaskRunner, *, experiments: Sequence[str] | None = None,
          limit: int | None = None, quiet: bool = False) -> dict[str, int]:
    """Run every experiment's trials that have no file yet (at most ``limit`` per experiment);
    return how many ran, by experiment."""
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    ran = {}
    for experiment in _selected(config, experiments):
        missing = [s for s in trial_seeds(config)
                   if not run.finished(run.trial_path(experiment.name, s), TrialResult.load)]
        missing = missing[:limit] if limit is not None else missing
        ran[experiment.name] = len(missing)
        if not missing:
            continue
        run.experiment_dir(experiment.name).mkdir(parents=True, exist_ok=True)
        inputs = TrialInputs(items=experiment_items(run, experiment), recognizer=recognizer,
                             ordering=experiment.ordering, phase_one=experiment.phase_one, learning=config.learning,
                             body=config.imitator_body())
        with progress(total=len(missing), desc=f"learn {experiment.name}", quiet=quiet) as bar:
            for seed, text in runner.map(trial_task, inputs, missing):
                atomic_write_text(run.trial_path(experiment.name, seed), text)
                bar.update(1)
    return ran


class SavedEvaluation(TypedDict):
    """What an evaluation file holds: one trial's imitator driven by one control."""

    trial_seed: int
    control: str
    seed: int
    goals: int
    own_goals: int
    attempts: int
    outcomes: list[str]


def load_evaluation(path: str | os.PathLike[str]) -> SavedEvaluation:
    """An evaluation file, checked whole: every key there with a value of its type and range,
    and goals and own goals as its outcomes count them.

    Raises
    ------
    polymimic.ModelFileError
        Naming the file and the key, for anything missing, damaged, truncated or foreign.
    """
    where = os.fspath(path)
    try:
        data = json.loads(pathlib.Path(path).read_bytes().decode("utf-8"))
    except (OSError, ValueError) as error:
        raise ModelFileError(f"{where}: not a saved evaluation ({error})") from error
    if not isinstance(data, dict):
        raise ModelFileError(f"{where}: not a saved evaluation (a JSON object is expected)")
    if "control_used" in data:  # builds that could not choose the control wrote which one drove
        data["control"] = data.pop("control_used")

    def integer(key: str, low: int, high: int | None = None) -> int:
        value = data.get(key)
        if type(value) is not int or value < low or (high is not None and value > high):
            span = f"{low}..{high}" if high is not None else f"at least {low}"
            raise ModelFileError(f"{where}: key {key!r} must be an integer {span}, got {value!r}")
        return value

    attempts, control, outcomes = integer("attempts", 1), data.get("control"), data.get("outcomes")
    if control not in CONTROLS:
        raise ModelFileError(f"{where}: key 'control' must be one of {', '.join(CONTROLS)}, got {control!r}")
    if not isinstance(outcomes, list) or len(outcomes) != attempts or not all(o in OUTCOMES for o in outcomes):
        raise ModelFileError(f"{where}: key 'outcomes' must list {attempts} outcomes, each one of "
                             f"{', '.join(OUTCOMES)}")
    saved = SavedEvaluation(trial_seed=integer("trial_seed", 0), control=control, seed=integer("seed", 0),
                            goals=integer("goals", 0, attempts), own_goals=integer("own_goals", 0, attempts),
                            attempts=attempts, outcomes=outcomes)
    for key, value, outcome in (("goals", saved["goals"], "goal"), ("own_goals", saved["own_goals"], "own_goal")):
        if value != outcomes.count(outcome):
            raise ModelFileError(f"{where}: key {key!r} is {value} but its outcomes count {outcomes.count(outcome)}")
    return saved


def _evaluation_done(run: RunDir, path: pathlib.Path, control: str, attempts: int) -> bool:
    """Whether ``path`` holds this evaluation: whole, driven by ``control``, ``attempts`` long.
    A damaged file is removed (with a warning) and made again; a file another control drove or
    of another size is simply redone."""
    saved = run.loaded(path, load_evaluation)
    return saved is not None and saved["control"] == control and saved["attempts"] == attempts


def evaluate_imitators(run: RunDir, config: RunConfig, runner: TaskRunner, *,
                       experiments: Sequence[str] | None = None, quiet: bool = False) -> dict[str, int]:
    """Evaluate the imitators of every experiment's first ``evaluated_imitators`` trials, by each
    control, where not done yet; the first imitator's attempts are kept as a dataset. Returns how
    many evaluations ran, by experiment."""
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    attempts = config.evaluation_attempts()
    seeds = evaluated_seeds(config)
    ran = {}
    for experiment in _selected(config, experiments):
        jobs = []
        for seed in seeds:
            for control in CONTROLS:
                keep = seed == seeds[0]
                evaluation = run.evaluation_path(experiment.name, seed, control)
                if _evaluation_done(run, evaluation, control, attempts.count) and (
                        not keep or run.finished(run.attempts_path(experiment.name, control),
                                                 functools.partial(load_demonstrations, bodies=config.bodies))):
                    continue
                trial_path = run.trial_path(experiment.name, seed)
                if not run.finished(trial_path, TrialResult.load):
                    raise MissingInputError(f"{trial_path} is missing: run `polymimic learn --run-dir {run.path}` "
                                            "first")
                jobs.append((seed, trial_path.read_text(encoding="utf-8"), control, keep))
        ran[experiment.name] = len(jobs)
        if not jobs:
            continue
        inputs = EvaluationInputs(recognizer=recognizer, learning=config.learning, attempts=attempts,
                                  items=experiment_items(run, experiment), field=config.field,
                                  body=config.imitator_body())
        with progress(total=len(jobs), desc=f"evaluate {experiment.name}", quiet=quiet) as bar:
            for _, result in runner.map(evaluation_task, inputs, jobs):
                kept = result.pop("attempt_list")
                if kept is not None:
                    save_demonstrations(kept, run.attempts_path(experiment.name, result["control"]))
                atomic_write_text(run.evaluation_path(experiment.name, result["trial_seed"], result["control"]),
                                  json.dumps(result) + "\n")
                bar.update(1)
    return ran
