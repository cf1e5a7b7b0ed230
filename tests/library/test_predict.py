"""The imitator in a Gymnasium loop: ``predict`` as stable-baselines3 defines it, single and
batched, plays the episodes ``evaluate`` plays."""

import importlib.util

import gymnasium
import numpy as np
import pytest

import polymimic
from polymimic import recognition
from polymimic.learning import ImitatorPolicy, run_trial


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)


@pytest.fixture(scope="module", params=["thesis", "improved"])
def policy(request, recognizer):
    watched = [d for c in (1, 2) for name in ("expert", "poor") for d in polymimic.record(name, configuration=c, n=3,
                                                                                           seed=4)]
    trial = run_trial(watched, recognizer=recognizer, ordering=["expert", "poor"])
    return ImitatorPolicy(trial, recognizer=recognizer, control=request.param, demonstrations=watched)


def _through_the_env(policy, attempt, player):
    """``attempt``'s episode played in ``PenaltyKick-v0`` by ``predict``, decided by ``player``."""
    env = gymnasium.make("PenaltyKick-v0")
    observation, info = env.reset(options={"configuration": attempt["configuration"], "episode_seed": attempt["seed"]})
    assert info["episode_seed"] == attempt["seed"]
    state, done = (player,), False
    while not done:
        action, state = policy.predict(observation, state=state)
        assert action.shape == () and env.action_space.contains(action)
        observation, _, terminated, truncated, info = env.step(action)
        done = terminated or truncated
    return env.unwrapped._episode.frames, info["outcome"]


def test_a_gymnasium_loop_through_predict_plays_evaluates_episodes(policy):
    played = policy.evaluate(5, seed=9)
    identical = 0
    for attempt in played:
        player = policy.player()
        player.reset(start=attempt["configuration"], seed=attempt["seed"])
        frames, outcome = _through_the_env(policy, attempt, player)
        identical += frames.tobytes() == attempt["frames"].tobytes()
    # The env's observations are float32: a decision near a tie may flip on the rounding (none
    # did in 100 attempts measured, 50 per control); a systematic difference would part them all.
    assert identical >= len(played) - 1, f"{identical} of {len(played)} identical"


def test_predict_on_a_batch_is_predict_on_each_observation(policy):
    envs = gymnasium.make_vec("PenaltyKick-v0", num_envs=4, vectorization_mode="vector_entry_point")
    observations, _ = envs.reset(seed=3)
    state, episode_start = None, np.ones(4, dtype=bool)
    singles = [None] * 4
    for _ in range(6):
        actions, state = policy.predict(observations, state=state, episode_start=episode_start)
        assert actions.shape == (4,) and actions.dtype == np.int64 and len(state) == 4
        for i in range(4):
            alone, singles[i] = policy.predict(observations[i], state=singles[i], episode_start=episode_start[i])
            assert alone == actions[i]
        observations, _, terminated, truncated, _ = envs.step(actions)
        episode_start = terminated | truncated


def test_predict_refuses_what_is_not_the_envs_observation(policy):
    with pytest.raises(ValueError, match=r"shape \(5,\) or \(n, 5\), got shape \(4,\)"):
        policy.predict(np.zeros(4, dtype=np.float32))
    with pytest.raises(ValueError, match="state holds 1 players for a batch of 2"):
        _, state = policy.predict(np.array([-170.0, 0.0, 0.0, 170.0, 0.0]))
        policy.predict(np.zeros((2, 5)), state=state)
    with pytest.raises(ValueError, match="episode_start must hold one flag per observation"):
        policy.predict(np.zeros((2, 5)) + [-170.0, 0.0, 0.0, 170.0, 0.0], episode_start=[True])


def test_reset_options_pick_a_start_and_an_episode_seed_or_are_refused_by_name():
    env = gymnasium.make("PenaltyKick-v0")
    observation, info = env.reset(options={"start": {"robot": (0.0, 100.0, 1.0), "ball": (250.0, -50.0)},
                                           "episode_seed": 2**64 - 1})
    assert info["episode_seed"] == 2**64 - 1
    assert np.allclose(observation, [0.0, 100.0, 1.0, 250.0, -50.0], atol=5.0)
    with pytest.raises(ValueError, match="give 'configuration' or 'start', not both"):
        env.reset(options={"start": {"robot": (0.0, 0.0, 0.0), "ball": (250.0, 0.0)}, "configuration": 1})
    with pytest.raises(ValueError, match="overlaps the lego robot"):
        env.reset(options={"start": {"robot": (0.0, 0.0, 0.0), "ball": (70.0, 0.0)}})
    with pytest.raises(ValueError, match=r"episode_seed must be in"):
        env.reset(options={"episode_seed": -1})
    with pytest.raises(ValueError, match="unknown reset option.*'seed'"):
        env.reset(options={"seed": 1})


def test_the_humanoids_env_acts_in_its_own_eight_and_kicks_with_the_foot_the_ball_is_on():
    env = gymnasium.make("PenaltyKick-v0", body="humanoid")
    assert env.action_space.n == 8 and env.unwrapped.primitives[7] == "kick"
    ids = {c["name"]: c["id"] for c in polymimic.command_table()}
    for ball_y_mm, foot in ((40.0, "Kick Left"), (-40.0, "Kick Right")):
        env.reset(options={"start": {"robot": (0.0, 0.0, 0.0), "ball": (150.0, ball_y_mm)}, "episode_seed": 1})
        env.step(7)
        assert set(env.unwrapped._episode.frames[:, 6].astype(int).tolist()) == {ids[foot]}


@pytest.mark.skipif(importlib.util.find_spec("stable_baselines3") is None,
                    reason="stable-baselines3 is the optional `rl` extra")
def test_stable_baselines3s_evaluate_policy_runs_the_imitator_unchanged(policy):
    from stable_baselines3.common.evaluation import evaluate_policy
    from stable_baselines3.common.monitor import Monitor

    env = Monitor(gymnasium.make("PenaltyKick-v0", configuration=1))
    rewards, lengths = evaluate_policy(policy, env, n_eval_episodes=4, return_episode_rewards=True)
    assert len(rewards) == 4 and all(r in (-1.0, 0.0, 1.0) for r in rewards)
