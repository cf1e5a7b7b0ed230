"""The typed learning boundary: the config, a segmented batch and a trial's result refuse bad
values by name, and round-trip exactly (trial files keep the text earlier versions wrote)."""

import json
import pickle

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import polymimic
from polymimic import _native, learning, recognition

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
    assert len(values) == 32
    assert values["world_weighting"] == "outcome"
    assert type(values["prefer_sooner_goals"]) is bool and values["prefer_sooner_goals"] is False
    assert type(values["push_heading_tail"]) is float and values["push_heading_tail"] == 0.1
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
    (dict(lp_own_goal_weight=-1.0), ValueError, "lp_own_goal_weight = -1 must be a finite number ≥ 0"),
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
    assert list(first) == ["demonstrator", "outcome", "segments", "pitch", "reach_mm"]
    assert first["reach_mm"] is None, "a reach not given is unknown"
    assert first["segments"]["label"] == ("forward", "gap")
    assert first["segments"]["first_frame"].dtype == np.int64
    assert (first["segments"]["end"] == 1.0).all() and (first["segments"]["scores"] == -3.0).all()
    assert batch[-1]["demonstrator"] == "tiny"
    with pytest.raises(IndexError):
        batch[2]
    assert [d["pitch"] for d in batch] == ["large", "small"]


def test_a_demonstrations_reach_is_kept_and_a_bad_one_refused_naming_it():
    batch = polymimic.SegmentedDemonstrations([_item(reach_mm=120.0)])
    assert batch[0]["reach_mm"] == 120.0
    for bad in (-1.0, 0.0, float("nan"), True, "far"):
        with pytest.raises(ValueError, match=r"demonstration 0: reach_mm must be a positive number of millimetres "
                                             r"or None"):
            polymimic.SegmentedDemonstrations([_item(reach_mm=bad)])


def _change_label(item):
    item["segments"]["label"] = ["forward", "jump"]


def _change_a_label_in_place(item):
    item["segments"]["label"][1] = "jump"


def _shorten_a_column(item):
    item["segments"]["first_frame"].resize(1, refcheck=False)


def _move_a_frame(item):
    item["segments"]["first_frame"][0] = 5


def _rename_the_pitch(item):
    item["pitch"] = "medium"


def _delete_the_segments(item):
    del item["segments"]


def _clear_the_item(item):
    item.clear()


@pytest.mark.parametrize("change, error, match", [
    (_change_label, TypeError, "does not support item assignment"),
    (_change_a_label_in_place, TypeError, "does not support item assignment"),
    (_shorten_a_column, ValueError, "cannot resize this array"),
    (_move_a_frame, ValueError, "assignment destination is read-only"),
    (_rename_the_pitch, TypeError, "does not support item assignment"),
    (_delete_the_segments, TypeError, "does not support item deletion"),
    (_clear_the_item, AttributeError, "has no attribute 'clear'"),
])
def test_what_a_batch_hands_out_cannot_be_changed_behind_the_learners_back(change, error, match):
    batch = polymimic.SegmentedDemonstrations([_item(), _item(demonstrator="tiny", pitch="small")])
    before = pickle.dumps(batch)
    for item in (batch[0], next(iter(batch))):
        with pytest.raises(error, match=match):
            change(item)
    assert batch == pickle.loads(before)


def test_a_copy_of_an_item_is_checked_again_when_it_becomes_a_batch():
    batch = polymimic.SegmentedDemonstrations([_item()])
    copy = dict(batch[0])
    copy["segments"] = {**copy["segments"], "label": ["forward", "jump"]}
    with pytest.raises(ValueError, match="demonstration 0: segment 1: label 'jump' is not one of"):
        polymimic.SegmentedDemonstrations([copy])
    copy["segments"] = {**copy["segments"], "label": ["forward", "gap"], "first_frame": np.array([0])}
    with pytest.raises(ValueError, match="demonstration 0: first_frame has 1 values for 2 labels"):
        polymimic.SegmentedDemonstrations([copy])
    copy["segments"] = dict(batch[0]["segments"])
    assert polymimic.SegmentedDemonstrations([copy]) == batch


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
     "demonstration 0: segment 1: label 'jump' is not one of 'forward', 'backward', 'left', 'right', 'stop', "
     "'sidestep_left', 'sidestep_right', 'kick', 'gap'"),
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


# Trials on real demonstrations.

@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(60, seed=1), codebook_size=32)


@pytest.fixture(scope="module")
def recorded():
    return [d for who in ("expert", "tiny") for d in polymimic.record(who, configuration=1, n=3, seed=1)]


@pytest.fixture(scope="module")
def trial(recognizer, recorded):
    return polymimic.run_trial(recorded, recognizer=recognizer, ordering=["expert", "tiny"], seed=2)


def test_segmented_is_one_checked_batch_shared_by_trials(recognizer, recorded, trial):
    batch = learning.segmented(recorded, recognizer)
    assert isinstance(batch, polymimic.SegmentedDemonstrations)
    assert batch.pitches == ["large"] * 3 + ["small"] * 3
    assert polymimic.run_trial(batch, recognizer=recognizer, ordering=["expert", "tiny"], seed=2) == trial
    as_dicts = [dict(d) for d in batch]  # the dictionaries earlier versions passed, still taken
    assert polymimic.run_trial(as_dicts, recognizer=recognizer, ordering=["expert", "tiny"], seed=2) == trial


def test_trial_json_is_the_text_earlier_versions_wrote(trial):
    # Earlier versions wrote json.dumps(dataclasses.asdict(trial)); to_dict is that dictionary.
    assert trial.to_json() == json.dumps(trial.to_dict())
    assert list(trial.to_dict()) == ["models", "imitator", "seed", "imitator_model"]
    assert list(trial.imitator.to_dict()) == [
        "name", "lp", "lp_history", "match_rate", "created", "deleted", "permanent", "candidates", "duplicates",
        "candidates_permanent", "rounds", "rounds_matched", "behaviours", "lp_causes"]
    again = polymimic.TrialResult.from_json(trial.to_json())
    assert again == trial and again.to_json() == trial.to_json()
    assert pickle.loads(pickle.dumps(trial)) == trial


@settings(max_examples=500, deadline=None)
@given(st.lists(st.floats(min_value=0.0, max_value=1.0), min_size=1, max_size=20),
       st.floats(allow_nan=False, allow_infinity=False), st.integers(0, 2**63))
def test_floats_and_counts_are_written_as_python_writes_them(history, permanency, seed):
    behaviour = {"primitives": "FL", "permanency": permanency, "permanent": False, "age": 3, "selected": 1,
                 "ball_samples": 0, "ball_angle_deg": [permanency, 0.0], "ball_distance_mm": [0.0, 1e-7]}
    model = polymimic.ModelResult("expert", history[-1], history, history[0], 1, 0, 0, 0, 0, 0, 4, 2, [behaviour],
                                  {"goal": 1})
    imitator = polymimic.ModelResult("imitator", 0.9, [0.9], 0.0, 0, 0, 0, 0, 0, 0, 0, 0, [])
    result = polymimic.TrialResult({"expert": model}, imitator, seed)
    assert result.to_json() == json.dumps(result.to_dict())
    assert polymimic.TrialResult.from_json(result.to_json()) == result


def _damaged(tmp_path, trial, old, new):
    text = trial.to_json()
    assert old in text
    path = tmp_path / "trial.json"
    path.write_text(text.replace(old, new, 1))
    return path


def test_a_damaged_trial_file_is_named_by_file_and_key(tmp_path, trial):
    lp = json.dumps(trial.models["expert"].lp)
    path = _damaged(tmp_path, trial, f'"lp": {lp}', '"lp": "high"')
    with pytest.raises(polymimic.ModelFileError,
                       match=f'{path}: not a saved trial result: models.expert.lp: "high" is not a number'):
        polymimic.TrialResult.load(path)
    path = _damaged(tmp_path, trial, '"seed": 2', '"seed": -2')
    with pytest.raises(polymimic.ModelFileError, match="seed: -2 is not a whole number ≥ 0"):
        polymimic.TrialResult.load(path)
    path = _damaged(tmp_path, trial, '"seed": 2', '"seed": 2, "colour": "red"')
    with pytest.raises(polymimic.ModelFileError, match="colour: unknown key"):
        polymimic.TrialResult.load(path)
    path = _damaged(tmp_path, trial, '"permanent": true', '"permanent": 1')
    with pytest.raises(polymimic.ModelFileError, match=r"behaviours\[0\].permanent: 1 is not true or false"):
        polymimic.TrialResult.load(path)
    path = _damaged(tmp_path, trial, '\\"format\\":\\"polymimic.ForwardModel\\"', '\\"format\\":\\"other\\"')
    with pytest.raises(polymimic.ModelFileError, match="imitator_model: "):
        polymimic.TrialResult.load(path)


def test_a_truncated_binary_or_foreign_trial_file_is_refused_by_name(tmp_path, trial):
    truncated = tmp_path / "truncated.json"
    truncated.write_text(trial.to_json()[:200])
    with pytest.raises(polymimic.ModelFileError,
                       match=rf"{truncated}: not a saved trial result: models.expert.lp_history\[\d+\]: the text ends"):
        polymimic.TrialResult.load(truncated)
    binary = tmp_path / "binary.json"
    binary.write_bytes(bytes(range(256)))
    with pytest.raises(polymimic.ModelFileError, match=f"{binary} is not a polymimic file"):
        polymimic.TrialResult.load(binary)
    foreign = tmp_path / "foreign.json"
    foreign.write_text('{"format": "polymimic.Codebook"}')
    with pytest.raises(polymimic.ModelFileError, match="format: unknown key"):
        polymimic.TrialResult.load(foreign)
    with pytest.raises(FileNotFoundError):
        polymimic.TrialResult.load(tmp_path / "missing.json")


def test_model_and_trial_results_check_their_values_when_made(trial):
    with pytest.raises(ValueError, match=r"lp_history\[1\]: 1.5 is not a number in \[0, 1\]"):
        polymimic.ModelResult("expert", 0.5, [0.5, 1.5], 0.0, 0, 0, 0, 0, 0, 0, 0, 0, [])
    with pytest.raises(ValueError, match="lp_causes.luck: unknown key"):
        polymimic.ModelResult("expert", 0.5, [0.5], 0.0, 0, 0, 0, 0, 0, 0, 0, 0, [], {"luck": 1})
    with pytest.raises(ValueError, match="models.poor: the model is named 'expert'"):
        polymimic.TrialResult({"poor": trial.models["expert"]}, trial.imitator, 0)
    with pytest.raises(ValueError, match="imitator_model: "):
        polymimic.TrialResult({}, trial.imitator, 0, imitator_model="{}")


def test_a_trial_without_its_imitator_model_drives_nothing(recognizer, trial):
    bare = polymimic.TrialResult(trial.models, trial.imitator, trial.seed)
    with pytest.raises(polymimic.ModelFileError, match="imitator model: this trial result keeps none"):
        polymimic.ImitatorPolicy(bare, recognizer=recognizer)


# The shared selections.

def test_net_goals_and_spare_attempts_are_the_learn_crates():
    assert _native.net_goals(["goal", "own_goal", "goal", "time_up", "ball_out"]) == 1
    with pytest.raises(ValueError, match='outcome 1 must be "goal" or "own_goal"'):
        _native.net_goals(["goal", "own-goal"])
    assert learning.spare_attempts(25) == 5 and learning.spare_attempts(100) == 20


def test_lp_order_hits_counts_strictly_rising_final_lps():
    def model(name, lp):
        return polymimic.ModelResult(name, lp, [lp], 0.0, 0, 0, 0, 0, 0, 0, 0, 0, [])

    def trial(poor, average, expert):
        return polymimic.TrialResult({"poor": model("poor", poor), "average": model("average", average),
                                      "expert": model("expert", expert)}, model("imitator", 0.9), 0)

    trials = [trial(0.2, 0.5, 0.9), trial(0.5, 0.5, 0.9), trial(0.1, 0.6, 0.55)]
    assert _native.lp_order_hits(trials, ["poor", "average", "expert"]) == 1
    assert _native.lp_order_hits(trials, ["poor", "expert"]) == 3
    assert _native.lp_order_hits(trials, ["poor", "nobody"]) == 0
