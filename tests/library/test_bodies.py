"""Bodies as data: wheeled robots of the user's own, and the thesis's two as entries of a table."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest

import polymimic
from polymimic import record
from polymimic._toml import loads
from polymimic.bodies import THESIS_BODIES, Slip, WheeledBody, as_body, bodies_by_name, bodies_from_tables
from polymimic.datasets import load_demonstrations, save_demonstrations
from polymimic.field import check_config

NOISELESS = json.dumps(check_config({"tracker": {"position_sigma_mm": 0.0, "heading_sigma_rad": 0.0,
                                                 "spike_probability": 0.0, "loss_probability": 0.0}}))


def test_the_thesis_bodies_as_data_are_those_bodies_bit_for_bit():
    for name, demonstrator in (("lego", "poor"), ("tiny", "tiny"), ("lego", "expert")):
        copy = dataclasses.replace(THESIS_BODIES[name], name=f"{name}_as_data")
        ours = record(demonstrator, body=copy, configuration=2, n=2, seed=3)
        theirs = record(demonstrator, configuration=2, n=2, seed=3)
        assert [d.seed for d in ours] == [d.seed for d in theirs]
        for a, b in zip(ours, theirs):
            assert a.body.name == f"{name}_as_data" and b.body.name == name
            assert a.frames.tobytes() == b.frames.tobytes()


def test_the_thesis_bodies_hold_the_calibrated_constants():
    lego, tiny = THESIS_BODIES["lego"], THESIS_BODIES["tiny"]
    assert (lego.length_mm, lego.width_mm, lego.wheel_base_mm, lego.top_wheel_speed_mm_s) == (140, 150, 175, 130)
    assert lego.primitives_mm_s["forward"] == (51.55, 47.86) and lego.slip_of("backward") == Slip(0.248, 0.343)
    assert (tiny.field, tiny.wheel_base_mm, tiny.expert_commands) == ("small", 12, False)
    assert (as_body("lego").field.length_mm, as_body("tiny").field.length_mm) == (1020.0, 560.0)


def test_a_new_body_drives_as_its_constants_say():
    """Without slip or tracker noise, one second of Forward from rest covers what the field's
    integrator gives for a first-order lag: N substeps of dt, the speed after substep k being
    v(1 − aᵏ) with a = e^(−dt/τ), so v·dt·(N − a(1 − aᴺ)/(1 − a)) (v·(T − τ(1 − e^(−T/τ)))
    as dt → 0)."""
    top, lag = 150.0, 0.1
    body = WheeledBody("sprinter", length_mm=100, width_mm=100, wheel_base_mm=90, top_wheel_speed_mm_s=top,
                       motor_lag_s=lag, slip=Slip(0.0, 0.0))
    episode = polymimic.Episode(body, configuration=None, config=NOISELESS)
    frames, _ = episode.run(["forward"] * 30)
    speed = 0.4 * top
    expected_mm = speed * _lagged_seconds(lag)
    # The 31st reading (after 30 frames of driving) is where the robot stands at 1 s.
    end = episode.observation()["robot"]
    assert end[0] - frames[0, 1] == pytest.approx(expected_mm, rel=1e-9)
    assert abs(end[1]) < 1e-9 and abs(end[2]) < 1e-12
    # A left spin turns counter-clockwise at (2 · 0.35 · top / wheel base) rad/s once the lag settles.
    spin = polymimic.Episode(body, configuration=None, config=NOISELESS)
    spin.run(["left"] * 30)
    rate = 2 * 0.35 * top / 90
    assert spin.observation()["robot"][2] == pytest.approx(rate * _lagged_seconds(0.03), rel=1e-9)


def _lagged_seconds(lag_s: float, substeps: int = 240) -> float:
    """Seconds of full speed a first-order lag delivers over one second from rest."""
    dt = 1.0 / substeps
    a = math.exp(-dt / lag_s)
    return dt * (substeps - a * (1 - a**substeps) / (1 - a))


def test_python_policies_and_built_in_controllers_drive_a_new_body(tmp_path):
    rover = WheeledBody("rover_test", length_mm=200, width_mm=180, wheel_base_mm=160, top_wheel_speed_mm_s=150)
    mine = record(lambda r: "forward", body=rover, name="straight", configuration=1, n=2, seed=1)
    poor = record("poor", body=rover, name="poor_rover", configuration=2, n=2, seed=1)
    assert {(d.demonstrator, d.body.name) for d in mine + poor} == {("straight", "rover_test"),
                                                                    ("poor_rover", "rover_test")}
    save_demonstrations(mine + poor, tmp_path / "rover.parquet")
    assert [d.body for d in load_demonstrations(tmp_path / "rover.parquet", bodies=[rover])] == [as_body(rover)] * 4
    assert as_body(rover).field == as_body("lego").field
    with pytest.raises(ValueError, match="the expert controller cannot drive the rover_test body"):
        record("expert", body=rover, configuration=1, n=1)


def test_a_small_field_body_plays_on_the_small_field():
    mouse = WheeledBody("mouse", length_mm=20, width_mm=20, wheel_base_mm=16, top_wheel_speed_mm_s=40, field="small")
    demo = record("tiny", body=mouse, configuration=1, n=1, seed=2)[0]
    assert np.nanmax(np.abs(demo.frames["robot_x_mm"])) <= 280.0 + 1e-6
    assert polymimic.Episode(mouse).observation()["field"] == (560.0, 345.0)


def test_bodies_read_from_toml_tables():
    text = """
[bodies.trolley]
length_mm = 90
width_mm = 80
wheel_base_mm = 70
top_wheel_speed_mm_s = 60
motor_lag_s = 0.08
field = "small"
slip = { common_sd = 0.1, differential_sd = 0.02 }
primitives_mm_s = { forward = [30, 28] }

[bodies.skid]
length_mm = 120
width_mm = 120
wheel_base_mm = 100
top_wheel_speed_mm_s = 140
expert_commands = true
[bodies.skid.slip]
forward = { common_sd = 0.1, differential_sd = 0.01 }
backward = { common_sd = 0.3, differential_sd = 0.3 }
left = { common_sd = 0.5, differential_sd = 0.05 }
right = { common_sd = 0.5, differential_sd = 0.05 }
stop = { common_sd = 0.0, differential_sd = 0.0 }
"""
    bodies = bodies_from_tables(loads(text)["bodies"])
    cart, skid = bodies["trolley"], bodies["skid"]
    assert cart.primitives_mm_s["forward"] == (30.0, 28.0) and cart.primitives_mm_s["backward"] == (-24.0, -24.0)
    assert cart.slip == Slip(0.1, 0.02) and cart.field == "small" and cart.motor_lag_s == 0.08
    assert skid.slip_of("backward") == Slip(0.3, 0.3) and skid.expert_commands
    assert len(record("expert", body=skid, configuration=1, n=1, seed=0)) == 1


@pytest.mark.parametrize(("table", "message"), [
    ({"width_mm": 80, "wheel_base_mm": 70, "top_wheel_speed_mm_s": 60}, r"missing 1 required .*'length_mm'"),
    ({"length_mm": -5}, r"length_mm must be a positive number, got -5"),
    ({"wheel_base_mm": 0}, r"wheel_base_mm must be a positive number, got 0"),
    ({"top_wheel_speed_mm_s": math.inf}, r"top_wheel_speed_mm_s must be a positive number, got inf"),
    ({"motor_lag_s": "fast"}, r"motor_lag_s must be a positive number, got 'fast'"),
    ({"colour": "red"}, r"unknown key 'colour'; known keys: length_mm"),
    ({"field": "huge"}, r"field must be one of large, small or a polymimic.bodies.Field, got 'huge'"),
    ({"field": {"length_mm": 900}}, r"missing 1 required positional argument: 'width_mm'"),
    ({"field": {"length_mm": 900, "width_mm": 600, "goal_mouth_mm": 700}},
     r"field.goal_mouth_mm must be a positive number at most 600, got 700"),
    ({"field": {"length_mm": 900, "width_mm": 600, "ball_diameter_mm": 400}},
     r"field.ball_diameter_mm must be a positive number at most 300, got 400"),
    ({"field": {"length_mm": 900, "width_mm": 600, "goals": 2}}, r"unknown key field.'goals'"),
    ({"primitives_mm_s": {"forward": [100, 30]}}, r"primitives_mm_s.forward must be a number in \[-60, 60\], got 100"),
    ({"primitives_mm_s": {"jump": [1, 1]}}, r"unknown key primitives_mm_s.jump"),
    ({"primitives_mm_s": {"stop": [1, 0]}}, r"primitives_mm_s.stop must be \(0, 0\)"),
    ({"primitives_mm_s": {"left": [1]}}, r"primitives_mm_s.left must be a \(left, right\) pair"),
    ({"primitives_mm_s": {"forward": [20, 20], "backward": [20, 20]}},
     r"primitives_mm_s.forward and primitives_mm_s.backward are both \(20.0, 20.0\): a recogniser cannot tell them"),
    ({"primitives_mm_s": {"right": [0, 0]}}, r"primitives_mm_s.right and primitives_mm_s.stop are both \(0.0, 0.0\)"),
    ({"slip": {"common_sd": -0.1, "differential_sd": 0.0}}, r"slip.common_sd must be a number in \[0, 10\]"),
    ({"slip": {"common": 0.1}}, r"unknown key slip.'common'"),
    ({"slip": {"forward": {"common_sd": 0.1, "differential_sd": 0.0}}}, r"slip by primitive lacks backward"),
    ({"expert_commands": True}, r"expert_commands needs a top_wheel_speed_mm_s of at least 130"),
    ({"fresh_slip_frames": 0}, r"fresh_slip_frames must be a whole number ≥ 1, got 0"),
])
def test_bad_body_tables_are_refused_naming_the_table_and_key(table, message):
    base = {"length_mm": 90, "width_mm": 80, "wheel_base_mm": 70, "top_wheel_speed_mm_s": 60}
    if "length_mm" not in table and "width_mm" in table:
        base = {}
    with pytest.raises(ValueError, match=r"\[bodies.bad\]: .*" + message):
        WheeledBody.from_table("bad", {**base, **table})


def test_a_name_is_no_body_and_the_thesis_names_are_the_thesis_bodies():
    twin = WheeledBody("twin", length_mm=50, width_mm=50, wheel_base_mm=40, top_wheel_speed_mm_s=50)
    small = WheeledBody("twin", length_mm=50, width_mm=50, wheel_base_mm=40, top_wheel_speed_mm_s=50, field="small")
    assert (as_body(twin).field.length_mm, as_body(small).field.length_mm) == (1020.0, 560.0), "each is itself"
    with pytest.raises(ValueError, match="bodies: two bodies are named 'twin', with other constants"):
        bodies_by_name([twin, small])
    assert bodies_by_name([twin, dataclasses.replace(twin), polymimic.Body(twin)]) == {"twin": as_body(twin)}
    assert dataclasses.replace(THESIS_BODIES["lego"]) == THESIS_BODIES["lego"]
    with pytest.raises(ValueError, match="body 'lego' is already described with other constants"):
        dataclasses.replace(THESIS_BODIES["lego"], wheel_base_mm=100)
    with pytest.raises(ValueError, match="body name 'humanoid' is the thesis's"):
        WheeledBody("humanoid", length_mm=50, width_mm=50, wheel_base_mm=40, top_wheel_speed_mm_s=50)
    with pytest.raises(ValueError, match="a body's name must be a word"):
        WheeledBody("my bot", length_mm=50, width_mm=50, wheel_base_mm=40, top_wheel_speed_mm_s=50)
    with pytest.raises(ValueError, match='unknown body "never_made": the built-in bodies are lego, tiny, humanoid; '
                                         'describe a body of your own'):
        as_body("never_made")
    with pytest.raises(ValueError, match='unknown body "twin"'):
        as_body("twin")  # made above, and still only a name


def test_a_field_of_ones_own_sets_where_the_goals_are():
    """On a 1500 × 1000 mm field with a 300 mm mouth, a kick that scores on the thesis's large
    field goes wide when it crosses more than 150 mm off the centre line."""
    from polymimic.bodies import Field

    pitch = Field(1500, 1000, goal_mouth_mm=300, ball_diameter_mm=80)
    wide = WheeledBody("wide_field_rover", length_mm=150, width_mm=150, wheel_base_mm=130,
                       top_wheel_speed_mm_s=150, field=pitch)
    seen = polymimic.Episode(wide).observation()
    assert (seen["field"], seen["goal_mouth_mm"], seen["ball_diameter_mm"]) == ((1500.0, 1000.0), 300.0, 80.0)
    # Configuration 1 puts the robot a sixth of the length behind the centre, the ball a sixth ahead.
    assert seen["robot"][0] == pytest.approx(-250.0, abs=2) and seen["ball"][0] == pytest.approx(250.0, abs=2)
    demos = record("poor", body=wide, configuration=1, n=3, seed=1)
    for d in demos:
        last = d.frames[-1]
        if d.outcome == "goal":
            assert last["ball_x_mm"] > 750 - 5 and abs(last["ball_y_mm"]) <= 150 + 5
    assert as_body(wide).field == pitch
    assert WheeledBody.from_table("wide_field_rover", wide.to_table()) == wide


def test_the_learner_reads_a_field_of_ones_own():
    from polymimic import recognition
    from polymimic.bodies import Field
    from polymimic.learning import segmented

    small_goals = WheeledBody("small_goals", length_mm=150, width_mm=150, wheel_base_mm=130,
                              top_wheel_speed_mm_s=150, field=Field(1200, 900, goal_mouth_mm=250))
    recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=16)
    batch = segmented(record("poor", body=small_goals, configuration=1, n=2, seed=0), recognizer)
    assert batch.pitches == ['{"length_mm": 1200.0, "width_mm": 900.0, "goal_mouth_mm": 250.0}'] * 2
    again = polymimic.SegmentedDemonstrations([batch[0]])
    assert again.pitches == batch.pitches[:1]
    bad = dict(batch[0], pitch='{"length_mm": 1200.0, "width_mm": 900.0, "goal_mouth_mm": 1000.0}')
    with pytest.raises(ValueError, match="pitch .* is not one of 'large', 'small' nor a field's sizes as JSON"):
        polymimic.SegmentedDemonstrations([bad])
