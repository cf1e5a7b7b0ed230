"""Practice on a run's imitators: what the benchmark's practice stage and ``polymimic practice``
share — the task a worker runs, the file each practice leaves, and their summary.

A practice is one piece of work (an interrupted one starts again): the imitator of one trial of
one group (a benchmark's profile or a reproduction's experiment) practises for a budget of
environment steps under the trial's seed (:func:`polymimic.practice.practice`) and is scored at
every checkpoint on the run's evaluation attempts.

Each kind of run whose imitators can practise says what its practice needs as a
:class:`PracticeSource`: ``polymimic practice`` knows runs only through it.
"""

from __future__ import annotations

import dataclasses
import json
import os
import pathlib
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypedDict

from polymimic._atomic import atomic_write_text
from polymimic._native import ModelFileError, PrimitiveRecognizer
from polymimic.bodies import Body
from polymimic.evaluation import Attempts
from polymimic.learning import ImitatorPolicy, LearningConfig, SegmentedDemonstrations, TrialResult, evaluate
from polymimic.plots import MeanSd
from polymimic.practice.curve import plot_curves
from polymimic.practice.methods import DEFAULT_METHOD, METHODS, RETIRED_METHODS, practise
from polymimic.runs.backends import TaskRunner
from polymimic.runs.checked_json import checked_checkpoints, integer_key, json_object, name_key
from polymimic.runs.config import ConfigError
from polymimic.runs.progress import progress
from polymimic.runs.rundir import RunHouse
from polymimic.runs.stats import mean_sd

__all__ = ["CHECKPOINT_KEYS", "FORMAT", "VERSION", "PracticeCurve", "PracticeInputs", "PracticeSource", "RunPractice",
           "SavedPractice", "chosen_groups", "is_practice_of", "load_practice", "practice_task", "practise_run",
           "summarise"]

CHECKPOINT_KEYS = ("checkpoint", "steps", "net_goals", "goals", "own_goals", "attempts_learned", "attempts_lost")
"""A checkpoint's keys in a practice file (:class:`polymimic.practice.CurvePoint`'s)."""


@dataclasses.dataclass(frozen=True)
class PracticeInputs:
    """What every practice of a run shares: the imitator's recogniser, learning constants and
    body, each group's segmented demonstrations, the field, the segmenter's settings, the budget
    and the evaluation attempts."""

    recognizer: PrimitiveRecognizer
    learning: LearningConfig
    demonstrations: Mapping[str, SegmentedDemonstrations]
    body: Body
    field: dict[str, Any]
    segmenter: dict[str, Any]
    steps: int
    attempts: Attempts
    """The run's evaluation attempts, on which every checkpoint is scored."""
    method: str = DEFAULT_METHOD
    """How the imitators practise (:data:`polymimic.practice.methods.METHODS`)."""


@dataclasses.dataclass(frozen=True)
class RunPractice:
    """A finished run's imitators ready to practise: the run, the groups chosen, every trial's
    seed (in order; the first ones practise), what every practice shares, and where each trial's
    file is (``trial_path(group, seed)``)."""

    run: RunHouse[Any]
    groups: list[str]
    trial_seeds: list[int]
    inputs: PracticeInputs
    trial_path: Callable[[str, int], pathlib.Path]


@dataclasses.dataclass(frozen=True)
class PracticeSource:
    """What a kind of run directory offers practice: the format its manifest names, the command
    that makes it, the name ``practice.json`` gives it (``kind``), what a group of it is called,
    and ``practice(path, only, steps, method)``: the run at ``path`` ready to practise, its groups
    those of ``only`` (all for None, checked by :func:`chosen_groups`)."""

    manifest_format: str
    command: str
    kind: str
    group: str
    practice: Callable[[pathlib.Path, Sequence[str] | None, int, str], RunPractice]


def chosen_groups(names: Sequence[str], only: Sequence[str] | None, group: str) -> list[str]:
    """The groups of ``names`` that ``only`` (``--only``) names, in the run's order; all of them
    for None. A name the run lacks is a :class:`~polymimic.runs.config.ConfigError` naming it, as a
    ``group`` of the run, and listing the run's."""
    if only is None:
        return list(names)
    unknown = [n for n in only if n not in names]
    if unknown:
        raise ConfigError(f"--only: the run has no {group} {unknown[0]!r}; it has {', '.join(names)}")
    return [n for n in names if n in only]


def practice_task(inputs: PracticeInputs, job: tuple[str, int, str]) -> dict[str, Any]:
    """``(group, trial seed, the trial's JSON)`` → the improved imitator of that trial,
    practising: its file's contents, and (``"outcomes"``) the practised policy's outcomes on the
    evaluation attempts."""
    group, trial_seed, trial_json = job
    policy = ImitatorPolicy(TrialResult.from_json(trial_json), recognizer=inputs.recognizer, config=inputs.learning,
                            control="improved", demonstrations=inputs.demonstrations[group], body=inputs.body)
    result = practise(policy, method=inputs.method, steps=inputs.steps, seed=trial_seed, evaluation=inputs.attempts,
                      field_config=inputs.field, segmenter=inputs.segmenter)
    final = evaluate(result.policy, attempts=inputs.attempts, field_config=inputs.field)
    return {"group": group, "trial_seed": trial_seed, "evaluation_seed": inputs.attempts.seed,
            "attempts": inputs.attempts.count, "budget": inputs.steps, "steps": result.steps,
            "method": inputs.method,
            "attempts_learned": len(result.attempts), "attempts_lost": result.attempts_lost,
            "checkpoints": [p.to_dict() for p in result.curve], "outcomes": [a.outcome for a in final.attempts]}


class SavedPractice(TypedDict):
    """One practice as its file keeps it: the group, the trial, the budget and every checkpoint."""

    group: str
    trial_seed: int
    evaluation_seed: int
    attempts: int
    budget: int
    steps: int
    attempts_learned: int
    attempts_lost: int
    checkpoints: list[dict[str, int]]
    method: str
    """How it practised: one of :data:`~polymimic.practice.methods.METHODS`, or ``"refine"``
    (:data:`~polymimic.practice.methods.RETIRED_METHODS`) in a file from before the method had to earn its place."""


def load_practice(path: str | os.PathLike[str]) -> SavedPractice:
    """A practice file, checked: checkpoints rising from 0 to the budget, none played beyond its
    checkpoint, each one's goals and own goals within the attempts and its net goals their
    difference."""
    where, data = os.fspath(path), json_object(path, "practice")
    attempts, budget = integer_key(data, "attempts", where, 1), integer_key(data, "budget", where, 1)
    checkpoints = checked_checkpoints(data, where, attempts)
    marks = []
    for index, point in enumerate(checkpoints):
        at = f"{where}: checkpoint {index}"
        # net goals may be negative; checked_checkpoints checked them against the goals
        values = {key: integer_key(point, key, at, 0) for key in CHECKPOINT_KEYS if key != "net_goals"}
        if values["steps"] > values["checkpoint"]:
            raise ModelFileError(f"{at}: it played {values['steps']} steps, beyond its checkpoint "
                                 f"{values['checkpoint']}")
        marks.append(values["checkpoint"])
    if marks[0] != 0 or marks != sorted(set(marks)) or marks[-1] != budget:
        raise ModelFileError(f"{where}: the checkpoints must rise from 0 to the budget {budget}, got {marks}")
    return SavedPractice(group=name_key(data, "group", where), trial_seed=integer_key(data, "trial_seed", where, 0),
                         evaluation_seed=integer_key(data, "evaluation_seed", where, 0), attempts=attempts,
                         budget=budget, steps=integer_key(data, "steps", where, 0, budget),
                         attempts_learned=integer_key(data, "attempts_learned", where, 0),
                         attempts_lost=integer_key(data, "attempts_lost", where, 0), checkpoints=checkpoints,
                         method=_method(data, where))


def _method(data: dict[str, Any], where: str) -> str:
    method = data.get("method", "refine")
    if method not in METHODS + RETIRED_METHODS:
        raise ModelFileError(f"{where}: key 'method' must be one of {', '.join(METHODS)}, got {method!r}")
    return str(method)


class PracticeCurve(TypedDict):
    checkpoints: list[int]
    steps: list[MeanSd]
    """Steps played by each checkpoint (at most the checkpoint: a round's attempt that would pass
    it waits for the next)."""
    net_goals: list[MeanSd]
    attempts_lost: int
    """Attempts the tracker lost, over every practice (left out of learning, counted)."""
    trials: int


def summarise(saved: Sequence[SavedPractice]) -> PracticeCurve:
    """The practices of one group: mean (sd) over them at every checkpoint."""
    marks = [int(p["checkpoint"]) for p in saved[0]["checkpoints"]]
    at = range(len(marks))
    return PracticeCurve(checkpoints=marks, steps=[mean_sd(p["checkpoints"][k]["steps"] for p in saved) for k in at],
                         net_goals=[mean_sd(p["checkpoints"][k]["net_goals"] for p in saved) for k in at],
                         attempts_lost=sum(p["attempts_lost"] for p in saved), trials=len(saved))


FORMAT, VERSION = "polymimic.practice", 1


def is_practice_of(saved: SavedPractice | None, group: str, trial_seed: int, *, evaluation: Attempts, budget: int,
                   method: str = DEFAULT_METHOD) -> bool:
    """Whether ``saved`` (a practice file read whole, or None) is the practice asked for: of this
    group's trial, scored on the ``evaluation`` attempts (the file keeps their seed and count),
    for this budget of steps, by this method."""
    return saved is not None and (saved["group"], saved["trial_seed"], saved["evaluation_seed"], saved["attempts"],
                                  saved["budget"], saved["method"]) == (group, trial_seed, evaluation.seed,
                                                                        evaluation.count, budget, method)


def practise_run(run: RunHouse[Any], folder: pathlib.Path, inputs: PracticeInputs, jobs: Sequence[tuple[str, int]],
                 trial_json: Callable[[str, int], str], runner: TaskRunner, *, kind: str,
                 quiet: bool = False) -> tuple[pathlib.Path, int]:
    """Practise the imitators of ``jobs`` (group, trial seed) into ``folder`` (within ``run``),
    each practice's file at ``<group>/practice_<seed>.json`` as it finishes, redoing only what is
    missing or damaged; then ``practice.json`` (every group's curve), ``practice.csv`` and
    ``practice_curve.png`` beside them. Returns the summary's path and how many practices ran."""
    def path(group: str, seed: int) -> pathlib.Path:
        return folder / group / f"practice_{seed}.json"

    def done(group: str, seed: int) -> bool:
        return is_practice_of(run.loaded(path(group, seed), load_practice), group, seed, evaluation=inputs.attempts,
                              budget=inputs.steps, method=inputs.method)

    todo = [(group, seed, trial_json(group, seed)) for group, seed in jobs if not done(group, seed)]
    for group in {group for group, _ in jobs}:
        (folder / group).mkdir(parents=True, exist_ok=True)
    with progress(total=len(todo), desc="practice", quiet=quiet) as bar:
        for _, result in runner.map(practice_task, inputs, todo):
            result.pop("outcomes")
            atomic_write_text(path(result["group"], result["trial_seed"]), json.dumps(result, sort_keys=True) + "\n")
            bar.update(1)
    groups = dict.fromkeys(group for group, _ in jobs)
    curves = {group: summarise([load_practice(path(group, seed)) for g, seed in jobs if g == group])
              for group in groups}
    summary = {"format": FORMAT, "version": VERSION, "run": kind, "steps": inputs.steps,
               "evaluation_seed": inputs.attempts.seed, "attempts": inputs.attempts.count,
               "groups": curves}
    atomic_write_text(folder / "practice.json", json.dumps(summary, indent=1) + "\n")
    rows = ["group,checkpoint,steps_mean,net_goals_mean,net_goals_sd,trials"]
    for group, curve in curves.items():
        for mark, steps, net in zip(curve["checkpoints"], curve["steps"], curve["net_goals"]):
            rows.append(f"{group},{mark},{steps['mean']:.1f},{net['mean']:.2f},{net['sd']:.2f},{curve['trials']}")
    atomic_write_text(folder / "practice.csv", "\n".join(rows) + "\n")
    points: dict[str, Sequence[tuple[float, float]]] = {
        group: [(m, float(n["mean"] or 0.0)) for m, n in zip(c["checkpoints"], c["net_goals"])]
        for group, c in curves.items()}
    plot_curves(folder / "practice_curve.png", points,
                title=f"Net goals over {inputs.steps:,} steps of practice, mean over each group's trials")
    return folder / "practice.json", len(todo)
