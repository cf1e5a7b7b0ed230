"""Tracker logs with gaps: dropped frames and lost readings bridged under ``max_gap_s`` by linear
interpolation, longer gaps still lost tracking, and an import without ``max_gap_s`` as before."""

import re

import pytest
from _track_logs import HEADER, _csv, _readings

import polymimic
from polymimic.tracks import LostTrackingWarning, import_tracks, write_tracks

# Gaps bridged under max_gap_s: a robot speeding up along a curve, so that a bridged frame is
# the straight line between the readings either side, not the curve the tracker missed.

def _curving(n):
    """n readings 1/30 s apart: robot x and y on a parabola, the heading turning, the ball rolling."""
    return [[i / 30, -300 + 3 * i + 0.05 * i**2, 2 * i - 0.03 * i**2, 0.01 * i, 170 + 0.5 * i, 0.2 * i]
            for i in range(n)]


def _dropped_frames():
    """Readings 0–59 as episode 7, with readings 11–24 missing (no reading for 0.5 s after
    reading 10), no robot position in readings 40–44 and no ball x in reading 50: three gaps."""
    rows = _curving(60)
    for i in range(40, 45):
        rows[i][1] = rows[i][2] = ""
    rows[50][4] = ""
    return [[7] + r for i, r in enumerate(rows) if not 11 <= i <= 24]


def _between(truth, column, k, before, after):
    """Column ``column`` of frame ``k`` on the straight line between readings ``before`` and ``after``."""
    a, b = truth[before][column], truth[after][column]
    return a + (b - a) * (k - before) / (after - before)


def test_max_gap_s_bridges_dropped_frames_and_nan_readings_by_linear_interpolation(tmp_path):
    path = _csv(tmp_path, _dropped_frames(), header="episode," + HEADER)
    with pytest.warns(LostTrackingWarning):
        strict = import_tracks(path, demonstrator="x")
    assert strict.invalid == [("7", "lost tracking at 0.33 s (no reading for 0.50 s after data row 11)")]
    assert strict.gaps_bridged == [] and not strict.demonstrations

    imported = import_tracks(path, demonstrator="x", max_gap_s=0.6)
    assert repr(imported) == "1 episode from log.csv: 1 demonstration (3 gaps bridged), 0 invalid"
    assert imported.gaps_bridged == [3]
    frames = imported.demonstrations[0].frames
    assert len(frames) == 60 and imported.demonstrations[0].outcome == "time_up"
    truth = _curving(60)
    for k in range(11, 25):  # the 0.5 s hole: every value on the line from reading 10 to reading 25
        for column, name in enumerate(("robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"), 1):
            assert frames[name][k] == pytest.approx(_between(truth, column, k, 10, 25)), (k, name)
    assert frames["robot_x_mm"][17] != pytest.approx(truth[17][1], abs=1.0)  # not the curve itself
    for k in range(40, 45):  # no robot position: the line from reading 39 to 45; the ball as read
        assert frames["robot_x_mm"][k] == pytest.approx(_between(truth, 1, k, 39, 45))
        assert frames["robot_y_mm"][k] == pytest.approx(_between(truth, 2, k, 39, 45))
        assert (frames["ball_x_mm"][k], frames["robot_theta_rad"][k]) == pytest.approx((truth[k][4], truth[k][3]))
    assert frames["ball_x_mm"][50] == pytest.approx((truth[49][4] + truth[51][4]) / 2)
    assert frames["robot_x_mm"][50] == pytest.approx(truth[50][1])
    for k in (*range(11), *range(25, 40), *range(45, 50), *range(51, 60)):  # read, not bridged: as read
        assert frames["robot_x_mm"][k] == pytest.approx(truth[k][1])


def test_a_gap_longer_than_max_gap_s_is_still_lost_tracking_and_names_it(tmp_path):
    path = _csv(tmp_path, _dropped_frames(), header="episode," + HEADER)
    with pytest.warns(LostTrackingWarning, match="max_gap_s=0.4"):
        short = import_tracks(path, demonstrator="x", max_gap_s=0.4)
    assert short.invalid == [("7", "lost tracking at 0.33 s (no reading for 0.50 s after data row 11, longer than "
                                   "max_gap_s=0.4)")]
    rows = _dropped_frames()[11:]  # the readings after the hole: its NaN runs as episode 7
    with pytest.warns(LostTrackingWarning):
        nan_run = import_tracks(_csv(tmp_path, rows, header="episode," + HEADER, name="nan.csv"), demonstrator="x",
                                max_gap_s=0.15)
    assert nan_run.invalid == [("7", "lost tracking at 0.50 s (data rows 16–20: no robot_x_mm, robot_y_mm; 0.20 s "
                                     "between readings, longer than max_gap_s=0.15)")]
    # max_gap_s is the longest pause bridged: below three periods it refuses what the default takes.
    skipped = [r for i, r in enumerate(_readings(10)) if i != 5]  # one reading missing: 0.07 s
    path = _csv(tmp_path, skipped, name="skipped.csv")
    assert not import_tracks(path, demonstrator="x").invalid
    with pytest.warns(LostTrackingWarning):
        strict = import_tracks(path, demonstrator="x", max_gap_s=0.05)
    assert strict.invalid == [(0, "lost tracking at 0.13 s (no reading for 0.07 s after data row 5, longer than "
                                  "max_gap_s=0.05)")]


def test_nan_readings_at_an_episodes_start_or_end_are_never_bridged(tmp_path):
    rows = _readings(10)
    rows[0][4] = rows[1][4] = ""
    rows[9][5] = ""
    with pytest.warns(LostTrackingWarning):
        start = import_tracks(_csv(tmp_path, rows), demonstrator="x", max_gap_s=1.0)
    assert start.invalid == [(0, "lost tracking at 0.00 s (data rows 1–2: no ball_x_mm; at the episode's start, no "
                                 "reading before to interpolate from)")]
    rows[0][4] = rows[1][4] = 170.0
    with pytest.warns(LostTrackingWarning):
        end = import_tracks(_csv(tmp_path, rows, name="end.csv"), demonstrator="x", max_gap_s=1.0)
    assert end.invalid == [(0, "lost tracking at 0.30 s (data row 10: no ball_y_mm; at the episode's end, no reading "
                               "after to interpolate from)")]


def test_without_an_episode_column_max_gap_s_bridges_nothing_an_episode_cut_would_cut(tmp_path):
    # A pause over 0.5 s starts a new episode, whatever max_gap_s says.
    first = _readings(10)
    pauses = first + _readings(10, start_s=first[-1][0] + 0.6)
    imported = import_tracks(_csv(tmp_path, pauses), demonstrator="x", max_gap_s=1.0)
    assert imported.episodes == 2 and [len(d.frames) for d in imported.demonstrations] == [10, 10]
    assert imported.gaps_bridged == [0, 0]
    # NaN readings lasting over 0.5 s are not bridged there; with an episode column they are.
    blind = _readings(40)
    for row in blind[5:24]:  # readings 4 to 24 with every value: 0.67 s apart
        row[4] = row[5] = ""
    with pytest.warns(LostTrackingWarning):
        cut = import_tracks(_csv(tmp_path, blind, name="blind.csv"), demonstrator="x", max_gap_s=1.0)
    assert cut.invalid == [(0, "lost tracking at 0.17 s (data rows 6–24: no ball_x_mm, ball_y_mm; 0.67 s between "
                               "readings, longer than the 0.5 s pause that starts an episode in a log without an "
                               "episode column)")]
    named = import_tracks(_csv(tmp_path, [[0] + r for r in blind], header="episode," + HEADER, name="named.csv"),
                          demonstrator="x", max_gap_s=1.0)
    assert named.gaps_bridged == [1] and not named.invalid
    # Nor NaN readings across which the ball was put back, as a reset would be cut.
    reset = _readings(20, ball=(500.0, 0.0))
    for i, row in enumerate(reset):
        row[4] = "" if 8 <= i < 12 else (500.0 if i < 8 else 170.0)
    with pytest.warns(LostTrackingWarning, match="the robot or the ball moved 330 mm across it, as far as a reset"):
        import_tracks(_csv(tmp_path, reset, name="reset.csv"), demonstrator="x", max_gap_s=1.0)


def test_without_max_gap_s_imports_are_as_before_and_clean_logs_the_same_with_it(tmp_path):
    demos = polymimic.record("expert", configuration=1, n=3, seed=5)
    write_tracks(demos, tmp_path / "log.csv", rate_hz=45, include=("episode",))
    default = import_tracks(tmp_path / "log.csv", demonstrator="x", rate_hz=45)
    same = import_tracks(tmp_path / "log.csv", demonstrator="x", rate_hz=45, max_gap_s=None)
    bridging = import_tracks(tmp_path / "log.csv", demonstrator="x", rate_hz=45, max_gap_s=0.1)
    assert repr(default) == repr(same) == repr(bridging) == "3 episodes from log.csv: 3 demonstrations, 0 invalid"
    assert default.gaps_bridged == same.gaps_bridged == bridging.gaps_bridged == [0, 0, 0]
    for a, b, c in zip(default.demonstrations, same.demonstrations, bridging.demonstrations):
        assert a.frames.tobytes() == b.frames.tobytes() == c.frames.tobytes() and a.outcome == b.outcome == c.outcome


@pytest.mark.parametrize("bad", [-0.1, -1, float("nan"), float("inf"), -float("inf"), 10**400, True, False, "0.5",
                                 [0.5]], ids=lambda bad: repr(bad)[:8])
def test_a_bad_max_gap_s_is_refused_before_the_log_is_read(tmp_path, bad):
    message = rf"max_gap_s must be a finite number of seconds, at least 0 \(or None: .*\), got {re.escape(repr(bad))}$"
    with pytest.raises(ValueError, match=message):
        import_tracks(tmp_path / "absent.csv", demonstrator="x", max_gap_s=bad)  # no FileNotFoundError: not read
