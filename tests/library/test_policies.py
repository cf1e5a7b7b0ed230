"""Python demonstrators: a policy of the user's own drives a body on the Rust field."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

import polymimic
from polymimic import PolicyError, record
from polymimic.datasets import load_demonstrations, save_demonstrations


def chase(reading: polymimic.Reading) -> str:
    """The Poor demonstrator's rule, in Python: turn toward the ball, then drive at it."""
    if not reading.ball_seen:
        return "stop"
    bearing = math.atan2(reading.ball_y_mm - reading.robot_y_mm, reading.ball_x_mm - reading.robot_x_mm)
    error = math.remainder(bearing - reading.robot_theta_rad, math.tau)
    return "forward" if abs(error) < math.radians(20) else ("left" if error > 0 else "right")


class Counting:
    """An object policy that remembers what it was told."""

    decision_hz = 10
    name = "counting"

    def __init__(self) -> None:
        self.starts: list[dict] = []
        self.times: list[list[float]] = []

    def reset(self, episode: dict) -> None:
        self.starts.append(episode)
        self.times.append([])

    def act(self, reading: polymimic.Reading) -> str:
        self.times[-1].append(reading.t_s)
        return chase(reading)


def _replay(demo: polymimic.Demonstration, policy, every_frames: int) -> np.ndarray:
    """The same episode stepped by hand through polymimic.Episode."""
    episode = polymimic.Episode(demo.body, configuration=demo.configuration, seed=demo.seed)
    command = None
    for index in range(100_000):
        if episode.finished:
            break
        if index % every_frames == 0:
            seen = episode.observation()
            reading = _Reading(seen)
            command = policy(reading)
        episode.step(command)
    return episode.frames


class _Reading:
    def __init__(self, seen: dict) -> None:
        self.t_s = seen["t_s"]
        self.robot_x_mm, self.robot_y_mm, self.robot_theta_rad = seen["robot"]
        ball = seen["ball"]
        self.ball_seen = ball is not None
        self.ball_x_mm, self.ball_y_mm = ball if ball is not None else (math.nan, math.nan)


@pytest.mark.parametrize("decision_hz", [30, 10, 3])
def test_a_recorded_policy_is_the_same_episode_stepped_by_hand(decision_hz):
    demos = record(chase, body="lego", name="chaser", configuration=2, n=2, seed=11, decision_hz=decision_hz)
    for demo in demos:
        by_hand = _replay(demo, chase, 30 // decision_hz)
        assert by_hand.shape[0] == len(demo.frames)
        for i, column in enumerate(demo.frames.dtype.names):
            np.testing.assert_array_equal(by_hand[:, i], demo.frames[column].astype(float), err_msg=column)


def test_decisions_come_at_the_declared_rate_and_reset_starts_every_attempt():
    policy = Counting()
    demos = record(policy, body="lego", configuration=1, n=3, seed=4)
    assert [d.demonstrator for d in demos] == ["counting"] * 3
    # One reset per attempt (all valid here), with the attempt's seed and configuration.
    assert [s["seed"] for s in policy.starts] == [d.seed for d in demos]
    assert {(s["configuration"], s["body"]) for s in policy.starts} == {(1, "lego")}
    assert [s["attempt"] for s in policy.starts] == [0, 1, 2]
    for demo, times in zip(demos, policy.times):
        steps = len(demo.frames) - 1
        assert len(times) == math.ceil(steps / 3)
        np.testing.assert_allclose(times, np.arange(len(times)) / 10.0, atol=1e-9)
        commands = demo.frames["command"][:steps]
        assert all(len(set(commands[i:i + 3])) == 1 for i in range(0, steps, 3))


def test_a_policy_is_deterministic_and_its_seeds_are_its_own():
    a = record(chase, body="tiny", name="c", configuration=2, n=2, seed=8, decision_hz=5)
    b = record(chase, body="tiny", name="c", configuration=2, n=2, seed=8, decision_hz=5)
    assert [d.seed for d in a] == [d.seed for d in b]
    assert all(np.array_equal(x.frames, y.frames) for x, y in zip(a, b))
    builtin = record("tiny", configuration=2, n=2, seed=8)
    assert {d.seed for d in a}.isdisjoint(d.seed for d in builtin)


def test_every_language_of_the_body_is_accepted():
    expert_words = record(lambda r: "arc_left_tight_fast", body="lego", name="arcs", configuration=1, n=1, seed=2,
                          config={"time_limit_s": 2.0})
    table = {row["name"]: row["id"] for row in polymimic.command_table()}
    assert set(expert_words[0].frames["command"]) == {table["arc_left_tight_fast"]}
    walker = record(lambda r: "Walk Forward", body="humanoid", name="walker", configuration=1, n=1, seed=2,
                    config={"time_limit_s": 2.0})
    assert set(walker[0].frames["command"]) == {table["Walk Forward"]}
    by_id = record(lambda r: 3, body="tiny", name="ids", configuration=1, n=1, seed=2, config={"time_limit_s": 1.0})
    assert set(by_id[0].frames["command"]) == {3}


def test_recordings_save_and_load_with_their_name_and_body(tmp_path):
    demos = record(chase, body="tiny", name="my_tiny", configuration=1, n=2, seed=1, decision_hz=6)
    save_demonstrations(demos, tmp_path / "mine.parquet")
    back = load_demonstrations(tmp_path / "mine.parquet")
    assert [(d.demonstrator, d.body.name, d.seed, d.outcome) for d in back] == \
        [(d.demonstrator, d.body.name, d.seed, d.outcome) for d in demos]


def test_a_policy_that_raises_surfaces_with_the_attempt_and_time():
    def late_failure(reading):
        if reading.t_s >= 1.0:
            raise KeyError("no such gain")
        return "forward"

    with pytest.raises(PolicyError, match=r"'late' on the lego body failed with KeyError\('no such gain'\) in "
                                          r"attempt 0 of configuration 1 \(seed \d+\) at t = 1\.00 s") as caught:
        record(late_failure, body="lego", name="late", configuration=1, n=1, decision_hz=10)
    assert isinstance(caught.value.__cause__, KeyError)

    class BadReset:
        def reset(self, episode):
            raise RuntimeError("not ready")

        def act(self, reading):
            return "stop"

    with pytest.raises(PolicyError, match=r"failed with RuntimeError\('not ready'\) in attempt 0 .* at t = 0\.00 s"):
        record(BadReset(), body="lego", name="bad", configuration=2, n=1)


@pytest.mark.parametrize(("answer", "message"), [
    ("jump", r"unknown command \"jump\""),
    (3.5, r"got 3.5 \(float\)"),
    (None, r"got None \(NoneType\)"),
    (True, r"got True \(bool\)"),
    (999, r"unknown command id 999"),
])
def test_an_answer_that_is_no_command_is_refused_with_the_episode(answer, message):
    with pytest.raises(PolicyError, match=message) as caught:
        record(lambda r: answer, body="lego", name="odd", configuration=1, n=1)
    assert "attempt 0" in str(caught.value) and "t = 0.00 s" in str(caught.value)


def test_a_command_the_body_cannot_execute_is_refused():
    with pytest.raises(PolicyError, match=r"'wheels' in attempt 0 .*t = 0\.00 s: command `forward` cannot drive the "
                                          r"humanoid body"):
        record(lambda r: "forward", body="humanoid", name="wheels", configuration=1, n=1)


def test_a_policy_that_hangs_is_interrupted_after_its_timeout():
    def hang(reading):
        if reading.t_s > 0.5:
            while True:
                pass
        return "forward"

    started = time.monotonic()
    with pytest.raises(PolicyError, match=r"'stuck' on the lego body did not answer within 0.2 s in attempt 0 .* at "
                                          r"t = 0\.53 s") as caught:
        record(hang, body="lego", name="stuck", configuration=1, n=1, timeout_s=0.2)
    assert isinstance(caught.value.__cause__, TimeoutError)
    assert time.monotonic() - started < 5.0, "interrupted within two timeouts, not left running"
    # Nothing pending is left to strike later: Python code running for several timeouts after
    # the recording ended (where a stray TimeoutError would land) runs to its end.
    ran_until = time.monotonic() + 0.6
    while time.monotonic() < ran_until:
        pass
    assert len(record(chase, body="lego", name="after", configuration=1, n=1, timeout_s=0.2)) == 1


@pytest.mark.parametrize(("kwargs", "error", "message"), [
    ({"body": "lego"}, ValueError, r"needs a name: record\(policy, name=\.\.\.\)"),
    ({"body": "lego", "name": "expert"}, ValueError, r"name 'expert' is a built-in demonstrator's"),
    ({"body": "lego", "name": "a/b"}, ValueError, r"a demonstrator's name must be a word .* got 'a/b'"),
    ({"body": "lego", "name": "average"}, ValueError, r"name 'average' is a built-in demonstrator's"),
    ({"name": "x"}, ValueError, r"needs its body: body= one of lego, tiny, humanoid or a polymimic.bodies.WheeledBody"),
    ({"name": "x", "body": "wheelie"}, ValueError, r"body must be one of .* got 'wheelie'"),
    ({"name": "x", "body": "lego", "decision_hz": 7}, ValueError, r"decision_hz must divide .* got 7"),
    ({"name": "x", "body": "lego", "decision_hz": 60}, ValueError, r"got 60"),
    ({"name": "x", "body": "lego", "lapse": 0.2}, ValueError, r"lapse= is for the built-in demonstrators"),
    ({"name": "x", "body": "lego", "timeout_s": 0}, ValueError, r"timeout_s must be between 0.001 s and 86400 s"),
    ({"name": "x", "body": "lego", "timeout_s": math.nan}, ValueError, r"timeout_s must be between .* got NaN"),
    ({"name": "x", "body": "lego", "timeout_s": 1e300}, ValueError, r"timeout_s must be between .* got 1e300"),
    ({"name": "x", "body": "lego", "timeout_s": "1"}, TypeError, r"timeout_s must be a number of seconds or None"),
])
def test_bad_policy_arguments_are_refused_by_name(kwargs, error, message):
    with pytest.raises(error, match=message):
        record(chase, configuration=1, n=1, **kwargs)


def test_neither_a_name_nor_a_policy_is_refused():
    with pytest.raises(TypeError, match=r"a built-in's name, a callable .* got 42"):
        record(42, body="lego", name="x", configuration=1, n=1)
    with pytest.raises(ValueError, match=r"the expert controller cannot drive the tiny body"):
        record("expert", body="tiny", configuration=1, n=1)
    with pytest.raises(ValueError, match=r"decision_hz= is for a Python policy; the built-in 'poor' decides every"):
        record("poor", decision_hz=10, configuration=1, n=1)
    with pytest.raises(ValueError, match=r"name 'expert' is another demonstrator's"):
        record("poor", name="expert", configuration=1, n=1)
    with pytest.raises(ValueError, match=r"unknown demonstrator 'expret'"):
        record("expret", configuration=1, n=1)


def test_wheel_speeds_drive_as_the_experts_named_pair_of_the_same_speeds():
    table = {row["name"]: row["id"] for row in polymimic.command_table()}
    named = record(lambda r: "arc_left_medium_fast", body="lego", name="named", configuration=1, n=2, seed=6)
    pairs = record(lambda r: (55.0, 100.0), body="lego", name="pairs", configuration=1, n=2, seed=6)
    for a, b in zip(named, pairs):
        for column in ("robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"):
            np.testing.assert_array_equal(a.frames[column], b.frames[column], err_msg=column)
        # Frames record wheel speeds by the primitive they resemble: an arc this wide is Forward.
        assert set(b.frames["command"]) == {table["wheels_forward"]}
        assert set(a.frames["command"]) == {table["arc_left_medium_fast"]}
    assert polymimic.field.command_primitives()[table["wheels_left"]] == "left"


def test_wheel_speeds_beyond_the_bodys_top_speed_are_refused():
    with pytest.raises(PolicyError, match=r"'fast' in attempt 0 .*: wheel speeds \(140, 140\) mm/s exceed the lego "
                                          r"body's top speed of 130 mm/s"):
        record(lambda r: [140, 140], body="lego", name="fast", configuration=1, n=1)
    with pytest.raises(PolicyError, match=r"'flag' .*command id 300 stands for wheel speeds"):
        record(lambda r: "wheels_forward", body="lego", name="flag", configuration=1, n=1)
    with pytest.raises(PolicyError, match=r"got \(1.0, 'a'\) \(tuple\)"):
        record(lambda r: (1.0, "a"), body="lego", name="half", configuration=1, n=1)


def test_a_policy_that_swallows_its_timeout_is_interrupted_again():
    def stubborn(reading):
        if reading.t_s > 0.2:
            while True:
                try:
                    while True:
                        pass
                except TimeoutError:
                    if reading.t_s > 1e9:  # never: it goes on after the first one
                        break
                    raise
        return "forward"

    with pytest.raises(PolicyError, match="did not answer within 0.1 s") as caught:
        record(stubborn, body="lego", name="stubborn", configuration=1, n=1, timeout_s=0.1)
    assert isinstance(caught.value.__cause__, TimeoutError)

    def swallows(reading):
        caught = 0
        while caught < 2:
            try:
                while True:
                    pass
            except TimeoutError:
                caught += 1
        raise RuntimeError(f"caught {caught} timeouts")

    with pytest.raises(PolicyError, match="did not answer within 0.1 s"):
        record(swallows, body="lego", name="swallows", configuration=1, n=1, timeout_s=0.1)


def test_ctrl_c_in_a_policy_is_not_the_policys_failure():
    def interrupted(reading):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        record(interrupted, body="lego", name="ctrl_c", configuration=1, n=1)


def test_no_limit_means_no_watchdog():
    assert len(record(chase, body="lego", name="unlimited", configuration=1, n=1, timeout_s=None)) == 1
