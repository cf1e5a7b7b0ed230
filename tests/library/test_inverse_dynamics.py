"""bco's inverse dynamics model (learned from the imitator's exploration) on answers known from
the field: the primitives it executed itself, a demonstrator that only drives forward, the
commands the Expert sent; and bco's tuning choosing between it and the recogniser."""

import math

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

import polymimic
from polymimic import baselines, recognition
from polymimic.baselines import bco, inverse_dynamics
from polymimic.baselines.agreement import command_agreement
from polymimic.baselines.hyperparameters import DEFAULT, Hyperparameters, with_labellings
from polymimic.baselines.labels import NO_LABEL, command_labels, window_labels
from polymimic.field import PRIMITIVES, as_frames

FORWARD = PRIMITIVES.index("forward")


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    with threadpool_limits(limits=1):
        yield


@pytest.fixture(scope="module")
def model():
    return inverse_dynamics.learn("lego")  # the one bco labels with


@pytest.fixture(scope="module")
def forward_demos():
    """A scripted demonstrator that only drives forward, from each configuration's start."""
    demos = []
    for seed, configuration in ((1, 1), (2, 2)):
        episode = polymimic.Episode("lego", configuration=configuration, seed=seed)
        episode.run(["forward"] * 240)
        demos.append(polymimic.Demonstration(frames=as_frames(episode.frames), outcome=episode.outcome or "time_up",
                                             demonstrator="scripted", configuration=configuration, seed=seed,
                                             body="lego"))
    return demos


def test_the_model_names_the_primitive_it_executed_in_held_out_exploration(model):
    """Its own exploration under a seed it never learned from, a window from every third frame:
    91.5 % named as executed (the rest mostly a primitive held a few frames only, or one that
    starts within the window's first frames)."""
    named, executed = [], []
    for frames, primitives in inverse_dynamics.explore("lego", episodes=30, seed=99):
        starts = np.arange(0, len(frames) - model.window_frames, 3)
        named.append(model.name_windows(frames, starts))
        executed.append(primitives[starts])
    assert np.mean(np.concatenate(named) == np.concatenate(executed)) >= 0.88


def test_the_model_names_most_self_observed_primitives_from_the_second_before(model):
    """Held-out self-observation: each one-second primitive read with the second before it (the
    sequences run on from one another), from the frame it starts: 79 % named as executed. A
    window from the very frame its primitive starts is the hardest to read: the body's lag
    still shows the primitive before in its first frames."""
    sequences = polymimic.self_observation(40, seed=5)
    hits = [model.name_windows(np.concatenate([before.frames, now.frames]), [30])[0] == PRIMITIVES.index(now.primitive)
            for before, now in zip(sequences, sequences[1:])
            if math.isclose(now.frames["t_s"][0] - before.frames["t_s"][-1], 1 / 30, abs_tol=1e-6)]
    assert len(hits) >= 150 and np.mean(hits) >= 0.7


def test_a_demonstrator_that_only_drives_forward_is_labelled_forward(model, forward_demos):
    labelled = inverse_dynamics.inverse_dynamics_labels(forward_demos, model, stride_frames=1)
    for item in labelled:
        assert (item.labels == FORWARD).mean() >= 0.98, np.bincount(item.labels, minlength=5)
    # From its first frame, at rest: the second ahead is a forward one.
    assert all(item.labels[0] == FORWARD for item in labelled)


def test_labels_at_given_frames_are_those_frames_alone_and_stride_repeats(model, forward_demos):
    every = inverse_dynamics.inverse_dynamics_labels(forward_demos, model, stride_frames=1)[0].labels
    strided = inverse_dynamics.inverse_dynamics_labels(forward_demos, model, stride_frames=7)[0].labels
    assert (strided == np.repeat(every[::7], 7)[:len(every)]).all()
    frames = np.array([0, 4, 5, 31, len(every) - 1])
    chosen = inverse_dynamics.inverse_dynamics_labels(forward_demos[:1], model, frames=[frames])[0].labels
    assert (chosen[frames] == every[frames]).all() and (np.delete(chosen, frames) == NO_LABEL).all()


def test_the_experts_commands_are_followed_by_both_labellings_far_above_chance(model):
    """Four Expert demonstrations, every frame named: the inverse model's labels agree with
    the commands sent in 78 % of frames, the recogniser's steps (a small test recogniser) in
    88 %, where naming one of five primitives at random agrees in about 20 %; the commands' own
    labels agree with themselves in every frame. (In the world before the calibration the inverse
    model led: 94 % against 87 %.)"""
    demos = polymimic.record("expert", configuration=1, n=2, seed=2) + polymimic.record("expert", configuration=2, n=2)
    recognizer = recognition.train_recognizer(polymimic.self_observation(40, seed=1), codebook_size=32)
    inverse = command_agreement(inverse_dynamics.inverse_dynamics_labels(demos, model, stride_frames=1), demos)
    steps = command_agreement(window_labels(demos, recognizer, stride_frames=1), demos)
    assert inverse.coverage == 1.0 and inverse.agreement >= 0.75 and steps.agreement >= 0.85
    assert command_agreement(command_labels(demos), demos).agreement == 1.0


def test_the_same_seed_learns_the_same_model_and_another_seed_another():
    probe = inverse_dynamics.explore("lego", episodes=2, seed=7)[0][0]
    starts = np.arange(0, len(probe) - 30, 1)

    def probabilities(seed):
        inverse_dynamics._learned.cache_clear()  # learn afresh, not from the process's cache
        learned = inverse_dynamics.learn("lego", seed=seed, episodes=12)
        return learned.classifier.predict_proba(learned.features(probe, starts))

    assert np.array_equal(probabilities(3), probabilities(3))
    assert not np.array_equal(probabilities(3), probabilities(4))


def test_another_imitator_explores_its_own_body():
    tiny = inverse_dynamics.learn("tiny", episodes=12)
    assert tiny.imitator.name == "tiny"
    (demo,) = polymimic.record("poor", configuration=1, n=1, seed=0, body="tiny")
    (item,) = inverse_dynamics.inverse_dynamics_labels([demo], tiny)
    assert item.imitator.name == "tiny" and (item.labels == FORWARD).mean() >= 0.8


def test_bad_input_is_refused_by_name(model, forward_demos):
    with pytest.raises(ValueError, match='unknown body "wheelie"'):
        inverse_dynamics.learn("wheelie")
    with pytest.raises(ValueError, match="imitator must be a body's name"):
        inverse_dynamics.learn(3)
    for window in (1, 151, 2.5, True):
        with pytest.raises(ValueError, match=r"window_frames must be an integer in 2\.\.150 .*got "):
            inverse_dynamics.learn("lego", window_frames=window)
    with pytest.raises(ValueError, match="episodes must be an integer ≥ 1, got 0"):
        inverse_dynamics.learn("lego", episodes=0)
    with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 2\*\*63\)"):
        inverse_dynamics.learn("lego", seed=-1)
    with pytest.raises(ValueError, match="stride_frames must be an integer ≥ 1, got 0"):
        inverse_dynamics.inverse_dynamics_labels(forward_demos, model, stride_frames=0)
    with pytest.raises(ValueError, match="model must be an InverseDynamics"):
        inverse_dynamics.inverse_dynamics_labels(forward_demos, "recognizer")
    with pytest.raises(ValueError, match="frames must list the frames to name for each of the 2 demonstrations"):
        inverse_dynamics.inverse_dynamics_labels(forward_demos, model, frames=[[0]])
    with pytest.raises(ValueError, match=r"starts\[1\] = 240 is not a frame index of these 240 frames"):
        model.name_windows(forward_demos[0].frames, [0, 240])
    with pytest.raises(ValueError, match="labelled holds 1 demonstrations; demonstrations holds 2"):
        command_agreement(command_labels(forward_demos[:1]), forward_demos)


# bco with the inverse model ----------------------------------------------------------------

def test_bco_labels_by_the_inverse_model_without_a_recognizer(forward_demos):
    policy = baselines.fit("bco", forward_demos, hyperparameters=Hyperparameters.from_dict(
        {**DEFAULT.to_dict(), "labels": "inverse_dynamics"}), max_samples=500)
    assert policy.method == "bco" and policy.hyperparameters.labels == "inverse_dynamics"
    with pytest.raises(ValueError, match="bco needs recognizer"):
        baselines.fit("bco", forward_demos, max_samples=500)
    with pytest.raises(ValueError, match="unknown labels 'frames'; expected one of 'steps', 'segments', "
                                         "'inverse_dynamics'"):
        bco.labelled(forward_demos, labels="frames")


def test_bcos_tuning_chooses_between_the_labellings_on_the_same_classifiers(forward_demos):
    recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=16)
    tuning = baselines.tune("bco", forward_demos, budget=2, attempts_per_configuration=1, recognizer=recognizer,
                            max_samples=500)
    tried = [(s["hyperparameters"]["classifier"], s["hyperparameters"]["labels"]) for s in tuning.scores]
    assert tried == [("mlp", "steps"), ("mlp", "inverse_dynamics")]
    assert tuning.chosen["labels"] == tuning.hyperparameters.labels
    assert Hyperparameters.from_dict(tuning.hyperparameters.to_dict()) == tuning.hyperparameters
    bc_tuning = baselines.tune("bc", forward_demos, budget=2, attempts_per_configuration=1, max_samples=500)
    assert "labels" not in bc_tuning.chosen  # bc learns from the commands sent


def test_labellings_pair_over_the_candidates_and_unknown_labels_are_refused():
    drawn = baselines.candidates(5, seed=0)
    paired = with_labellings(drawn)
    assert len(paired) == 5 and [h.labels for h in paired] == ["steps", "inverse_dynamics"] * 2 + ["steps"]
    assert [dataclass_without_labels(h) for h in paired] == [dataclass_without_labels(h) for h in
                                                              (drawn[0], drawn[0], drawn[1], drawn[1], drawn[2])]
    assert "labels" not in DEFAULT.to_dict()  # recorded as before for every method that ignores it
    with pytest.raises(ValueError, match="unknown labels 'commands'; expected one of 'steps'"):
        Hyperparameters("knn", (), "raw", 10, True, labels="commands")


def dataclass_without_labels(hyperparameters):
    return {k: v for k, v in hyperparameters.to_dict().items() if k != "labels"}
