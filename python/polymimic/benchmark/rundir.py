"""A benchmark's run directory.

::

    manifest.json                    version, config, start and finish of every stage
    datasets/self_observation_train.parquet, models/recognizer.json
    datasets/crowd_<profile>.parquet every member's demonstrations (load_demonstrations reads it)
    datasets/controller_skill.json   each controller's net goals per attempt without lapses
    models/benchmark/<profile>/trial_<seed>.json               the LP-weighted trial
    models/benchmark/<profile>/trial_<seed>_uniform_lp.json    every LP held at 0.5
    models/benchmark/<profile>/tuning_<method>.json            the candidates tried, the choice
    models/benchmark/<profile>/weighing_<weighting>.json       polymimic under one world weighting,
                                                               on the validation attempts
    models/benchmark/<profile>/evaluation_<method>_<seed>.json one method's attempts after one trial
    models/benchmark/<profile>/practice_<seed>.json            the imitator's practice after one trial
    models/benchmark/ppo/curve_<seed>.json, policy_<seed>.pmp  a ppo run's checkpoints, its policy
    models/benchmark/<profile>/ppo_bc_tuning.json              ppo_bc's cloning, chosen on validation
    models/benchmark/<profile>/ppo_bc_curve_<seed>.json, ppo_bc_policy_<seed>.pmp  a ppo_bc run
    benchmark.json, benchmark.md, benchmark.html, plots/benchmark_*.png

>>> import tempfile
>>> run = BenchmarkDir(tempfile.mkdtemp())
>>> run.trial_path("linear", 3, uniform_lp=True).name
'trial_3_uniform_lp.json'
"""

from __future__ import annotations

import pathlib

from polymimic.benchmark.config import BenchmarkConfig
from polymimic.runs.rundir import RunHouse

__all__ = ["BenchmarkDir"]


class BenchmarkDir(RunHouse[BenchmarkConfig]):
    """Paths of a benchmark's files."""

    manifest_format = "polymimic.benchmark_run"
    config_type = BenchmarkConfig
    results_name = report_name = "benchmark"

    def crowd_path(self, profile: str) -> pathlib.Path:
        """The profile's recorded crowd (Parquet)."""
        return self.datasets / f"crowd_{profile}.parquet"

    @property
    def controller_skill_path(self) -> pathlib.Path:
        """Each controller's net goals per attempt without lapses, measured in the record stage."""
        return self.datasets / "controller_skill.json"

    def weighing_path(self, profile: str, weighting: str) -> pathlib.Path:
        """One world weighting's validation score on the profile."""
        return self.profile_dir(profile) / f"weighing_{weighting}.json"

    def profile_dir(self, profile: str) -> pathlib.Path:
        """The folder of the profile's trials, tunings and evaluations."""
        return self.models / "benchmark" / profile

    def trial_path(self, profile: str, seed: int, *, uniform_lp: bool = False) -> pathlib.Path:
        """A learning trial's file (the uniform-LP ablation's with ``uniform_lp``)."""
        return self.profile_dir(profile) / f"trial_{seed}{'_uniform_lp' if uniform_lp else ''}.json"

    def tuning_path(self, profile: str, method: str) -> pathlib.Path:
        """A baseline's tuning on the profile."""
        return self.profile_dir(profile) / f"tuning_{method}.json"

    def evaluation_path(self, profile: str, method: str, seed: int) -> pathlib.Path:
        """One evaluation of a method (a trial's or a fit's seed)."""
        return self.profile_dir(profile) / f"evaluation_{method}_{seed}.json"

    def practice_path(self, profile: str, seed: int) -> pathlib.Path:
        """One trial's practice curve."""
        return self.profile_dir(profile) / f"practice_{seed}.json"

    def ppo_curve_path(self, seed: int) -> pathlib.Path:
        """One ``ppo`` run's learning curve."""
        return self.models / "benchmark" / "ppo" / f"curve_{seed}.json"

    def ppo_bc_tuning_path(self, profile: str) -> pathlib.Path:
        """``ppo_bc``'s cloning choice on the profile."""
        return self.profile_dir(profile) / "ppo_bc_tuning.json"

    def ppo_bc_curve_path(self, profile: str, seed: int) -> pathlib.Path:
        """One ``ppo_bc`` run's learning curve on the profile."""
        return self.profile_dir(profile) / f"ppo_bc_curve_{seed}.json"

    def ppo_bc_policy_path(self, profile: str, seed: int) -> pathlib.Path:
        """One ``ppo_bc`` run's final policy."""
        return self.profile_dir(profile) / f"ppo_bc_policy_{seed}.pmp"

    def ppo_policy_path(self, seed: int) -> pathlib.Path:
        """One ``ppo`` run's final policy."""
        return self.models / "benchmark" / "ppo" / f"policy_{seed}.pmp"
