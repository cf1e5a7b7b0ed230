"""ppo_bc: its network really clones the commands before PPO fine-tunes it, its cloning is
chosen on validation attempts, and its curve starts from the cloned network. Skipped without
stable-baselines3 (the optional `rl` extra)."""

import numpy as np
import pytest

import polymimic
from polymimic import baselines
from polymimic.baselines.evaluation import evaluate_policy

pytest.importorskip("stable_baselines3")

from polymimic.baselines import ppo_bc  # noqa: E402


def _recorded(n, seed):
    return [d for who in ("expert", "poor") for c in (1, 2) for d in polymimic.record(who, configuration=c, n=n,
                                                                                    seed=seed)]


@pytest.fixture(scope="module")
def demos():
    return _recorded(4, seed=0)


@pytest.fixture(scope="module")
def held_out():
    return _recorded(3, seed=7)


def test_cloning_agrees_with_the_commands_on_held_out_steps_at_least_as_often_as_bc(demos, held_out):
    cloned = ppo_bc.pretrained(demos, ppo_bc.Pretraining(100, 1e-3), seed=0)
    untrained = ppo_bc.pretrained(demos, ppo_bc.Pretraining(0, 1e-3), seed=0)
    bc = baselines.fit("bc", demos, seed=0)
    ours, theirs, before = (ppo_bc.agreement(p, held_out) for p in (cloned, bc, untrained))
    assert ours >= theirs, (ours, theirs)
    # Cloning is what made it agree: the same network before it cloned agrees far less.
    assert ours > before + 0.2, (ours, before)


def test_the_same_seed_clones_the_same_network(demos):
    one, two = (ppo_bc.pretrained(demos, ppo_bc.Pretraining(5, 1e-3), seed=3) for _ in range(2))
    observations = np.array([[-170.0, 0.0, 0.0, 170.0, 0.0], [170.0, 0.0, np.pi, -170.0, 0.0]])
    assert one.predict(observations).tolist() == two.predict(observations).tolist()
    for a, b in zip(one.model.policy.parameters(), two.model.policy.parameters()):
        assert np.array_equal(a.detach().numpy(), b.detach().numpy())


def test_pretraining_is_chosen_on_validation_attempts(demos):
    choice = ppo_bc.tune_pretraining(demos, budget=2, attempts_per_configuration=2)
    assert len(choice.scores) == 2 and choice.chosen in ppo_bc.PRETRAINING_CANDIDATES[:2]
    best = max(choice.scores, key=lambda s: (s["goals"] - s["own_goals"], s["goals"]))
    assert (choice.chosen.epochs, choice.chosen.learning_rate) == (best["epochs"], best["learning_rate"])
    with pytest.raises(ValueError, match="budget must be an integer in 1..6, got 0"):
        ppo_bc.tune_pretraining(demos, budget=0)


def test_pretraining_refuses_validation_attempts_the_evaluation_plays(demos, monkeypatch):
    from polymimic.baselines import tuning
    clash = tuning.validation_attempts(2, validation_seed=0)[0][1]
    monkeypatch.setattr(polymimic.Attempts, "episodes", lambda self: [(1, clash)])
    with pytest.raises(ValueError, match="share episode seeds"):
        ppo_bc.tune_pretraining(demos, budget=1, attempts_per_configuration=2)


def test_the_curve_starts_from_the_cloned_network(demos):
    pretraining = ppo_bc.Pretraining(10, 1e-3)
    _, curve, _ = ppo_bc.learning_curve(demos, pretraining, total_timesteps=256, eval_every=256,
                                        evaluation=polymimic.Attempts(per_configuration=2), seed=1)
    cloned = evaluate_policy(ppo_bc.pretrained(demos, pretraining, seed=1), attempts_per_configuration=2)
    assert curve[0].env_steps == 0
    assert (curve[0].goals, curve[0].own_goals) == (cloned.goals, cloned.own_goals)


def test_the_curve_plays_attempts_from_the_thesis_configurations_only(demos):
    with pytest.raises(ValueError, match="evaluation must be attempts from the thesis's configurations"):
        ppo_bc.learning_curve(demos, ppo_bc.Pretraining(10, 1e-3), total_timesteps=256, eval_every=256,
                              evaluation=polymimic.Attempts(starts=[1]))
