"""The baselines' tuning and attempts: validation never sees the evaluation, every method gets
the same candidates, and attempt seeds are the native field's."""

import pytest
from threadpoolctl import threadpool_limits

import polymimic
from polymimic import Attempts, _native, baselines
from polymimic.baselines import random_primitive
from polymimic.baselines.evaluation import attempts_of


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    """Small fits on a shared node: threads only add contention."""
    with threadpool_limits(limits=1):
        yield


def test_tuning_never_sees_the_evaluation_and_repeats_its_choice():
    demos = polymimic.record("poor", configuration=1, n=1, seed=0)
    one, two = (baselines.tune("bc", demos, budget=2, attempts_per_configuration=2, evaluation=Attempts(seed=3))
                for _ in range(2))
    validation = {s for _, s in one.validation_attempts}
    assert validation.isdisjoint(s for _, s in attempts_of(25, seed=3))
    assert validation.isdisjoint(s for _, s in attempts_of(25, seed=0))
    assert one.chosen == two.chosen and one.scores == two.scores
    assert len(one.scores) == 2 and one.hyperparameters == baselines.Hyperparameters.from_dict(one.chosen)


def test_validation_attempts_sharing_an_evaluation_seed_are_refused(monkeypatch):
    from polymimic.baselines import tuning
    validation = tuning.validation_attempts(2, validation_seed=0)
    assert tuning.validation_attempts_apart(2, validation_seed=0, evaluation=Attempts()) == validation
    # A 64-bit collision, forced: the evaluation's attempts are made to hold a validation seed.
    clash = validation[1][1]
    monkeypatch.setattr(Attempts, "episodes", lambda self: [(1, clash)])
    with pytest.raises(ValueError, match=rf"validation attempts share episode seeds \[{clash}\] with the evaluation"):
        tuning.validation_attempts_apart(2, validation_seed=0, evaluation=Attempts())
    demos = polymimic.record("poor", configuration=1, n=1, seed=0)
    with pytest.raises(ValueError, match="share episode seeds"):
        baselines.tune("bc", demos, budget=1, attempts_per_configuration=2)


def test_the_evaluation_validation_must_not_meet_is_one_attempts_value():
    from polymimic.baselines import tuning

    with pytest.raises(TypeError, match="evaluation must be a polymimic.Attempts, got int"):
        tuning.validation_attempts_apart(2, validation_seed=0, evaluation=25)
    with pytest.raises(ValueError, match="evaluation must be attempts from the thesis's configurations"):
        tuning.validation_attempts_apart(2, validation_seed=0, evaluation=Attempts(starts=[1, 2]))
    with pytest.raises(ValueError, match=r"evaluation's seed must be below 2\*\*62"):
        tuning.validation_attempts_apart(2, validation_seed=0, evaluation=Attempts(seed=baselines.VALIDATION_SEED_BASE))


def test_every_method_gets_the_same_candidates():
    assert baselines.candidates(6, seed=1) == baselines.candidates(6, seed=1)
    assert len(set(baselines.candidates(12))) == 12
    assert baselines.candidates(12)[0] == baselines.DEFAULT


def test_evaluation_seeds_stay_below_the_validation_seeds():
    with pytest.raises(ValueError, match="seed must be an integer in"):
        baselines.evaluate_policy(random_primitive.fit(), attempts_per_configuration=1,
                                  seed=baselines.VALIDATION_SEED_BASE)


def test_attempt_seeds_are_the_natives():
    assert attempts_of(2, seed=1) == [(int(c), int(s)) for c, s in _native.attempt_seeds(2, seed=1)]
