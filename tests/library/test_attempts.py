"""Which attempts a policy plays is one value, polymimic.Attempts: the imitator's evaluation and
a baseline's play the same attempts from it as from the keywords it stands for, and a bad one is
refused by the argument's name."""

import pytest

import polymimic
from polymimic import Attempts, baselines
from polymimic._native import attempt_seeds
from polymimic.baselines.evaluation import attempts_of
from polymimic.baselines.policy import RandomPolicy

NEAR = {"robot": (150.0, 0.0, 0.0), "ball": (300.0, 0.0)}


def played(evaluation):
    return [(a.configuration, a.seed, a.outcome, len(a.frames)) for a in evaluation.attempts]


def test_the_value_plays_what_the_keywords_play(expert_imitator):
    by_value = polymimic.evaluate(expert_imitator, attempts=Attempts(per_configuration=2, seed=7, starts=[NEAR, 2]))
    by_keywords = polymimic.evaluate(expert_imitator, attempts_per_configuration=2, seed=7, starts=[NEAR, 2])
    assert played(by_value) == played(by_keywords)
    assert [a.configuration for a in by_value.attempts] == [0, 0, 2, 2]


def test_the_defaults_are_the_thesis_attempts(expert_imitator):
    attempts = Attempts()
    assert (attempts.per_configuration, attempts.seed, attempts.starts, attempts.count) == (25, 0, None, 50)
    one = polymimic.evaluate(expert_imitator, attempts=Attempts(per_configuration=1))
    assert played(one) == played(polymimic.evaluate(expert_imitator, attempts_per_configuration=1))


def test_its_episodes_are_the_native_attempt_seeds_and_a_baselines_attempts():
    attempts = Attempts(per_configuration=3, seed=6)
    assert attempts.episodes() == [(int(c), int(s)) for c, s in attempt_seeds(3, seed=6)]
    assert attempts.episodes() == attempts_of(3, seed=6)
    assert [c for c, _ in attempts.episodes()] == [1, 1, 1, 2, 2, 2] and attempts.count == 6
    by_value = baselines.evaluate_policy(RandomPolicy(seed=0), attempts=attempts)
    by_keywords = baselines.evaluate_policy(RandomPolicy(seed=0), attempts_per_configuration=3, seed=6)
    assert played(by_value) == played(by_keywords)
    assert [(a.configuration, a.seed) for a in by_value.attempts] == attempts.episodes()


def test_chosen_starts_count_and_stay_the_imitators():
    attempts = Attempts(per_configuration=4, starts=[NEAR, 1, NEAR])
    assert attempts.count == 12 and attempts.starts == (NEAR, 1, NEAR)
    with pytest.raises(ValueError, match="starts of your own are played by polymimic.evaluate"):
        attempts.episodes()
    with pytest.raises(ValueError, match="starts of your own"):
        baselines.evaluate_policy(RandomPolicy(seed=0), attempts=attempts)


@pytest.mark.parametrize(("arguments", "error", "message"), [
    ({"per_configuration": 0}, ValueError, "per_configuration must be at least 1, got 0"),
    ({"per_configuration": 2.5}, TypeError, "per_configuration must be an integer, got 2.5"),
    ({"per_configuration": True}, TypeError, "per_configuration must be an integer, got True"),
    ({"seed": -1}, ValueError, r"seed must be in 0\.\.18446744073709551615, got -1"),
    ({"seed": 2**64}, ValueError, "seed must be in 0"),
    ({"starts": "12"}, TypeError, "starts must be a sequence of starts"),
    ({"starts": NEAR}, TypeError, "starts must be a sequence of starts"),
])
def test_a_bad_value_is_refused_by_its_name(arguments, error, message):
    with pytest.raises(error, match=message):
        Attempts(**arguments)


def test_the_value_and_its_keywords_are_not_given_together(expert_imitator):
    with pytest.raises(TypeError, match="give attempts= or seed=, not both"):
        polymimic.evaluate(expert_imitator, attempts=Attempts(per_configuration=1), seed=3)
    with pytest.raises(TypeError, match="give attempts= or attempts_per_configuration=, starts=, not both"):
        polymimic.evaluate(expert_imitator, attempts=Attempts(), attempts_per_configuration=1, starts=[1])
    with pytest.raises(TypeError, match="attempts must be a polymimic.Attempts, got int"):
        polymimic.evaluate(expert_imitator, attempts=5)
    with pytest.raises(TypeError, match="give attempts= or attempts_per_configuration=, not both"):
        baselines.evaluate_policy(RandomPolicy(seed=0), attempts=Attempts(), attempts_per_configuration=1)


def test_the_keywords_keep_their_own_refusals(expert_imitator):
    with pytest.raises(ValueError, match="attempts_per_configuration must be at least 1, got 0"):
        polymimic.evaluate(expert_imitator, attempts_per_configuration=0)
    with pytest.raises(ValueError, match="attempts_per_configuration must be an integer ≥ 1, got 0"):
        baselines.evaluate_policy(RandomPolicy(seed=0), attempts_per_configuration=0)


def test_a_baseline_is_never_evaluated_on_validation_seeds():
    validation = Attempts(per_configuration=1, seed=baselines.VALIDATION_SEED_BASE)
    with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 4611686018427387904\)"):
        baselines.evaluate_policy(RandomPolicy(seed=0), attempts=validation)
