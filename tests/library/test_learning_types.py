"""The typed learning boundary: the config refuses bad values by name and round-trips."""

import pickle

import pytest

import polymimic

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
