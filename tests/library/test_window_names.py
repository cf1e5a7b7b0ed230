"""Naming windows: the settings and starts refused by name, and lost readings filled from the
nearest good one."""

import math

import numpy as np
import pytest

import polymimic
from polymimic.field import as_frames
from polymimic.window_names import NO_NAME, name_windows, repeat_last_good, segmenter_settings, window_settings


class _Impossible:
    """A recogniser to which every window is impossible: every HMM scores it −inf."""

    def log_likelihoods_many(self, windows):
        return np.full((len(windows), 4), -np.inf)


@pytest.fixture(scope="module")
def frames():
    frames, _ = polymimic.Episode("lego", configuration=1, seed=0).run(["forward"] * 60)
    return as_frames(frames)


def test_a_misspelt_segmenter_setting_is_refused_by_name():
    with pytest.raises(ValueError, match="segmenter has no setting 'gap_margn'; its settings are min_frames, "
                                         "stop_distance_mm, stop_rotation_deg, limit_sds, gap_margin"):
        window_settings({"gap_margin": 1.0, "gap_margn": 3.0})
    with pytest.raises(ValueError, match="segmenter has no setting 'stop_distance', 'window'"):
        segmenter_settings({"stop_distance": 1.0, "window": 30})


def test_window_settings_keep_the_segmenters_window_tolerances_only():
    assert window_settings({"min_frames": 12, "limit_sds": 3.0, "gap_margin": 1.5, "stop_distance_mm": 2.0}) == {
        "gap_margin": 1.5, "stop_distance_mm": 2.0}
    assert window_settings(None) == {}


@pytest.mark.parametrize("name", ["gap_margin", "stop_distance_mm", "stop_rotation_deg"])
@pytest.mark.parametrize("value", [-0.5, math.nan, math.inf, True, "2"])
def test_a_bad_tolerance_or_gap_margin_is_refused_by_name(frames, name, value):
    with pytest.raises(ValueError, match=f"{name} must be a finite number ≥ 0, got {value!r}"):
        name_windows(frames, _Impossible(), [0, 30], **{name: value})


def test_numpy_tolerances_and_zero_are_taken(frames):
    named = name_windows(frames, _Impossible(), np.array([0, 30]), gap_margin=np.float64(0.0),
                         stop_distance_mm=np.int64(0), stop_rotation_deg=np.float32(20.0))
    assert named.tolist() == [NO_NAME, NO_NAME]


@pytest.mark.parametrize(("starts", "message"), [
    ([0, -1], r"starts\[1\] = -1 is not a frame index of these 60 frames \(0 to 59\)"),
    ([0, 60], r"starts\[1\] = 60 is not a frame index of these 60 frames \(0 to 59\)"),
    ([0, 30, 10], r"starts must not decrease: starts\[2\] = 10 follows starts\[1\] = 30"),
    ([0.0, 30.0], r"starts must be a sequence of integer frame indices, got \[0.0, 30.0\]"),
    ([True, False], r"starts must be a sequence of integer frame indices"),
    ([[0, 30]], r"starts must be a sequence of integer frame indices"),
])
def test_bad_starts_are_refused_by_name(frames, starts, message):
    with pytest.raises(ValueError, match=message):
        name_windows(frames, _Impossible(), starts)


def test_starts_may_repeat_be_numpy_integers_or_be_empty(frames):
    assert name_windows(frames, _Impossible(), np.array([0, 0, 59], dtype=np.int32)).tolist() == [NO_NAME] * 3
    assert name_windows(frames, _Impossible(), []).tolist() == []


def test_a_lost_reading_repeats_the_last_good_one_and_the_first_good_one_before_any():
    values = np.array([math.nan, math.nan, 1.0, math.nan, 3.0, math.nan])
    assert repeat_last_good(values).tolist() == [1.0, 1.0, 1.0, 1.0, 3.0, 3.0]
    assert np.isnan(values[0]), "the input is left as it was"


def test_each_column_is_filled_on_its_own_and_a_column_never_seen_stays_lost():
    values = np.array([[math.nan, 5.0, math.nan],
                       [2.0, math.nan, math.nan],
                       [math.nan, 7.0, math.nan]], dtype=np.float32)
    filled = repeat_last_good(values)
    assert filled.dtype == np.float32
    np.testing.assert_array_equal(filled[:, :2], [[2.0, 5.0], [2.0, 5.0], [2.0, 7.0]])
    assert np.isnan(filled[:, 2]).all()
    assert repeat_last_good(np.zeros((0, 5))).shape == (0, 5)
