"""``benchmark.json``: what a benchmark measured, gathered from its run directory (docs/results/benchmark.md).

Per profile: every member's own outcomes and true skill (its controller's net goals per attempt
without lapses times 1 − ε, :meth:`polymimic.crowds.Crowd.skill`); skill recovery (Spearman ρ
and Kendall τ between the members' final LPs and true skill, mean and sd over trials, and how
many trials put a member of the highest true skill on top) beside the same for the plain
estimator that ranks members by the net goals of their own demonstrations; every method's goals,
own goals and net goals after every trial, and, where the run has the ``random`` crowd, its
floor (its net goals there) and its gain over it: what the demonstrations add. ``None`` stands
where a number does not exist (ρ where every member has the same skill).

``ppo``, where it ran, learns no crowd's data: its final checkpoints stand in every profile's
methods, with the environment steps each run took to first score ``polymimic``'s mean net goals
there, and its curves once, under ``ppo``.

``ppo_bc``, where it ran, clones each profile's commands before learning from the reward: its
final checkpoints stand in that profile's methods, its cloning chosen on validation attempts.

``polymimic_practice``, where it ran, is ``polymimic``'s imitator after practice, on the first
``practice_trials`` trials; each profile's ``practice`` holds its curve (mean and sd over those
trials at every checkpoint) and, beside ppo, the steps each needs to reach the other's net goals.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any, TypedDict

import numpy as np

from polymimic._native import __version__
from polymimic.baselines.ppo import steps_to_reach
from polymimic.baselines.tuning import validation_rank
from polymimic.benchmark.config import BenchmarkConfig
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.benchmark.task_files import (
    load_controller_skill,
    load_method_evaluation,
    load_ppo_bc_curve,
    load_ppo_bc_tuning,
    load_ppo_curve,
    load_tuning,
)
from polymimic.benchmark.tasks import POLYMIMIC_METHODS, PRACTISED, WEIGHED, final_lps, ppo_hyperparameters
from polymimic.benchmark.weighing import chosen_world_weighting
from polymimic.crowds import FLOOR, Crowd
from polymimic.datasets import load_demonstrations
from polymimic.field import PRIMITIVES
from polymimic.learning import LearningConfig, TrialResult
from polymimic.plots import MeanSd
from polymimic.ranking import kendall, spearman
from polymimic.runs.practising import PracticeCurve, load_practice, summarise
from polymimic.runs.stats import mean_sd

__all__ = ["FORMAT", "VERSION", "MemberSummary", "MethodSummary", "PPOSummary", "PracticeSummary", "ProfileSummary",
           "SkillRecovery", "Validation", "ValidationScore", "gather", "validation", "with_floors"]

FORMAT, VERSION = "polymimic.benchmark", 1
LP_POINTS = 200
"""LP-over-training curves keep at most this many points per member."""


class MemberSummary(TypedDict):
    controller: str
    body: str
    lapse: float
    goals: int
    own_goals: int
    attempts: int
    final_lp: MeanSd
    true_skill: float


class SkillRecovery(TypedDict):
    spearman: MeanSd
    kendall: MeanSd
    best_hits: int | None
    """Trials whose top-ranked member is the one of highest true skill (None where no single one is)."""
    top_among_best: int | None
    """Trials whose top-ranked member is one of those of highest true skill (None where all share it)."""


class ValidationScore(TypedDict):
    goals: int
    own_goals: int
    net_goals: int


class Validation(TypedDict):
    """A tuned baseline's candidates on the validation attempts: how far the choice stood out."""

    attempts: int
    candidates: int
    chosen: ValidationScore
    runner_up: ValidationScore | None
    """The best of the other candidates (None where only one was tried)."""


class MethodSummary(TypedDict):
    goals: MeanSd
    own_goals: MeanSd
    net_goals: MeanSd
    attempts: int
    evaluated: int
    hyperparameters: dict[str, Any]
    validation: Validation | None
    """A tuned method's validation scores (polymimic's: its world weighting's); None for
    polymimic's untuned methods and ppo."""
    floor: float | None
    """The method's mean net goals on the ``random`` crowd (None where the run has none)."""
    gain_over_floor: float | None
    """Its mean net goals here less its floor: what the demonstrations add."""


class PPOSummary(MethodSummary):
    env_steps_to_polymimic: list[int | None]
    """Per run, the steps of its first checkpoint with at least polymimic's mean net goals in
    this profile (None: not within its budget)."""


class PracticeSummary(PracticeCurve):
    steps_to_ppo: int | None
    """The first checkpoint whose mean net goals reach ppo's final mean (None: none does, or no ppo)."""
    ppo_steps_to_practice: list[int | None]
    """Per ppo run, the steps of its first checkpoint with at least the practised mean net goals."""
    ppo_bc_steps_to_practice: list[int | None]
    """The same for each ppo_bc run on this profile (empty where ppo_bc did not run)."""
    self_observation_steps: int
    """The seconds of babbling the imitator learned its primitives from, before any
    demonstration: steps ppo never takes, to add to practice's for a count of all its play."""


class ProfileSummary(TypedDict):
    demonstrators: dict[str, MemberSummary]
    trials: int
    skill_recovery: SkillRecovery
    skill_by_outcomes: SkillRecovery
    methods: dict[str, MethodSummary]
    lp_over_training: dict[str, list[float]]
    practice: PracticeSummary | None


def recovery(rankings: Sequence[Mapping[str, float]], crowd: Crowd,
             controllers: Mapping[str, float] | None = None) -> SkillRecovery:
    """How well each ranking (a score per member, higher is better) recovers true skill
    (:meth:`Crowd.skill` under ``controllers``' measured skills; by ε alone without them)."""
    true_skill = crowd.skill(controllers)
    names = list(crowd.names)
    skill = [true_skill[n] for n in names]
    rhos, taus, on_top = [], [], 0
    best = set(crowd.best(controllers))
    for scores in rankings:
        values = [scores[n] for n in names]
        rho, tau = spearman(values, skill), kendall(values, skill)
        if rho is not None and tau is not None:
            rhos.append(rho)
            taus.append(tau)
        top = [n for n in names if scores[n] == max(values)]
        on_top += len(top) == 1 and top[0] in best
    return SkillRecovery(spearman=mean_sd(rhos), kendall=mean_sd(taus), best_hits=on_top if len(best) == 1 else None,
                         top_among_best=None if len(best) == len(names) else on_top)


def _downsampled(history: Sequence[float], points: int = LP_POINTS) -> list[float]:
    if len(history) <= points:
        return [float(v) for v in history]
    picks = np.linspace(0, len(history) - 1, points).round().astype(int)
    return [float(history[i]) for i in picks]


_IMPROVED_CONTROL_CHOICES = ("prefer_sooner_goals", "push_heading_tail")
"""The learning constants only the improved control reads."""


def _improved_control_choices(learning: LearningConfig) -> dict[str, Any]:
    """The improved control's choices in ``learning`` that are not the defaults (the report
    prints only those)."""
    defaults = LearningConfig()
    return {name: getattr(learning, name) for name in _IMPROVED_CONTROL_CHOICES
            if getattr(learning, name) != getattr(defaults, name)}


def _score(entry: Mapping[str, Any]) -> ValidationScore:
    return ValidationScore(goals=int(entry["goals"]), own_goals=int(entry["own_goals"]),
                           net_goals=int(entry["goals"]) - int(entry["own_goals"]))


def validation(tuning: Mapping[str, Any]) -> Validation:
    """The chosen candidate's validation score and the runner-up's, from a saved tuning, ranked
    as :func:`polymimic.baselines.tune` ranks them (:func:`~polymimic.baselines.tuning.validation_rank`).

    >>> scores = [{"goals": 5, "own_goals": 1}, {"goals": 7, "own_goals": 1}, {"goals": 6, "own_goals": 0}]
    >>> v = validation({"scores": scores, "validation_attempts": 20})
    >>> v["chosen"]["net_goals"], v["runner_up"]["net_goals"], v["candidates"]
    (6, 6, 3)
    """
    scores = list(tuning["scores"])
    # A stable sort keeps the first of equals first, as tune keeps the first best.
    ranked = sorted(range(len(scores)), key=lambda i: validation_rank(scores[i]), reverse=True)
    return Validation(attempts=int(tuning["validation_attempts"]), candidates=len(scores),
                      chosen=_score(scores[ranked[0]]),
                      runner_up=_score(scores[ranked[1]]) if len(ranked) > 1 else None)


def _method_summary(run: BenchmarkDir, config: BenchmarkConfig, profile: str, method: str) -> MethodSummary:
    saved = [load_method_evaluation(run.require(run.evaluation_path(profile, method, s), "benchmark"))
             for s in config.evaluated_seeds(method)]
    scored: Validation | None = None
    if method in POLYMIMIC_METHODS:
        control, uniform = POLYMIMIC_METHODS[method]
        chosen: dict[str, Any] = {"control": control, "lp": "held at 0.5" if uniform else "learned",
                                  "imitator_weighting": config.learning.imitator_weighting}
        if control == "improved":
            chosen.update(_improved_control_choices(config.learning))
            chosen["world_weighting"] = config.learning.world_weighting
        if method == PRACTISED:
            chosen.update(practice_steps=config.benchmark.practice_steps, practice_trials=len(saved),
                          practice_method=config.benchmark.practice_method)
        chosen["tuned"] = "no: the thesis's constants"
        if method == WEIGHED:
            weighting, scores = chosen_world_weighting(run, config, profile)
            chosen["world_weighting"] = weighting
            if scores:
                chosen["tuned"] = "the world weighting alone; else the thesis's constants"
                scored = validation({"scores": scores, "validation_attempts": scores[0]["attempts"]})
    else:
        tuning = load_tuning(run.require(run.tuning_path(profile, method), "benchmark"))
        chosen, scored = tuning["chosen"], validation(tuning)
    return MethodSummary(goals=mean_sd(e["goals"] for e in saved), own_goals=mean_sd(e["own_goals"] for e in saved),
                         net_goals=mean_sd(e["goals"] - e["own_goals"] for e in saved),
                         attempts=2 * config.benchmark.sizes.attempts_per_configuration, evaluated=len(saved),
                         hyperparameters=chosen, validation=scored, floor=None, gain_over_floor=None)


def _ppo_curves(run: BenchmarkDir, config: BenchmarkConfig) -> list[dict[str, Any]]:
    return [dict(load_ppo_curve(run.require(run.ppo_curve_path(seed), "benchmark")))
            for seed in range(config.benchmark.ppo_runs)]


def _ppo_summary(curves: Sequence[Mapping[str, Any]], config: BenchmarkConfig, target: float | None) -> PPOSummary:
    """ppo's final checkpoints over its runs, and the steps each took to reach ``target``."""
    finals = [c["checkpoints"][-1] for c in curves]
    return PPOSummary(goals=mean_sd(f["goals"] for f in finals), own_goals=mean_sd(f["own_goals"] for f in finals),
                      net_goals=mean_sd(f["net_goals"] for f in finals),
                      attempts=2 * config.benchmark.sizes.attempts_per_configuration, evaluated=len(curves),
                      hyperparameters=ppo_hyperparameters(config), validation=None, floor=None,
                      gain_over_floor=None,
                      env_steps_to_polymimic=[None if target is None else steps_to_reach(c["checkpoints"], target)
                                              for c in curves])


def _practice_summary(run: BenchmarkDir, config: BenchmarkConfig, profile: str,
                      ppo_curves: Sequence[Mapping[str, Any]] | None,
                      bc_curves: Sequence[Mapping[str, Any]] | None) -> PracticeSummary:
    """The practised imitators' curves over their trials, and how they stand against ppo's."""
    curve = summarise([load_practice(run.require(run.practice_path(profile, s), "benchmark"))
                       for s in config.evaluated_seeds(PRACTISED)])
    marks, net = curve["checkpoints"], curve["net_goals"]
    practised = net[-1]["mean"]

    def reaching(curves: Sequence[Mapping[str, Any]] | None) -> list[int | None]:
        """Per run, the steps of its first checkpoint with at least the practised net goals."""
        return [None if practised is None else steps_to_reach(c["checkpoints"], practised) for c in curves or []]

    steps_to_ppo = None
    if ppo_curves is not None:
        ppo_final = float(np.mean([c["checkpoints"][-1]["net_goals"] for c in ppo_curves]))
        steps_to_ppo = next((m for m, n in zip(marks, net) if n["mean"] is not None and n["mean"] >= ppo_final), None)
    return PracticeSummary(**curve, steps_to_ppo=steps_to_ppo, ppo_steps_to_practice=reaching(ppo_curves),
                           ppo_bc_steps_to_practice=reaching(bc_curves),
                           self_observation_steps=len(PRIMITIVES) * config.recognizer.train_per_primitive)


def _profile(run: BenchmarkDir, config: BenchmarkConfig, crowd: Crowd, ppo_curves: Sequence[Mapping[str, Any]] | None,
             controllers: Mapping[str, float]) -> ProfileSummary:
    demos = load_demonstrations(run.require(run.crowd_path(crowd.name), "benchmark"), bodies=config.run.bodies)
    trials = [TrialResult.load(run.require(run.trial_path(crowd.name, s), "benchmark")) for s in config.trial_seeds()]
    lps = [final_lps(t) for t in trials]
    net: dict[str, float] = {}
    members: dict[str, MemberSummary] = {}
    true_skill = crowd.skill(controllers)
    for member in crowd.members:
        own = [d for d in demos if d.demonstrator == member.name]
        goals, own_goals = sum(d.outcome == "goal" for d in own), sum(d.outcome == "own_goal" for d in own)
        net[member.name] = (goals - own_goals) / len(own)
        members[member.name] = MemberSummary(controller=member.controller, body=member.body, lapse=member.lapse,
                                             goals=goals, own_goals=own_goals, attempts=len(own),
                                             final_lp=mean_sd(lp[member.name] for lp in lps),
                                             true_skill=true_skill[member.name])
    methods: dict[str, MethodSummary] = {m: _method_summary(run, config, crowd.name, m)
                                         for m in config.benchmark.methods if m not in ("ppo", "ppo_bc")}
    ours = methods["polymimic"]["net_goals"]["mean"] if "polymimic" in methods else None
    if ppo_curves is not None:
        methods["ppo"] = _ppo_summary(ppo_curves, config, ours)
    bc_curves = None
    if "ppo_bc" in config.benchmark.methods:
        bc_curves = [load_ppo_bc_curve(run.require(run.ppo_bc_curve_path(crowd.name, seed), "benchmark"))
                     for seed in range(config.benchmark.ppo_runs)]
        tuning = load_ppo_bc_tuning(run.require(run.ppo_bc_tuning_path(crowd.name), "benchmark"))
        methods["ppo_bc"] = _ppo_summary(bc_curves, config, ours)
        methods["ppo_bc"]["hyperparameters"] = {**ppo_hyperparameters(config), "tuned": "the cloning only",
                                                **{f"cloning_{k}": v for k, v in tuning["chosen"].items()}}
        methods["ppo_bc"]["validation"] = validation(tuning)
    return ProfileSummary(
        demonstrators=members, trials=len(trials), skill_recovery=recovery(lps, crowd, controllers),
        skill_by_outcomes=recovery([net] * len(trials), crowd, controllers), methods=methods,
        lp_over_training={name: _downsampled(model.lp_history) for name, model in trials[0].models.items()},
        practice=_practice_summary(run, config, crowd.name, ppo_curves, bc_curves) if PRACTISED in methods else None)


def with_floors(profiles: Mapping[str, ProfileSummary]) -> None:
    """Every method's floor (its mean net goals on the ``random`` crowd) and gain over it, where
    both exist, set in place.

    >>> net = lambda mean: {"net_goals": {"mean": mean, "sd": 0.0}}
    >>> profiles = {"one_good": {"methods": {"bc": net(20.0), "ppo": net(40.0)}},
    ...             FLOOR: {"methods": {"bc": net(5.0)}}}
    >>> with_floors(profiles)
    >>> profiles["one_good"]["methods"]["bc"]["gain_over_floor"], profiles["one_good"]["methods"]["ppo"]["floor"]
    (15.0, None)
    """
    floors: Mapping[str, MethodSummary] = profiles[FLOOR]["methods"] if FLOOR in profiles else {}
    for profile in profiles.values():
        for method, s in profile["methods"].items():
            floor = floors[method]["net_goals"]["mean"] if method in floors else None
            here = s["net_goals"]["mean"]
            s["floor"] = floor
            s["gain_over_floor"] = None if floor is None or here is None else round(here - floor, 10)


def gather(run: BenchmarkDir, config: BenchmarkConfig) -> dict[str, Any]:
    """The whole ``benchmark.json`` of a finished run (the same seeds give the same bytes)."""
    settings, tuning = config.benchmark, config.benchmark.tuning
    sizes = {**dataclasses.asdict(settings.sizes),
             "validation_attempts_per_configuration": tuning.validation_attempts_per_configuration,
             "tuning_budget": tuning.tuning_budget, "max_decision_samples": tuning.max_decision_samples,
             "lp_plugin_trials": settings.lp_plugin_trials, "baseline_fits": settings.baseline_fits,
             "practice_steps": settings.practice_steps, "practice_trials": settings.practice_trials,
             "evaluation_seed": config.seeds.evaluation,
             "validation_seed": tuning.validation_seed}
    # ppo's runs serve every profile: read once.
    curves = _ppo_curves(run, config) if "ppo" in settings.methods else None
    controllers = load_controller_skill(run.require(run.controller_skill_path, "benchmark"))
    profiles = {crowd.name: _profile(run, config, crowd, curves, controllers) for crowd in config.crowds()}
    with_floors(profiles)
    summary = {"format": FORMAT, "version": VERSION, "polymimic_version": __version__,
               "imitator": config.run.imitator.body, "sizes": sizes, "controller_skill": controllers,
               "profiles": profiles}
    if curves is not None:
        runs = [{"seed": c["seed"], "checkpoints": c["checkpoints"]} for c in curves]
        summary["ppo"] = {"hyperparameters": ppo_hyperparameters(config), "eval_every": settings.ppo_eval_every,
                          "runs": runs}
    return summary
