"""Practice: the imitator plays from seeds of its own, learns from what the tracker showed, and
its curve, file and errors say what happened."""

import json

import numpy as np
import pytest

import polymimic
from polymimic import learning, recognition
from polymimic._native import attempt_seeds
from polymimic.practice import PRACTICE_SEED_BASE, curve_csv, practice, round_seed, steps_of
from polymimic.practice.seeds import check_apart

SMALL = {"attempts_per_round": 3, "evaluation": polymimic.Attempts(per_configuration=3)}


def _policy(body, demonstrators):
    recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1, body=body), codebook_size=32)
    demos = [d for who in demonstrators for c in (1, 2) for d in polymimic.record(who, configuration=c, n=3, seed=0)]
    batch = learning.segmented(demos, recognizer)
    trial = learning.run_trial(batch, recognizer=recognizer, ordering=list(demonstrators), seed=0, body=body)
    return learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch, body=body)


@pytest.fixture(scope="module")
def lego():
    return _policy("lego", ("expert",))


@pytest.fixture(scope="module")
def practised(lego):
    return practice(lego, steps=400, checkpoints=[0, 200, 400], seed=5, **SMALL)


def _frames(evaluation):
    return [a.frames.tobytes() for a in evaluation.attempts]


def test_zero_steps_is_the_policy_as_it_was_bit_for_bit(lego):
    result = practice(lego, steps=0, **SMALL)
    assert result.steps == 0 and result.attempts == [] and [p.checkpoint for p in result.curve] == [0]
    assert result.policy is lego
    before = learning.evaluate(lego, attempts_per_configuration=3)
    assert result.curve[0].net_goals == before.goals - before.own_goals


def test_practice_stays_within_its_checkpoints_and_learns_its_own_attempts(practised):
    assert [p.checkpoint for p in practised.curve] == [0, 200, 400]
    for point in practised.curve:
        assert point.steps <= point.checkpoint
    # Within one attempt (at most 60 s) of each checkpoint.
    assert practised.curve[-1].steps > 400 - 61
    assert sum(steps_of(a) for a in practised.attempts) <= practised.steps
    assert practised.curve[-1].attempts_learned == len(practised.attempts) > 0
    assert all(a.demonstrator == "imitator" and a.body.name == "lego" for a in practised.attempts)
    assert practised.policy.made_from.practice is not None and len(practised.policy.made_from.practice) == len(
        practised.attempts)


def test_by_default_it_explores_around_the_ball_and_learns_physics_alone(lego, practised):
    """The first round is the exploring play of the policy as it was, cut where the tracker
    shows the field left; only the ball's response learns from it."""
    from polymimic.practice.exploring import EXPLORE_RATE, explored_attempts

    explored = explored_attempts(lego, attempts_per_configuration=3, seed=round_seed(5, 0), epsilon=EXPLORE_RATE)
    plain = learning.evaluate(lego, attempts_per_configuration=3, seed=round_seed(5, 0)).attempts
    by_seed = {a.seed: a for a in practised.attempts}  # the tracker may have lost some: left out
    first = [(by_seed[e.seed], e, p) for e, p in zip(explored, plain) if e.seed in by_seed]
    assert len(first) >= 3  # the round ends where its next attempt would pass the checkpoint
    assert all(a.frames.tobytes() == e.frames[:len(a.frames)].tobytes() for a, e, _ in first)
    assert any(a.frames.tobytes() != p.frames[:len(a.frames)].tobytes() for a, _, p in first)
    assert practised.policy.made_from.practice_refines == ("ball_response",)


def test_replaying_its_own_play_learns_the_states_values_too(lego):
    """``explore=0, refines=None``: the first round is the policy's own play, as evaluate plays it."""
    replayed = practice(lego, steps=200, checkpoints=[0, 200], seed=5, explore=0, refines=None, **SMALL)
    plain = {a.seed: a for a in learning.evaluate(lego, attempts_per_configuration=3, seed=round_seed(5, 0)).attempts}
    first = [(a, plain[a.seed]) for a in replayed.attempts if a.seed in plain]
    assert len(first) >= 3
    assert all(a.frames.tobytes() == p.frames[:len(a.frames)].tobytes() for a, p in first)
    assert replayed.policy.made_from.practice_refines is None


def test_own_attempts_outcomes_are_read_off_the_frames(practised):
    from polymimic.bodies import as_body
    from polymimic.tracks.outcomes import outcome_of

    for attempt in practised.attempts:
        assert outcome_of(attempt.frames, as_body("lego").field) == (attempt.outcome, len(attempt.frames))


def test_practice_seeds_never_meet_the_evaluations(practised):
    assert round_seed(0, 0) == PRACTICE_SEED_BASE and round_seed(2**62 - 1, 2**24 - 1) < 2**64
    scored = set(attempt_seeds(25, seed=0)) | set(attempt_seeds(3, seed=0))
    assert not {(a.configuration, a.seed) for a in practised.attempts} & scored
    # The check itself refuses a practice attempt that is the evaluation's.
    with pytest.raises(ValueError, match="evaluation's attempt"):
        check_apart([attempt_seeds(3, seed=0)[1]], evaluation=polymimic.Attempts(per_configuration=3, seed=0))


def test_same_seed_same_bits(lego, practised):
    again = practice(lego, steps=400, checkpoints=[0, 200, 400], seed=5, **SMALL)
    assert again.curve == practised.curve
    assert [a.frames.tobytes() for a in again.attempts] == [a.frames.tobytes() for a in practised.attempts]
    other = practice(lego, steps=200, checkpoints=[0, 200], seed=6, **SMALL)
    assert [a.seed for a in other.attempts] != [a.seed for a in practised.attempts][: len(other.attempts)]


def test_a_practised_policy_saves_and_plays_the_same(practised, tmp_path):
    path = tmp_path / "practised.zip"
    practised.policy.save(path)
    again = learning.ImitatorPolicy.load(path)
    assert again.made_from.practice is not None
    a = learning.evaluate(practised.policy, attempts_per_configuration=2, seed=9)
    b = learning.evaluate(again, attempts_per_configuration=2, seed=9)
    assert _frames(a) == _frames(b)


def test_the_curve_as_csv_and_json(practised, tmp_path):
    from polymimic.practice import write_curve

    text = curve_csv(practised.curve)
    header, *rows = text.splitlines()
    assert header == "checkpoint,steps,net_goals,goals,own_goals,attempts_learned,attempts_lost"
    assert [int(r.split(",")[0]) for r in rows] == [0, 200, 400]
    write_curve(tmp_path, practised.curve, seed=5, body="lego")
    data = json.loads((tmp_path / "practice_curve.json").read_text())
    assert data["seed"] == 5 and data["points"][2]["checkpoint"] == 400
    assert set(data["points"][0]) == {"checkpoint", "steps", "net_goals", "goals", "own_goals", "attempts_learned",
                                      "attempts_lost"}
    assert (tmp_path / "practice_curve.csv").read_text() == text


def test_any_imitator_body_practises():
    tiny = _policy("tiny", ("tiny",))
    result = practice(tiny, steps=150, checkpoints=[0, 150], **SMALL)
    assert result.attempts and all(a.body.name == "tiny" for a in result.attempts)
    assert result.policy.body.name == "tiny"


@pytest.mark.parametrize(("arguments", "message"), [
    ({"steps": -1}, "steps must be an integer of at least 0, got -1"),
    ({"steps": 10.5}, "steps must be an integer of at least 0, got 10.5"),
    ({"steps": True}, "steps must be an integer of at least 0, got True"),
    ({"steps": 100, "checkpoints": [0, 50, 20]}, r"checkpoints must rise, got \[0, 50, 20\]"),
    ({"steps": 100, "checkpoints": [10, 50]}, "checkpoints must start at 0"),
    ({"steps": 100, "checkpoints": [0, 200]}, "checkpoint 200 lies beyond the budget of 100 steps"),
    ({"steps": 100, "attempts_per_round": 0}, "attempts_per_round must be an integer of at least 1"),
    ({"steps": 100, "explore": 1.5}, r"explore must be a number in \[0, 1\], got 1.5"),
    ({"steps": 100, "explore": -0.1}, r"explore must be a number in \[0, 1\], got -0.1"),
    ({"steps": 100, "explore": True}, r"explore must be a number in \[0, 1\], got True"),
    ({"steps": 100, "explore": "0.3"}, r"explore must be a number in \[0, 1\], got '0.3'"),
    ({"steps": 100, "evaluation": polymimic.Attempts(starts=[1])},
     r"evaluation must be attempts from the thesis's configurations, got starts=\(1,\)"),
])
def test_bad_arguments_are_named(lego, arguments, message):
    with pytest.raises(ValueError, match=message):
        practice(lego, **arguments)


def test_the_evaluation_is_one_attempts_value(lego):
    with pytest.raises(TypeError, match="evaluation must be a polymimic.Attempts, got int"):
        practice(lego, steps=10, evaluation=25)


def test_policies_practice_cannot_refine_are_refused(lego):
    thesis = learning.ImitatorPolicy(lego.made_from.trial, recognizer=lego.made_from.recognizer)
    with pytest.raises(ValueError, match="control='improved'"):
        practice(thesis, steps=10)
    with pytest.raises(ValueError, match="made with its constructor"):
        practice(lego.for_trial(lego.made_from.trial), steps=10)
    with pytest.raises(ValueError, match="made with its constructor"):
        practice("expert", steps=10)


def test_the_default_checkpoints_end_at_the_budget(lego):
    from polymimic.practice.loop import _checkpoints

    assert _checkpoints(None, 25_000) == [0, 1_000, 2_500, 5_000, 10_000, 25_000]
    assert _checkpoints(None, 3_000) == [0, 1_000, 2_500, 3_000]
    assert _checkpoints(None, 0) == [0]
    assert np.all(np.diff(_checkpoints(None, 50_000)) > 0)
