"""ppo and ppo_bc drive any imitator body on that body's own field, and their policies remember
the body. Skipped without stable-baselines3 (the optional `rl` extra)."""

import numpy as np
import pytest

import polymimic
from polymimic import baselines
from polymimic.baselines.evaluation import evaluate_policy
from polymimic.baselines.features import features

pytest.importorskip("stable_baselines3")

from polymimic.baselines import ppo, ppo_bc  # noqa: E402

TINY_FIELD_LENGTH_MM = 560.0  # the small field the tiny plays on
SMALL_PPO = dict(total_timesteps=128, n_steps=32, batch_size=32, n_epochs=1, seed=0)


def test_the_lego_sees_what_it_saw_before_bodies_were_named():
    observations = np.array([[-170.0, 20.0, 0.3, 170.0, -10.0], [300.0, -200.0, 2.0, 100.0, 50.0]])
    before = features(observations, feature_set="goal_relative")
    millimetres = [i for i, name in enumerate(ppo.FEATURE_NAMES["goal_relative"]) if name.endswith("_mm")]
    before[:, millimetres] /= 500.0
    assert np.array_equal(ppo.scaled(observations, "goal_relative"), before.astype(np.float32))
    assert np.array_equal(ppo.scaled(observations, "goal_relative", "lego"), before.astype(np.float32))


def test_a_field_in_proportion_is_seen_alike_by_a_body_in_proportion():
    lego = np.array([[-170.0, 20.0, 0.3, 170.0, -10.0]])
    tiny = lego * [560 / 1020, 560 / 1020, 1.0, 560 / 1020, 560 / 1020]
    assert np.allclose(ppo.scaled(lego, "goal_relative"), ppo.scaled(tiny, "goal_relative", "tiny"), atol=1e-6)


def test_ppo_trains_and_plays_the_tiny_on_its_own_field_and_its_file_keeps_the_body(tmp_path):
    policy = ppo.fit(imitator="tiny", **SMALL_PPO)
    assert policy.body.name == "tiny"
    assert policy.model.get_env().envs[0].unwrapped.body.name == "tiny"
    played = evaluate_policy(policy, attempts_per_configuration=2, seed=3)
    assert {attempt.body.name for attempt in played.attempts} == {"tiny"}
    # Each attempt starts where the tiny's field puts the robot, a sixth of 560 mm from the centre.
    starts = [abs(float(attempt.frames["robot_x_mm"][0])) for attempt in played.attempts]
    assert np.allclose(starts, TINY_FIELD_LENGTH_MM / 6, atol=2.0), starts
    policy.save(tmp_path / "tiny.pmp")
    loaded = baselines.load_policy(tmp_path / "tiny.pmp")
    observations = played.attempts[0].frames[["robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm",
                                               "ball_y_mm"]]
    observations = np.column_stack([observations[name] for name in observations.dtype.names])
    assert loaded.body.name == "tiny"
    assert (loaded.predict(observations) == policy.predict(observations)).all()


def test_ppo_drives_the_humanoid():
    policy, curve, played = ppo.learning_curve(imitator="humanoid", eval_every=128,
                                               evaluation=polymimic.Attempts(per_configuration=1), **SMALL_PPO)
    assert policy.body.name == "humanoid" and {a.body.name for a in played.attempts} == {"humanoid"}
    assert [c.env_steps for c in curve][0] == 0 and all(c.attempts == 2 for c in curve)


def test_ppo_bc_clones_the_tiny_controller_for_a_tiny_imitator_as_well_as_bc_does():
    demos = [d for c in (1, 2) for d in polymimic.record("tiny", configuration=c, n=4, seed=0)]
    held_out = [d for c in (1, 2) for d in polymimic.record("tiny", configuration=c, n=3, seed=7)]
    cloned = ppo_bc.pretrained(demos, ppo_bc.Pretraining(100, 1e-3), seed=0, imitator="tiny")
    bc = baselines.fit("bc", demos, seed=0, imitator="tiny")
    assert cloned.body.name == "tiny"
    ours = ppo_bc.agreement(cloned, held_out, imitator="tiny")
    theirs = ppo_bc.agreement(bc, held_out, imitator="tiny")
    assert ours >= theirs, (ours, theirs)
