"""The Gymnasium environment: passes Gymnasium's checker, ends with an outcome, reproducible."""

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

import polymimic  # noqa: E402
from polymimic.env import ENV_ID, PenaltyKickEnv  # noqa: E402
from polymimic.field import OUTCOMES  # noqa: E402


def test_env_checker_passes():
    from gymnasium.utils.env_checker import check_env

    for render_mode in (None, "rgb_array"):
        check_env(gymnasium.make(ENV_ID, render_mode=render_mode).unwrapped)


def test_make_with_the_module_prefix_registers_it():
    env = gymnasium.make(f"polymimic.env:{ENV_ID}", configuration=2)
    observation, info = env.reset(seed=0)
    assert observation.shape == (5,) and observation.dtype == np.float32
    seed = info.pop("episode_seed")
    assert info == {"t_s": 0.0, "outcome": None, "valid": True}
    assert isinstance(seed, int) and 0 <= seed < 2**63


def play(env, seed, configuration):
    """Random actions from a seeded generator until the episode ends."""
    rng = np.random.default_rng(seed)
    observation, _ = env.reset(seed=seed, options={"configuration": configuration})
    observations, rewards = [observation], []
    for _ in range(61):
        observation, reward, terminated, truncated, info = env.step(int(rng.integers(5)))
        observations.append(observation)
        rewards.append(reward)
        if terminated or truncated:
            return np.array(observations), rewards, terminated, truncated, info
    raise AssertionError("the field's 60 s limit should have ended the episode")


@pytest.mark.parametrize("configuration", [1, 2])
def test_random_play_ends_with_an_outcome(configuration):
    env = PenaltyKickEnv()
    for seed in range(3):
        observations, rewards, terminated, truncated, info = play(env, seed, configuration)
        assert info["outcome"] in OUTCOMES
        assert terminated != truncated
        assert truncated == (info["outcome"] == "time_up")
        assert rewards[-1] == {"goal": 1.0, "own_goal": -1.0}.get(info["outcome"], 0.0)
        assert all(r == 0.0 for r in rewards[:-1])
        assert info["t_s"] <= 60.0 + 1e-9
        assert all(env.observation_space.contains(o) for o in observations)


def _configuration_of(observation):
    """Configuration 1 starts the robot at −L/6, configuration 2 at +L/6."""
    return 1 if observation[0] < 0 else 2


def test_random_configurations_come_from_the_envs_own_generator():
    env = PenaltyKickEnv()
    drawn = [_configuration_of(env.reset(seed=seed)[0]) for seed in range(40)]
    assert 10 <= drawn.count(1) <= 30 and drawn.count(1) + drawn.count(2) == 40
    assert drawn == [_configuration_of(PenaltyKickEnv().reset(seed=seed)[0]) for seed in range(40)]
    # Unseeded resets go on drawing from the same generator; an option overrides the default.
    env.reset(seed=5)
    following = [_configuration_of(env.reset()[0]) for _ in range(30)]
    assert set(following) == {1, 2}
    assert _configuration_of(env.reset(options={"configuration": 2})[0]) == 2
    fixed = PenaltyKickEnv(configuration=1)
    assert {_configuration_of(fixed.reset(seed=seed)[0]) for seed in range(10)} == {1}
    assert {_configuration_of(fixed.reset(seed=seed, options={"configuration": "random"})[0])
            for seed in range(20)} == {1, 2}


def test_same_seed_same_trajectory_other_seed_another():
    a = play(PenaltyKickEnv(), 7, 2)[0]
    b = play(PenaltyKickEnv(), 7, 2)[0]
    c = play(PenaltyKickEnv(), 8, 2)[0]
    np.testing.assert_array_equal(a, b)
    assert a.shape != c.shape or not np.array_equal(a, c)


def test_a_step_is_one_second_of_one_primitive():
    env = PenaltyKickEnv(configuration=1)
    start, _ = env.reset(seed=1)
    moved, _, _, _, info = env.step(0)
    assert info["t_s"] == pytest.approx(1.0)
    assert moved[0] - start[0] > 10  # forward moves toward +x in configuration 1
    half = PenaltyKickEnv(configuration=1, frames_per_action=15)
    half.reset(seed=1)
    assert half.step(0)[4]["t_s"] == pytest.approx(0.5)


def test_the_imitator_may_be_another_body_on_its_own_field():
    tiny = PenaltyKickEnv(configuration=1, body="tiny")
    start, _ = tiny.reset(seed=1)
    assert tiny.body.name == "tiny" and tiny.observation_space.high[0] == pytest.approx(0.75 * 560.0)
    assert start[0] == pytest.approx(-560.0 / 6, abs=5.0)  # a sixth of the small field behind the centre
    # The humanoid takes no primitives: forward is its walk forward, the same episode to the bit.
    humanoid = PenaltyKickEnv(configuration=1, body="humanoid")
    stood, _ = humanoid.reset(seed=4)
    walked = humanoid.step(0)[0]
    drawn = int(gymnasium.utils.seeding.np_random(4)[0].integers(0, 2**63))  # the env's episode seed
    episode = polymimic.Episode("humanoid", configuration=1, seed=drawn)
    episode.run(["Walk Forward"] * 30)
    assert walked.tolist() == np.array([*episode.observation()["robot"], *episode.observation()["ball"]],
                                       dtype=np.float32).tolist()
    assert walked[0] > stood[0] + 10  # it walked toward the ball
    with pytest.raises(ValueError, match='unknown body "tinny"'):
        PenaltyKickEnv(body="tinny")


def test_misuse_is_named():
    env = PenaltyKickEnv()
    with pytest.raises(polymimic.FieldRunError, match=r"call reset\(\) before step\(\)"):
        env.step(0)
    env.reset(seed=0)
    with pytest.raises(ValueError, match="action must be an integer in 0..4"):
        env.step(5)
    with pytest.raises(ValueError, match='configuration must be 1, 2 or "random", got 3'):
        env.reset(options={"configuration": 3})
    with pytest.raises(ValueError, match="got 'Random'"):
        env.reset(options={"configuration": "Random"})
    with pytest.raises(ValueError, match="unknown reset option"):
        env.reset(options={"speed": 2})
    with pytest.raises(ValueError, match="configuration must be 1, 2 or"):
        PenaltyKickEnv(configuration=0)
    with pytest.raises(ValueError, match="frames_per_action must be an integer ≥ 1"):
        PenaltyKickEnv(frames_per_action=0)
    with pytest.raises(ValueError, match="unknown key 'nonsense' in the field config"):
        PenaltyKickEnv(config='{"nonsense": 1}')


def test_stepping_after_the_end_is_a_field_run_error():
    env = PenaltyKickEnv()
    play(env, 0, 1)
    with pytest.raises(polymimic.FieldRunError, match=r"the episode has ended \(\w+\); call reset\(\)"):
        env.step(0)


def test_render_shows_the_field():
    env = PenaltyKickEnv(render_mode="rgb_array")
    env.reset(seed=0)
    image = env.render()
    assert image.ndim == 3 and image.shape[2] == 3 and image.dtype == np.uint8
    assert PenaltyKickEnv().render() is None


def test_importing_polymimic_registers_the_environment():
    import subprocess
    import sys

    code = "import gymnasium, polymimic; print(gymnasium.make('PenaltyKick-v0').action_space)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "Discrete(5)"
