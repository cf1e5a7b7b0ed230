"""The uniform-LP ablation (``hold_lp``) and the imitator's weighting of demonstrations by
their demonstrators' LPs (``imitator_weighting``): configured, saved and refused by name, and
acting on trials and on the improved control."""

import json

import pytest

import polymimic
from polymimic import _native, learning, recognition


def test_the_switches_default_to_the_thesis():
    config = polymimic.LearningConfig()
    assert (config.hold_lp, config.imitator_weighting) == (False, "even")
    values = config.to_dict()
    assert type(values["hold_lp"]) is bool and values["imitator_weighting"] == "even"


def test_the_switches_round_trip_through_toml_and_files(tmp_path):
    config = polymimic.LearningConfig(hold_lp=True, imitator_weighting="lp")
    assert (config.hold_lp, config.imitator_weighting) == (True, "lp")
    text = config.to_toml()
    assert "hold_lp = true\n" in text and 'imitator_weighting = "lp"\n' in text
    assert polymimic.LearningConfig.from_toml(text) == config
    config.save(tmp_path / "learning.toml")
    again = polymimic.LearningConfig.load(tmp_path / "learning.toml")
    assert again == config and type(again) is polymimic.LearningConfig
    assert config != polymimic.LearningConfig() and config.replace(hold_lp=False).hold_lp is False
    assert "hold_lp=True" in repr(config) and "imitator_weighting='lp'" in repr(config)


@pytest.mark.parametrize("change, error, match", [
    (dict(imitator_weighting="lpp"), ValueError, 'imitator_weighting must be "even" or "lp" or "lp_gain", got "lpp"'),
    (dict(imitator_weighting=1), TypeError, "imitator_weighting must be a string, got 1"),
    (dict(hold_lp="yes"), TypeError, "hold_lp must be True or False, got 'yes'"),
    (dict(hold_lp=1), TypeError, "hold_lp must be True or False, got 1"),
])
def test_bad_switches_are_named(change, error, match):
    with pytest.raises(error, match=match):
        polymimic.LearningConfig(**change)


def test_a_bad_switch_in_a_file_is_named():
    with pytest.raises(TypeError, match="hold_lp must be True or False, got 'yes'"):
        polymimic.LearningConfig.from_toml('hold_lp = "yes"\n')
    with pytest.raises(ValueError, match="imitator_weighting must be"):
        polymimic.LearningConfig.from_toml('imitator_weighting = "lpp"\n')


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(60, seed=1), codebook_size=32)


@pytest.fixture(scope="module")
def demonstrations(recognizer):
    recorded = [d for who in ("expert", "poor") for c in (1, 2)
                for d in polymimic.record(who, configuration=c, n=3, seed=4)]
    return learning.segmented(recorded, recognizer)


HELD = polymimic.LearningConfig(hold_lp=True)
ORDERING = ["poor", "expert"]


def test_held_lps_never_move(recognizer, demonstrations):
    held = polymimic.run_trial(demonstrations, recognizer=recognizer, ordering=ORDERING, config=HELD, seed=3)
    for model in held.models.values():
        assert model.lp_history == [0.5] and model.lp == 0.5, model.name
    moving = polymimic.run_trial(demonstrations, recognizer=recognizer, ordering=ORDERING, seed=3)
    assert all(len(m.lp_history) > 1 for m in moving.models.values())
    # Equal LPs weigh every demonstration 1: the weighted trial is the even one, bit for bit.
    weighted = polymimic.run_trial(demonstrations, recognizer=recognizer, ordering=ORDERING,
                                   config=HELD.replace(imitator_weighting="lp"), seed=3)
    assert weighted.to_json() == held.to_json()


def test_the_improved_control_weighs_the_demonstrations_by_the_trials_lps(recognizer, demonstrations):
    by_lp = HELD.replace(imitator_weighting="lp")
    trial = polymimic.run_trial(demonstrations, recognizer=recognizer, ordering=ORDERING, config=HELD, seed=3)

    def frames(config):
        policy = polymimic.ImitatorPolicy(trial, recognizer=recognizer, config=config, control="improved",
                                          demonstrations=demonstrations)
        attempts = polymimic.evaluate(policy, attempts_per_configuration=2, seed=5).attempts
        return [a.frames.tobytes() for a in attempts]

    # Every LP held at 0.5: every weight is 1 and the imitator plays exactly as evenly.
    assert frames(by_lp) == frames(HELD)
    # A demonstration whose demonstrator has no model in the trial has no weight.
    stranger = [dict(d) for d in demonstrations] + [dict(demonstrations[0], demonstrator="tiny")]
    with pytest.raises(ValueError, match=f"demonstration {len(demonstrations)} is \"tiny\"'s, who has no model"):
        polymimic.ImitatorPolicy(trial, recognizer=recognizer, config=by_lp, control="improved",
                                 demonstrations=stranger)
    polymimic.ImitatorPolicy(trial, recognizer=recognizer, config=HELD, control="improved", demonstrations=stranger)


def test_the_gain_leaves_out_a_member_whose_lp_never_rose(recognizer, demonstrations):
    trial = polymimic.run_trial(demonstrations, recognizer=recognizer, ordering=ORDERING, seed=3)
    record = json.loads(trial.to_json())
    record["models"]["poor"]["lp"] = 0.45  # below the 0.5 every model starts from
    sunk = polymimic.TrialResult.from_json(json.dumps(record))
    expert_only = [d for d in demonstrations if d["demonstrator"] == "expert"]

    def frames(config, demos):
        policy = polymimic.ImitatorPolicy(sunk, recognizer=recognizer, config=config, control="improved",
                                          demonstrations=demos)
        return [a.frames.tobytes() for a in polymimic.evaluate(policy, attempts_per_configuration=2, seed=5).attempts]

    # The Poor weighs (0.45 − 0.5)⁺ = 0 and the Expert 1: with the weights reaching every part of
    # the world model, as if only the Expert had been watched.
    gain = polymimic.LearningConfig(imitator_weighting="lp_gain", world_weighting="every")
    assert frames(gain, demonstrations) == frames(polymimic.LearningConfig(), expert_only)
    # Under "lp" the Poor still weighs 0.45 / LP_expert: it is not left out.
    assert frames(gain.replace(imitator_weighting="lp"), demonstrations) != frames(gain, demonstrations)
    # Reaching no part ("outcome"), the weights change nothing the improved control learns.
    outcome = gain.replace(world_weighting="outcome")
    assert frames(outcome, demonstrations) == frames(outcome.replace(imitator_weighting="even"), demonstrations)


def test_the_world_weighting_is_configured_and_refused_by_name():
    config = polymimic.LearningConfig()
    assert config.world_weighting == "outcome" and config.to_dict()["world_weighting"] == "outcome"
    every = config.replace(world_weighting="every")
    assert every.world_weighting == "every" and polymimic.LearningConfig.from_toml(every.to_toml()) == every
    with pytest.raises(ValueError, match='world_weighting must be "every" or "intent" or "outcome", got "physics"'):
        polymimic.LearningConfig(world_weighting="physics")


def test_parts_learned_from_no_demonstration_ignore_the_demonstrations(recognizer, demonstrations):
    trial = polymimic.run_trial(demonstrations, recognizer=recognizer, ordering=ORDERING, seed=3)
    expert_only = [d for d in demonstrations if d["demonstrator"] == "expert"]

    def frames(demos, unlearned):
        policy = _native.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demos,
                                        unlearned=unlearned)
        return [a.frames.tobytes() for a in polymimic.evaluate(policy, attempts_per_configuration=2, seed=5).attempts]

    # With no part of the world model learned, what was watched makes no difference…
    world = ["ball_response", "push_region", "state_value"]
    assert frames(demonstrations, world) == frames(expert_only, world)
    # …and with every part learned, it does.
    assert frames(demonstrations, []) != frames(expert_only, [])
    with pytest.raises(ValueError, match='unlearned: "ball" is no part'):
        _native.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demonstrations,
                               unlearned=["ball"])
