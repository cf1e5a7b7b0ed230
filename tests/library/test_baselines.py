"""The benchmark's baselines (docs/results/benchmark.md), on scripted demonstrators whose right answers are known."""

import math
import re

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

import polymimic
from polymimic import baselines, recognition
from polymimic.baselines import bc, bc_best, bco, bco_lp, labels, random_primitive
from polymimic.baselines.features import features
from polymimic.baselines.labels import NO_LABEL
from polymimic.field import PRIMITIVES, as_frames

FORWARD, LEFT, RIGHT = PRIMITIVES.index("forward"), PRIMITIVES.index("left"), PRIMITIVES.index("right")


def scripted(rule, *, seed, configuration=1, place=None, hold_frames=1, max_frames=1800):
    """One demonstration by a scripted demonstrator: ``rule(observation) -> primitive`` every
    ``hold_frames`` frames, from the configuration's start (or a placed robot)."""
    episode = polymimic.Episode("lego", configuration=configuration, seed=seed)
    if place is not None:
        episode.place_robot(*place)
    while not episode.finished and len(episode.frames) < max_frames:
        seen = episode.observation()
        observation = np.array([*seen["robot"], *(seen["ball"] or (math.nan, math.nan))])
        episode.run([rule(observation)] * hold_frames)
    return polymimic.Demonstration(frames=as_frames(episode.frames), outcome=episode.outcome or "time_up",
                                   demonstrator="scripted", configuration=configuration, seed=seed, body="lego")


def always_forward(observation):
    return "forward"


def ball_bearing_rad(observations):
    observations = np.atleast_2d(observations)
    bearing = np.arctan2(observations[:, 4] - observations[:, 1], observations[:, 3] - observations[:, 0])
    return np.angle(np.exp(1j * (bearing - observations[:, 2])))


def turn_to_ball(observation):
    """Left when the ball is to the robot's left, right when it is to its right."""
    return "left" if ball_bearing_rad(observation)[0] > 0 else "right"


def turning_demonstrations(seed, n):
    rng = np.random.default_rng(seed)
    return [scripted(turn_to_ball, seed=seed * 1000 + i, max_frames=40,
                     place=(rng.uniform(-400, 400), rng.uniform(-300, 300), rng.uniform(-math.pi, math.pi)))
            for i in range(n)]


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    """Small fits on a shared node: threads only add contention (three times slower here)."""
    with threadpool_limits(limits=1):
        yield


@pytest.fixture(scope="module")
def forward_demos():
    return [scripted(always_forward, seed=s) for s in (1, 2)]


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(40, seed=1), codebook_size=32)


@pytest.fixture(scope="module")
def mixed_demos():
    return (polymimic.record("poor", configuration=1, n=2, seed=3)
            + polymimic.record("expert", configuration=1, n=2, seed=3))


def grid_observations(n=400, seed=0):
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(-450, 450, n), rng.uniform(-350, 350, n), rng.uniform(-math.pi, math.pi, n),
                            rng.uniform(-450, 450, n), rng.uniform(-350, 350, n)])


# Known answers ------------------------------------------------------------------------------

def test_bc_on_an_always_forward_demonstrator_plays_forward_at_every_step(forward_demos):
    policy = bc.fit(forward_demos)
    assert (policy.predict(grid_observations()) == FORWARD).all()
    result = baselines.evaluate_policy(policy, attempts_per_configuration=2, seed=0)
    assert all(set(chosen) == {"F"} for chosen in result.behaviours)


def test_a_smaller_field_is_taken_as_recorded_and_a_longer_ones_ball_crosses_by_the_correspondence():
    """The tiny's field (560 mm) lies within the imitator's (1020 mm): the cloning baselines take
    its frames as recorded (the correspondence weakens them: see polymimic.baselines.labels). A
    longer field's ball comes across by the correspondence, goal mouth onto goal mouth, while the
    robot keeps its offset from the ball in millimetres and its heading."""
    from polymimic.bodies import Field, WheeledBody, onto_field

    (tiny,) = polymimic.record("tiny", configuration=1, n=1, seed=0)
    raw = np.column_stack([tiny.frames[c] for c in ("robot_x_mm", "robot_y_mm", "robot_theta_rad",
                                                     "ball_x_mm", "ball_y_mm")])
    assert np.isfinite(raw).all()
    np.testing.assert_array_equal(labels.command_labels([tiny])[0].observations, raw)
    robocup = WheeledBody("robocup", length_mm=180, width_mm=180, wheel_base_mm=150, top_wheel_speed_mm_s=500,
                          field=Field(3060.0, 2430.0, goal_mouth_mm=1215.0))
    (far,) = polymimic.record("poor", body=robocup, name="far", configuration=1, n=1, seed=0)
    seen = np.column_stack([far.frames[c] for c in ("robot_x_mm", "robot_y_mm", "robot_theta_rad",
                                                     "ball_x_mm", "ball_y_mm")])
    onto = labels.observations_of(far)
    np.testing.assert_allclose(onto[:, 3:], onto_field(seen, recorded_by=robocup)[:, 3:])
    np.testing.assert_allclose(onto[:, 3:], seen[:, 3:] / 3.0)
    np.testing.assert_allclose(onto[:, :2] - onto[:, 3:], seen[:, :2] - seen[:, 3:], atol=1e-9)
    np.testing.assert_array_equal(onto[:, 2], seen[:, 2])


def test_a_humanoids_kick_is_labelled_forward_and_every_other_command_as_it_looks():
    from polymimic.field import command_primitives, command_table

    lookup, cloning = command_primitives(), labels.cloning_primitives()
    for row in command_table():
        expected = "forward" if row["name"] in ("Kick Left", "Kick Right") else row["primitive"]
        assert PRIMITIVES[cloning[row["id"]]] == expected, row
    kicks = [r["id"] for r in command_table() if r["name"].startswith("Kick")]
    assert {lookup[i] for i in kicks} == {"backward"}  # as it looks from above (Table 4.4)
    demos = polymimic.record("humanoid", configuration=1, n=3, seed=0)
    (item, *_) = labels.command_labels(demos)
    kicked = np.isin(demos[0].frames["command"], kicks)
    assert kicked.any() and (item.labels[kicked] == PRIMITIVES.index("forward")).all()


def test_bc_reproduces_a_turn_toward_the_ball_rule_on_held_out_observations():
    policy = bc.fit(turning_demonstrations(1, 40))
    held_out = np.concatenate([bc.labelled([d])[0].observations for d in turning_demonstrations(2, 15)])
    truth = np.where(ball_bearing_rad(held_out) > 0, LEFT, RIGHT)
    assert (policy.predict(held_out) == truth).mean() >= 0.95


def test_bco_labels_an_always_forward_demonstrator_forward(forward_demos, recognizer):
    """bco names the frames a fit samples (every third, from a first frame its seed draws) and
    no other: nearly all of them forward, none anything else."""
    from polymimic.baselines.training import sample_rows

    for seed in (0, 1):
        items = bco.labelled(forward_demos, recognizer=recognizer, seed=seed)
        rows = sample_rows([(d.demonstrator, len(d.frames)) for d in forward_demos], seed=seed)
        named = np.concatenate([item.labels[r] for item, r in zip(items, rows)])
        assert (named != NO_LABEL).mean() > 0.8 and (named[named != NO_LABEL] == FORWARD).all()
        others = np.concatenate([np.delete(item.labels, r) for item, r in zip(items, rows)])
        assert (others == NO_LABEL).all()


def held_primitives(plan, *, seed, hold_frames=30):
    """One demonstration holding each primitive of ``plan`` for ``hold_frames`` frames."""
    steps = iter(plan)
    return scripted(lambda observation: next(steps), seed=seed, hold_frames=hold_frames,
                    max_frames=hold_frames * len(plan), place=(-300.0, 0.0, 0.0))


def test_window_labels_name_each_held_primitive_as_it_was_sent(recognizer):
    """Primitives held for a second each, in a known order: the second read from a sixth of a
    second into each one (past the body's lag) is named as the primitive sent, nearly every
    move (the test's recogniser learned from 40 sequences only); a stop is named stop where
    the robot has come to rest (after a turn) and can read as motion while it still rolls
    (after a backward)."""
    plan = ["forward", "left", "left", "stop", "right", "forward", "backward", "stop", "right", "forward"] * 2
    demos = [held_primitives(plan, seed=s) for s in (5, 6)]
    named = []
    for labelled in labels.window_labels(demos, recognizer, stride_frames=1):
        named.extend(PRIMITIVES[label] if label != NO_LABEL else "gap" for label in labelled.labels[5:-30:30])
    sent = plan[:-1] * 2
    assert len(named) == len(sent)
    moves = [(n, s) for n, s in zip(named, sent) if s != "stop"]
    assert np.mean([n == s for n, s in moves]) >= 0.9, [(i, n, s) for i, (n, s) in enumerate(moves) if n != s]
    stops = [n for n, s, before in zip(named, sent, ["forward", *sent[:-1]]) if s == "stop" and before != "backward"]
    assert stops == ["stop"] * len(stops) and len(stops) == 4


def test_window_labels_follow_the_commands_far_better_than_segment_labels(recognizer):
    """The Expert turns in about a third of its frames; its segments, grown to the most one
    primitive can move, are nearly all forward. Step labels agree with the commands sent in
    most frames, and in more than segment labels do by a wide margin."""
    demos = polymimic.record("expert", configuration=1, n=2, seed=2) + polymimic.record("expert", configuration=2, n=2)
    sent = np.concatenate([item.labels for item in labels.command_labels(demos)])

    def agreement(labelled):
        named = np.concatenate([item.labels for item in labelled])
        both = (sent != NO_LABEL) & (named != NO_LABEL)
        return (sent[both] == named[both]).mean()

    steps, segments = agreement(labels.window_labels(demos, recognizer)), agreement(bco.labelled(
        demos, recognizer=recognizer, labels="segments"))
    assert steps >= 0.8 and steps >= segments + 0.1, (steps, segments)


def test_window_labels_at_a_stride_are_the_labels_of_the_frames_named(recognizer):
    demos = polymimic.record("expert", configuration=2, n=1, seed=4)
    every = labels.window_labels(demos, recognizer, stride_frames=1)[0].labels
    strided = labels.window_labels(demos, recognizer, stride_frames=7)[0].labels
    assert (strided[::7] == every[::7]).all()
    assert (strided == np.repeat(every[::7], 7)[:len(every)]).all()


def test_window_labels_at_given_frames_are_the_labels_of_those_frames_alone(recognizer):
    demos = polymimic.record("expert", configuration=2, n=1, seed=4)
    every = labels.window_labels(demos, recognizer, stride_frames=1)[0].labels
    frames = np.array([0, 4, 5, 31, len(every) - 1])
    chosen = labels.window_labels(demos, recognizer, frames=[frames])[0].labels
    assert (chosen[frames] == every[frames]).all()
    assert (np.delete(chosen, frames) == NO_LABEL).all()
    with pytest.raises(ValueError, match="frames must list the frames to name for each of the 1 demonstrations, got 2"):
        labels.window_labels(demos, recognizer, frames=[frames, frames])


def test_a_fit_seed_draws_which_frames_give_samples():
    """Every demonstration's first frame, then every stride-th frame from one in [1, stride]
    drawn per demonstration: the same seed the same frames, other seeds other frames, and as
    many samples (give or take the first frames) either way."""
    from polymimic.baselines.training import sample_rows

    lengths = [(f"d{i % 3}", 900) for i in range(10)]
    for max_samples, stride in ((20_000, 3), (1000, 9)):
        drawn = [sample_rows(lengths, max_samples=max_samples, seed=seed) for seed in range(4)]
        for rows in drawn:
            assert all(r[0] == 0 and 1 <= r[1] <= stride and (np.diff(r[1:]) == stride).all() for r in rows)
            assert 9000 // stride <= sum(map(len, rows)) <= 9000 // stride + 10
        assert all((a == b).all() for a, b in zip(drawn[0], sample_rows(lengths, max_samples=max_samples, seed=0)))
        assert len({tuple(int(r[1]) for r in rows) for rows in drawn}) == 4
    for bad in (-1, 2**32, 1.5, True):
        with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 2\*\*32\)"):
            sample_rows(lengths, seed=bad)


def test_fits_under_other_seeds_differ_even_for_a_deterministic_classifier(mixed_demos):
    chosen = baselines.Hyperparameters("logistic_regression", (("C", 1.0),), "ball_relative", 15, False)
    probe = np.concatenate([item.observations for item in bc.labelled(mixed_demos)])
    again, other = (baselines.fit("bc", mixed_demos, hyperparameters=chosen, seed=s) for s in (0, 0))
    assert (again.classifier.predict_proba(features(probe, feature_set="ball_relative"))
            == other.classifier.predict_proba(features(probe, feature_set="ball_relative"))).all()
    other = baselines.fit("bc", mixed_demos, hyperparameters=chosen, seed=1)
    assert not np.array_equal(again.classifier.predict_proba(features(probe, feature_set="ball_relative")),
                              other.classifier.predict_proba(features(probe, feature_set="ball_relative")))


def test_bad_window_label_settings_are_refused_by_name(forward_demos, recognizer):
    with pytest.raises(ValueError, match="window_frames must be an integer ≥ 2, got 1"):
        labels.window_labels(forward_demos, recognizer, window_frames=1)
    with pytest.raises(ValueError, match="stride_frames must be an integer ≥ 1, got 0"):
        labels.window_labels(forward_demos, recognizer, stride_frames=0)
    with pytest.raises(ValueError, match="unknown labels 'frames'; expected one of 'steps', 'segments'"):
        bco.labelled(forward_demos, recognizer=recognizer, labels="frames")
    with pytest.raises(ValueError, match="gap_margin must be a finite number ≥ 0, got nan"):
        labels.window_labels(forward_demos, recognizer, gap_margin=math.nan)
    for labelling in ("steps", "segments"):
        with pytest.raises(ValueError, match="segmenter has no setting 'stop_rotation'; its settings are "):
            bco.labelled(forward_demos, recognizer=recognizer, labels=labelling, segmenter={"stop_rotation": 10.0})


def test_bco_lp_with_weight_zero_equals_fitting_without_that_member(mixed_demos, recognizer):
    weighted = bco_lp.fit(mixed_demos, recognizer=recognizer, weights={"poor": 0.0, "expert": 0.7})
    expert_only = [d for d in mixed_demos if d.demonstrator == "expert"]
    without = bco_lp.fit(expert_only, recognizer=recognizer, weights={"expert": 0.7})
    observations = grid_observations()
    assert (weighted.predict(observations) == without.predict(observations)).all()


def test_numpy_weights_count_as_the_numbers_they_are(mixed_demos, recognizer):
    as_numpy = bco_lp.fit(mixed_demos, recognizer=recognizer, weights={"poor": np.int64(1), "expert": np.float64(0.5)})
    as_python = bco_lp.fit(mixed_demos, recognizer=recognizer, weights={"poor": 1.0, "expert": 0.5})
    observations = grid_observations()
    assert (as_numpy.predict(observations) == as_python.predict(observations)).all()


def test_bc_best_learns_from_the_named_member_only(mixed_demos):
    best = bc_best.fit(mixed_demos, member="expert")
    alone = bc.fit([d for d in mixed_demos if d.demonstrator == "expert"])
    observations = grid_observations()
    assert (best.predict(observations) == alone.predict(observations)).all()
    assert best.method == "bc_best"


def test_random_is_uniform_and_seeded():
    counts = np.bincount(random_primitive.fit(seed=4).predict(np.zeros((50_000, 5))), minlength=5)
    expected = counts.sum() / 5
    assert ((counts - expected) ** 2 / expected).sum() < 18.47  # χ², 4 degrees of freedom, p = 0.001
    first, again, other = (random_primitive.fit(seed=s).predict(np.zeros((100, 5))) for s in (4, 4, 5))
    assert (first == again).all() and not (first == other).all()


def test_a_random_evaluation_repeats_and_chooses_uniformly():
    policy = random_primitive.fit(seed=2, frames_per_action=10)
    one, two = (baselines.evaluate_policy(policy, attempts_per_configuration=3, seed=1) for _ in range(2))
    assert one.behaviours == two.behaviours
    letters = np.array([c for chosen in one.behaviours for c in chosen])
    counts = np.array([(letters == c).sum() for c in "FBLRS"])
    expected = counts.sum() / 5
    assert ((counts - expected) ** 2 / expected).sum() < 18.47


# Evaluation and tuning -------------------------------------------------------------------------

@pytest.fixture(scope="module")
def imitator_evaluation(recognizer):
    demos = polymimic.record("expert", configuration=1, n=2, seed=1) + polymimic.record("poor", configuration=2, n=2)
    trial = polymimic.run_trial(demos, recognizer=recognizer, ordering=["expert", "poor"], seed=0)
    imitator = polymimic.ImitatorPolicy(trial, recognizer=recognizer)
    return polymimic.evaluate(imitator, attempts_per_configuration=3, seed=6)


def start(attempt):
    return attempt.frames[0][["robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"]].tolist()


def test_an_evaluation_starts_where_the_imitators_does(imitator_evaluation):
    ours = baselines.evaluate_policy(random_primitive.fit(), attempts_per_configuration=3, seed=6)
    assert [a.configuration for a in ours.attempts] == [a.configuration for a in imitator_evaluation.attempts]
    assert [a.seed for a in ours.attempts] == [a.seed for a in imitator_evaluation.attempts]
    assert any(a.seed >= 2**63 for a in ours.attempts)  # the seeds a 63-bit binding could not take


def test_every_attempt_seed_reaches_its_episode(imitator_evaluation):
    ours = baselines.evaluate_policy(random_primitive.fit(), attempts_per_configuration=3, seed=6)
    assert [start(a) for a in ours.attempts] == [start(a) for a in imitator_evaluation.attempts]


def test_a_policy_returning_the_wrong_number_of_actions_is_refused():
    class Short(baselines.RandomPolicy):
        def predict(self, observations):
            return super().predict(observations)[:-1]

    with pytest.raises(ValueError, match="returned shape"):
        baselines.evaluate_policy(Short(), attempts_per_configuration=1, seed=0)


# Files ---------------------------------------------------------------------------------------

def test_a_policy_saves_and_loads_back_identically(tmp_path, forward_demos):
    observations = grid_observations()
    for policy in (bc.fit(turning_demonstrations(3, 6)), random_primitive.fit(seed=9)):
        path = tmp_path / f"{policy.method}.pmp"
        policy.save(path)
        loaded = baselines.load_policy(path)
        policy.reset()
        assert (loaded.predict(observations) == policy.predict(observations)).all()
        assert loaded.frames_per_action == policy.frames_per_action


def test_a_policy_saved_with_its_bodys_name_loads_with_that_body(tmp_path):
    from polymimic.baselines.policy_file import write_policy_file

    for name, loads in (("tiny", True), ("rover", False)):
        policy = random_primitive.fit(seed=9)
        policy.body = name  # as a policy kept its body before bodies were values
        path = tmp_path / f"{name}.pmp"
        write_policy_file(path, {"kind": "random", "method": "random", "seed": 9, "body": name,
                                 "frames_per_action": 30}, policy)
        if loads:
            assert baselines.load_policy(path).body == polymimic.Body("tiny")
        else:
            with pytest.raises(polymimic.ModelFileError, match="names its body 'rover', which is not built in"):
                baselines.load_policy(path)


@pytest.mark.parametrize("damage", ["truncate", "flip", "header", "empty"])
def test_a_damaged_policy_file_is_refused_by_name(tmp_path, forward_demos, damage):
    path = tmp_path / "policy.pmp"
    bc.fit(forward_demos).save(path)
    data = bytearray(path.read_bytes())
    if damage == "truncate":
        data = data[: len(data) // 2]
    elif damage == "flip":
        data[-10] ^= 0xFF
    elif damage == "header":
        data[:10] = b"not a file"
    else:
        data = bytearray()
    path.write_bytes(bytes(data))
    with pytest.raises(polymimic.ModelFileError, match="policy.pmp"):
        baselines.load_policy(path)


# Bad input -------------------------------------------------------------------------------------

def test_no_demonstrations_is_refused():
    for method in ("bc", "bco", "bc_best"):
        with pytest.raises(ValueError, match="demonstrations is empty"):
            baselines.fit(method, [], member="x", recognizer=None)


def test_an_unknown_member_is_refused_by_name(mixed_demos):
    with pytest.raises(ValueError, match="unknown member 'novice'.*'expert', 'poor'"):
        bc_best.fit(mixed_demos, member="novice")


@pytest.mark.parametrize("weight", [-0.1, 1.5, math.nan, "high", True])
def test_a_weight_outside_zero_one_is_refused_by_name(mixed_demos, recognizer, weight):
    with pytest.raises(ValueError, match=r"weights\['poor'\] must be a number in \[0, 1\]"):
        bco_lp.fit(mixed_demos, recognizer=recognizer, weights={"poor": weight, "expert": 0.5})


def test_a_missing_weight_and_all_zero_weights_are_refused(mixed_demos, recognizer):
    with pytest.raises(ValueError, match="no weight for demonstrator 'poor'"):
        bco_lp.fit(mixed_demos, recognizer=recognizer, weights={"expert": 0.5})
    with pytest.raises(ValueError, match="every weight 0"):
        bco_lp.fit(mixed_demos, recognizer=recognizer, weights={"expert": 0.0, "poor": 0.0})


def test_an_unknown_method_is_refused_by_name(mixed_demos):
    with pytest.raises(ValueError, match="unknown method 'dagger'; expected one of bc, bco"):
        baselines.fit("dagger", mixed_demos)
    with pytest.raises(ValueError, match="unknown method 'dagger'"):
        baselines.tune("dagger", mixed_demos)


@pytest.mark.parametrize("shape", [(3, 4), (5,), (2, 6)])
def test_a_wrong_length_observation_batch_is_refused(forward_demos, shape):
    for policy in (bc.fit(forward_demos), random_primitive.fit()):
        with pytest.raises(ValueError, match=re.escape("observations must be an (n, 5) batch")) as error:
            policy.predict(np.zeros(shape))
        assert f"got shape {shape}" in str(error.value)


def test_a_missing_recognizer_or_member_is_refused(mixed_demos):
    with pytest.raises(ValueError, match="bco needs recognizer"):
        baselines.fit("bco", mixed_demos)
    with pytest.raises(ValueError, match="recognizer must be a trained polymimic.PrimitiveRecognizer"):
        bco.fit(mixed_demos, recognizer="hmm")
    with pytest.raises(ValueError, match="bc_best needs member"):
        baselines.fit("bc_best", mixed_demos)


def test_max_samples_widens_the_stride_evenly():
    from polymimic.baselines.labels import Labelled
    from polymimic.baselines.training import MAX_DECISION_SAMPLES, decision_samples

    items = [Labelled(f"d{i}", np.full((900, 5), float(i)), np.zeros(900, dtype=np.int64)) for i in range(10)]
    X, _, _ = decision_samples(items)  # the first frame, then every third
    assert 3000 <= len(X) <= 3010
    X, y, w = decision_samples(items, max_samples=1000)  # the first, then every ninth, from every item alike
    assert len(X) == len(y) == len(w) and 1000 <= len(X) <= 1010
    assert all(100 <= int((X[:, 0] == i).sum()) <= 101 for i in range(10))
    from polymimic.benchmark.config import BenchmarkSettings
    assert BenchmarkSettings().tuning.max_decision_samples == MAX_DECISION_SAMPLES


def test_only_the_imitators_own_body_gives_its_first_frame():
    from polymimic.baselines.labels import Labelled
    from polymimic.baselines.training import decision_samples, sample_rows

    # Frame k of each item holds k; the first frame is 0, and a strided sample never is.
    items = [Labelled(f"d_{body}", np.tile(np.arange(300.0)[:, None], (1, 5)), np.zeros(300, dtype=np.int64),
                      body=body) for body in ("lego", "tiny", "humanoid")]
    X, _, _ = decision_samples(items, seed=4)
    starts = X[X[:, 0] == 0.0]
    assert len(starts) == 1  # the Lego's alone
    named = [(item.demonstrator, 300) for item in items]
    with_all = sample_rows(named, seed=4)
    assert sum(len(rows) for rows in with_all) == len(X) + 2  # the same strided frames, two first frames more
    with pytest.raises(ValueError, match=r"first_frames must hold one flag per demonstration \(3\), got 2"):
        sample_rows(named, first_frames=[True, False])


@pytest.mark.parametrize("bad", [0, -5, 2.5, True, "1000"])
def test_a_bad_sample_cap_is_refused_before_any_work(mixed_demos, bad):
    with pytest.raises(ValueError, match=r"max_samples must be an integer ≥ 1 .*got"):
        baselines.fit("bc", mixed_demos, max_samples=bad)
    with pytest.raises(ValueError, match=r"max_samples must be an integer ≥ 1"):
        baselines.tune("bc", mixed_demos, budget=1, attempts_per_configuration=1, max_samples=bad)


def test_bad_hyperparameters_are_refused_by_name():
    with pytest.raises(ValueError, match="unknown classifier 'svm'"):
        baselines.Hyperparameters("svm", (), "raw", 10, True)
    with pytest.raises(ValueError, match="frames_per_action must be an integer ≥ 1, got 0"):
        baselines.Hyperparameters("knn", (), "raw", 0, True)
    with pytest.raises(ValueError, match="budget must be an integer ≥ 1"):
        baselines.candidates(0)


# PPO (optional) ----------------------------------------------------------------------------------

def test_ppo_imports_without_stable_baselines3():
    assert baselines.ppo.available() in (True, False)
    if not baselines.ppo.available():
        with pytest.raises(ModuleNotFoundError, match="stable-baselines3"):
            baselines.ppo.fit(total_timesteps=10)


def test_ppo_trains_evaluates_and_saves_and_leaves_no_log_folder_behind(tmp_path, monkeypatch):
    pytest.importorskip("stable_baselines3")
    import tempfile

    scratch = tmp_path / "tmp"
    scratch.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(scratch))
    policy = baselines.ppo.fit(total_timesteps=128, n_steps=32, batch_size=32, n_epochs=1, seed=0)
    assert not list(scratch.glob("SB3-*"))  # stable-baselines3's own quiet logger makes one
    result = baselines.evaluate_policy(policy, attempts_per_configuration=1, seed=0)
    assert len(result.attempts) == 2
    policy.save(tmp_path / "ppo.pmp")
    observations = grid_observations(20)
    assert (baselines.load_policy(tmp_path / "ppo.pmp").predict(observations) == policy.predict(observations)).all()


def test_a_ball_out_of_sight_is_read_where_it_was_last_seen_or_where_the_configuration_puts_it():
    from polymimic.baselines.evaluation import ball_as_read

    last = np.array([-100.0, 0.0, 0.0, 40.0, -30.0])
    assert ball_as_read((12.0, 5.0), last, robot_x_mm=-100.0, field_length_mm=1020.0) == (12.0, 5.0)
    assert ball_as_read((float("nan"), float("nan")), last, robot_x_mm=-100.0, field_length_mm=1020.0) == (40.0, -30.0)
    assert ball_as_read(None, None, robot_x_mm=-170.0, field_length_mm=1020.0) == (170.0, 0.0)
    assert ball_as_read(None, None, robot_x_mm=93.0, field_length_mm=560.0) == (-560.0 / 6, 0.0)
