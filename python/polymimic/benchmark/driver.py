"""``polymimic benchmark``: the crowds recorded, every method trained on every trial, every method
evaluated on the same attempts, and the summary and report written.

Steps, each resumable (every result is written to the run directory, atomically, as it
arrives, and a rerun redoes only what is missing or damaged):

1. **recognise** — self-observation and the recogniser, as a reproduction makes them;
2. **record** — each profile's crowd, 25 valid demonstrations per member and configuration,
   to ``datasets/crowd_<profile>.parquet``, and as many of each controller without lapses, whose
   net goals are its members' true skill (``datasets/controller_skill.json``);
3. **learn** — every trial of every profile, LP-weighted and with every LP held at 0.5;
   **weigh** — polymimic's world weighting, each candidate played after the first trial on the
   validation attempts (:mod:`polymimic.benchmark.weighing`);
4. **tune** — every baseline's hyperparameters on validation attempts (``bco_lp`` weighs by
   the first trial's LPs); the chosen candidate, fitted as the evaluation after the first
   trial would fit it, is evaluated there and then;
5. **evaluate** — every method after every trial, on the evaluation attempts;
6. **practice** — where the methods name ``polymimic_practice``, polymimic's imitator after each
   of the first ``practice_trials`` trials practises for ``practice_steps`` environment steps
   (a practice is one piece of work: an interrupted one starts again);
7. **ppo** — where the methods name it, each ppo run, learning from the reward and played on
   the evaluation attempts at every checkpoint (a run is one piece of work: an interrupted one
   starts again);
8. **ppo_bc** — where the methods name it, each profile's cloning chosen on validation attempts,
   then each ppo_bc run (cloned, then learning from the reward), as ppo's;
9. **report** — ``benchmark.json``, ``benchmark.md``, ``benchmark.html`` and the plots.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import pathlib
import time
from typing import Any

from polymimic._atomic import atomic_write_text
from polymimic._native import PrimitiveRecognizer
from polymimic.benchmark.config import FROM_THE_REWARD, BenchmarkConfig
from polymimic.benchmark.figures import draw_figures
from polymimic.benchmark.report import benchmark_html, benchmark_markdown
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.benchmark.summary import gather
from polymimic.benchmark.task_files import (
    load_controller_skill,
    load_method_evaluation,
    load_ppo_bc_curve,
    load_ppo_bc_tuning,
    load_ppo_curve,
    load_tuning,
    load_weighing,
)
from polymimic.benchmark.tasks import (
    POLYMIMIC_METHODS,
    PRACTISED,
    WEIGHED,
    ProfileInputs,
    Shared,
    dumps,
    evaluation_task,
    ppo_bc_task,
    ppo_bc_tuning_task,
    ppo_task,
    practice_inputs,
    practised_evaluation,
    trial_task,
    tuning_task,
    weighing_task,
)
from polymimic.benchmark.weighing import chosen_world_weighting, is_weighed
from polymimic.crowds import Crowd, controller_skill, record_crowd
from polymimic.datasets import load_demonstrations, load_self_observation, save_demonstrations, save_self_observation
from polymimic.field import PRIMITIVES, PrimitiveSequence, self_observation
from polymimic.learning import TrialResult, segmented
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError
from polymimic.runs.practising import is_practice_of, load_practice, practice_task
from polymimic.runs.progress import progress
from polymimic.runs.stages import Staged, counted, each_member_recorded

__all__ = ["Benchmark"]

_LONGEST_FIRST = {"offline_rl": -1, "bco_lp": 0, "bco": 0, "bc": 0, "bc_best": 1, "random": 2}
"""The order the tasks of a stage start in, by method: offline_rl's (thousands of gradient
steps a fit), then those that fit on a whole crowd, then bc_best (one member's data), then
random (no fit), so that no worker is left idle while the other finishes a long fit begun last."""


@dataclasses.dataclass
class Benchmark(Staged):
    """One benchmark run: its directory, config, where tasks run, and whether to keep quiet."""

    run: BenchmarkDir
    config: BenchmarkConfig
    runner: TaskRunner
    quiet: bool = False

    @staticmethod
    def check_extras(config: BenchmarkConfig) -> None:
        """A :class:`ConfigError` if ``config`` names a method whose optional extra is missing."""
        if {"ppo", "ppo_bc"} & set(config.benchmark.methods):
            from polymimic.baselines import ppo

            if not ppo.available():
                raise ConfigError("[benchmark] methods: ppo and ppo_bc need stable-baselines3 and torch: "
                                  "pip install \"polymimic[rl]\"")
        if "polymimic_practice" in config.benchmark.methods:
            from polymimic.practice.methods import needs_rl_extra

            try:
                needs_rl_extra(config.benchmark.practice_method)
            except ModuleNotFoundError as error:
                raise ConfigError(f"[benchmark] methods: polymimic_practice practises by "
                                  f"{config.benchmark.practice_method}: {error}") from None
        if "offline_rl" in config.benchmark.methods:
            from polymimic.baselines import offline_rl

            if not offline_rl.available():
                raise ConfigError("[benchmark] methods: offline_rl needs d3rlpy and torch: "
                                  "pip install \"polymimic[offline]\"")

    def run_all(self) -> float:
        """Every step, in order; the seconds they took."""
        self.check_extras(self.config)
        started = time.perf_counter()
        self._stage("recognise", self.recognise)
        self._stage("record", self.record)
        shared = self.shared()
        self._stage("learn", lambda: self.learn(shared))
        if is_weighed(self.config):
            self._stage("weigh", lambda: self.weigh(shared))
        self._stage("tune", lambda: self.tune(shared))
        self._stage("evaluate", lambda: self.evaluate(shared))
        if PRACTISED in self.config.benchmark.methods:
            self._stage("practice", lambda: self.practice(shared))
        if "ppo" in self.config.benchmark.methods:
            self._stage("ppo", lambda: self.ppo(shared))
        if "ppo_bc" in self.config.benchmark.methods:
            self._stage("ppo_bc", lambda: self.ppo_bc(shared))
        self._stage("report", self.report)
        return time.perf_counter() - started

    # 1. The recogniser.

    def recognise(self) -> int:
        """Stage: self-observation and the recogniser; returns how many were made (0 if done)."""
        if self.run.finished(self.run.recognizer_path, PrimitiveRecognizer.load):
            return 0
        settings, path = self.config.recognizer, self.run.self_observation_path("train")
        count = len(PRIMITIVES) * settings.train_per_primitive
        if not self.run.finished(path, lambda p: counted(self._self_observation(p), count)):
            save_self_observation(self_observation(settings.train_per_primitive,
                                                   seed=self.config.seeds.self_observation_train,
                                                   config=self.config.field, body=self.config.imitator_body()), path)
        settings.train(self._self_observation(path)).save(self.run.recognizer_path)
        return 1

    def _self_observation(self, path: pathlib.Path) -> list[PrimitiveSequence]:
        """The self-observation of the file ``path``, the imitator's body read as the config describes it."""
        return load_self_observation(path, bodies=self.config.run.bodies)

    # 2. The crowds.

    def record(self) -> int:
        """Stage: every profile's crowd recorded; returns the crowds recorded now."""
        made, n = 0, self.config.benchmark.sizes.demonstrations_per_configuration
        crowds = self.config.crowds()
        with progress(total=len(crowds), desc="record", quiet=self.quiet) as bar:
            for crowd in crowds:
                path = self.run.crowd_path(crowd.name)
                if not self.run.finished(path, functools.partial(each_member_recorded, names=crowd.names, n=n,
                                                                    bodies=self.config.run.bodies)):
                    save_demonstrations(record_crowd(crowd, n=n, seed=self.config.seeds.demonstrations,
                                                     config=self.config.field), path)
                    made += 1
                bar.update(1)
        if not self.run.finished(self.run.controller_skill_path, load_controller_skill):
            controllers = sorted({m.controller for crowd in crowds for m in crowd.members})
            skill = controller_skill(controllers, n=n, seed=self.config.seeds.demonstrations, config=self.config.field)
            atomic_write_text(self.run.controller_skill_path, dumps(skill))
            made += 1
        return made

    def shared(self) -> Shared:
        """What every task reads: the recogniser and each profile's demonstrations and segments."""
        recognizer = PrimitiveRecognizer.load(self.run.require(self.run.recognizer_path, "benchmark"))
        segmenter = dataclasses.asdict(self.config.segmenter)
        profiles = {}
        for crowd in self.config.crowds():
            demos = load_demonstrations(self.run.require(self.run.crowd_path(crowd.name), "benchmark"),
                                        bodies=self.config.run.bodies)
            profiles[crowd.name] = ProfileInputs(crowd, demos, segmented(demos, recognizer, **segmenter))
        skill = load_controller_skill(self.run.require(self.run.controller_skill_path, "benchmark"))
        return Shared(self.config, recognizer, profiles, skill)

    # 3. Trials.

    def learn(self, shared: Shared) -> int:
        """Stage: polymimic's learning trials (uniform-LP ones too where asked); returns the trials run."""
        jobs = [(crowd.name, seed, uniform) for crowd in self.config.crowds() for seed in self.config.trial_seeds()
                for uniform in self._trial_kinds()
                if not self.run.finished(self.run.trial_path(crowd.name, seed, uniform_lp=uniform), TrialResult.load)]
        for crowd in self.config.crowds():
            self.run.profile_dir(crowd.name).mkdir(parents=True, exist_ok=True)
        with progress(total=len(jobs), desc="learn", quiet=self.quiet) as bar:
            for (profile, seed, uniform), text in self.runner.map(trial_task, shared, jobs):
                atomic_write_text(self.run.trial_path(profile, seed, uniform_lp=uniform), text)
                bar.update(1)
        return len(jobs)

    def _trial_kinds(self) -> list[bool]:
        """Whether trials with every LP held are needed, besides the LP-weighted ones."""
        methods = self.config.benchmark.methods
        return [False] + ([True] if "polymimic_uniform_lp" in methods else [])

    def _trial_json(self, profile: str, seed: int, *, uniform_lp: bool = False) -> str:
        path = self.run.require(self.run.trial_path(profile, seed, uniform_lp=uniform_lp), "benchmark")
        return path.read_text(encoding="utf-8")

    # 3b. polymimic's world weighting, on validation.

    def weigh(self, shared: Shared) -> int:
        """Stage: polymimic's world weighting chosen per profile on the validation attempts (each
        candidate played after the first trial); returns the weighings run."""
        first = self.config.seeds.first_trial
        jobs = [(crowd.name, weighting, self._trial_json(crowd.name, first)) for crowd in self.config.crowds()
                for weighting in self.config.benchmark.world_weightings
                if not self.run.finished(self.run.weighing_path(crowd.name, weighting), load_weighing)]
        with progress(total=len(jobs), desc="weigh", quiet=self.quiet) as bar:
            for _, result in self.runner.map(weighing_task, shared, jobs):
                atomic_write_text(self.run.weighing_path(result["profile"], result["weighting"]), dumps(result))
                bar.update(1)
        return len(jobs)

    # 4. Tuning.

    def _baselines(self) -> list[str]:
        return [m for m in self.config.benchmark.methods if m not in POLYMIMIC_METHODS and m not in FROM_THE_REWARD]

    def _bc_best_is_bc(self, crowd: Crowd, skill: dict[str, float] | None) -> bool:
        """Whether ``bc_best`` learns just what ``bc`` does in ``crowd`` (every member shares the
        highest true skill): the same demonstrations, candidates and seeds make the same fits, so
        its tuning is ``bc``'s, copied rather than run again."""
        return set(crowd.best(skill)) == set(crowd.names) and {"bc", "bc_best"} <= set(self._baselines())

    def tune(self, shared: Shared) -> int:
        """Stage: each baseline's hyperparameters chosen on the validation attempts; returns the tunings run."""
        first = self.config.seeds.first_trial
        copies = [crowd.name for crowd in self.config.crowds() if self._bc_best_is_bc(crowd, shared.controller_skill)
                  and not self.run.finished(self.run.tuning_path(crowd.name, "bc_best"), load_tuning)]
        jobs = [(crowd.name, method, self._trial_json(crowd.name, first) if method == "bco_lp" else None)
                for crowd in self.config.crowds() for method in self._baselines()
                if not (method == "bc_best" and crowd.name in copies)
                and not self.run.finished(self.run.tuning_path(crowd.name, method), load_tuning)]
        jobs.sort(key=lambda job: _LONGEST_FIRST.get(job[1], 0))
        with progress(total=len(jobs) + len(copies), desc="tune", quiet=self.quiet) as bar:
            for _, result in self.runner.map(tuning_task, shared, jobs):
                self._write_tuning(result)
                bar.update(1)
            for profile in copies:
                tuning = load_tuning(self.run.require(self.run.tuning_path(profile, "bc"), "benchmark"))
                evaluated = self.run.evaluation_path(profile, "bc", first)
                # Where bc's evaluation was lost, the evaluate stage makes bc_best's too.
                saved = self.run.loaded(evaluated, load_method_evaluation)
                evaluation = None if saved is None else {**saved, "method": "bc_best"}
                self._write_tuning({**tuning, "method": "bc_best", "evaluation": evaluation})
                bar.update(1)
        return len(jobs) + len(copies)

    def _write_tuning(self, result: dict[str, Any]) -> None:
        # The evaluation first: a tuning on disk is done, and a lost evaluation is redone.
        evaluation = result.pop("evaluation")
        if evaluation is not None:
            self._write_evaluation(evaluation)
        atomic_write_text(self.run.tuning_path(result["profile"], result["method"]), dumps(result))

    # 5. Evaluation.

    def _evaluation_done(self, profile: str, method: str, seed: int, world_weighting: str | None = None) -> bool:
        """Whether the evaluation is on disk, whole, of these attempts and (where given) played
        under ``world_weighting``: one played under another than validation now chooses is redone."""
        path = self.run.evaluation_path(profile, method, seed)
        saved = self.run.loaded(path, load_method_evaluation)
        attempts = self.config.evaluation_attempts()
        done = saved is not None and (saved["attempts"], saved["seed"]) == (attempts.count, attempts.seed)
        if done and world_weighting is not None:
            return bool(json.loads(path.read_text(encoding="utf-8")).get("world_weighting") == world_weighting)
        return done

    def evaluation_jobs(self) -> list[tuple[str, str, int, str | None, dict[str, Any] | None]]:
        """The evaluations still to run: ``(profile, method, seed, trial JSON, tuned hyperparameters)``."""
        jobs: list[tuple[str, str, int, str | None, dict[str, Any] | None]] = []
        methods = self.config.benchmark.methods
        for crowd in self.config.crowds():
            for method in (m for m in methods if m not in FROM_THE_REWARD and m != PRACTISED):
                tuned = None if method in POLYMIMIC_METHODS else load_tuning(
                    self.run.require(self.run.tuning_path(crowd.name, method), "benchmark"))["hyperparameters"]
                weighting = None
                if method == WEIGHED:
                    weighting = chosen_world_weighting(self.run, self.config, crowd.name)[0]
                    tuned = {"world_weighting": weighting}
                for seed in self.config.evaluated_seeds(method):
                    if self._evaluation_done(crowd.name, method, seed, weighting):
                        continue
                    uniform = POLYMIMIC_METHODS.get(method, ("", False))[1]
                    needs_trial = method in POLYMIMIC_METHODS or method == "bco_lp"
                    trial = self._trial_json(crowd.name, seed, uniform_lp=uniform) if needs_trial else None
                    jobs.append((crowd.name, method, seed, trial, tuned))
        return jobs

    def evaluate(self, shared: Shared) -> int:
        # bco_lp's refits first: the other evaluations are short and fill in around them.
        """Stage: every method plays the evaluation attempts; returns the evaluations run."""
        jobs = sorted(self.evaluation_jobs(), key=lambda job: job[1] != "bco_lp")
        with progress(total=len(jobs), desc="evaluate", quiet=self.quiet) as bar:
            for _, result in self.runner.map(evaluation_task, shared, jobs):
                self._write_evaluation(result)
                bar.update(1)
        return len(jobs)

    # 6. Practice.

    def _practice_done(self, profile: str, seed: int) -> bool:
        settings = self.config.benchmark
        saved = self.run.loaded(self.run.practice_path(profile, seed), load_practice)
        return self._evaluation_done(profile, PRACTISED, seed) and is_practice_of(
            saved, profile, seed, evaluation=self.config.evaluation_attempts(), budget=settings.practice_steps,
            method=settings.practice_method)

    def practice(self, shared: Shared) -> int:
        """Stage: the first trials' imitators practise; returns the practices run."""
        jobs = [(crowd.name, seed, self._trial_json(crowd.name, seed)) for crowd in self.config.crowds()
                for seed in self.config.evaluated_seeds(PRACTISED) if not self._practice_done(crowd.name, seed)]
        with progress(total=len(jobs), desc="practice", quiet=self.quiet) as bar:
            for _, result in self.runner.map(practice_task, practice_inputs(shared), jobs):
                # The evaluation first: the practice file marks the work done.
                self._write_evaluation(practised_evaluation(shared, result))
                atomic_write_text(self.run.practice_path(result["group"], result["trial_seed"]), dumps(result))
                bar.update(1)
        return len(jobs)

    # 7. ppo, from the reward.

    def _ppo_done(self, seed: int) -> bool:
        if not self.run.ppo_policy_path(seed).is_file():
            return False
        saved = self.run.loaded(self.run.ppo_curve_path(seed), load_ppo_curve)
        if saved is None:
            return False
        return self._curve_of(saved, seed)

    def ppo(self, shared: Shared) -> int:
        """Stage: ``ppo``'s runs and their curves; returns the runs made."""
        jobs = [seed for seed in range(self.config.benchmark.ppo_runs) if not self._ppo_done(seed)]
        self.run.ppo_curve_path(0).parent.mkdir(parents=True, exist_ok=True)
        with progress(total=len(jobs), desc="ppo", quiet=self.quiet) as bar:
            for seed, result in self.runner.map(ppo_task, shared, jobs):
                result.pop("policy").save(self.run.ppo_policy_path(seed))  # the policy first: the curve marks done
                atomic_write_text(self.run.ppo_curve_path(seed), dumps(result))
                bar.update(1)
        return len(jobs)

    # 8. ppo_bc: each crowd's commands cloned, then the reward.

    def _ppo_bc_done(self, profile: str, seed: int, chosen: dict[str, Any]) -> bool:
        if not self.run.ppo_bc_policy_path(profile, seed).is_file():
            return False
        saved = self.run.loaded(self.run.ppo_bc_curve_path(profile, seed), load_ppo_bc_curve)
        return saved is not None and saved["pretraining"] == chosen and self._curve_of(saved, seed)

    def _curve_of(self, saved: Any, seed: int) -> bool:
        """Whether a saved curve (ppo's or ppo_bc's) is training seed ``seed``'s, on this run's
        evaluation attempts, steps and checkpoints."""
        settings, attempts = self.config.benchmark, self.config.evaluation_attempts()
        return bool((saved["seed"], saved["evaluation_seed"], saved["attempts"], saved["total_timesteps"],
                     saved["eval_every"]) == (seed, attempts.seed, attempts.count, settings.ppo_timesteps,
                                              settings.ppo_eval_every))

    def ppo_bc(self, shared: Shared) -> int:
        """Stage: ``ppo_bc``'s cloning tuned per profile, then its runs; returns the pieces of work done."""
        profiles = [crowd.name for crowd in self.config.crowds()]
        untuned = [p for p in profiles if not self.run.finished(self.run.ppo_bc_tuning_path(p), load_ppo_bc_tuning)]
        with progress(total=len(untuned), desc="ppo_bc tune", quiet=self.quiet) as bar:
            for _, result in self.runner.map(ppo_bc_tuning_task, shared, untuned):
                atomic_write_text(self.run.ppo_bc_tuning_path(result["profile"]), dumps(result))
                bar.update(1)
        chosen = {p: load_ppo_bc_tuning(self.run.ppo_bc_tuning_path(p))["chosen"] for p in profiles}
        jobs = [(p, seed, chosen[p]) for p in profiles for seed in range(self.config.benchmark.ppo_runs)
                if not self._ppo_bc_done(p, seed, chosen[p])]
        with progress(total=len(jobs), desc="ppo_bc", quiet=self.quiet) as bar:
            for (profile, seed, _), result in self.runner.map(ppo_bc_task, shared, jobs):
                result.pop("policy").save(self.run.ppo_bc_policy_path(profile, seed))  # the curve marks done
                atomic_write_text(self.run.ppo_bc_curve_path(profile, seed), dumps(result))
                bar.update(1)
        return len(untuned) + len(jobs)

    def _write_evaluation(self, result: dict[str, Any]) -> None:
        path = self.run.evaluation_path(result["profile"], result["method"], result["trial_seed"])
        atomic_write_text(path, dumps(result))


    # 9. The summary and the report.

    def report(self) -> int:
        """Stage: ``benchmark.json``, its figures and the report; returns the files written (3)."""
        summary = gather(self.run, self.config)
        atomic_write_text(self.run.results_path, json.dumps(summary, indent=1) + "\n")
        draw_figures(summary, self.run.plots)
        stages = self.run.manifest()["stages"]
        steps = ("recognise", "record", "learn", "weigh", "tune", "evaluate", "practice", "ppo", "ppo_bc")
        seconds = {name: float(stages[name]["seconds"]) for name in steps
                   if isinstance(stages.get(name, {}).get("seconds"), (int, float))}
        markdown = benchmark_markdown(summary, seconds=seconds)
        atomic_write_text(self.run.report_md_path, markdown + "\n")
        atomic_write_text(self.run.report_html_path, benchmark_html(markdown, images_from=str(self.run.path)))
        return 3
