"""A trained imitator stepped one tracker reading at a time plays exactly what ``evaluate``
plays; starts of one's own are played and refused by name; an imitator demonstrates."""

import math

import numpy as np
import pytest

import polymimic
from polymimic import recognition
from polymimic.learning import ImitatorPolicy, evaluate, run_trial


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)


@pytest.fixture(scope="module")
def watched():
    return [d for c in (1, 2) for name in ("expert", "poor") for d in polymimic.record(name, configuration=c, n=3,
                                                                                        seed=4)]


@pytest.fixture(scope="module", params=["thesis", "improved"])
def policy(request, recognizer, watched):
    trial = run_trial(watched, recognizer=recognizer, ordering=["expert", "poor"])
    return ImitatorPolicy(trial, recognizer=recognizer, control=request.param, demonstrations=watched)


def _played_by_stepping(player, body, start, seed, *, as_reading):
    """The player driving a fresh episode from ``start`` one tracker reading at a time."""
    player.reset(start=start, seed=seed)
    episode = polymimic.Episode(body, start=start, seed=seed)
    while not episode.finished:
        seen = episode.observation()
        ball = seen["ball"] if seen["ball"] is not None else (math.nan, math.nan)
        reading = np.array([seen["t_s"], *seen["robot"], *ball], dtype=np.float64)
        episode.step(player.act(reading if as_reading == "array" else tuple(reading.tolist())))
    return episode


def test_stepping_the_player_through_the_field_is_evaluate_frame_for_frame_bit_for_bit(policy):
    played = policy.evaluate(4, seed=11)
    player = policy.player()
    outcomes = set()
    for attempt, kind in zip(played, ["array", "tuple"] * 4):
        episode = _played_by_stepping(player, policy.body, attempt["configuration"], attempt["seed"], as_reading=kind)
        assert episode.frames.tobytes() == attempt["frames"].tobytes()
        assert episode.outcome == attempt["outcome"]
        assert player.executed == attempt["behaviours"]
        outcomes.add(attempt["outcome"])
    assert len(played) == 8


def test_a_chosen_start_is_played_by_evaluate_and_by_the_stepped_player_alike(policy):
    start = {"robot": (-100.0, 150.0, 0.5), "ball": (120.0, -60.0)}
    played = policy.evaluate(2, seed=3, starts=[start, 2])
    assert [a["configuration"] for a in played] == [None, None, 2, 2]
    assert played[0]["start"] == {"configuration": None, "robot": (-100.0, 150.0, 0.5), "ball": (120.0, -60.0)}
    # The named configuration keeps evaluate's own seeds whatever else is listed.
    assert [a["seed"] for a in played[2:]] == [a["seed"] for a in policy.evaluate(2, seed=3)[2:]]
    player = policy.player()
    for attempt in played[:2]:
        episode = _played_by_stepping(player, policy.body, start, attempt["seed"], as_reading="array")
        assert episode.frames.tobytes() == attempt["frames"].tobytes()
        first = attempt["frames"][0]
        assert abs(first[1] - -100.0) < 5 and abs(first[4] - 120.0) < 5, "the tracker sees the chosen start"


@pytest.mark.parametrize(("start", "match"), [
    ({"robot": (900.0, 0.0, 0.0), "ball": (0.0, 0.0)}, r"robot at \(900\.0, 0\.0\) mm is outside the field"),
    ({"robot": (0.0, 0.0, 0.0), "ball": (0.0, 999.0)}, r"ball at \(0\.0, 999\.0\) mm is outside the field"),
    ({"robot": (0.0, 0.0, 0.0), "ball": (60.0, 0.0)}, r"overlaps the lego robot by 50\.0 mm"),
    ({"robot": (0.0, 0.0), "ball": (300.0, 0.0)}, r"'robot' must be 3 numbers"),
    ({"robot": (0.0, 0.0, 0.0)}, r"a start needs 'ball'"),
    ({"robot": (0.0, 0.0, 0.0), "ball": (300.0, 0.0), "heading": 1}, r"unknown key 'heading'"),
    (3, r"configuration must be 1 or 2"),
])
def test_a_start_off_the_field_on_the_robot_or_misspelt_is_refused_by_name(recognizer, watched, start, match):
    trial = run_trial(watched, recognizer=recognizer, ordering=["expert", "poor"])
    policy = ImitatorPolicy(trial, recognizer=recognizer)
    with pytest.raises(ValueError, match=match):
        evaluate(policy, attempts_per_configuration=1, starts=[start])
    with pytest.raises(ValueError, match=match):
        policy.player().reset(start=start)
    with pytest.raises(ValueError, match=match):
        polymimic.Episode("lego", start=start)


def test_a_reading_that_is_not_one_is_a_type_error_and_act_before_reset_says_so(policy):
    player = policy.player()
    with pytest.raises(polymimic.FieldRunError, match=r"call reset\(\) first"):
        player.act((0.0, 0.0, 0.0, 0.0, 100.0, 0.0))
    player.reset(start=1, seed=0)
    for bad in ["forward", (0.0, 1.0), (True, 0.0, 0.0, 0.0, 0.0, 0.0), None]:
        with pytest.raises(TypeError, match="a reading is a polymimic.Reading or six numbers"):
            player.act(bad)
    with pytest.raises(ValueError, match="a reading's time must be a finite number"):
        player.act((math.nan, 0.0, 0.0, 0.0, 100.0, 0.0))


def test_a_primitive_is_held_for_a_second_and_a_lost_reading_stands_on_the_last_good_one(policy):
    player = policy.player()
    player.reset(start=1, seed=0)
    first = player.act((0.0, -170.0, 0.0, 0.0, 170.0, 0.0))
    # Readings within the second hold the command, whatever they show; the robot lost
    # (NaN) at the next decision is read where it last was.
    held = [player.act((k / 30, math.nan, math.nan, math.nan, math.nan, math.nan)) for k in range(1, 30)]
    assert held == [first] * 29
    decisions = len(player.executed)
    player.act((1.0, math.nan, math.nan, math.nan, math.nan, math.nan))
    assert len(player.executed) >= decisions


def test_an_imitator_demonstrates_and_another_learns_from_it(recognizer, policy):
    shown = polymimic.record(policy, configuration=1, n=2, seed=5)
    assert [(d.demonstrator, d.body.name, d.configuration) for d in shown] == [("imitator", "lego", 1)] * 2
    # The same episodes as its player recorded through the Python-policy path.
    again = polymimic.record(policy.player(), configuration=1, n=2, seed=5, body="lego", name="player")
    assert [d.frames.tobytes() for d in shown] == [d.frames.tobytes() for d in again]
    named = polymimic.record(policy, configuration=2, n=1, seed=5, name="teacher")
    assert named[0].demonstrator == "teacher"
    with pytest.raises(ValueError, match="the imitator drives the 'lego' body"):
        polymimic.record(policy, configuration=1, n=1, body="tiny")
    with pytest.raises(ValueError, match="lapse= is for the built-in demonstrators"):
        polymimic.record(policy, configuration=1, n=1, lapse=0.5)
    tiny_recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1, body="tiny"),
                                                   codebook_size=32)
    both = shown + polymimic.record(policy, configuration=2, n=2, seed=5)
    trial = run_trial(both, recognizer=tiny_recognizer, ordering=["imitator"], body="tiny")
    assert len(trial.imitator.behaviours) > 0
