"""The simulated field from Python: shapes, determinism, the command table and bad input."""

import json
import math

import numpy as np
import pytest

import polymimic
from polymimic.field import (
    DEMONSTRATORS,
    FRAME_DTYPE,
    OUTCOMES,
    PRIMITIVES,
    command_primitives,
    default_config,
)


@pytest.fixture(scope="module")
def demos():
    return {(who, c): polymimic.record(who, configuration=c, n=2, seed=11) for who in DEMONSTRATORS for c in (1, 2)}


@pytest.mark.parametrize("who", DEMONSTRATORS)
@pytest.mark.parametrize("configuration", [1, 2])
def test_record_gives_n_demonstrations_of_tracker_frames(who, configuration):
    recorded = polymimic.record(who, configuration=configuration, n=2, seed=3)
    assert len(recorded) == 2
    for demo in recorded:
        assert isinstance(demo, polymimic.Demonstration)
        assert (demo.demonstrator, demo.configuration) == (who, configuration)
        assert demo.outcome in OUTCOMES
        frames = demo.frames
        assert frames.dtype == FRAME_DTYPE and frames.ndim == 1 and len(frames) > 1
        # 30 frames a second from 0; valid demonstrations have no tracking gaps.
        np.testing.assert_allclose(frames["t_s"], np.arange(len(frames)) / 30, atol=1e-9)
        assert np.isfinite(frames[["robot_x_mm", "robot_y_mm", "robot_theta_rad"]].tolist()).all()
        assert np.isfinite(frames["ball_x_mm"]).all() and np.isfinite(frames["ball_y_mm"]).all()
        assert (np.abs(frames["robot_theta_rad"]) <= np.pi + 1e-9).all()


def test_record_starts_from_the_configuration(demos):
    first = demos["expert", 1][0].frames[0]
    assert first["robot_x_mm"] == pytest.approx(-170, abs=3) and first["ball_x_mm"] == pytest.approx(170, abs=3)
    first = demos["expert", 2][0].frames[0]
    assert first["robot_x_mm"] == pytest.approx(170, abs=3) and first["ball_x_mm"] == pytest.approx(-170, abs=3)
    first = demos["tiny", 1][0].frames[0]
    assert first["robot_x_mm"] == pytest.approx(-560 / 6, abs=3)


def test_self_observation_gives_one_second_sequences_of_each_primitive():
    sequences = polymimic.self_observation(3, seed=1)
    assert len(sequences) == 15
    assert sorted(s.primitive for s in sequences) == sorted(PRIMITIVES * 3)
    for s in sequences:
        assert isinstance(s, polymimic.PrimitiveSequence)
        assert s.frames.dtype == FRAME_DTYPE and s.frames.shape == (30,)
        assert np.isnan(s.frames["ball_x_mm"]).all()  # the imitator is alone on the field
        assert set(command_primitives()[s.frames["command"]]) == {s.primitive}


def _travel_mm(sequence):
    """How far a sequence's robot went along its starting heading (mm)."""
    f = sequence.frames
    heading = f["robot_theta_rad"][0]
    return ((f["robot_x_mm"][-1] - f["robot_x_mm"][0]) * np.cos(heading)
            + (f["robot_y_mm"][-1] - f["robot_y_mm"][0]) * np.sin(heading))


@pytest.mark.parametrize(("body", "half_length_mm"), [("tiny", 280.0), ("humanoid", 510.0)])
def test_any_body_observes_itself_on_its_own_field(body, half_length_mm):
    sequences = polymimic.self_observation(4, seed=3, body=body)
    assert sorted(s.primitive for s in sequences) == sorted(PRIMITIVES * 4)
    assert {s.body.name for s in sequences} == {body}
    for s in sequences:
        assert (np.abs(s.frames["robot_x_mm"]) < half_length_mm).all()
        # Each frame records the command the body was sent: its own language's on the humanoid.
        assert set(command_primitives()[s.frames["command"]]) == {s.primitive}
    forward = [_travel_mm(s) for s in sequences if s.primitive == "forward"]
    backward = [_travel_mm(s) for s in sequences if s.primitive == "backward"]
    assert min(forward) > 0 > max(backward)
    humanoid_ids = {r["id"] for r in polymimic.field.command_table() if r["language"] == "humanoid"}
    sent = np.concatenate([s.frames["command"] for s in sequences])
    assert set(sent.tolist()) <= humanoid_ids if body == "humanoid" else not set(sent.tolist()) & humanoid_ids


def test_the_lego_is_the_default_imitator_bit_for_bit():
    default, lego = polymimic.self_observation(2, seed=4), polymimic.self_observation(2, seed=4, body="lego")
    assert all(a.frames.tobytes() == b.frames.tobytes() and a.body.name == b.body.name == "lego"
               for a, b in zip(default, lego))
    with pytest.raises(ValueError, match="body must be one of lego, tiny, humanoid .*got 'lgeo'"):
        polymimic.self_observation(1, body="lgeo")


def test_same_seed_same_frames_different_seed_different_frames():
    a = polymimic.record("poor", configuration=2, n=3, seed=5)
    b = polymimic.record("poor", configuration=2, n=3, seed=5)
    c = polymimic.record("poor", configuration=2, n=3, seed=6)
    assert [d.frames.tobytes() for d in a] == [d.frames.tobytes() for d in b]
    assert [d.outcome for d in a] == [d.outcome for d in b]
    assert all(x.frames.tobytes() != y.frames.tobytes() for x, y in zip(a, c))
    s1, s2 = polymimic.self_observation(2, seed=9), polymimic.self_observation(2, seed=9)
    assert [s.frames.tobytes() for s in s1] == [s.frames.tobytes() for s in s2]
    assert s1[0].frames.tobytes() != polymimic.self_observation(2, seed=10)[0].frames.tobytes()


def test_every_recorded_command_has_an_equivalent_primitive(demos):
    table = polymimic.command_table()
    ids = {row["id"] for row in table}
    assert len(ids) == len(table)
    assert {row["primitive"] for row in table} == set(PRIMITIVES)
    lookup = command_primitives()
    for recorded in demos.values():
        for demo in recorded:
            commands = demo.frames["command"]
            assert set(commands.tolist()) <= ids
            assert set(lookup[commands]) <= set(PRIMITIVES)


def test_episode_steps_and_runs_like_the_recorder():
    episode = polymimic.Episode("lego", configuration=1, seed=2)
    seen = episode.observation()
    assert seen["field"] == (1020.0, 810.0) and seen["t_s"] == 0.0
    row, outcome = episode.step("forward")
    assert row.shape == (7,) and outcome is None
    frames, outcome = episode.run(["forward"] * 29 + [polymimic.command_table()[4]["id"]])
    assert frames.shape == (30, 7) and outcome is None
    assert episode.frames.shape == (31, 7)
    assert episode.observation()["t_s"] == pytest.approx(31 / 30)
    assert episode.valid and not episode.finished


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(demonstrator="nobody", configuration=1, n=1), "unknown demonstrator 'nobody'"),
        (dict(demonstrator="expert", configuration=3, n=1), "configuration must be in 1..2, got 3"),
        (dict(demonstrator="expert", configuration=1, n=0), "n must be at least 1, got 0"),
        (dict(demonstrator="expert", configuration=1, n=-1), "n must be at least 1, got -1"),
        (dict(demonstrator="expert", configuration=1, n=1, seed=-1), "seed must be in 0..18446744073709551615, got -1"),
    ],
)
def test_bad_record_arguments_are_named(kwargs, match):
    who = kwargs.pop("demonstrator")
    with pytest.raises(ValueError, match=match):
        polymimic.record(who, **kwargs)


@pytest.mark.parametrize("n, match", [(0, "at least 1, got 0"), (-1, "at least 1, got -1")])
def test_bad_self_observation_counts_are_named(n, match):
    with pytest.raises(ValueError, match=f"n_per_primitive must be {match}"):
        polymimic.self_observation(n)


@pytest.mark.parametrize(
    "command, match",
    [("jump", 'unknown command "jump"'), (9999, "unknown command id 9999"), (-1, "unknown command id -1")],
)
def test_unknown_commands_are_named(command, match):
    episode = polymimic.Episode()
    with pytest.raises(ValueError, match=match):
        episode.step(command)
    with pytest.raises(ValueError, match=match):
        episode.run(["forward", command])
    assert len(episode.frames) == 0  # nothing ran


def test_a_body_refuses_another_language():
    expert_only = next(row["id"] for row in polymimic.command_table() if row["language"] == "expert")
    with pytest.raises(ValueError, match="cannot drive the tiny body"):
        polymimic.Episode("tiny").step(expert_only)


def test_stepping_a_finished_episode_is_a_field_run_error():
    config = default_config()
    config["time_limit_s"] = 0.5
    episode = polymimic.Episode(config=json.dumps(config))
    frames, outcome = episode.run(["stop"] * 100)
    assert outcome == "time_up" and episode.finished
    assert len(frames) == 16  # 15 steps and the final state
    with pytest.raises(polymimic.FieldRunError, match="already ended"):
        episode.step("forward")
    with pytest.raises(polymimic.FieldRunError, match="already ended"):
        episode.run(["forward"])
    with pytest.raises(polymimic.PolymimicError):
        episode.place_robot(0.0, 0.0, 0.0)


def test_field_configs_are_checked_whole_by_name():
    with pytest.raises(ValueError, match="unknown key 'time_limt_s' in the field config; known keys: "):
        polymimic.record("expert", configuration=1, n=1, config={"time_limt_s": 30.0})
    with pytest.raises(ValueError, match="unknown key 'tracker.sigma'"):
        polymimic.self_observation(1, config={"tracker": {"sigma": 1.0}})
    with pytest.raises(TypeError, match="'substeps_per_frame' must be an integer, like the default 8; got 2.5"):
        polymimic.record("expert", configuration=1, n=1, config={"substeps_per_frame": 2.5})
    with pytest.raises(ValueError, match=r"field config: parameter `substeps_per_frame` = -1 is not a count: a whole "
                                         r"number, 1 ≤ substeps ≤ 64$"):
        polymimic.record("expert", configuration=1, n=1, config={"substeps_per_frame": -1})
    with pytest.raises(ValueError, match=r"parameter `substeps_per_frame` = -3 is not a count"):
        polymimic.Episode(config='{"substeps_per_frame": -3}')
    with pytest.raises(TypeError, match="'tracker' must be a table"):
        polymimic.record("expert", configuration=1, n=1, config={"tracker": 3})
    with pytest.raises(ValueError, match="position_sigma_mm"):
        polymimic.record("expert", configuration=1, n=1, config={"tracker": {"position_sigma_mm": -1.0}})
    with pytest.raises(ValueError, match="'time_limit_s' must be a finite number, got nan"):
        polymimic.record("expert", configuration=1, n=1, config={"time_limit_s": float("nan")})
    with pytest.raises(ValueError, match="not valid JSON"):
        polymimic.record("expert", configuration=1, n=1, config="{time_limit_s: 1}")
    partial = default_config()
    partial["time_limit_s"] = 5.0
    assert polymimic.field.check_config({"time_limit_s": 5.0}) == partial


def test_bad_episode_arguments_are_named():
    with pytest.raises(ValueError, match="configuration must be 1 or 2, got 3"):
        polymimic.Episode(configuration=3)
    # The body is a polymimic.Body: an unknown name is named, with the built-in ones and how to describe one's own.
    with pytest.raises(ValueError, match='unknown body "wheelbarrow": the built-in bodies are lego, tiny, humanoid; '
                                         'describe a body of your own with polymimic.bodies.WheeledBody'):
        polymimic.Episode("wheelbarrow")
    with pytest.raises(ValueError, match="field config"):
        polymimic.Episode(config='{"time_limit_s": 1.0}')


def test_the_humanoid_is_configured_by_its_own_table():
    config = default_config()
    assert config["humanoid"]["look_after_s"] == 0.0 and config["humanoid"]["foot_window_s"] == [0.3, 0.959]
    default = polymimic.record("humanoid", configuration=2, n=1, seed=5)[0]
    # Saying the defaults again changes nothing, bit for bit.
    same = polymimic.record("humanoid", configuration=2, n=1, seed=5, config={"humanoid": {"turn_pivot_mm": 20.3}})[0]
    assert same.frames.tobytes() == default.frames.tobytes()
    pivoting = polymimic.record("humanoid", configuration=2, n=1, seed=5,
                                config={"humanoid": {"turn_pivot_mm": 28.0}})[0]
    assert pivoting.frames.tobytes() != default.frames.tobytes()
    # The wheeled robots do not read it.
    expert = polymimic.record("expert", configuration=2, n=1, seed=5)[0]
    again = polymimic.record("expert", configuration=2, n=1, seed=5, config={"humanoid": {"turn_pivot_mm": 28.0}})[0]
    assert again.frames.tobytes() == expert.frames.tobytes()


@pytest.mark.parametrize(("humanoid", "error", "match"), [
    ({"look_s": -2.0}, ValueError, r"humanoid\.look_s.*0 ≤ s ≤ 3600"),
    ({"foot_window_s": [0.6, 0.3]}, ValueError, r"humanoid\.foot_window_s.*start < end"),
    ({"foot_window_s": [0.3]}, TypeError, r"'humanoid\.foot_window_s' must be 2 numbers"),
    ({"foot_window_s": ["a", 0.3]}, TypeError, r"'humanoid\.foot_window_s\[0\]' must be a number"),
    ({"step_s": 0.0}, ValueError, r"humanoid\.step_s.*positive"),
    ({"look_sec": 1.0}, ValueError, r"unknown key 'humanoid\.look_sec'"),
])
def test_bad_humanoid_constants_are_named(humanoid, error, match):
    with pytest.raises(error, match=match):
        polymimic.field.check_config({"humanoid": humanoid})


def test_the_presets_in_the_docs_are_valid_run_configs():
    import pathlib

    from polymimic.runs.config import RunConfig

    configs = pathlib.Path(__file__).parents[2] / "docs" / "configs"
    tracker = RunConfig.load(configs / "tracker_table_3_1.toml").field["tracker"]
    assert tracker["spike_probability"] == 0.001
    assert tracker["position_sigma_mm"] == default_config()["tracker"]["position_sigma_mm"] == 0.107
    config = RunConfig.load(configs / "humanoid_thesis_like.toml")
    assert config.field["humanoid"]["turn_pivot_mm"] == 28.0
    assert config.field["humanoid"]["foot_window_s"] == [0.3, 0.9]
    assert config.field["humanoid"]["walk_mm_s"] == default_config()["humanoid"]["walk_mm_s"]
    before = RunConfig.load(configs / "world_before_calibration.toml")
    assert before.field["tracker"]["heading_sigma_rad"] == pytest.approx(math.radians(3.0))
    assert before.field["humanoid"]["turn_pivot_mm"] == 0.0 and before.learning.lp_own_goal_weight == 1.0
