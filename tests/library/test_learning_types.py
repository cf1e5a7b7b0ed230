"""The typed learning boundary: the config and a segmented batch refuse bad values by name, and
round-trip."""

import pickle

import numpy as np
import pytest

import polymimic

OUTCOMES = "'goal', 'own_goal', 'ball_out', 'robot_out', 'time_up'"

# The learning config.

def test_config_attributes_are_the_defaults_and_read_only():
    config = polymimic.LearningConfig()
    assert (config.creation_threshold, config.ball_min_samples, config.lp_scope) == (0.3, 5, "own_demonstrator")
    with pytest.raises(AttributeError):
        config.decay_step = 0.1  # type: ignore[misc]


def test_config_to_dict_lists_every_constant_in_order_with_python_types():
    values = polymimic.LearningConfig().to_dict()
    assert list(values)[:3] == ["creation_threshold", "default_permanency", "permanency_threshold"]
    assert list(values)[-4:] == ["lp_bounds", "lp_scope", "lp_criteria", "lp_approach_weight"]
    assert len(values) == 26
    assert type(values["deletion_threshold"]) is float and values["deletion_threshold"] == 0.0
    assert type(values["ball_min_samples"]) is int
    assert polymimic.LearningConfig(**values) == polymimic.LearningConfig()


def test_config_replace_changes_only_what_it_is_given_and_checks_again():
    base = polymimic.LearningConfig(permanency_step=0.03)
    changed = base.replace(lp_bounds="clamp", ball_min_samples=8)
    assert type(changed) is polymimic.LearningConfig
    assert (changed.permanency_step, changed.lp_bounds, changed.ball_min_samples) == (0.03, "clamp", 8)
    assert base.lp_bounds == "soft"
    with pytest.raises(ValueError, match="config: initial_lp = 2 must be in"):
        base.replace(initial_lp=2)


def test_config_pickles_compares_and_hashes_by_value():
    config = polymimic.LearningConfig(decay_step=0.01, lp_criteria="both")
    again = pickle.loads(pickle.dumps(config))
    assert again == config and type(again) is polymimic.LearningConfig
    assert hash(again) == hash(config)
    assert config != polymimic.LearningConfig()
    assert repr(config).startswith("LearningConfig(creation_threshold=0.3, ")
    assert "decay_step=0.01" in repr(config) and "lp_criteria='both'" in repr(config)


@pytest.mark.parametrize("change, error, match", [
    (dict(speed=3), TypeError, "no constant 'speed'; the constants are creation_threshold, default_permanency"),
    (dict(lp_bounds="hard"), ValueError, 'lp_bounds must be "soft" or "clamp", got "hard"'),
    (dict(decay_step="fast"), TypeError, "decay_step must be a number, got 'fast'"),
    (dict(decay_step=True), TypeError, "decay_step must be a number, got True"),
    (dict(ball_min_samples=2.5), TypeError, "ball_min_samples must be a whole number, got 2.5"),
    (dict(ball_min_samples=-1), ValueError, "ball_min_samples = -1 must be ≥ 0"),
    (dict(initial_lp=float("nan")), ValueError, "initial_lp = NaN must be in"),
])
def test_bad_config_values_are_named(change, error, match):
    with pytest.raises(error, match=match):
        polymimic.LearningConfig(**change)


# Segmented demonstrations.

def _item(**changes):
    segments = {"label": ["forward", "gap"], "first_frame": np.array([0, 9]), "last_frame": np.array([9, 20]),
                "start": np.zeros((2, 5)), "end": np.ones((2, 5)), "scores": np.full((2, 4), -3.0)}
    segments.update(changes.pop("segments", {}))
    return {"demonstrator": "expert", "outcome": "goal", "segments": segments, "pitch": "large", **changes}


def test_a_batch_gives_back_what_it_was_given():
    batch = polymimic.SegmentedDemonstrations([_item(), _item(demonstrator="tiny", pitch="small", outcome="time_up")])
    assert len(batch) == 2
    assert (batch.demonstrators, batch.outcomes, batch.pitches) == (
        ["expert", "tiny"], ["goal", "time_up"], ["large", "small"])
    first = batch[0]
    assert list(first) == ["demonstrator", "outcome", "segments", "pitch"]
    assert first["segments"]["label"] == ["forward", "gap"]
    assert first["segments"]["first_frame"].dtype == np.int64
    assert (first["segments"]["end"] == 1.0).all() and (first["segments"]["scores"] == -3.0).all()
    assert batch[-1]["demonstrator"] == "tiny"
    with pytest.raises(IndexError):
        batch[2]
    assert [d["pitch"] for d in batch] == ["large", "small"]


def test_batches_add_concatenate_and_pickle():
    one = polymimic.SegmentedDemonstrations([_item()])
    two = polymimic.SegmentedDemonstrations([_item(outcome="own_goal")])
    assert (one + two).outcomes == ["goal", "own_goal"]
    assert polymimic.SegmentedDemonstrations.concat([one, two, one]).outcomes == ["goal", "own_goal", "goal"]
    both = one + two
    assert pickle.loads(pickle.dumps(both)) == both
    assert both != one


@pytest.mark.parametrize("item, error, match", [
    (_item(outcome="own-goal"), ValueError, f"demonstration 0: outcome 'own-goal' is not one of {OUTCOMES}"),
    (_item(pitch="huge"), ValueError, "demonstration 0: pitch 'huge' is not one of 'large', 'small'"),
    (_item(segments={"label": ["forward", "jump"]}), ValueError,
     "demonstration 0: segment 1: label 'jump' is not one of 'forward', 'backward', 'left', 'right', 'stop', 'gap'"),
    (_item(segments={"first_frame": np.array([0, -4])}), ValueError,
     "demonstration 0: segment 1: first_frame -4 is negative"),
    (_item(segments={"first_frame": np.array([12, 9])}), ValueError,
     "demonstration 0: segment 0: first_frame 12 is after last_frame 9"),
    (_item(segments={"end": np.array([[0.0] * 5, [0.0, 0.0, np.nan, 0.0, 0.0]])}), ValueError,
     "demonstration 0: segment 1: end robot_theta_rad = NaN; states must be finite"),
    (_item(segments={"start": np.zeros((2, 3))}), ValueError, r"demonstration 0: start has shape \[2, 3\]"),
    (_item(segments={"last_frame": np.array([9])}), ValueError, "demonstration 0: last_frame has 1 values for 2"),
    (_item(segments={"first_frame": np.array([0.0, 9.0])}), TypeError, "first_frame has dtype float64"),
    (_item(demonstrator=3), TypeError, "demonstration 0: demonstrator must be a string"),
    ({"demonstrator": "expert", "pitch": "large", "segments": {}}, ValueError, 'demonstration 0: no "outcome" given'),
])
def test_bad_demonstrations_are_named(item, error, match):
    with pytest.raises(error, match=match):
        polymimic.SegmentedDemonstrations([item])


def test_a_bad_demonstration_is_named_by_its_index():
    with pytest.raises(ValueError, match="demonstration 1: outcome 'won'"):
        polymimic.SegmentedDemonstrations([_item(), _item(outcome="won")])


def test_frame_counts_keep_segments_inside_their_demonstration():
    polymimic.SegmentedDemonstrations([_item()], frame_counts=[21])
    with pytest.raises(ValueError, match="demonstration 0: segment 1: last_frame 20 is outside the demonstration's "
                                         r"20 frames \(0..20\)"):
        polymimic.SegmentedDemonstrations([_item()], frame_counts=[20])
    with pytest.raises(ValueError, match="1 frame_counts for 2 demonstrations"):
        polymimic.SegmentedDemonstrations([_item(), _item()], frame_counts=[21])
