"""``bc`` against the plain cloner of ``benches/plain_cloner_vs_bc.py`` on a small mixed-body
crowd: the same demonstrations, validation attempts and evaluation attempts, three fits each.
``bc`` must not be beaten by more than its own spread over fits."""

import importlib.util
import pathlib
import statistics

import pytest

pytest.importorskip("sklearn")

from polymimic import baselines  # noqa: E402
from polymimic.baselines.evaluation import attempts_of, play  # noqa: E402
from polymimic.baselines.tuning import validation_attempts  # noqa: E402
from polymimic.crowds import PROFILES, record_crowd  # noqa: E402

BENCH = pathlib.Path(__file__).parents[2] / "benches" / "plain_cloner_vs_bc.py"
FITS, MAX_SAMPLES, EVALUATION_SEED = (0, 1, 2), 3000, 1000


def _plain_cloner():
    spec = importlib.util.spec_from_file_location("plain_cloner_vs_bc", BENCH)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _net(policy, attempts):
    played = play(policy, attempts)
    return played.goals - played.own_goals


def test_bc_is_not_beaten_by_the_plain_cloner_by_more_than_its_spread_over_fits():
    demos = record_crowd(PROFILES["mixed_bodies"], n=3, seed=0)
    validation = validation_attempts(20, validation_seed=0)
    evaluation = attempts_of(25, seed=EVALUATION_SEED)
    plain = _plain_cloner()
    frames, _ = plain.chosen_step(demos, validation, max_samples=MAX_SAMPLES)
    plain_nets = [_net(plain.fit(demos, frames, max_samples=MAX_SAMPLES, seed=seed), evaluation) for seed in FITS]
    tuned = baselines.tune("bc", demos, budget=3, attempts_per_configuration=20, evaluation_seed=EVALUATION_SEED,
                           evaluation_attempts_per_configuration=25, max_samples=MAX_SAMPLES)
    bc_nets = [_net(baselines.fit("bc", demos, hyperparameters=tuned.hyperparameters, seed=seed,
                                  max_samples=MAX_SAMPLES), evaluation) for seed in FITS]
    assert statistics.mean(bc_nets) >= statistics.mean(plain_nets) - statistics.stdev(bc_nets), (bc_nets, plain_nets)
