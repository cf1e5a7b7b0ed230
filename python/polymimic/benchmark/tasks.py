"""The benchmark's tasks: module-level functions of what every task shares and its own job, so
that process-pool and Ray workers can import them (see
:class:`~polymimic.runs.backends.TaskRunner`). Each returns plain data the driver writes
to the run directory; each depends on its job and the shared inputs alone.
"""

from __future__ import annotations

import dataclasses
import json
from typing import Any

from polymimic import baselines
from polymimic._native import PrimitiveRecognizer
from polymimic.baselines.evaluation import VALIDATION_SEED_BASE
from polymimic.baselines.tuning import validation_attempts_apart
from polymimic.benchmark.config import BenchmarkConfig
from polymimic.crowds import Crowd
from polymimic.evaluation import Attempts
from polymimic.field import Demonstration
from polymimic.learning import ImitatorPolicy, LearningConfig, SegmentedDemonstrations, TrialResult, evaluate, run_trial
from polymimic.runs.practising import PracticeInputs

__all__ = ["POLYMIMIC_METHODS", "PRACTISED", "WEIGHED", "ProfileInputs", "Shared", "evaluation_task", "final_lps",
           "ppo_bc_task", "ppo_bc_tuning_task", "ppo_hyperparameters", "ppo_task", "practice_inputs",
           "practised_evaluation", "trial_task", "tuning_task", "weighing_task"]

POLYMIMIC_METHODS = {"polymimic": ("improved", False), "polymimic_thesis_control": ("thesis", False),
                     "polymimic_uniform_lp": ("improved", True), "polymimic_practice": ("improved", False)}
"""polymimic's own methods: (control, whether every LP is held at 0.5). ``polymimic_practice`` is
``polymimic``'s imitator after practice, evaluated by the practice stage
(:func:`polymimic.runs.practising.practice_task`)."""

PRACTISED = "polymimic_practice"

WEIGHED = "polymimic"
"""The method whose world weighting is chosen on the validation attempts (the uniform-LP one
weighs every member 1, the thesis's control has no world model, and practice keeps the config's)."""


@dataclasses.dataclass(frozen=True)
class ProfileInputs:
    """One crowd and what it demonstrated, as recordings and segmented."""

    crowd: Crowd
    demonstrations: list[Demonstration]
    segmented: SegmentedDemonstrations


@dataclasses.dataclass(frozen=True)
class Shared:
    """What every task of a benchmark shares."""

    config: BenchmarkConfig
    recognizer: PrimitiveRecognizer
    profiles: dict[str, ProfileInputs]
    controller_skill: dict[str, float] | None = None
    """Each controller's net goals per attempt without lapses (who is best: :meth:`Crowd.best`)."""

    def learning(self, uniform_lp: bool, world_weighting: str | None = None) -> LearningConfig:
        """The learning constants, ``world_weighting`` laid over them if given, with every LP held
        (``hold_lp``) for the uniform-LP ablation."""
        config: LearningConfig = self.config.learning
        if world_weighting is not None:
            config = config.replace(world_weighting=world_weighting)
        return config.replace(hold_lp=True) if uniform_lp else config


def trial_task(shared: Shared, job: tuple[str, int, bool]) -> str:
    """``(profile, trial seed, uniform LP)`` → the trial as :meth:`TrialResult.to_json` writes it."""
    profile, seed, uniform_lp = job
    inputs = shared.profiles[profile]
    return run_trial(inputs.segmented, recognizer=shared.recognizer, ordering=list(inputs.crowd.names),
                     config=shared.learning(uniform_lp), phase_one="interleaved", seed=seed,
                     body=shared.config.imitator_body()).to_json()


def final_lps(trial: TrialResult) -> dict[str, float]:
    """Every member's final LP in ``trial``."""
    return {name: model.lp for name, model in trial.models.items()}


def _baseline_inputs(shared: Shared, profile: str, method: str, trial_json: str | None) -> dict[str, Any]:
    """What :func:`polymimic.baselines.fit` needs for ``method`` beyond the demonstrations."""
    inputs = shared.profiles[profile]
    extra: dict[str, Any] = {"recognizer": shared.recognizer,
                             "segmenter": dataclasses.asdict(shared.config.segmenter),
                             "imitator": shared.config.imitator_body()}
    if method == "bco_lp":
        assert trial_json is not None, "bco_lp weighs by a trial's LPs"
        extra["weights"] = final_lps(TrialResult.from_json(trial_json))
    if method == "bc_best":
        best = inputs.crowd.best(shared.controller_skill)
        extra["member"] = best[0] if len(best) == 1 else best
    return extra


def tuning_task(shared: Shared, job: tuple[str, str, str | None]) -> dict[str, Any]:
    """``(profile, method, the first trial's JSON for bco_lp)`` → the hyperparameters chosen on
    validation attempts, every candidate's score there, and (``"evaluation"``) the chosen
    policy's evaluation after the first trial. That policy is the fit the evaluation would make
    again (the same demonstrations, hyperparameters and the first trial's seed), so it is
    evaluated here rather than fitted twice; the choice was made before, on validation alone."""
    profile, method, trial_json = job
    settings = shared.config.benchmark
    if method == "offline_rl":
        return _offline_tuning(shared, profile)
    tuning = baselines.tune(method, shared.profiles[profile].demonstrations, budget=settings.tuning.tuning_budget,
                            **_tuning_inputs(shared), **_baseline_inputs(shared, profile, method, trial_json))
    return _tuned(shared, profile, method, tuning)


def _tuning_inputs(shared: Shared) -> dict[str, Any]:
    """What every baseline's tuning takes from the config: the validation and evaluation
    attempts, the first trial's seed, the field and the sample cap."""
    tuning = shared.config.benchmark.tuning
    return {"validation_seed": tuning.validation_seed,
            "attempts_per_configuration": tuning.validation_attempts_per_configuration,
            "evaluation": shared.config.evaluation_attempts(), "seed": shared.config.seeds.first_trial,
            "field_config": shared.config.field, "max_samples": tuning.max_decision_samples}


def _tuned(shared: Shared, profile: str, method: str, tuning: Any) -> dict[str, Any]:
    """A tuning task's answer: the choice, every candidate's validation score, and the chosen
    policy's evaluation after the first trial."""
    return {"profile": profile, "method": method, "chosen": tuning.chosen,
            "hyperparameters": tuning.hyperparameters.to_dict(), "scores": tuning.scores,
            "validation_attempts": len(tuning.validation_attempts),
            "evaluation": _evaluated(shared, profile, method, shared.config.seeds.first_trial, tuning.policy)}


def _offline_tuning(shared: Shared, profile: str) -> dict[str, Any]:
    """offline_rl's tuning, as :func:`tuning_task` returns a cloner's. Torch runs on one thread,
    so the fits are the same on any machine's number of cores."""
    import torch  # type: ignore[import-not-found, unused-ignore]

    from polymimic.baselines import offline_rl
    from polymimic.baselines.offline_hyperparameters import candidates

    torch.set_num_threads(1)
    settings = shared.config.benchmark
    tried = [dataclasses.replace(h, gradient_steps=settings.offline_gradient_steps)
             for h in candidates(settings.tuning.tuning_budget)]
    tuning = offline_rl.tune(shared.profiles[profile].demonstrations, candidates=tried, **_tuning_inputs(shared),
                             **_baseline_inputs(shared, profile, "offline_rl", None))
    return _tuned(shared, profile, "offline_rl", tuning)


def weighing_task(shared: Shared, job: tuple[str, str, str]) -> dict[str, Any]:
    """``(profile, world weighting, the first trial's JSON)`` → polymimic's imitator after that
    trial, its world model weighed so, played on the validation attempts the baselines are tuned
    on (never the evaluation's): polymimic's tuning, with a baseline's effort."""
    profile, weighting, trial_json = job
    tuning = shared.config.benchmark.tuning
    attempts = validation_attempts_apart(tuning.validation_attempts_per_configuration,
                                         validation_seed=tuning.validation_seed,
                                         evaluation=shared.config.evaluation_attempts())
    policy = _imitator(shared, profile, WEIGHED, trial_json, weighting)
    played = evaluate(policy, attempts=Attempts(per_configuration=tuning.validation_attempts_per_configuration,
                                                seed=VALIDATION_SEED_BASE + tuning.validation_seed),
                      field_config=shared.config.field)
    if [(a.configuration, a.seed) for a in played.attempts] != attempts:
        raise RuntimeError("the imitator's validation attempts are not the baselines'")  # the seed rule, guarded
    return {"profile": profile, "weighting": weighting, "seed": shared.config.seeds.first_trial,
            "validation_seed": tuning.validation_seed, "goals": played.goals, "own_goals": played.own_goals,
            "attempts": len(played.attempts)}


def _imitator(shared: Shared, profile: str, method: str, trial_json: str,
              world_weighting: str | None = None) -> ImitatorPolicy:
    """polymimic's imitator (``method`` one of :data:`POLYMIMIC_METHODS`) after the trial, its
    world model weighed by ``world_weighting`` (default the config's)."""
    control, uniform_lp = POLYMIMIC_METHODS[method]
    return ImitatorPolicy(TrialResult.from_json(trial_json), recognizer=shared.recognizer,
                          config=shared.learning(uniform_lp, world_weighting), control=control,
                          demonstrations=shared.profiles[profile].segmented if control == "improved" else None,
                          body=shared.config.imitator_body())


def practice_inputs(shared: Shared) -> PracticeInputs:
    """What every practice of the benchmark shares (:mod:`polymimic.runs.practising`)."""
    config = shared.config
    return PracticeInputs(recognizer=shared.recognizer, learning=shared.learning(False),
                          demonstrations={name: p.segmented for name, p in shared.profiles.items()},
                          body=config.imitator_body(), field=config.field,
                          segmenter=dataclasses.asdict(config.segmenter), steps=config.benchmark.practice_steps,
                          attempts=config.evaluation_attempts(), method=config.benchmark.practice_method)


def practised_evaluation(shared: Shared, result: dict[str, Any]) -> dict[str, Any]:
    """A practice's final outcomes (popped from ``result``) as ``polymimic_practice``'s evaluation."""
    return _evaluation(shared, result["group"], PRACTISED, result["trial_seed"], result.pop("outcomes"))


def evaluation_task(shared: Shared, job: tuple[str, str, int, str | None, dict[str, Any] | None]) -> dict[str, Any]:
    """``(profile, method, trial seed, the trial's JSON, the tuned hyperparameters)`` → the
    method's goals and own goals on the evaluation attempts after that trial (polymimic's
    hyperparameters: its ``world_weighting``, chosen on validation)."""
    profile, method, trial_seed, trial_json, hyperparameters = job
    settings, inputs = shared.config.benchmark, shared.profiles[profile]
    if method in POLYMIMIC_METHODS:
        assert trial_json is not None and method != PRACTISED, "the practice stage evaluates practised imitators"
        weighting = None if hyperparameters is None else hyperparameters["world_weighting"]
        result = evaluate(_imitator(shared, profile, method, trial_json, weighting),
                          attempts=shared.config.evaluation_attempts(), field_config=shared.config.field)
        outcomes = [a.outcome for a in result.attempts]
        return {**_evaluation(shared, profile, method, trial_seed, outcomes),
                **({} if weighting is None else {"world_weighting": weighting})}
    assert hyperparameters is not None
    if method == "offline_rl":
        return _offline_evaluation(shared, profile, trial_seed, hyperparameters)
    chosen = baselines.Hyperparameters.from_dict(hyperparameters)
    demos = inputs.demonstrations if method != "random" else []
    fitted = baselines.fit(method, demos, hyperparameters=chosen, seed=trial_seed,
                           max_samples=settings.tuning.max_decision_samples,
                           **(_baseline_inputs(shared, profile, method, trial_json) if method != "random"
                              else {"imitator": shared.config.imitator_body()}))
    return _evaluated(shared, profile, method, trial_seed, fitted)


def _offline_evaluation(shared: Shared, profile: str, fit_seed: int, hyperparameters: dict[str, Any]) -> dict[str, Any]:
    """offline_rl fitted with the tuned ``hyperparameters`` under ``fit_seed``, evaluated."""
    import torch  # type: ignore[import-not-found, unused-ignore]

    from polymimic.baselines import offline_rl
    from polymimic.baselines.offline_hyperparameters import OfflineHyperparameters

    torch.set_num_threads(1)
    fitted = offline_rl.fit(shared.profiles[profile].demonstrations,
                            hyperparameters=OfflineHyperparameters.from_dict(hyperparameters), seed=fit_seed,
                            max_samples=shared.config.benchmark.tuning.max_decision_samples,
                            **_baseline_inputs(shared, profile, "offline_rl", None))
    return _evaluated(shared, profile, "offline_rl", fit_seed, fitted)


def _evaluated(shared: Shared, profile: str, method: str, trial_seed: int, policy: baselines.Policy) -> dict[str, Any]:
    """A fitted baseline's evaluation after trial ``trial_seed``."""
    result = baselines.evaluate_policy(policy, attempts=shared.config.evaluation_attempts(),
                                       field_config=shared.config.field)
    return _evaluation(shared, profile, method, trial_seed, [a.outcome for a in result.attempts])


def _evaluation(shared: Shared, profile: str, method: str, trial_seed: int, outcomes: list[str]) -> dict[str, Any]:
    """An evaluation as the run directory keeps it, from its attempts' outcomes."""
    return {"profile": profile, "method": method, "trial_seed": trial_seed, "seed": shared.config.seeds.evaluation,
            "goals": outcomes.count("goal"), "own_goals": outcomes.count("own_goal"), "attempts": len(outcomes),
            "outcomes": outcomes}


PPO_FEATURE_SET, PPO_FRAMES_PER_ACTION = "goal_relative", 30
"""What ``ppo`` sees and how long it holds a primitive: the goal-relative features and the
imitator's one-second primitives (:func:`polymimic.baselines.ppo.fit`'s defaults)."""


def ppo_hyperparameters(config: BenchmarkConfig) -> dict[str, Any]:
    """What a ppo run of ``config`` is, as the report prints it."""
    return {"total_timesteps": config.benchmark.ppo_timesteps, "feature_set": PPO_FEATURE_SET,
            "frames_per_action": PPO_FRAMES_PER_ACTION, "environments": "one per field configuration",
            "tuned": "no: stable-baselines3's defaults", "torch_threads": 1}


def ppo_task(shared: Shared, seed: int) -> dict[str, Any]:
    """A ppo run of training seed ``seed``: its checkpoints on the evaluation attempts, as the
    run directory keeps them (without their wall-clock times, so the same seed gives the same
    bytes), and (``"policy"``) the final policy. Torch runs on one thread, so the curve is the
    same on any machine's number of cores."""
    import torch  # type: ignore[import-not-found, unused-ignore]

    torch.set_num_threads(1)
    settings, attempts = shared.config.benchmark, shared.config.evaluation_attempts()
    policy, curve, _ = baselines.ppo.learning_curve(
        total_timesteps=settings.ppo_timesteps, eval_every=settings.ppo_eval_every, evaluation=attempts, seed=seed,
        frames_per_action=PPO_FRAMES_PER_ACTION, feature_set=PPO_FEATURE_SET, field_config=shared.config.field,
        imitator=shared.config.imitator_body())
    return {"seed": seed, "evaluation_seed": attempts.seed, "attempts": attempts.count,
            "total_timesteps": settings.ppo_timesteps,
            "eval_every": settings.ppo_eval_every,
            "checkpoints": [{k: v for k, v in c.to_dict().items() if k != "wall_s"} for c in curve], "policy": policy}


def ppo_bc_tuning_task(shared: Shared, profile: str) -> dict[str, Any]:
    """``profile`` → ppo_bc's cloning chosen on the validation attempts (the first
    ``tuning_budget`` candidates, cloned under the first trial's seed), every candidate's score."""
    import torch  # type: ignore[import-not-found, unused-ignore]

    from polymimic.baselines import ppo_bc

    torch.set_num_threads(1)
    tuning = shared.config.benchmark.tuning
    choice = ppo_bc.tune_pretraining(
        shared.profiles[profile].demonstrations, budget=min(tuning.tuning_budget, len(ppo_bc.PRETRAINING_CANDIDATES)),
        validation_seed=tuning.validation_seed, attempts_per_configuration=tuning.validation_attempts_per_configuration,
        evaluation=shared.config.evaluation_attempts(), seed=shared.config.seeds.first_trial,
        feature_set=PPO_FEATURE_SET, frames_per_action=PPO_FRAMES_PER_ACTION, field_config=shared.config.field,
        imitator=shared.config.imitator_body(), max_samples=tuning.max_decision_samples)
    return {"profile": profile, "chosen": choice.chosen.to_dict(), "scores": choice.scores,
            "validation_attempts": 2 * tuning.validation_attempts_per_configuration}


def ppo_bc_task(shared: Shared, job: tuple[str, int, dict[str, Any]]) -> dict[str, Any]:
    """``(profile, training seed, the chosen cloning)`` → a ppo_bc run: its checkpoints on the
    evaluation attempts, the first the cloned network's, as the run directory keeps them, and
    (``"policy"``) the final policy."""
    import torch  # type: ignore[import-not-found, unused-ignore]

    from polymimic.baselines import ppo_bc

    torch.set_num_threads(1)
    profile, seed, chosen = job
    settings, attempts = shared.config.benchmark, shared.config.evaluation_attempts()
    policy, curve, _ = ppo_bc.learning_curve(
        shared.profiles[profile].demonstrations, ppo_bc.Pretraining(**chosen), total_timesteps=settings.ppo_timesteps,
        eval_every=settings.ppo_eval_every, evaluation=attempts, seed=seed, frames_per_action=PPO_FRAMES_PER_ACTION,
        feature_set=PPO_FEATURE_SET, field_config=shared.config.field, imitator=shared.config.imitator_body(),
        max_samples=settings.tuning.max_decision_samples)
    return {"profile": profile, "seed": seed, "evaluation_seed": attempts.seed,
            "attempts": attempts.count, "total_timesteps": settings.ppo_timesteps,
            "eval_every": settings.ppo_eval_every, "pretraining": chosen,
            "checkpoints": [{k: v for k, v in c.to_dict().items() if k != "wall_s"} for c in curve], "policy": policy}


def dumps(data: dict[str, Any]) -> str:
    return json.dumps(data, sort_keys=True) + "\n"
