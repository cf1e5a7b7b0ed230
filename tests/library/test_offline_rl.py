"""offline_rl: on scripted episodes where one action always leads to a goal and another to an
own goal, from the same states, both algorithms learn to take the first (CQL at half its
paper's alpha: at alpha 1, 2000 steps leave it near the data's even split at some starts); fits repeat bit for
bit; a policy saves and loads; tuning chooses on validation attempts. Skipped without d3rlpy
(the optional `offline` extra)."""

import dataclasses
import pathlib

import numpy as np
import pytest

import polymimic
from polymimic import baselines
from polymimic.baselines.labels import Labelled
from polymimic.baselines.offline_hyperparameters import DEFAULT_BCQ, DEFAULT_CQL, OfflineHyperparameters, candidates
from polymimic.field import PRIMITIVES, as_frames

pytest.importorskip("d3rlpy")

from polymimic.baselines import offline_rl  # noqa: E402

FORWARD, BACKWARD = PRIMITIVES.index("forward"), PRIMITIVES.index("backward")
SMALL = {"gradient_steps": 2000, "learning_rate": 1e-3}


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    import torch

    threads = torch.get_num_threads()
    torch.set_num_threads(1)
    yield
    torch.set_num_threads(threads)


def _branch(start, step_mm, action, ball_x_mm, length=25):
    """An episode from observation ``start``: ``action`` at every sample, the robot and ball
    moving ``step_mm`` along x each time, the ball last read at ``ball_x_mm`` (a goal or an own
    goal)."""
    observations = start + np.outer(np.arange(length), [step_mm, 0.0, 0.0, step_mm, 0.0])
    table = np.column_stack([np.arange(length) / 30, observations, np.zeros(length)])
    table[-1, 4] = ball_x_mm
    frames = as_frames(table)
    demo = polymimic.Demonstration(frames=frames, outcome="goal" if ball_x_mm > 0 else "own_goal",
                                   demonstrator="scripted", configuration=1, seed=0, body="lego")
    return demo, Labelled("scripted", observations, np.full(length, action), "lego")


@pytest.fixture(scope="module")
def forked():
    """From each of 20 starts, two episodes: forward at every sample, the robot and ball moving
    on towards the target goal and scoring, or backward at every sample, towards the own goal,
    scoring there."""
    rng = np.random.default_rng(0)
    starts = np.column_stack([rng.uniform(-300, 0, 20), rng.uniform(-200, 200, 20), rng.uniform(-0.5, 0.5, 20),
                              rng.uniform(0, 100, 20), rng.uniform(-100, 100, 20)])
    pairs = [_branch(start, sign * 20.0, action, sign * 510.3) for start in starts
             for sign, action in ((1, FORWARD), (-1, BACKWARD))]
    prepared = offline_rl.Prepared([d for d, _ in pairs], {"inverse_dynamics": [item for _, item in pairs]}, seed=0,
                                   max_samples=20_000, imitator="lego")
    return prepared, starts


@pytest.mark.parametrize("algorithm", [dataclasses.replace(DEFAULT_CQL, conservatism=0.5), DEFAULT_BCQ])
def test_the_action_that_leads_to_goals_is_the_one_taken(forked, algorithm):
    prepared, starts = forked
    policy = offline_rl.fit_prepared(prepared, hyperparameters=dataclasses.replace(algorithm, **SMALL))
    chosen = policy.predict(starts)
    assert (chosen == FORWARD).all(), np.bincount(chosen, minlength=5)
    values = policy.values(starts)
    assert (values[:, FORWARD] > values[:, BACKWARD]).all() and (values[:, FORWARD] > 0.3).all(), values


def test_the_same_seed_fits_the_same_network_and_it_saves_and_loads(forked, tmp_path):
    hyperparameters = dataclasses.replace(DEFAULT_CQL, **{**SMALL, "gradient_steps": 300})
    prepared, _ = forked
    one, two = (offline_rl.fit_prepared(prepared, hyperparameters=hyperparameters) for _ in range(2))
    rng = np.random.default_rng(0)
    observations = np.column_stack([rng.uniform(-500, 500, 50), rng.uniform(-400, 400, 50), rng.uniform(-3, 3, 50),
                                    rng.uniform(-500, 500, 50), rng.uniform(-400, 400, 50)])
    assert np.array_equal(one.values(observations), two.values(observations))
    path = pathlib.Path(tmp_path) / "offline.pmp"
    one.save(path)
    again = baselines.load_policy(path)
    assert isinstance(again, offline_rl.OfflineRLPolicy) and again.hyperparameters == hyperparameters
    assert np.array_equal(again.values(observations), one.values(observations))
    assert again.predict(observations).tolist() == one.predict(observations).tolist()
    assert offline_rl.fit_prepared(dataclasses.replace(prepared, seed=1), hyperparameters=hyperparameters).values(
        observations).tolist() != one.values(observations).tolist()


def test_tuning_chooses_the_best_candidate_on_validation_attempts():
    demos = polymimic.record("expert", configuration=1, n=2, seed=0) + polymimic.record("poor", configuration=1, n=2,
                                                                                          seed=0)
    tried = [dataclasses.replace(h, **{**SMALL, "gradient_steps": 200}) for h in (DEFAULT_CQL, DEFAULT_BCQ)]
    result = offline_rl.tune(demos, candidates=tried, attempts_per_configuration=2)
    assert [s["hyperparameters"] for s in result.scores] == [h.to_dict() for h in tried]
    best = max(range(2), key=lambda i: (result.scores[i]["goals"] - result.scores[i]["own_goals"],
                                        result.scores[i]["goals"], -i))
    assert result.hyperparameters == tried[best] and result.chosen == tried[best].to_dict()
    steps = dataclasses.replace(tried[0], labels="steps")  # the recogniser's labels need one
    with pytest.raises(ValueError, match="recognizer"):
        offline_rl.tune(demos, candidates=[steps], attempts_per_configuration=1)


def test_the_candidates_pair_each_draw_with_both_of_bcos_labellings():
    drawn = candidates(6, seed=0)
    assert [h.labels for h in drawn] == ["steps", "inverse_dynamics"] * 3
    assert drawn[0] == dataclasses.replace(DEFAULT_CQL, labels="steps") and drawn[2].algorithm == "discrete_bcq"
    assert len({dataclasses.replace(h, labels="steps") for h in drawn}) == 3


def test_bad_hyperparameters_are_refused_by_name():
    with pytest.raises(ValueError, match="unknown algorithm 'cql'"):
        OfflineHyperparameters("cql", 1.0, 1e-3, (64,), "raw", 10)
    with pytest.raises(ValueError, match="must be below 1"):
        dataclasses.replace(DEFAULT_BCQ, conservatism=1.5)
    with pytest.raises(ValueError, match="learning_rate must be a positive number"):
        dataclasses.replace(DEFAULT_CQL, learning_rate=0.0)
    with pytest.raises(ValueError, match="unknown key 'alpha'"):
        OfflineHyperparameters.from_dict({**DEFAULT_CQL.to_dict(), "alpha": 1.0})
