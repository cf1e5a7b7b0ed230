"""PrimitiveRecognizer on synthetic unicycle motion whose truth is known."""

import pickle

import numpy as np
import pytest

import polymimic

MOTION = {"forward": (42.0, -1.0), "backward": (-48.0, 2.0), "left": (4.0, 30.0), "right": (3.0, -29.0),
          "stop": (0.0, 0.0)}
FRAME_FIELDS = [("robot_x_mm", "f8"), ("robot_y_mm", "f8"), ("robot_theta_rad", "f8"), ("ball_x_mm", "f8"),
                ("ball_y_mm", "f8")]


def unicycle(primitive, n_frames, rng, start=None):
    speed, turn = (m * rng.uniform(0.9, 1.1) for m in MOTION[primitive])
    x, y, theta = start if start is not None else (rng.uniform(-300, 300), rng.uniform(-200, 200), rng.uniform(-3, 3))
    poses = []
    for _ in range(n_frames):
        poses.append((x, y, theta))
        x += speed / 30 * np.cos(theta)
        y += speed / 30 * np.sin(theta)
        theta = (theta + np.deg2rad(turn) / 30 + np.pi) % (2 * np.pi) - np.pi
    return np.array(poses)


@pytest.fixture(scope="module")
def observed():
    rng = np.random.default_rng(5)
    labels = [p for p in MOTION for _ in range(60)]
    return [unicycle(p, 30, rng) for p in labels], labels


@pytest.fixture(scope="module")
def recognizer(observed):
    sequences, labels = observed
    return polymimic.PrimitiveRecognizer.train(sequences, labels, n_states=3, codebook_size=64, seed=1)


def test_classifies_held_out_motion(recognizer):
    rng = np.random.default_rng(9)
    for primitive in ("forward", "backward", "left", "right"):
        named = [recognizer.classify(unicycle(primitive, 30, rng)) for _ in range(20)]
        assert named.count(primitive) >= 18, (primitive, named)


def test_table_3_1_of_the_training_set(recognizer):
    stats = recognizer.motion_stats()
    assert stats["forward"]["count"] == 60
    assert stats["forward"]["distance_mean_mm"] == pytest.approx(42 * 29 / 30, abs=2)
    assert stats["right"]["rotation_mean_deg"] == pytest.approx(-29 * 29 / 30, abs=1.5)


def test_each_model_reads_its_own_representation(recognizer):
    assert recognizer.representations == {"forward": "positional", "backward": "positional",
                                          "left": "rotational", "right": "rotational"}
    assert recognizer.hmm("left").n_states == 3 and recognizer.codebook("left").size == 64


def test_segments_a_structured_demonstration(recognizer):
    rng = np.random.default_rng(2)
    stop = unicycle("stop", 25, rng, start=(0.0, 0.0, 0.0))
    turn = unicycle("left", 200, rng, start=tuple(stop[-1]))
    poses = np.concatenate([stop, turn])
    frames = np.zeros(len(poses), dtype=FRAME_FIELDS)
    frames["robot_x_mm"], frames["robot_y_mm"], frames["robot_theta_rad"] = poses.T
    segments = recognizer.segment(frames)
    assert segments["label"][0] == "stop"
    assert set(segments["label"][1:]) == {"left"}
    assert segments["start"].shape == (len(segments["label"]), 5)
    np.testing.assert_array_equal(segments["last_frame"][:-1], segments["first_frame"][1:])


def test_bad_frames_are_named(recognizer):
    with pytest.raises(ValueError, match="frame 2 is not finite"):
        recognizer.classify(np.array([[0, 0, 0], [1, 0, 0], [np.nan, 0, 0]], dtype=float))
    with pytest.raises(ValueError, match="has 4 frames; at least 10"):
        recognizer.segment(np.zeros((4, 5)))
    with pytest.raises(ValueError, match='no field "ball_x_mm"'):
        recognizer.segment(np.zeros(12, dtype=FRAME_FIELDS[:3]))
    with pytest.raises(ValueError, match="expected at least 3"):
        recognizer.classify(np.zeros((5, 2)))
    with pytest.raises(ValueError, match='unknown primitive "jump"'):
        polymimic.PrimitiveRecognizer.train([np.zeros((5, 3))], ["jump"])
    with pytest.raises(ValueError, match="no training sequences of backward"):
        polymimic.PrimitiveRecognizer.train([np.zeros((5, 3))], ["forward"])


def test_frames_whose_time_runs_backwards_are_refused_at_that_frame(recognizer):
    demo = polymimic.record("expert", configuration=1, n=1, seed=4)[0]
    frames = demo.frames.copy()
    frames["t_s"][40] = frames["t_s"][38]
    with pytest.raises(ValueError, match=r"^demonstration: frame 40 has t_s 1.2666\d* s, before frame 39's 1.3 s; "
                                         r"time must not run backwards$"):
        recognizer.segment(frames)
    with pytest.raises(ValueError, match=r"^demonstration 1: frame 40 has t_s"):
        recognizer.segment_many([demo.frames, frames])
    with pytest.raises(ValueError, match="frame 40 has t_s"):
        polymimic.learning.segmented([polymimic.Demonstration(frames, "goal", "expert", 1, 0)], recognizer)
    frames["t_s"][40] = np.nan
    with pytest.raises(ValueError, match=r"^demonstration: frame 40 has t_s NaN; every frame needs its time$"):
        recognizer.segment(frames)
    frames["t_s"][40] = frames["t_s"][39]  # a repeated time is not a step back
    assert len(recognizer.segment(frames)["label"]) == len(recognizer.segment(demo.frames)["label"])


def test_save_load_and_pickle(tmp_path, recognizer, observed):
    recognizer.save(tmp_path / "r.json")
    loaded = polymimic.PrimitiveRecognizer.load(tmp_path / "r.json")
    seq = observed[0][3]
    np.testing.assert_array_equal(loaded.log_likelihoods(seq), recognizer.log_likelihoods(seq))
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(recognizer)).log_likelihoods(seq),
                                  recognizer.log_likelihoods(seq))
    polymimic.Codebook(np.eye(3)).save(tmp_path / "c.json")
    with pytest.raises(polymimic.ModelFileError, match="expected format"):
        polymimic.PrimitiveRecognizer.load(tmp_path / "c.json")


def test_reads_fields_of_structured_arrays_with_odd_strides(recognizer):
    # A uint16 column makes the record 50 bytes long: no float field is 8-byte aligned.
    odd = np.dtype(FRAME_FIELDS[:3] + [("command", "u2")])
    rng = np.random.default_rng(1)
    poses = unicycle("forward", 30, rng)
    frames = np.zeros(30, dtype=odd)
    frames["robot_x_mm"], frames["robot_y_mm"], frames["robot_theta_rad"] = poses.T
    np.testing.assert_array_equal(recognizer.log_likelihoods(frames), recognizer.log_likelihoods(poses))
