"""offline_rl's data, without d3rlpy: the outcome read off the frames against the outcome the
field recorded, and episodes whose actions are bco's labels of the same frames."""

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

import polymimic
from polymimic import recognition
from polymimic.baselines import bco
from polymimic.baselines.labels import NO_LABEL, Labelled
from polymimic.baselines.offline_data import ENDINGS, REWARDS, outcome_read, transitions
from polymimic.crowds import PROFILES, record_crowd


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    with threadpool_limits(limits=1):
        yield


@pytest.fixture(scope="module")
def crowd():
    return record_crowd(PROFILES["half"], n=2, seed=0)


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(40, seed=1), codebook_size=32)


def _ending(frames, ball_mm, robot_mm=None):
    """``frames`` with the last readings of the ball (and robot) moved."""
    moved = frames.copy()
    moved["ball_x_mm"][-1], moved["ball_y_mm"][-1] = ball_mm
    if robot_mm is not None:
        moved["robot_x_mm"][-1], moved["robot_y_mm"][-1] = robot_mm
    return moved


@pytest.mark.parametrize(("ball_mm", "robot_mm", "body", "outcome"), [
    ((510.4, 30.0), None, "lego", "goal"),            # past the target line, inside the 405 mm mouth
    ((509.3, -150.0), None, "lego", "goal"),          # within the tracker's tolerance of the line
    ((-510.2, 202.0), None, "lego", "own_goal"),      # the own goal, at the mouth's edge (202.5)
    ((510.3, 203.0), None, "lego", "ball_out"),       # past the line, outside the mouth
    ((0.0, -405.2), None, "lego", "ball_out"),        # over a side line
    ((400.0, 0.0), (-300.0, 405.3), "lego", "robot_out"),
    ((505.0, 0.0), None, "lego", "time_up"),          # short of the line: still in play
    ((280.4, 10.0), None, "tiny", "goal"),            # the tiny's 560 mm field
    ((290.0, 120.0), None, "tiny", "ball_out"),       # inside the Lego's mouth, outside the tiny's (86 mm)
])
def test_the_outcome_is_read_off_the_last_readings(crowd, ball_mm, robot_mm, body, outcome):
    frames = crowd[0].frames
    if robot_mm is None:
        robot_mm = (0.0, 0.0)
    assert outcome_read(_ending(frames, ball_mm, robot_mm), body=body) == outcome


def test_a_lost_last_reading_repeats_the_last_good_one(crowd):
    frames = _ending(crowd[0].frames, (510.5, 0.0), (0.0, 0.0))
    frames["ball_x_mm"][-1] = np.nan
    frames["ball_x_mm"][-2], frames["ball_y_mm"][-2] = -510.5, 0.0
    assert outcome_read(frames, body="lego") == "own_goal"
    frames["ball_x_mm"][:] = np.nan
    with pytest.raises(ValueError, match="never read the ball"):
        outcome_read(frames, body="lego")
    with pytest.raises(ValueError, match="frames is empty"):
        outcome_read(frames[:0], body="lego")


def test_the_outcomes_read_are_the_ones_the_field_recorded(crowd):
    assert {d.outcome for d in crowd} >= {"goal", "time_up"}  # both kinds are met
    assert [outcome_read(d.frames, body=d.body) for d in crowd] == [d.outcome for d in crowd]


def test_the_episodes_actions_are_bcos_labels_of_the_same_frames(crowd, recognizer):
    for labels in ("steps", "inverse_dynamics"):
        labelled = bco.labelled(crowd, recognizer=recognizer, labels=labels, max_samples=2000, seed=4)
        data = transitions(crowd, labelled)
        rows = [np.flatnonzero(item.labels != NO_LABEL) for item in labelled]
        kept = [len(r) > 1 or (len(r) == 1 and d.outcome in ENDINGS) for r, d in zip(rows, crowd)]
        expected = np.concatenate([item.labels[r] for item, r, k in zip(labelled, rows, kept) if k])
        assert data.actions.tolist() == expected.tolist()
        assert np.array_equal(data.observations,
                              np.concatenate([item.observations[r] for item, r, k in zip(labelled, rows, kept) if k]))


def test_each_episode_ends_in_its_outcomes_reward(crowd, recognizer):
    labelled = bco.labelled(crowd, recognizer=recognizer, labels="inverse_dynamics", max_samples=2000, seed=0)
    data = transitions(crowd, labelled)
    lasts = np.flatnonzero(data.terminals + data.timeouts)
    assert len(lasts) == len(data.outcomes) == len(crowd)
    assert data.rewards.tolist() == [REWARDS[data.outcomes[list(lasts).index(i)]] if i in lasts else 0.0
                                     for i in range(len(data.rewards))]
    goals = [i for i, o in zip(lasts, data.outcomes) if o == "goal"]
    assert goals and all(data.terminals[i] == 1.0 and data.rewards[i] == 1.0 for i in goals)
    assert all(data.timeouts[i] == 1.0 for i, o in zip(lasts, data.outcomes) if o == "time_up")


def test_transitions_refuse_labels_of_other_demonstrations(crowd):
    own = Labelled("someone", np.zeros((len(crowd[0].frames), 5)), np.zeros(len(crowd[0].frames), dtype=np.int64))
    with pytest.raises(ValueError, match=r"labelled\[0\] is 'someone'"):
        transitions(crowd[:1], [own])
    with pytest.raises(ValueError, match="one item per demonstration"):
        transitions(crowd[:2], [own])
    unlabelled = Labelled(crowd[0].demonstrator, own.observations, np.full(len(own.labels), NO_LABEL))
    with pytest.raises(ValueError, match="no episode to learn from"):
        transitions(crowd[:1], [unlabelled])
