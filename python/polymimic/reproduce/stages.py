"""The stages of a reproduction, each reading its inputs from the run directory and writing its
outputs there; ``reproduce`` runs them all. A stage skips what is already done, so rerunning
one (or all) after an interruption goes on where it stopped.

=============  ==================================================  ==========================
stage          writes                                              reads
=============  ==================================================  ==========================
self-observe   datasets/self_observation_{train,test}.parquet
record         datasets/demonstrations_<demonstrator>.parquet      (models/recognizer.json)
train          models/recognizer.json                              self_observation_train
segment        datasets/segments_<demonstrator>.parquet            recogniser, demonstrations
learn          models/experiments/<experiment>/trial_<seed>.json   recogniser, segments
evaluate       …/evaluation_<seed>_<control>.json, attempts        recogniser, trials
report         results.json, plots/, report.md, report.html        everything
=============  ==================================================  ==========================

The Average demonstrator is an imitator trained in the heterogeneous experiment, so it needs
the recogniser: ``record`` records it when the recogniser exists, ``segment`` otherwise.
"""

from __future__ import annotations

import dataclasses
import json
import pathlib
import sys
import time
from collections.abc import Callable, Sequence, Sized
from typing import cast

from polymimic import _native
from polymimic._atomic import atomic_write_text
from polymimic._native import PrimitiveRecognizer
from polymimic.datasets import load_demonstrations, load_self_observation, save_demonstrations, save_self_observation
from polymimic.field import PRIMITIVES, Demonstration, PrimitiveSequence, record, self_observation
from polymimic.learning import TrialResult, average_demonstrator
from polymimic.reproduce.experiments import evaluate_imitators, learn
from polymimic.reproduce.report import write_report
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import RunConfig
from polymimic.runs.roster import DEMONSTRATORS, HETEROGENEOUS, RECORDED
from polymimic.runs.roster_config import (
    DemonstratorSpec,
    ImportedDemonstrator,
    demonstrations_expected,
    file_digest,
    record_demonstrator,
    source_file,
)
from polymimic.runs.rundir import MissingInputError, RunError
from polymimic.segments import load_segments, save_segments, segment_demonstrations

__all__ = ["STAGES", "Context", "reproduce", "run_stage"]


@dataclasses.dataclass
class Context:
    """A run directory, its config, where tasks run, and whether to keep quiet."""

    run: RunDir
    config: RunConfig
    runner: TaskRunner
    quiet: bool = False

    def say(self, message: str) -> None:
        """Prints a stage message to stderr, unless quiet."""
        if not self.quiet:
            print(message, file=sys.stderr)

    def finished(self, path: pathlib.Path, load: Callable[[pathlib.Path], object], *,
                 count: int | None = None) -> bool:
        """Whether ``path`` holds a whole output (``count`` items, where given); a damaged one is
        removed, with a warning, so that the stage makes it again."""
        def checked(p: pathlib.Path) -> object:
            loaded = load(p)
            if count is not None and len(cast(Sized, loaded)) != count:
                raise RunError(f"it holds {len(cast(Sized, loaded))} items where the config asks for {count}")
            return loaded
        return self.run.finished(path, checked)

    def demonstrations(self, path: pathlib.Path) -> list[Demonstration]:
        """The demonstrations of the file ``path``, a body of the run's own read as its config describes it."""
        return load_demonstrations(path, bodies=self.config.bodies)

    def self_observation(self, path: pathlib.Path) -> list[PrimitiveSequence]:
        """The self-observation of the file ``path``, the imitator's body read as the config describes it."""
        return load_self_observation(path, bodies=self.config.bodies)


def _self_observe(ctx: Context) -> int:
    settings, seeds, made = ctx.config.recognizer, ctx.config.seeds, 0
    for split, n, seed in (("train", settings.train_per_primitive, seeds.self_observation_train),
                           ("test", settings.test_per_primitive, seeds.self_observation_test)):
        path = ctx.run.self_observation_path(split)
        if not ctx.finished(path, ctx.self_observation, count=len(PRIMITIVES) * n):
            save_self_observation(self_observation(n, seed=seed, config=ctx.config.field,
                                                   body=ctx.config.imitator_body()), path)
            made += 1
    return made


def _record(ctx: Context) -> int:
    n, made = ctx.config.experiments.sizes.demonstrations_per_configuration, 0
    for who in RECORDED:
        path = ctx.run.demonstrations_path(who)
        if not ctx.finished(path, ctx.demonstrations, count=2 * n):
            demos = [d for configuration in (1, 2)
                     for d in record(who, configuration=configuration, n=n, seed=ctx.config.seeds.demonstrations,
                                     config=ctx.config.field)]
            save_demonstrations(demos, path)
            made += 1
    for name, spec in ctx.config.demonstrators.items():
        made += _record_own(ctx, name, spec)
    if ctx.run.recognizer_path.exists():
        made += _record_average(ctx)
    return made


def _record_own(ctx: Context, name: str, spec: DemonstratorSpec) -> int:
    """A demonstrator of the run config's. A log or a policy file is fingerprinted when its
    demonstrations are made, so that a rerun after it changed says so rather than going on with
    demonstrations of another file."""
    n, path = ctx.config.experiments.sizes.demonstrations_per_configuration, ctx.run.demonstrations_path(name)
    source, fingerprint = source_file(spec), path.with_name(f"{path.stem}.source.json")
    if ctx.finished(path, ctx.demonstrations, count=demonstrations_expected(spec, n)):
        if source is not None and source.exists() and fingerprint.exists():
            recorded = json.loads(fingerprint.read_text(encoding="utf-8")).get("sha256")
            if recorded != file_digest(source):
                raise RunError(f"{source} has changed since {path.name} was made from it: start a new run (or remove "
                               f"{path} and what was made from it)")
        return 0
    if isinstance(spec, ImportedDemonstrator):
        raise MissingInputError(f"{path} is missing: [demonstrators.{name}] is imported; bring its log in with "
                                f"`polymimic import-tracks FILE --as {name} --run-dir {ctx.run.path}`")
    try:
        demos, said = record_demonstrator(spec, n=n, seed=ctx.config.seeds.demonstrations,
                                          field_config=ctx.config.field, bodies=ctx.config.bodies)
    except (ValueError, TypeError, OSError) as error:
        raise RunError(f"[demonstrators.{name}]: {error}") from error
    if not demos:
        raise RunError(f"[demonstrators.{name}]: no valid demonstration ({said})")
    if source is not None:
        atomic_write_text(fingerprint, json.dumps({"file": str(source), "sha256": file_digest(source)}) + "\n")
    save_demonstrations(demos, path)
    ctx.say(f"  {said}")
    return 1


def _record_average(ctx: Context) -> int:
    """The Average demonstrator: of the heterogeneous (RCB) imitators tried, driven by the thesis's
    rule, the one whose net goals lie nearest the middle of the Poor's and the Expert's (§4.4.2;
    see :func:`polymimic.average_demonstrator`)."""
    path, n = ctx.run.demonstrations_path("average"), ctx.config.experiments.sizes.demonstrations_per_configuration
    if ctx.finished(ctx.run.average_trial_path, TrialResult.load) and ctx.finished(path, ctx.demonstrations,
                                                                                   count=2 * n):
        return 0
    recognizer = PrimitiveRecognizer.load(ctx.run.require(ctx.run.recognizer_path, "train"))
    settings = ctx.config.experiments
    try:
        recorded = {who: ctx.demonstrations(ctx.run.require(ctx.run.demonstrations_path(who), "record"))
                    for who in (*HETEROGENEOUS, "poor")}
        demos, trial = average_demonstrator(recognizer, n=settings.sizes.demonstrations_per_configuration,
                                            seed=ctx.config.seeds.demonstrations,
                                            max_trials=settings.average_max_trials, config=ctx.config.learning,
                                            recorded=recorded, field_config=ctx.config.field,
                                            segmenter=dataclasses.asdict(ctx.config.segmenter),
                                            body=ctx.config.imitator_body())
    except _native.PolymimicError as error:
        raise RunError(f"no Average demonstrator: {error}; raise [experiments] average_max_trials") from error
    trial.save(ctx.run.average_trial_path)
    save_demonstrations(demos, path)
    return 1


def _train(ctx: Context) -> int:
    if ctx.finished(ctx.run.recognizer_path, PrimitiveRecognizer.load):
        return 0
    sequences = ctx.self_observation(ctx.run.require(ctx.run.self_observation_path("train"), "self-observe"))
    ctx.config.recognizer.train(sequences).save(ctx.run.recognizer_path)  # atomically
    return 1


def _segment(ctx: Context) -> int:
    recognizer = PrimitiveRecognizer.load(ctx.run.require(ctx.run.recognizer_path, "train"))
    made = _record_average(ctx)
    segmenter = dataclasses.asdict(ctx.config.segmenter)
    n = ctx.config.experiments.sizes.demonstrations_per_configuration
    for who in (*DEMONSTRATORS, *ctx.config.demonstrators):
        path, recorded = ctx.run.segments_path(who), ctx.run.demonstrations_path(who)
        count, demos = demonstrations_expected(ctx.config.demonstrators.get(who), n), None
        if count is None:  # as many segmented as there are demonstrations, read once for both
            demos = ctx.demonstrations(ctx.run.require(recorded, "record"))
            count = len(demos)
        if not ctx.finished(path, load_segments, count=count):
            demos = demos if demos is not None else ctx.demonstrations(ctx.run.require(recorded, "record"))
            save_segments(segment_demonstrations(demos, recognizer, **segmenter), path)
            made += 1
    return made


def _learn(ctx: Context, experiments: Sequence[str] | None = None, limit: int | None = None) -> int:
    ran = learn(ctx.run, ctx.config, ctx.runner, experiments=experiments, limit=limit, quiet=ctx.quiet)
    ctx.say("  trials run: " + ", ".join(f"{name} {n}" for name, n in ran.items()))
    return sum(ran.values())


def _evaluate(ctx: Context, experiments: Sequence[str] | None = None) -> int:
    ran = evaluate_imitators(ctx.run, ctx.config, ctx.runner, experiments=experiments, quiet=ctx.quiet)
    ctx.say("  evaluations run: " + ", ".join(f"{name} {n}" for name, n in ran.items()))
    return sum(ran.values())


def _report(ctx: Context) -> int:
    write_report(ctx.run, ctx.config, runner=ctx.runner, quiet=ctx.quiet)
    return 1


STAGES: dict[str, Callable[..., int]] = {
    "self-observe": _self_observe,
    "record": _record,
    "train": _train,
    "segment": _segment,
    "learn": _learn,
    "evaluate": _evaluate,
    "report": _report,
}
"""Every stage, in the order ``reproduce`` runs them; each returns how many outputs it made."""


WORKER_MODULES = ("polymimic.reproduce.experiments", "polymimic.reproduce.figures", "matplotlib.figure",
                  "matplotlib.backends.backend_agg")
"""What the stages' tasks import, the lazy imports of the figures included."""


def run_stage(ctx: Context, stage: str, **options: object) -> float:
    """Run one stage, recording its start and finish in the manifest; return its time (s).

    A stage that finds everything done keeps the times of the run that did it."""
    with ctx.run.lock(f"polymimic {stage}"):
        ctx.say(f"{stage} …")
        before = ctx.run.manifest()["stages"].get(stage)
        ctx.run.stage_started(stage, backend=ctx.runner.backend, workers=ctx.runner.workers)
        started = time.perf_counter()
        made = STAGES[stage](ctx, **options)
        seconds = time.perf_counter() - started
        if made == 0 and isinstance(before, dict) and before.get("finished"):
            ctx.run.stage_restored(stage, before)
            ctx.say(f"{stage}: already done")
        else:
            ctx.run.stage_finished(stage, seconds)
            ctx.say(f"{stage} done in {seconds:.1f} s")
        return seconds


def reproduce(ctx: Context) -> float:
    """Every stage in turn; return the total time (s)."""
    started = time.perf_counter()
    # The workers' imports (the figures' matplotlib among them) overlap the first stages.
    ctx.runner.start(WORKER_MODULES)
    with ctx.run.lock("polymimic reproduce"):
        for stage in STAGES:
            run_stage(ctx, stage)
    return time.perf_counter() - started
