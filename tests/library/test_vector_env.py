"""The vector environment: the same episodes, rewards, ends and infos as Gymnasium's
SyncVectorEnv over single environments, step by step, and its misuse named."""

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

from polymimic.env import ENV_ID, PenaltyKickEnv  # noqa: E402
from polymimic.vector_env import PenaltyKickVectorEnv  # noqa: E402


def _sync(n, **kwargs):
    return gymnasium.vector.SyncVectorEnv([lambda: PenaltyKickEnv(**kwargs) for _ in range(n)])


def _assert_same(ours, theirs, what):
    for a, b, name in zip(ours, theirs, ("observations", "rewards", "terminations", "truncations")):
        np.testing.assert_array_equal(a, b, err_msg=f"{name} {what}")
    infos_a, infos_b = ours[-1], theirs[-1]
    assert set(infos_a) == set(infos_b), what
    for key in infos_a:
        np.testing.assert_array_equal(infos_a[key], infos_b[key], err_msg=f"info {key} {what}")
        assert infos_a[key].dtype == infos_b[key].dtype, (key, what)


@pytest.mark.parametrize("configuration", ["random", 2])
def test_the_same_as_sync_vector_env_step_by_step_through_autoresets(configuration):
    n, steps = 6, 130  # past the 60 s limit, so every sub-environment resets at least once
    ours, theirs = PenaltyKickVectorEnv(n, configuration=configuration), _sync(n, configuration=configuration)
    a_obs, a_info = ours.reset(seed=11)
    b_obs, b_info = theirs.reset(seed=11)
    np.testing.assert_array_equal(a_obs, b_obs)
    assert {k: v.tolist() for k, v in a_info.items()} == {k: v.tolist() for k, v in b_info.items()}
    rng, ended = np.random.default_rng(3), 0
    for t in range(steps):
        actions = rng.integers(0, 5, size=n)
        a, b = ours.step(actions), theirs.step(actions)
        _assert_same(a, b, f"at step {t}")
        ended += int((a[2] | a[3]).sum())
    assert ended >= n


@pytest.mark.parametrize("body", ["tiny", "humanoid"])
def test_another_body_is_the_same_as_its_single_environments(body):
    n = 3
    ours, theirs = PenaltyKickVectorEnv(n, body=body), _sync(n, body=body)
    assert ours.body.name == body and ours.single_observation_space == theirs.single_observation_space
    a_obs, _ = ours.reset(seed=2)
    b_obs, _ = theirs.reset(seed=2)
    np.testing.assert_array_equal(a_obs, b_obs)
    rng = np.random.default_rng(5)
    for t in range(70):
        actions = rng.integers(0, 5, size=n)
        _assert_same(ours.step(actions), theirs.step(actions), f"{body} at step {t}")


def test_seeds_per_sub_environment_and_partial_resets():
    ours, theirs = PenaltyKickVectorEnv(3), _sync(3)
    for seed in ([4, None, 9], 2):
        a, b = ours.reset(seed=seed), theirs.reset(seed=seed)
        if seed == 2:
            np.testing.assert_array_equal(a[0], b[0])
    mask = np.array([False, True, False])
    ours.step([0, 0, 0])
    theirs.step([0, 0, 0])
    a_obs, a_info = ours.reset(seed=5, options={"reset_mask": mask})
    b_obs, b_info = theirs.reset(seed=5, options={"reset_mask": mask.copy()})
    np.testing.assert_array_equal(a_obs, b_obs)
    assert a_info["_t_s"].tolist() == [False, True, False] == b_info["_t_s"].tolist()


def test_make_vec_builds_it_from_the_registry():
    envs = gymnasium.make_vec(ENV_ID, num_envs=3, vectorization_mode="vector_entry_point", configuration=1)
    observations, _ = envs.reset(seed=0)
    assert isinstance(envs.unwrapped, PenaltyKickVectorEnv) and observations.shape == (3, 5)
    assert bool((observations[:, 0] < 0).all())  # configuration 1: the robot at −L/6
    assert envs.observation_space.contains(observations)


def test_misuse_is_named():
    envs = PenaltyKickVectorEnv(4)
    with pytest.raises(gymnasium.error.ResetNeeded):
        envs.step([0, 0, 0, 0])
    envs.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions must be 4 integers in 0..4 \(one per sub-environment\), got shape "
                                         r"\(3,\)"):
        envs.step([0, 0, 0])
    with pytest.raises(ValueError, match=r"actions\[2\] = 7: an action is an integer in 0..4"):
        envs.step([0, 0, 7, 0])
    with pytest.raises(ValueError, match="got shape \\(4,\\) of float64"):
        envs.step([0.0, 1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="seed holds 2 seeds for 4 sub-environments"):
        envs.reset(seed=[1, 2])
    with pytest.raises(ValueError, match="unknown reset option"):
        envs.reset(options={"speed": 1})
    with pytest.raises(ValueError, match="reset_mask"):
        envs.reset(options={"reset_mask": [True, False, True, True]})
    with pytest.raises(ValueError, match="num_envs must be an integer ≥ 1, got 0"):
        PenaltyKickVectorEnv(0)
    with pytest.raises(ValueError, match="configuration must be 1, 2 or"):
        PenaltyKickVectorEnv(2, configuration=3)
    with pytest.raises(ValueError, match="first reset must reset every sub-environment"):
        PenaltyKickVectorEnv(2).reset(options={"reset_mask": np.array([True, False])})
