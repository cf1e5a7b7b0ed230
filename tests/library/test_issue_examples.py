"""The bad inputs a new user tried, each refused by a clean exception that names it."""

import json

import numpy as np
import pytest

import polymimic
from polymimic import recognition


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=16)


@pytest.fixture(scope="module")
def demos():
    return [d for who in ("expert", "poor") for d in polymimic.record(who, configuration=1, n=2, seed=1)]


def test_an_ordering_that_leaves_a_demonstrator_out(recognizer, demos):
    with pytest.raises(ValueError, match="demonstration 2 is \"poor\"'s, whom the ordering leaves out"):
        polymimic.run_trial(demos, recognizer=recognizer, ordering=["expert"], seed=0)


def test_an_evaluation_of_no_attempts(recognizer, demos):
    policy = polymimic.ImitatorPolicy(polymimic.run_trial(demos, recognizer=recognizer, ordering=["expert", "poor"]),
                                      recognizer=recognizer)
    with pytest.raises(ValueError, match="attempts_per_configuration must be at least 1, got 0"):
        polymimic.evaluate(policy, attempts_per_configuration=0)
    with pytest.raises(TypeError, match="attempts_per_configuration must be an integer, got 2.5"):
        polymimic.evaluate(policy, attempts_per_configuration=2.5)


@pytest.mark.parametrize("arguments, error, message", [
    ({"n": True}, TypeError, "n must be an integer, got True"),
    ({"n": 0}, ValueError, "n must be at least 1, got 0"),
    ({"configuration": 3}, ValueError, "configuration must be in 1..2, got 3"),
    ({"configuration": "1"}, TypeError, "configuration must be an integer, got '1'"),
    ({"seed": -1}, ValueError, "seed must be in 0.."),
    ({"seed": 2**70}, ValueError, "seed must be in 0.."),
])
def test_recording_arguments_are_named(arguments, error, message):
    with pytest.raises(error, match=message.replace("(", r"\(").replace(")", r"\)")):
        polymimic.record("expert", **{"configuration": 1, "n": 1, **arguments})


def test_a_saved_recognizer_without_its_motion_statistics(recognizer, tmp_path):
    recognizer.save(tmp_path / "recognizer.json")
    data = json.loads((tmp_path / "recognizer.json").read_text())
    data["payload"]["motion"] = []
    (tmp_path / "damaged.json").write_text(json.dumps(data))
    with pytest.raises(polymimic.ModelFileError, match=r"damaged\.json.*motion statistics"):
        polymimic.PrimitiveRecognizer.load(tmp_path / "damaged.json")


def test_a_missing_recognizer_file_is_named(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"absent\.json"):
        polymimic.PrimitiveRecognizer.load(tmp_path / "absent.json")


def test_a_finished_episode_refuses_to_run():
    config = polymimic.field.default_config()
    config["time_limit_s"] = 0.2
    episode = polymimic.Episode(config=json.dumps(config))
    episode.run(["stop"] * 10)
    with pytest.raises(polymimic.FieldRunError, match="already ended"):
        episode.run(["stop"])


def test_misspelt_field_keys_and_nan_config_values_are_named():
    with pytest.raises(ValueError, match="unknown key 'time_limt_s' in the field config"):
        polymimic.record("expert", configuration=1, n=1, config={"time_limt_s": 30.0})
    with pytest.raises(ValueError, match="'time_limit_s' must be a finite number, got nan"):
        polymimic.self_observation(1, config={"time_limit_s": np.nan})
    with pytest.raises(ValueError, match="decay_step"):
        polymimic.LearningConfig(decay_step=float("nan"))
