"""``results.json``: every number a run measured, gathered from its run directory.

Shares are fractions in [0, 1]; ``{mean, sd}`` pairs are over trials (sd with n − 1; 0 for one
trial); numbers that do not exist (a share of nothing) are ``null``. The schema is described in
docs/formats.md (“Results of a reproduction”). The summaries are pure functions of trial results, so they can
be checked on made-up trials:

>>> mean_sd([1.0, 2.0, 3.0])
{'mean': 2.0, 'sd': 1.0}
>>> lp_climb([[0.5, 0.7, 0.95, 0.9], [0.5, 0.4, 0.3, 0.2, 0.1]])
{'share': 0.9, 'changes': {'mean': 3.0, 'sd': 1.4142135623730951}}
"""

from __future__ import annotations

import collections
import dataclasses
import math
from collections.abc import Iterable, Sequence
from typing import Any, cast

from polymimic import __version__, recognition
from polymimic._native import PrimitiveRecognizer, lp_order_hits
from polymimic.datasets import load_demonstrations, load_self_observation
from polymimic.field import Demonstration, commands_recorded
from polymimic.learning import LearningConfig, ModelResult, TrialResult
from polymimic.reproduce.experiments import evaluated_seeds, load_evaluation, trial_seeds
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.schema import (
    AppendixB,
    BehaviourRow,
    ExperimentResults,
    ExperimentSummary,
    ImitatorScore,
    LpClimb,
    Outcomes,
    PrimitiveStats,
    Results,
    SegmentRow,
)
from polymimic.runs.config import RunConfig
from polymimic.runs.roster import DEMONSTRATORS, Experiment
from polymimic.runs.rundir import MissingInputError
from polymimic.runs.stats import mean_sd

__all__ = ["appendix_b", "gather", "lp_climb", "summarize_evaluations", "summarize_experiment"]

FORMAT = "polymimic.results"
FORMAT_VERSION = 1
BEHAVIOUR_COUNTS = ("created", "deleted", "permanent", "candidates", "duplicates", "candidates_permanent")
LP_CLIMB_SHARE = 0.9
"""The share of its way to its final value a model's LP must cover for :func:`lp_climb`."""
APPENDIX_B_ROWS = 30


def lp_climb(histories: Sequence[Sequence[float]], *, share: float = LP_CLIMB_SHARE) -> LpClimb:
    """How many LP changes a model took to first cover ``share`` of the way from its starting LP
    to its final one (up or down), over trials: how fast the learner made up its mind."""
    changes = []
    for h in histories:
        if not h:
            continue
        rise = h[-1] - h[0]
        target = h[0] + share * rise
        changes.append(next(i for i, lp in enumerate(h) if (lp - target) * rise >= 0))
    return {"share": share, "changes": mean_sd(changes)}


def _sampled(history: Sequence[float], stride: int) -> list[float]:
    """The LP at every ``stride``-th change, from the first (as the thesis plots it)."""
    return [float(v) for v in history[::stride]]


def summarize_experiment(experiment: Experiment, trials: Sequence[TrialResult], *,
                         lp_stride: int = 200) -> ExperimentSummary:
    """An experiment's trials summarised: match rates, behaviour counts, final LPs, how often the
    final LPs fell in skill order, and the LP over time of every trial."""
    models: dict[str, list[ModelResult]] = {"imitator": [t.imitator for t in trials]}
    for name in experiment.ordering:
        models[name] = [t.models[name] for t in trials]
    demonstrators = {name: results for name, results in models.items() if name != "imitator"}
    hits = None
    if experiment.skill_order is not None:  # most skilled first; the count takes the least first
        hits = lp_order_hits(trials, list(experiment.skill_order[::-1]))
    return {
        "title": experiment.title,
        "ordering": list(experiment.ordering),
        "phase_one": experiment.phase_one,
        "trials": len(trials),
        "match_rate": {name: mean_sd(m.match_rate for m in results) for name, results in models.items()},
        "behaviours": {name: {count: mean_sd(getattr(m, count) for m in results) for count in BEHAVIOUR_COUNTS}
                       for name, results in models.items()},
        "final_lp": {name: mean_sd(m.lp for m in results) for name, results in demonstrators.items()},
        "lp_order_hits": hits,
        "lp_climb": {name: lp_climb([m.lp_history for m in results]) for name, results in demonstrators.items()},
        "lp_over_time": {"stride": lp_stride,
                         "trials": {name: [_sampled(m.lp_history, lp_stride) for m in results]
                                    for name, results in demonstrators.items()}},
    }


def summarize_evaluations(evaluations: Sequence[dict[str, Any]], *, attempts: int) -> ImitatorScore:
    """Goals and own goals of the evaluated imitators: mean and sd over imitators.

    >>> summary = summarize_evaluations([{"goals": 10, "own_goals": 2, "control": "thesis"},
    ...                                  {"goals": 14, "own_goals": 0, "control": "thesis"}], attempts=50)
    >>> summary["goals"], summary["goals_sd"], summary["own_goals"], summary["imitators"], summary["control"]
    (12.0, 2.8284271247461903, 1.0, 2, 'thesis')
    """
    goals, own = mean_sd(e["goals"] for e in evaluations), mean_sd(e["own_goals"] for e in evaluations)
    used = sorted({e["control"] for e in evaluations})
    return {"goals": goals["mean"], "own_goals": own["mean"], "attempts": attempts, "goals_sd": goals["sd"],
            "own_goals_sd": own["sd"], "imitators": len(evaluations), "control": ", ".join(used) or None}


def _predicts_ball(behaviour: dict[str, Any], config: LearningConfig) -> bool:
    """The learner's own test: enough ball samples, bearing spread small enough."""
    angle = behaviour.get("ball_angle_deg") or [0.0, math.inf]
    return bool(behaviour.get("ball_samples", 0) >= config.ball_min_samples
                and angle[1] <= config.ball_max_angle_sd_deg)


def appendix_b(trials: Iterable[TrialResult], config: LearningConfig, *, rows: int = APPENDIX_B_ROWS) -> AppendixB:
    """Appendix B: over every forward model of every trial (the imitator's included), the
    behaviours of two or more primitives found in most models at the end of their trial
    (``created``), made permanent in most, and predicting the ball in most.

    Deleted behaviours leave no trace in a trial's result, so ``count`` is the models that still
    hold the behaviour at the end; the thesis counted every creation.
    """
    count: collections.Counter[str] = collections.Counter()
    permanent: collections.Counter[str] = collections.Counter()
    ball: collections.Counter[str] = collections.Counter()
    n_models = 0
    for trial in trials:
        for model in (*trial.models.values(), trial.imitator):
            n_models += 1
            seen: dict[str, tuple[bool, bool]] = {}
            for b in model.behaviours:
                if len(b["primitives"]) < 2:
                    continue
                was = seen.get(b["primitives"], (False, False))
                seen[b["primitives"]] = (was[0] or bool(b["permanent"]), was[1] or _predicts_ball(b, config))
            for letters, (is_permanent, predicts) in seen.items():
                count[letters] += 1
                permanent[letters] += is_permanent
                ball[letters] += predicts

    def row(letters: str) -> BehaviourRow:
        return {"primitives": ",".join(letters), "count": count[letters], "permanent": permanent[letters],
                "predicting_ball": ball[letters]}

    def top(key: collections.Counter[str]) -> list[BehaviourRow]:
        ranked = sorted((b for b in count if key[b] > 0), key=lambda b: (-key[b], -count[b], b))
        return [row(b) for b in ranked[:rows]]

    return {"models": n_models, "created": top(count), "permanent": top(permanent), "predicting_ball": top(ball)}


def load_trials(run: RunDir, config: RunConfig, experiment: str) -> list[TrialResult]:
    """Every trial of ``experiment``, by seed; all must have run."""
    paths = [run.trial_path(experiment, s) for s in trial_seeds(config)]
    missing = [p for p in paths if not p.exists()]
    if missing:
        raise MissingInputError(f"{len(missing)} of {len(paths)} trials of {experiment} are missing (first: "
                                f"{missing[0].name}): run `polymimic learn --run-dir {run.path}` first")
    return [TrialResult.load(p) for p in paths]


def load_evaluations(run: RunDir, config: RunConfig, experiment: str, control: str) -> list[dict[str, Any]]:
    paths = [run.evaluation_path(experiment, s, control) for s in evaluated_seeds(config)]
    missing = [p for p in paths if not p.exists()]
    if missing:
        raise MissingInputError(f"{len(missing)} of {len(paths)} evaluations of {experiment} are missing (first: "
                                f"{missing[0].name}): run `polymimic evaluate --run-dir {run.path}` first")
    return [dict(load_evaluation(p)) for p in paths]


def _primitive_stats(recognizer: PrimitiveRecognizer) -> dict[str, PrimitiveStats]:
    return {p: PrimitiveStats(distance_mean_mm=row["distance_mean_mm"], distance_sd_mm=row["distance_sd_mm"],
                              rotation_mean_deg=row["rotation_mean_deg"], rotation_sd_deg=row["rotation_sd_deg"],
                              count=cast(int, row["count"]))
            for p, row in recognizer.motion_stats().items()}


def _outcomes(demos: Sequence[Demonstration]) -> Outcomes:
    return {"goals": sum(d.outcome == "goal" for d in demos), "own_goals": sum(d.outcome == "own_goal" for d in demos),
            "attempts": len(demos)}


def gather(run: RunDir, config: RunConfig) -> Results:
    """Everything in the run directory, summarised as ``results.json`` holds it."""

    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    demos = {who: load_demonstrations(run.require(run.demonstrations_path(who), "record" if who != "average"
                                                  else "segment"), bodies=config.bodies)
             for who in (*DEMONSTRATORS, *config.demonstrators)}
    # Table 4.5 measures segments against the commands sent: not for a log that recorded none.
    to_segment = [d for who in demos for d in demos[who] if commands_recorded(d)]
    imitator_attempts = run.attempts_path("varying_skill", "thesis")
    if imitator_attempts.exists():  # the thesis's VaryingSkillTrained row of Table 4.5
        # As for every demonstrator, only attempts the tracker followed throughout.
        to_segment += [a for a in load_demonstrations(imitator_attempts, bodies=config.bodies)
                       if a.tracked_throughout]
    segments = recognition.segment_table(recognizer, to_segment, **dataclasses.asdict(config.segmenter))
    experiments: dict[str, ExperimentResults] = {}
    all_trials: list[TrialResult] = []
    attempts = 2 * config.experiments.sizes.attempts_per_configuration
    for name, experiment in config.all_experiments().items():
        trials = load_trials(run, config, name)
        all_trials += trials
        scores = {control: summarize_evaluations(load_evaluations(run, config, name, control), attempts=attempts)
                  for control in ("improved", "thesis")}
        experiments[name] = {**summarize_experiment(experiment, trials, lp_stride=config.experiments.lp_stride),
                             "imitator": scores["improved"], "imitator_thesis_control": scores["thesis"]}
    test = load_self_observation(run.require(run.self_observation_path("test"), "self-observe"), bodies=config.bodies)
    results: Results = {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "polymimic_version": __version__,
        "imitator": config.imitator.body,
        "sizes": {"train_per_primitive": config.recognizer.train_per_primitive,
                  "test_per_primitive": config.recognizer.test_per_primitive,
                  "codebook_size": config.recognizer.codebook_size,
                  "demonstrations_per_configuration": config.experiments.sizes.demonstrations_per_configuration,
                  "trials": config.experiments.sizes.trials,
                  "evaluated_imitators": len(evaluated_seeds(config)),
                  "attempts_per_configuration": config.experiments.sizes.attempts_per_configuration},
        "primitive_stats": _primitive_stats(recognizer),
        "hmm_accuracy": {**recognition.accuracy_table(recognizer, test)},
        "hmm_log_likelihood": {m: {**row} for m, row in recognition.log_likelihood_table(recognizer, test).items()},
        "segments": {who: SegmentRow(command_match=row["command_match"], gaps=row["gaps"],
                                     segments=int(row["segments"]), classifiable=int(row["classifiable"]))
                     for who, row in segments.items()},
        "demonstrators": {who: _outcomes(d) for who, d in demos.items()},
        "experiments": experiments,
        "appendix_b": appendix_b(all_trials, config.learning),
    }
    return cast(Results, finite(results))


def finite(value: Any) -> Any:
    """``value`` with every NaN and infinity replaced by ``None`` (strict JSON has neither)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [finite(v) for v in value]
    return value
