"""offline_rl in the benchmark, without d3rlpy: opt-in, fitted baseline_fits times, its tuning
files read back with its own kind of hyperparameters, and a clear error where the extra is
missing."""

import dataclasses
import json

import pytest

from polymimic import ModelFileError
from polymimic.baselines import offline_rl
from polymimic.baselines.offline_hyperparameters import DEFAULT_BCQ
from polymimic.benchmark.config import METHODS, OPTIONAL_METHODS, BenchmarkConfig
from polymimic.benchmark.driver import Benchmark
from polymimic.benchmark.task_files import load_tuning
from polymimic.runs.config import ConfigError


def test_offline_rl_is_opt_in_and_fitted_baseline_fits_times():
    config = BenchmarkConfig()
    assert "offline_rl" in OPTIONAL_METHODS and "offline_rl" not in METHODS
    assert config.evaluated_seeds("offline_rl") == config.evaluated_seeds("bco") == [config.seeds.first_trial + i
                                                                                     for i in range(3)]


def test_a_missing_extra_is_named(monkeypatch):
    config = BenchmarkConfig()
    config = dataclasses.replace(config, benchmark=dataclasses.replace(config.benchmark,
                                                                       methods=("polymimic", "offline_rl")))
    monkeypatch.setattr(offline_rl, "available", lambda: False)
    with pytest.raises(ConfigError, match=r'offline_rl needs d3rlpy and torch: pip install "polymimic\[offline\]"'):
        Benchmark.check_extras(config)


def test_its_tuning_file_reads_back_with_its_own_hyperparameters(tmp_path):
    tuning = {"profile": "half", "method": "offline_rl", "chosen": DEFAULT_BCQ.to_dict(),
              "hyperparameters": DEFAULT_BCQ.to_dict(), "validation_attempts": 100,
              "scores": [{"hyperparameters": DEFAULT_BCQ.to_dict(), "goals": 30, "own_goals": 2}]}
    path = tmp_path / "tuning.json"
    path.write_text(json.dumps(tuning))
    assert load_tuning(path)["hyperparameters"] == DEFAULT_BCQ.to_dict()
    path.write_text(json.dumps({**tuning, "hyperparameters": {**DEFAULT_BCQ.to_dict(), "algorithm": "cql"}}))
    with pytest.raises(ModelFileError, match="unknown algorithm 'cql'"):
        load_tuning(path)
