"""Minari datasets out and back: the environment's steps, rewards and ends, each episode's
metadata, and the refusals (an existing id, a body the environment does not simulate)."""

import numpy as np
import pytest

minari = pytest.importorskip("minari")

import polymimic  # noqa: E402
from polymimic import export, recognition  # noqa: E402
from polymimic.field import PRIMITIVES, as_frames  # noqa: E402


@pytest.fixture(autouse=True)
def datasets_here(tmp_path, monkeypatch):
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "minari"))


WHO = {"author": "polymimic tests", "author_email": "tests@polymimic.invalid", "code_permalink": "tests/library"}


@pytest.fixture(scope="module")
def expert():
    return [d for c in (1, 2) for d in polymimic.record("expert", configuration=c, n=2, seed=8)]


def _scripted(command, n_frames, seed=0):
    """A demonstration of the Lego robot sending one primitive throughout, from configuration 1."""
    episode = polymimic.Episode("lego", configuration=1, seed=seed)
    frames, outcome = episode.run([command] * (n_frames - 1))
    return polymimic.Demonstration(frames=as_frames(frames), outcome=outcome or "time_up", demonstrator="poor",
                                   configuration=1, seed=seed)


def test_steps_cut_the_frames_as_the_environment_steps():
    demo = _scripted("forward", 62)
    n = len(demo.frames)
    steps = export.steps_of(demo, step_frames=30, actions="commands")
    ends = [min(k * 30, n - 1) for k in range(1, -(-(n - 1) // 30) + 1)]
    assert len(steps.actions) == len(ends) and len(steps.observations) == len(ends) + 1
    columns = np.column_stack([demo.frames[c] for c in export.OBSERVED]).astype(np.float32)
    np.testing.assert_array_equal(steps.observations, columns[[0, *ends]])
    assert steps.actions.tolist() == [PRIMITIVES.index("forward")] * len(ends)
    assert steps.terminations.sum() + steps.truncations.sum() == 1
    assert (steps.truncations[-1] if demo.outcome == "time_up" else steps.terminations[-1])


def test_a_dropout_repeats_the_last_good_reading():
    demo = _scripted("stop", 40)
    frames = demo.frames.copy()
    frames["ball_x_mm"][30] = np.nan
    steps = export.steps_of(polymimic.Demonstration(frames=frames, outcome="time_up", demonstrator="poor",
                                                    configuration=1, seed=0), actions="commands")
    assert steps.observations[1, 3] == np.float32(frames["ball_x_mm"][29])


def test_a_reading_lost_from_the_start_takes_the_first_good_one():
    demo = _scripted("stop", 40)
    frames = demo.frames.copy()
    frames["ball_x_mm"][:3] = np.nan
    steps = export.steps_of(polymimic.Demonstration(frames=frames, outcome="time_up", demonstrator="poor",
                                                    configuration=1, seed=0), actions="commands")
    assert steps.observations[0, 3] == np.float32(frames["ball_x_mm"][3])
    assert np.isfinite(steps.observations).all()


def test_commands_round_trip_through_minari(expert):
    dataset = export.to_minari(expert, "polymimic/expert-v0", actions="commands", **WHO)
    loaded = minari.load_dataset("polymimic/expert-v0")
    assert loaded.total_episodes == len(expert)
    assert loaded.storage.metadata["learned_from_observation"] is False
    for demo, episode, meta in zip(expert, loaded.iterate_episodes(),
                                   loaded.storage.get_episode_metadata(range(len(expert)))):
        steps = export.steps_of(demo, actions="commands")
        np.testing.assert_array_equal(episode.observations, steps.observations)
        np.testing.assert_array_equal(episode.actions, steps.actions)
        np.testing.assert_array_equal(episode.rewards, steps.rewards)
        assert episode.rewards[-1] == {"goal": 1.0, "own_goal": -1.0}.get(demo.outcome, 0.0)
        np.testing.assert_array_equal(episode.terminations, steps.terminations)
        assert (meta["demonstrator"], meta["body"], meta["configuration"], meta["outcome"]) == (
            "expert", "lego", demo.configuration, demo.outcome)
        assert int(meta["episode_seed"]) == demo.seed
    back = export.from_minari(dataset)
    assert [(d.demonstrator, d.configuration, d.seed, d.outcome) for d in back] == [
        (d.demonstrator, d.configuration, d.seed, d.outcome) for d in expert]
    again = export.steps_of(back[0], step_frames=1, actions="commands")
    np.testing.assert_array_equal(again.observations, export.steps_of(expert[0], actions="commands").observations)


def test_the_recognizers_actions_are_learned_from_observation(expert):
    recognizer = recognition.train_recognizer(polymimic.self_observation(40, seed=2), codebook_size=32)
    forward = _scripted("forward", 91)
    dataset = export.to_minari([forward, *expert], "polymimic/observed-v0", recognizer=recognizer, **WHO)
    assert dataset.storage.metadata["learned_from_observation"] is True
    assert dataset.storage.metadata["polymimic_actions"] == "recognizer"
    first = next(dataset.iterate_episodes())
    assert first.actions.tolist() == [PRIMITIVES.index("forward")] * len(first.actions)


def test_refusals_name_what_is_wrong(expert):
    export.to_minari(expert[:1], "polymimic/once-v0", actions="commands", **WHO)
    with pytest.raises(ValueError, match="'polymimic/once-v0' exists already: pass overwrite=True"):
        export.to_minari(expert[:1], "polymimic/once-v0", actions="commands", **WHO)
    assert export.to_minari(expert, "polymimic/once-v0", actions="commands", overwrite=True, **WHO).total_episodes == 4
    tiny = polymimic.record("tiny", configuration=1, n=1, seed=1)
    with pytest.raises(ValueError, match=r"demonstration 1 \(tiny\) is of the tiny body; PenaltyKick-v0 simulates"):
        export.to_minari([expert[0], *tiny], "polymimic/mixed-v0", actions="commands", **WHO)
    with pytest.raises(ValueError, match="actions must be one of 'recognizer', 'commands', got 'cmds'"):
        export.to_minari(expert, "polymimic/x-v0", actions="cmds", **WHO)
    with pytest.raises(ValueError, match='actions="recognizer" needs the recognizer='):
        export.to_minari(expert, "polymimic/x-v0", **WHO)
    with pytest.raises(ValueError, match="no demonstrations"):
        export.to_minari([], "polymimic/x-v0", **WHO)
    with pytest.raises(ValueError, match="step_frames must be an integer ≥ 1, got 0"):
        export.steps_of(expert[0], step_frames=0, actions="commands")


def _shifting(commands, seed=0):
    """A demonstration of the Lego robot sending each of ``commands`` for one 30-frame step."""
    episode = polymimic.Episode("lego", configuration=1, seed=seed)
    frames, outcome = episode.run([c for c in commands for _ in range(30)])
    return polymimic.Demonstration(frames=as_frames(frames), outcome=outcome or "time_up", demonstrator="poor",
                                   configuration=1, seed=seed)


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(40, seed=2), codebook_size=32)


def test_each_step_is_named_by_the_second_of_motion_from_it(recognizer):
    # Each primitive sent for two steps: in the second the robot moves as the primitive alone
    # moves it (the first still carries the last one's momentum), so its name is known.
    held = ["forward", "left", "stop", "right", "backward"]
    right_by_steps = right_by_segments = 0
    for seed in range(3):
        demo = _shifting([c for c in held for _ in range(2)], seed=seed)
        steps = export.steps_of(demo, recognizer=recognizer)
        assert [PRIMITIVES[a] for a in steps.actions[1::2]] == held
        assert not steps.gap[1::2].any()
        sent = np.repeat([PRIMITIVES.index(c) for c in held], 2)
        right_by_steps += int((steps.actions == sent).sum())
        segments = export.steps_of(demo, recognizer=recognizer, labels="segments")
        right_by_segments += int((segments.actions == sent).sum())
    # A segment grows past a step's second: named by their segments, fewer steps are right.
    assert right_by_steps > right_by_segments


def test_a_step_too_close_to_call_takes_its_nearest_named_steps_primitive():
    chosen, gap = export._nearest_named(np.array([-1, 2, -1, -1, 0]))
    assert chosen.tolist() == [2, 2, 2, 0, 0] and gap.tolist() == [True, False, True, True, False]
    chosen, _ = export._nearest_named(np.array([1, -1, 3]))
    assert chosen.tolist() == [1, 1, 3], "a tie goes to the earlier step"
    with pytest.raises(ValueError, match="names no step of this demonstration: every second is a gap"):
        export._nearest_named(np.array([-1, -1]))


def test_each_episode_carries_its_demonstrators_lapse(expert, recognizer):
    poor = polymimic.record("poor", configuration=1, n=1, seed=3)
    dataset = export.to_minari([*expert, *poor], "polymimic/lapses-v0", recognizer=recognizer,
                               lapses={"expert": 0.25}, **WHO)
    meta = list(dataset.storage.get_episode_metadata(range(dataset.total_episodes)))
    assert [(m["demonstrator"], m["lapse"]) for m in meta] == [("expert", 0.25)] * len(expert) + [("poor", 0.0)]
    assert dataset.storage.metadata["polymimic_labels"] == "steps"
    with pytest.raises(ValueError, match=r"lapses\['expert'\] must be a number in \[0, 1\], got 1.5"):
        export.to_minari(expert, "polymimic/x-v0", recognizer=recognizer, lapses={"expert": 1.5}, **WHO)
    with pytest.raises(ValueError, match="lapses names 'tiny', who demonstrates none of these; they are by expert"):
        export.to_minari(expert, "polymimic/x-v0", recognizer=recognizer, lapses={"tiny": 0.1}, **WHO)
    with pytest.raises(ValueError, match="labels must be one of 'steps', 'segments', got 'frames'"):
        export.steps_of(expert[0], recognizer=recognizer, labels="frames")


def test_lapses_may_be_numpy_numbers_but_not_truth_values_or_nan():
    checked = export._checked_lapses({"expert": np.int64(1), "poor": np.float64(0.1)}, {"expert", "poor"})
    assert checked == {"expert": 1.0, "poor": 0.1} and all(type(v) is float for v in checked.values())
    assert export._checked_lapses({"poor": np.float32(0.5)}, {"poor"}) == {"poor": 0.5}
    for bad in (True, np.bool_(False), np.float64(np.nan), np.int64(2), -0.1, "0.1"):
        with pytest.raises(ValueError, match=r"lapses\['poor'\] must be a number in \[0, 1\]"):
            export._checked_lapses({"poor": bad}, {"poor"})


def test_a_misspelt_segmenter_setting_is_refused_under_either_labelling(expert, recognizer):
    for labels in export.LABELS:
        with pytest.raises(ValueError, match="segmenter has no setting 'gap_margn'; its settings are min_frames"):
            export.steps_of(expert[0], recognizer=recognizer, labels=labels, segmenter={"gap_margn": 5.0})
    with pytest.raises(ValueError, match="gap_margin must be a finite number ≥ 0, got -1.0"):
        export.steps_of(expert[0], recognizer=recognizer, segmenter={"gap_margin": -1.0})


def test_a_failed_overwrite_keeps_the_old_dataset(expert):
    export.to_minari(expert[:1], "polymimic/keep-v0", actions="commands", **WHO)
    with pytest.raises(ValueError, match="labels must be one of"):
        export.to_minari(expert, "polymimic/keep-v0", actions="commands", labels="frames", overwrite=True, **WHO)
    assert minari.load_dataset("polymimic/keep-v0").total_episodes == 1


class _Impossible:
    """A recogniser to which every window is impossible: every HMM scores it −inf."""

    def log_likelihoods_many(self, windows):
        return np.full((len(windows), 4), -np.inf)


def test_a_window_no_hmm_can_have_made_is_a_gap():
    from polymimic.window_names import NO_NAME, name_windows

    demo = _scripted("forward", 70)
    assert name_windows(demo.frames, _Impossible(), [0, 30]).tolist() == [NO_NAME, NO_NAME]
