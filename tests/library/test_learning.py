"""Learning trials on recorded demonstrations, and the learning config."""

import pytest

import polymimic
from polymimic import _native, learning, recognition


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(300, seed=1), codebook_size=128)


@pytest.fixture(scope="module")
def heterogeneous(recognizer):
    demos = [d for who in ("expert", "tiny", "humanoid") for c in (1, 2)
             for d in polymimic.record(who, configuration=c, n=10, seed=2)]
    return learning.segmented(demos, recognizer)


def _of(batch, *names):
    """The demonstrations of ``names`` only: a trial's ordering names every demonstrator it is given."""
    return [d for d in batch if d["demonstrator"] in names]


def test_python_defaults_are_the_cores():
    assert polymimic.LearningConfig().to_dict() == _native.LearningConfig().to_dict()


def test_config_round_trips_through_toml(tmp_path):
    config = polymimic.LearningConfig(permanency_step=0.03, ball_min_samples=8)
    config.save(tmp_path / "learning.toml")
    assert polymimic.LearningConfig.load(tmp_path / "learning.toml") == config


@pytest.mark.parametrize("change, match", [
    (dict(creation_threshold=1.5), "creation_threshold = 1.5 must be in"),
    (dict(decay_step=-0.1), "decay_step"),
    (dict(default_permanency=0.9), "strictly between"),
])
def test_out_of_range_config_is_named(change, match):
    with pytest.raises(ValueError, match=match):
        polymimic.LearningConfig(**change)


def test_unknown_toml_keys_are_refused():
    with pytest.raises(ValueError, match="unknown learning constants: speed"):
        polymimic.LearningConfig.from_toml("speed = 3\n")


def test_heterogeneous_trial_grows_behaviours_and_raises_lps(recognizer, heterogeneous):
    result = polymimic.run_trial(heterogeneous, recognizer=recognizer, ordering=["expert", "tiny", "humanoid"], seed=1)
    assert list(result.models) == ["expert", "tiny", "humanoid"]
    for model in result.models.values():
        assert model.created > 0 and model.rounds > 0
        assert 0.0 <= model.lp <= 1.0 and model.lp_history[0] == 0.5
        assert 0.0 <= model.match_rate <= 1.0
    assert result.imitator.lp == 0.9
    assert all(b["permanent"] for b in result.imitator.behaviours)
    assert {"F", "B", "L", "R", "S"} <= {b["primitives"] for b in result.imitator.behaviours}


def test_same_seed_same_trial_other_seed_other_trial(recognizer, heterogeneous):
    def run(seed):
        return polymimic.run_trial(_of(heterogeneous, "expert", "tiny"), recognizer=recognizer,
                                   ordering=["expert", "tiny"], seed=seed)

    assert run(4) == run(4)
    assert run(4).models["expert"].lp_history != run(5).models["expert"].lp_history


def test_trial_results_save_and_load(tmp_path, recognizer, heterogeneous):
    result = polymimic.run_trial(_of(heterogeneous, "tiny"), recognizer=recognizer, ordering=["tiny"], seed=0)
    result.save(tmp_path / "trial.json")
    assert polymimic.TrialResult.load(tmp_path / "trial.json") == result
    (tmp_path / "bad.json").write_text("{}")
    with pytest.raises(polymimic.ModelFileError, match="not a saved trial result"):
        polymimic.TrialResult.load(tmp_path / "bad.json")


def test_bad_trials_are_named(recognizer, heterogeneous):
    with pytest.raises(ValueError, match="ordering names \"poor\", which has no demonstrations"):
        polymimic.run_trial(heterogeneous, recognizer=recognizer, ordering=["expert", "poor"])
    with pytest.raises(ValueError, match="no demonstrations"):
        polymimic.run_trial([], recognizer=recognizer, ordering=["expert"])
    with pytest.raises(ValueError, match="phase_one"):
        polymimic.run_trial(_of(heterogeneous, "expert"), recognizer=recognizer, ordering=["expert"],
                            phase_one="random")
    with pytest.raises(ValueError, match="is \"humanoid\"'s, whom the ordering leaves out"):
        polymimic.run_trial(heterogeneous, recognizer=recognizer, ordering=["expert", "tiny"])


def test_the_imitator_drives_the_robot_and_scores(recognizer):
    demos = [d for who in ("expert", "tiny", "humanoid") for c in (1, 2)
             for d in polymimic.record(who, configuration=c, n=25, seed=1)]
    result = polymimic.run_trial(demos, recognizer=recognizer, ordering=["expert", "tiny", "humanoid"], seed=1)
    policy = polymimic.ImitatorPolicy(result, recognizer=recognizer)
    assert len(policy) == len(result.imitator.behaviours)
    evaluation = polymimic.evaluate(policy, attempts_per_configuration=10, seed=0)
    assert len(evaluation.attempts) == 20
    assert {a.configuration for a in evaluation.attempts} == {1, 2}
    assert evaluation.goals == sum(a.outcome == "goal" for a in evaluation.attempts)
    assert evaluation.goals >= 2, [a.outcome for a in evaluation.attempts]
    executed = {b for attempt in evaluation.behaviours for b in attempt}
    assert executed <= {b["primitives"] for b in result.imitator.behaviours}
    again = polymimic.evaluate(policy, attempts_per_configuration=10, seed=0)
    assert [a.frames.tobytes() for a in again.attempts] == [a.frames.tobytes() for a in evaluation.attempts]


def test_a_corrupt_imitator_model_is_refused(recognizer, heterogeneous):
    result = polymimic.run_trial(_of(heterogeneous, "tiny"), recognizer=recognizer, ordering=["tiny"], seed=0)
    text = result.to_json().replace('\\"format\\":\\"polymimic.ForwardModel\\"', '\\"format\\":\\"other\\"')
    with pytest.raises(polymimic.ModelFileError, match="imitator_model: "):
        polymimic.TrialResult.from_json(text)


@pytest.fixture(scope="module")
def expert_and_poor(recognizer):
    demos = [d for who in ("expert", "poor") for c in (1, 2)
             for d in polymimic.record(who, configuration=c, n=15, seed=3)]
    return learning.segmented(demos, recognizer)


def test_improved_control_learns_from_the_demonstrations_and_avoids_own_goals(recognizer, expert_and_poor):
    trial = polymimic.run_trial(expert_and_poor, recognizer=recognizer, ordering=["poor", "expert"],
                                phase_one="interleaved", seed=0)
    with pytest.raises(ValueError, match="demonstrations="):
        polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="improved")
    with pytest.raises(ValueError, match="control mode"):
        polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="best")
    thesis = polymimic.evaluate(polymimic.ImitatorPolicy(trial, recognizer=recognizer), attempts_per_configuration=10)
    policy = polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=expert_and_poor)
    assert policy.control == "improved"
    improved = polymimic.evaluate(policy, attempts_per_configuration=10)
    # Half the Poor's demonstrations end in its own goal when it starts facing it
    # (configuration 2); the improved imitator learns to keep the ball away from there.
    assert improved.own_goals <= 1 < thesis.own_goals, (improved.own_goals, thesis.own_goals)
    assert improved.goals >= 8, [a.outcome for a in improved.attempts]
    # The Poor never scores from configuration 2 (it pushes the ball the way it faces); the
    # improved imitator goes round the ball to where the Expert pushed from.
    assert sum(a.configuration == 2 and a.outcome == "goal" for a in improved.attempts) >= 2
    # Every step is one primitive of a behaviour of the model.
    assert all(len(step) == 1 for attempt in improved.behaviours for step in attempt)
    again = polymimic.evaluate(policy, attempts_per_configuration=10)
    assert [a.frames.tobytes() for a in again.attempts] == [a.frames.tobytes() for a in improved.attempts]


def test_a_policy_for_another_trial_shares_what_was_learned_and_plays_as_a_new_one(recognizer, expert_and_poor):
    first, second = (polymimic.run_trial(expert_and_poor, recognizer=recognizer, ordering=["poor", "expert"],
                                         phase_one="interleaved", seed=seed) for seed in (0, 1))
    assert first.imitator.behaviours != second.imitator.behaviours
    for control in ("improved", "thesis"):
        policy = polymimic.ImitatorPolicy(first, recognizer=recognizer, control=control,
                                          demonstrations=expert_and_poor)
        shared = policy.for_trial(second)
        fresh = polymimic.ImitatorPolicy(second, recognizer=recognizer, control=control,
                                         demonstrations=expert_and_poor)
        assert (shared.control, len(shared)) == (control, len(fresh))
        played, expected = (polymimic.evaluate(p, attempts_per_configuration=4, seed=5) for p in (shared, fresh))
        assert [a.frames.tobytes() for a in played.attempts] == [a.frames.tobytes() for a in expected.attempts]
        assert played.behaviours == expected.behaviours
    for weighting in ("lp", "lp_gain"):
        by_lp = polymimic.ImitatorPolicy(first, recognizer=recognizer, control="improved",
                                         demonstrations=expert_and_poor,
                                         config=polymimic.LearningConfig(imitator_weighting=weighting))
        with pytest.raises(ValueError, match=f'imitator_weighting="{weighting}".*trial\'s LPs'):
            by_lp.for_trial(second)


def test_preferring_sooner_goals_is_a_switch_of_the_improved_control(recognizer, expert_and_poor):
    config = polymimic.LearningConfig(prefer_sooner_goals=True)
    assert config.prefer_sooner_goals is True and polymimic.LearningConfig().prefer_sooner_goals is False
    assert "prefer_sooner_goals = true\n" in config.to_toml()
    assert polymimic.LearningConfig.from_toml(config.to_toml()) == config
    with pytest.raises(TypeError, match="prefer_sooner_goals must be True or False, got 1"):
        polymimic.LearningConfig(prefer_sooner_goals=1)
    trial = polymimic.run_trial(expert_and_poor, recognizer=recognizer, ordering=["poor", "expert"],
                                phase_one="interleaved", seed=0)
    policy = polymimic.ImitatorPolicy(trial, recognizer=recognizer, config=config, control="improved",
                                      demonstrations=expert_and_poor)
    sooner = polymimic.evaluate(policy, attempts_per_configuration=10)
    assert sooner.own_goals <= 1 and sooner.goals >= 8, [a.outcome for a in sooner.attempts]


def test_the_push_heading_tail_is_a_share_the_improved_control_checks(recognizer, expert_and_poor):
    config = polymimic.LearningConfig(push_heading_tail=0.2)
    assert config.push_heading_tail == 0.2 and polymimic.LearningConfig().push_heading_tail == 0.1
    assert "push_heading_tail = 0.2\n" in config.to_toml()
    assert polymimic.LearningConfig.from_toml(config.to_toml()) == config
    for value in (0.5, -0.1, float("nan")):
        with pytest.raises(ValueError, match=r"push_heading_tail = .* must be in \[0, 0.5\)"):
            polymimic.LearningConfig(push_heading_tail=value)
    trial = polymimic.run_trial(expert_and_poor, recognizer=recognizer, ordering=["poor", "expert"],
                                phase_one="interleaved", seed=0)
    played = {tail: polymimic.evaluate(polymimic.ImitatorPolicy(
        trial, recognizer=recognizer, config=polymimic.LearningConfig(push_heading_tail=tail), control="improved",
        demonstrations=expert_and_poor), attempts_per_configuration=5) for tail in (0.1, 0.3)}
    # A narrower heading window changes where the robot pushes from, so what it does.
    assert played[0.1].behaviours != played[0.3].behaviours
    assert all(p.own_goals <= 1 for p in played.values()), {t: p.own_goals for t, p in played.items()}
