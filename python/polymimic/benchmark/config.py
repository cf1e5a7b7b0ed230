"""Every parameter of a benchmark run; TOML in and out.

The sections a reproduction has (``[seeds]``, ``[field]``, ``[recognizer]``, ``[segmenter]``,
``[learning]``, read by :class:`~polymimic.runs.config.RunConfig`), then ``[benchmark]``
(sizes, methods, tuning effort) and one ``[profiles.<name>]`` table per crowd, whose
``members`` list tables of ``controller`` and ``lapse`` (and optionally ``name`` and
``count``). The built-in profiles are there unless a file redefines one; a file may add
its own and run it with ``profiles = [...]``.

>>> config = BenchmarkConfig()
>>> config.benchmark.sizes.trials, config.benchmark.profiles[:2], config.learning.imitator_weighting
(20, ('one_good', 'half'), 'lp')
>>> config.benchmark.world_weightings
('outcome', 'intent', 'every')
>>> text = '[benchmark]\\nprofiles = ["pair"]\\n[profiles.pair]\\nmembers = [{controller = "expert", lapse = 0.1}, ' \\
...        '{controller = "poor", lapse = 0.0}]\\n'
>>> BenchmarkConfig.from_toml(text).crowds()[0].names
('expert_00', 'poor_01')
>>> BenchmarkConfig.from_toml('[benchmark]\\nprofiles = ["one_goood"]\\n')
Traceback (most recent call last):
...
polymimic.runs.config.ConfigError: [benchmark] profiles: unknown profile 'one_goood'; expected one of one_good, ...
"""

from __future__ import annotations

import dataclasses
import os
from typing import Any

from polymimic._toml import documented as _doc
from polymimic._toml import write_table, write_value
from polymimic.bodies import Body
from polymimic.crowds import PROFILES, Crowd
from polymimic.evaluation import Attempts
from polymimic.practice.methods import DEFAULT_METHOD as DEFAULT_PRACTICE
from polymimic.practice.methods import METHODS as PRACTICE_METHODS
from polymimic.practice.methods import RETIRED_METHODS as RETIRED_PRACTICE_METHODS
from polymimic.runs.config import (
    ConfigError,
    ConfigFile,
    RunConfig,
    as_table,
    in_range,
    replaced_section,
    section_docs,
    section_table,
)
from polymimic.runs.sizes import Sizes, TuningSizes

__all__ = ["FROM_THE_REWARD", "METHODS", "OPTIONAL_METHODS", "WORLD_WEIGHTINGS", "BenchmarkConfig", "BenchmarkSettings"]

METHODS = ("polymimic", "polymimic_thesis_control", "polymimic_uniform_lp", "bco", "bco_lp", "bc", "bc_best",
           "random")
"""The methods a benchmark compares by default (docs/results/benchmark.md, docs/guides/practice.md)."""

OPTIONAL_METHODS = ("polymimic_practice", "ppo", "ppo_bc", "offline_rl")
"""Methods run only when named: ``polymimic_practice`` is polymimic's imitator after practice
(``practice_method``, by default ``distil``, which needs stable-baselines3: ``pip install
"polymimic[rl]"``; docs/guides/practice.md); ``ppo`` learns from the reward rather than from demonstrations,
needs stable-baselines3 (``pip install "polymimic[rl]"``) and took 13 minutes of one core per
million environment steps in the run docs/results/benchmark.md quotes (:mod:`polymimic.baselines.ppo`); ``ppo_bc``
clones each crowd's commands first, then learns from the reward as ``ppo`` does, so it runs
once per profile (:mod:`polymimic.baselines.ppo_bc`); ``offline_rl`` learns from the crowd's
frames and the outcomes read off them, needs d3rlpy (``pip install "polymimic[offline]"``), and
fits eight times per profile (six candidates, two more fits), each fit four minutes of one core
on a full-size crowd (:mod:`polymimic.baselines.offline_rl`)."""

FROM_THE_REWARD = ("ppo", "ppo_bc")
"""Methods that learn from the environment's reward, in stages of their own (no tuning or
evaluation stage of the baselines')."""

TRIAL_INDEPENDENT = ("bc", "bco", "bc_best", "random", "offline_rl")
"""Baselines that learn the same thing in every trial: the crowd's demonstrations, unweighted.
They are fitted ``baseline_fits`` times, each fit under its own seed."""

WORLD_WEIGHTINGS = ("every", "intent", "outcome")
"""The parts of polymimic's world model its LP weighting may reach (``LearningConfig``'s
``world_weighting``)."""

RENAMED = {"refit_baselines": "baseline_fits (how many fits of bc, bco, bc_best, random and offline_rl, each under its "
                              "own seed; "
                              "refit_baselines = true was baseline_fits = trials)"}
"""Keys an older config may hold, and what took their place."""


@dataclasses.dataclass(frozen=True)
class BenchmarkSettings:
    """How big a benchmark is, what it compares, and how hard every baseline is tuned."""

    profiles: tuple[str, ...] = _doc("the crowds to run, by name", tuple(PROFILES))
    methods: tuple[str, ...] = _doc("the methods to compare", METHODS)
    sizes: Sizes = Sizes(trials=20)
    tuning: TuningSizes = TuningSizes(tuning_budget=6, validation_attempts_per_configuration=50)
    lp_plugin_trials: int = _doc("trials after which bco_lp, refitted with each trial's LPs, is evaluated: the "
                                 "first ones", 3)
    offline_gradient_steps: int = _doc("gradient steps of each offline_rl fit (when methods name offline_rl)",
                                       10_000)
    ppo_timesteps: int = _doc("environment steps each ppo run learns from (when methods name ppo)", 1_000_000)
    ppo_eval_every: int = _doc("environment steps between ppo's checkpoints on the evaluation attempts", 50_000)
    ppo_runs: int = _doc("ppo training runs, seeds 0, 1, … (ppo learns no crowd's data: its runs serve every "
                         "profile; ppo_bc runs as many per profile)", 1)
    practice_steps: int = _doc("environment steps polymimic_practice's imitators practise for, after learning "
                               "(polymimic.practice; scored at 0, 1000, 2500, 5000, 10000, 25000 and 50000 steps "
                               "within it)", 25_000)
    practice_method: str = _doc("how polymimic_practice's imitators practise: distil, jsrl or explore "
                                "(polymimic.practice.methods; distil and jsrl need polymimic[rl])", DEFAULT_PRACTICE)
    practice_trials: int = _doc("trials whose polymimic imitator practises, the first ones (every trial where "
                                "there are fewer; each practice costs practice_steps)", 5)
    world_weightings: tuple[str, ...] = _doc("the parts of polymimic's world model its LP weighting may reach "
                                             "(outcome: none; intent: the push region and the states' values; "
                                             "every: the ball's response too), chosen per profile on the "
                                             "validation attempts, one trial each under the first trial's seed, "
                                             "as the baselines are tuned (the first of equals; one candidate: used "
                                             "untried)", ("outcome", "intent", "every"))
    baseline_fits: int = _doc("fits of bc, bco, bc_best, random and offline_rl, each evaluated, under seeds "
                              "first_trial, first_trial + 1, …: a seed draws the fit's decision samples and seeds its "
                              "classifier (bco_lp is fitted after each of the first lp_plugin_trials trials)", 3)

    def _check_practice_method(self) -> None:
        """One of practice's methods; a retired one only in a run that does not practise (a run
        made before it retired still opens)."""
        if self.practice_method in RETIRED_PRACTICE_METHODS:
            if "polymimic_practice" in self.methods:
                raise ConfigError(f"[benchmark] practice_method {self.practice_method!r} is retired (it earned no "
                                  f"place on validation: docs/guides/practice.md), so polymimic_practice cannot "
                                  f"practise by it; use one of {', '.join(PRACTICE_METHODS)} (explore needs no extra "
                                  f"either)")
        elif self.practice_method not in PRACTICE_METHODS:
            raise ConfigError(f"[benchmark] practice_method must be one of {', '.join(PRACTICE_METHODS)}, got "
                              f"{self.practice_method!r}")

    def __post_init__(self) -> None:
        for name in ("lp_plugin_trials", "baseline_fits", "offline_gradient_steps", "ppo_timesteps", "ppo_eval_every",
                     "ppo_runs", "practice_steps", "practice_trials"):
            in_range("benchmark", name, getattr(self, name), 1)
        for name in ("profiles", "methods", "world_weightings"):
            value = getattr(self, name)
            if not isinstance(value, (list, tuple)) or not value:
                raise ConfigError(f"[benchmark] {name} must be a non-empty list, got {value!r}")
            if len(set(value)) != len(value):
                raise ConfigError(f"[benchmark] {name} names {next(v for v in value if value.count(v) > 1)!r} twice")
            object.__setattr__(self, name, tuple(value))
        self._check_practice_method()
        for weighting in self.world_weightings:
            if weighting not in WORLD_WEIGHTINGS:
                raise ConfigError(f"[benchmark] world_weightings: unknown weighting {weighting!r}; expected one of "
                                  f"{', '.join(WORLD_WEIGHTINGS)}")
        for method in self.methods:
            if method not in METHODS + OPTIONAL_METHODS:
                raise ConfigError(f"[benchmark] methods: unknown method {method!r}; expected one of "
                                  f"{', '.join(METHODS + OPTIONAL_METHODS)}")


_FILE_ORDER = ("profiles", "methods", "trials", "demonstrations_per_configuration", "attempts_per_configuration",
               "validation_attempts_per_configuration", "tuning_budget", "validation_seed", "lp_plugin_trials")
"""The first keys of ``[benchmark]`` in the order its files have always had them."""


@dataclasses.dataclass(frozen=True)
class BenchmarkConfig(ConfigFile):
    """The whole benchmark. ``BenchmarkConfig()`` is the full one; :meth:`quick` is small."""

    run: RunConfig = dataclasses.field(default_factory=lambda: _with_lp_weighting(RunConfig()))
    benchmark: BenchmarkSettings = dataclasses.field(default_factory=BenchmarkSettings)
    profiles: dict[str, Crowd] = dataclasses.field(default_factory=lambda: dict(PROFILES))

    def __post_init__(self) -> None:
        for name in self.benchmark.profiles:
            if name not in self.profiles:
                raise ConfigError(f"[benchmark] profiles: unknown profile {name!r}; expected one of "
                                  f"{', '.join(self.profiles)}")

    # The run's sections, by their names.
    @property
    def seeds(self) -> Any:
        """The run's seeds (``[seeds]``)."""
        return self.run.seeds

    @property
    def field(self) -> dict[str, Any]:
        """The field's parameters (``[field]``)."""
        return self.run.field

    @property
    def recognizer(self) -> Any:
        """The recogniser's settings (``[recognizer]``)."""
        return self.run.recognizer

    @property
    def segmenter(self) -> Any:
        """The segmenter's settings (``[segmenter]``)."""
        return self.run.segmenter

    @property
    def learning(self) -> Any:
        """The learning constants (``[learning]``)."""
        return self.run.learning

    def imitator_body(self) -> Body:
        """The imitator's :class:`polymimic.Body` (``[imitator] body``)."""
        return self.run.imitator_body()

    def evaluation_attempts(self) -> Attempts:
        """The attempts every method plays after every trial (``[benchmark]
        attempts_per_configuration`` from each configuration, under ``[seeds] evaluation``)."""
        return self.benchmark.sizes.evaluation_attempts(seed=self.seeds.evaluation)

    def trial_seeds(self) -> list[int]:
        """Every profile's trial seeds: ``first_trial``, ``first_trial + 1``, …"""
        return [self.seeds.first_trial + i for i in range(self.benchmark.sizes.trials)]

    def evaluated_seeds(self, method: str) -> list[int]:
        """The seeds ``method`` is evaluated under: every trial's for polymimic's methods, the
        first ``lp_plugin_trials`` trials' for ``bco_lp`` (a fit per trial, with its LPs), and
        ``baseline_fits`` fit seeds (``first_trial``, ``first_trial + 1``, …) for a baseline
        whose data no trial changes, and the first ``practice_trials`` trials' for
        ``polymimic_practice``."""
        if method in TRIAL_INDEPENDENT:
            return [self.seeds.first_trial + i for i in range(self.benchmark.baseline_fits)]
        seeds = self.trial_seeds()
        if method == "polymimic_practice":
            return seeds[:self.benchmark.practice_trials]
        return seeds[:self.benchmark.lp_plugin_trials] if method == "bco_lp" else seeds

    def crowds(self) -> list[Crowd]:
        """The crowds this benchmark runs, in its order."""
        return [self.profiles[name] for name in self.benchmark.profiles]

    @classmethod
    def quick(cls) -> BenchmarkConfig:
        """A small benchmark: 2 trials per profile, 5 demonstrations per member and configuration,
        5 attempts per configuration, 3 tuning candidates on 3 attempts each, fits of at most
        1000 decision samples (offline_rl's, where named, of 300 gradient steps), ppo (where named)
        for 8192 steps, the first trial's imitator practising for 1000 steps, and the quick
        reproduction's recogniser."""
        full = cls()
        return dataclasses.replace(
            full, run=_with_lp_weighting(dataclasses.replace(RunConfig.quick(), experiments=full.run.experiments)),
            benchmark=dataclasses.replace(full.benchmark, sizes=Sizes(trials=2, demonstrations_per_configuration=5,
                                                                      attempts_per_configuration=5),
                                          tuning=TuningSizes(tuning_budget=3, validation_attempts_per_configuration=3,
                                                             max_decision_samples=1000),
                                          offline_gradient_steps=300, ppo_timesteps=8192, ppo_eval_every=4096,
                                          practice_steps=1000, practice_trials=1))

    def to_dict(self) -> dict[str, Any]:
        """The whole config as plain tables (the run's, ``[benchmark]`` and ``[profiles]``)."""
        run = self.run.to_dict()
        del run["experiments"]
        return {**run, "benchmark": section_table(self.benchmark, order=_FILE_ORDER),
                "profiles": {name: {"members": crowd.to_members()} for name, crowd in self.profiles.items()}}

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, base: BenchmarkConfig | None = None,
                  base_dir: str | os.PathLike[str] = ".") -> BenchmarkConfig:
        """A config from tables such as :meth:`to_dict` gives, laid over ``base`` (the defaults);
        the run's files (a demonstrator's log) are found relative to ``base_dir``.

        Raises
        ------
        ConfigError
            For an unknown key or a value out of range.
        """
        base = base or cls()
        own = {"benchmark", "profiles"}
        run = RunConfig.from_dict({k: v for k, v in data.items() if k not in own}, base=base.run, base_dir=base_dir)
        profiles = dict(base.profiles)
        for name, table in as_table("profiles", data.get("profiles", {})).items():
            members = as_table(f"profiles.{name}", table)
            unknown = sorted(set(members) - {"members"})
            if unknown:
                raise ConfigError(f"unknown key in [profiles.{name}]: {unknown[0]} (a profile has members only)")
            try:
                profiles[name] = Crowd.from_members(name, members.get("members", []))
            except ValueError as error:
                raise ConfigError(f"[profiles.{name}] {error}") from error
        benchmark = base.benchmark
        if "benchmark" in data:
            table = as_table("benchmark", data["benchmark"])
            for old, new in RENAMED.items():
                if old in table:
                    raise ConfigError(f"[benchmark] {old} is no more: use {new}")
            benchmark = replaced_section("benchmark", base.benchmark, table)
        return cls(run=run, benchmark=benchmark, profiles=profiles)

    def to_toml(self) -> str:
        """The config as commented TOML."""
        lines = self.run.to_toml().split("\n[experiments]")[0].rstrip().split("\n")
        lines[0] = "# polymimic benchmark configuration"
        lines.append("")
        write_table(lines, "benchmark", section_table(self.benchmark, order=_FILE_ORDER),
                    section_docs(self.benchmark, per="profile"))
        for name, crowd in self.profiles.items():
            lines.append(f"[profiles.{name}]")
            lines.append("members = [")
            lines.extend(f"  {{ {', '.join(f'{k} = {write_value(v)}' for k, v in m.items())} }},"
                         for m in crowd.to_members())
            lines.extend(["]", ""])
        return "\n".join(lines).rstrip() + "\n"


def _with_lp_weighting(run: RunConfig) -> RunConfig:
    """The benchmark's imitator learns more from members of higher LP (docs/results/benchmark.md)."""
    return dataclasses.replace(run, learning=run.learning.replace(imitator_weighting="lp"))
