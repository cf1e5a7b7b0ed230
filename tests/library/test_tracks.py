"""Tracker logs: round trips through other units and rates, known answers, and bad logs refused
with the file, row and column named."""

import csv
import math

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from _track_logs import HEADER, _csv, _readings
from hypothesis import given, settings
from hypothesis import strategies as st

import polymimic
from polymimic import recognition
from polymimic.baselines.labels import command_labels
from polymimic.export import steps_of
from polymimic.field import UNKNOWN_COMMAND, primitives_sent
from polymimic.tracks import LostTrackingWarning, TrackLogError, import_tracks, write_tracks
from polymimic.tracks.resampling import heading

METRES_DEGREES = {"length": "m", "angle": "deg"}
POSITIONS = ("robot_x_mm", "robot_y_mm", "ball_x_mm", "ball_y_mm")


def _errors(original, imported):
    """The largest position error (mm) and heading error (deg, along the shorter arc)."""
    a, b = original.frames, imported.frames
    position_mm = max(float(np.abs(a[c] - b[c]).max()) for c in POSITIONS)
    turn = np.angle(np.exp(1j * (a["robot_theta_rad"] - b["robot_theta_rad"])))
    return position_mm, float(np.degrees(np.abs(turn).max()))


def _round_trip(demos, path, rate_hz, **write):
    write_tracks(demos, path, units=METRES_DEGREES, rate_hz=rate_hz, **write)
    return import_tracks(path, demonstrator="tracked", body=demos[0].body, units=METRES_DEGREES, rate_hz=rate_hz)


@settings(max_examples=24, deadline=None, derandomize=True)
@given(who=st.sampled_from(polymimic.field.DEMONSTRATORS), configuration=st.sampled_from((1, 2)),
       seed=st.integers(0, 2**32), lapse=st.sampled_from((0.0, 0.9)), parquet=st.booleans())
def test_a_log_in_metres_and_degrees_at_60_hz_comes_back_as_the_demonstrations(tmp_path_factory, who, configuration,
                                                                               seed, lapse, parquet):
    demos = polymimic.record(who, configuration=configuration, n=2, seed=seed, lapse=lapse)
    path = tmp_path_factory.mktemp("logs") / ("log.parquet" if parquet else "log.csv")
    imported = _round_trip(demos, path, 60, include=("episode", "command"))  # no outcome: derived
    assert imported.episodes == 2 and not imported.invalid
    for original, again in zip(demos, imported.demonstrations):
        assert len(again.frames) == len(original.frames)
        position_mm, heading_deg = _errors(original, again)
        assert position_mm < 0.5 and heading_deg < 0.5
        assert again.outcome == original.outcome
        assert again.configuration == original.configuration
        assert (again.frames["command"] == original.frames["command"]).all()
        assert np.allclose(again.frames["t_s"], np.arange(len(again.frames)) / 30.0, atol=1e-9)
        assert again.demonstrator == "tracked" and again.body == original.body


@pytest.fixture(scope="module")
def sample():
    """Demonstrations of every demonstrator, configuration and lapse, every outcome among them."""
    demos = []
    for i, who in enumerate(polymimic.field.DEMONSTRATORS):
        for configuration in (1, 2):
            for lapse in (0.0, 0.9):
                demos += polymimic.record(who, configuration=configuration, n=4, seed=100 + i, lapse=lapse)
    return demos


# At 60 Hz every frame is a reading: errors are rounding (measured 3e-11 mm, 1e-10°). At 45 and
# 20 Hz most frames fall between readings that are themselves blends of frames: what is lost is
# a frame's departure from its neighbours' straight line, the heading jitter (σ 3°, spikes to
# 15°) and the ball's jolt at a kick. studies/what_a_tracker_log_loses.py, 128 episodes: 45 Hz up to
# 2.7 mm and 8.1° (95th percentile 1.2 mm, 6.9°); 20 Hz up to 5.3 mm and 15.3° (4.7 mm, 14.6°).
@pytest.mark.parametrize(("rate_hz", "bound_mm", "bound_deg"), [(60, 0.5, 0.5), (45, 5.0, 15.0), (20, 10.0, 30.0)])
def test_other_rates_keep_every_frame_and_outcome_within_a_measured_error(sample, tmp_path, rate_hz, bound_mm,
                                                                          bound_deg):
    errors, agree = [], 0
    for body in polymimic.field.BODY_NAMES:
        demos = [d for d in sample if d.body.name == body]
        imported = _round_trip(demos, tmp_path / f"{body}.csv", rate_hz, include=())  # episodes cut by the gaps
        assert imported.episodes == len(demos)
        for original, again in zip(demos, imported.demonstrations):
            assert len(again.frames) == len(original.frames)
            errors.append(_errors(original, again))
            agree += again.outcome == original.outcome
    errors = np.array(errors)
    assert errors[:, 0].max() < bound_mm and errors[:, 1].max() < bound_deg
    assert agree == len(sample)  # the outcome read off the geometry is the simulator's, every time
    assert {d.outcome for d in sample} >= {"goal", "own_goal", "robot_out", "time_up"}


def test_without_the_line_tolerance_jitter_ends_some_episodes_early(sample, tmp_path):
    # Why the tolerance: a ball pushed slowly over the line sits on it, and the tracker's
    # jitter puts a reading past it early, or the final reading back inside.
    demos = [d for d in sample if d.body.name == "lego"]
    write_tracks(demos, tmp_path / "log.csv", include=("episode",))
    strict = import_tracks(tmp_path / "log.csv", demonstrator="x", line_tolerance_mm=0.0).demonstrations
    tolerant = import_tracks(tmp_path / "log.csv", demonstrator="x").demonstrations
    assert all(a.outcome == d.outcome and len(a.frames) == len(d.frames) for a, d in zip(tolerant, demos))
    assert any(a.outcome != d.outcome or len(a.frames) != len(d.frames) for a, d in zip(strict, demos))


@pytest.fixture(scope="module")
def recognizer():
    return recognition.train_recognizer(polymimic.self_observation(40, seed=1), codebook_size=32)


def test_segmenting_the_imported_expert_gives_the_originals_labels(recognizer, tmp_path):
    experts = (polymimic.record("expert", configuration=1, n=10, seed=8)
               + polymimic.record("expert", configuration=2, n=10, seed=9))
    imported = _round_trip(experts, tmp_path / "expert.parquet", 60).demonstrations
    same, total = recognition.matching_segments(recognizer, experts, imported)
    assert same / total >= 0.99  # measured: 1.0
    # The logged outcomes and commands come back too, so the command match is the same.
    assert recognition.segment_table(recognizer, imported)["tracked"]["command_match"] == pytest.approx(
        recognition.segment_table(recognizer, experts)["expert"]["command_match"])


# Known answers.

def test_headings_are_resampled_along_the_shorter_arc(tmp_path):
    rows = [[0.0, -170, 0, math.radians(170), 170, 0], [2 / 30, -170, 0, math.radians(-170), 170, 0]]
    demo = import_tracks(_csv(tmp_path, rows), demonstrator="x").demonstrations[0]
    assert demo.frames["robot_theta_rad"][1] == pytest.approx(math.pi)  # 180°, not 0°
    assert demo.frames["t_s"].tolist() == pytest.approx([0, 1 / 30, 2 / 30])
    assert heading(np.array([0.0, 1.0]), np.radians([-170.0, 170.0]), np.array([0.25]))[0] == pytest.approx(
        math.radians(-175))


def test_positions_are_interpolated_linearly_from_the_first_reading(tmp_path):
    rows = [[5.0, -170, 0, 0, 170, 0], [5.1, -160, 10, 0, 170, 0]]  # 10 Hz, its clock not at 0
    demo = import_tracks(_csv(tmp_path, rows), demonstrator="x").demonstrations[0]
    assert demo.frames["t_s"].tolist() == pytest.approx([0, 1 / 30, 2 / 30, 0.1])
    assert demo.frames["robot_x_mm"].tolist() == pytest.approx([-170, -170 + 10 / 3, -170 + 20 / 3, -160])
    assert (demo.frames["command"] == UNKNOWN_COMMAND).all()


@pytest.mark.parametrize(("ball", "ball_step", "robot_step", "outcome", "frames"), [
    ((400.0, 0.0), (20.0, 0.0), (0.0, 0.0), "goal", 7),          # 400 … 520 > 510: frame 7 crosses
    ((-400.0, 100.0), (-20.0, 0.0), (0.0, 0.0), "own_goal", 7),  # inside the mouth (|y| <= 202.5)
    ((400.0, 300.0), (20.0, 0.0), (0.0, 0.0), "ball_out", 7),    # wide of the mouth
    ((0.0, 380.0), (0.0, 5.0), (0.0, 0.0), "ball_out", 7),       # over the side line: 410 > 405
    ((170.0, 0.0), (0.0, 0.0), (0.0, -40.0), "robot_out", 12),   # robot from y 0 to -440 < -405
    ((170.0, 0.0), (1.0, 0.0), (1.0, 0.0), "time_up", 14),       # nothing crosses
])
def test_outcomes_are_derived_from_the_field_and_later_frames_cut(tmp_path, ball, ball_step, robot_step, outcome,
                                                                  frames):
    rows = _readings(14, ball=ball, ball_step=ball_step, robot_step=robot_step)  # readings go on after the event
    demo = import_tracks(_csv(tmp_path, rows), demonstrator="x").demonstrations[0]
    assert (demo.outcome, len(demo.frames)) == (outcome, frames)


def test_a_log_ending_on_the_line_ended_there_and_the_tiny_field_is_smaller(tmp_path):
    rows = _readings(5, robot=(-90.0, 0.0), ball=(279.6, 0.0))  # the small field's line is at 280
    assert import_tracks(_csv(tmp_path, rows), demonstrator="x", body="tiny").demonstrations[0].outcome == "goal"
    assert import_tracks(_csv(tmp_path, rows), demonstrator="x", body="tiny",
                         line_tolerance_mm=0.0).demonstrations[0].outcome == "time_up"
    assert import_tracks(_csv(tmp_path, rows), demonstrator="x").demonstrations[0].outcome == "time_up"


def test_the_robot_leaving_before_the_ball_is_robot_out(tmp_path):
    rows = [[0.0, 500, 0, 0, 490, 0], [1 / 30, 530, 0, 0, 515, 0]]  # robot out at 1/3 of the step, ball at 4/5
    assert import_tracks(_csv(tmp_path, rows), demonstrator="x").demonstrations[0].outcome == "robot_out"


def test_a_logged_outcome_and_configuration_are_taken_as_logged(tmp_path):
    rows = [r + ["", "2"] for r in _readings(10)]
    rows[-1][-2] = "ball_out"
    path = _csv(tmp_path, rows, header=HEADER + ",outcome,configuration")
    demo = import_tracks(path, demonstrator="x").demonstrations[0]
    assert (demo.outcome, demo.configuration, len(demo.frames)) == ("ball_out", 2, 10)
    with pytest.raises(TrackLogError, match="configuration 2 in column 'configuration', but configuration=1"):
        import_tracks(path, demonstrator="x", configuration=1)


def test_the_configuration_is_read_from_the_first_reading(tmp_path):
    one = import_tracks(_csv(tmp_path, _readings(3)), demonstrator="x").demonstrations[0]
    two = import_tracks(_csv(tmp_path, _readings(3, robot=(170, 0), ball=(-170, 0)), name="b.csv"),
                        demonstrator="x").demonstrations[0]
    assert (one.configuration, two.configuration) == (1, 2)


def test_without_an_episode_column_a_pause_or_a_reset_starts_an_episode(tmp_path):
    first = _readings(10, ball=(400.0, 0.0), ball_step=(3.0, 0.0))
    after_pause = _readings(10, start_s=first[-1][0] + 0.6)              # a pause of 0.6 s > 0.5 s
    reset = _readings(10, start_s=after_pause[-1][0] + 1 / 30)           # the ball put back from 170+... by hand
    reset_rows = [[t, rx, ry, th, 500.0 if i < 5 else 170.0, by] for i, (t, rx, ry, th, bx, by) in enumerate(reset)]
    imported = import_tracks(_csv(tmp_path, first + after_pause + reset_rows), demonstrator="x")
    assert imported.episodes == 4 and [len(d.frames) for d in imported.demonstrations] == [10, 10, 5, 5]
    assert [d.seed for d in imported.demonstrations] == [0, 1, 2, 3]
    slow = _readings(10, ball_step=(30.0, 0.0))  # 30 mm a reading: a fast ball, no reset (255 mm)
    assert import_tracks(_csv(tmp_path, slow, name="slow.csv"), demonstrator="x").episodes == 1


def test_an_episode_column_names_the_episodes_in_order(tmp_path):
    rows = [["b"] + r for r in _readings(4)] + [["a"] + r for r in _readings(6)]
    imported = import_tracks(_csv(tmp_path, rows, header="episode," + HEADER), demonstrator="x")
    assert imported.episodes == 2 and [len(d.frames) for d in imported.demonstrations] == [4, 6]
    rows = rows + [["b"] + r for r in _readings(3)]
    with pytest.raises(TrackLogError, match=r"data row 11 \(line 12\), column 'episode': episode 'b' again"):
        import_tracks(_csv(tmp_path, rows, header="episode," + HEADER, name="again.csv"), demonstrator="x")


def test_lost_tracking_makes_an_episode_invalid_counted_and_reported(tmp_path):
    rows = [[e] + r for e in (0, 1, 2) for r in _readings(20)]
    rows[25][5] = ""     # episode 1, its 6th reading: no ball x
    rows[45][4] = "nan"  # episode 2, no heading
    path = _csv(tmp_path, rows, header="episode," + HEADER)
    with pytest.warns(LostTrackingWarning, match="2 invalid"):
        imported = import_tracks(path, demonstrator="x")
    assert imported.episodes == 3 and len(imported.demonstrations) == 1
    assert imported.invalid == [("1", "lost tracking at 0.17 s (data row 26: no ball_x_mm)"),
                                ("2", "lost tracking at 0.17 s (data row 46: no robot_theta_rad)")]
    assert repr(imported) == ("3 episodes from log.csv: 1 demonstration, 2 invalid (episode 1: lost tracking at "
                              "0.17 s (data row 26: no ball_x_mm); episode 2: lost tracking at 0.17 s (data row 46: "
                              "no robot_theta_rad))")


def test_missing_readings_inside_an_episode_are_lost_tracking(tmp_path):
    rows = _readings(20)
    del rows[5:10]  # 0.2 s without a reading: over three periods, under the 0.5 s that starts an episode
    with pytest.warns(LostTrackingWarning):
        imported = import_tracks(_csv(tmp_path, rows), demonstrator="x")
    assert imported.invalid == [(0, "lost tracking at 0.13 s (no reading for 0.20 s after data row 5)")]


def test_commands_are_ids_or_names_held_until_the_next(tmp_path):
    rows = [r + [c] for r, c in zip(_readings(4), ["forward", "forward", "4", "left"])]
    demo = import_tracks(_csv(tmp_path, rows, header=HEADER + ",command"), demonstrator="x").demonstrations[0]
    assert demo.frames["command"].tolist() == [0, 0, 4, 2]
    with pytest.raises(TrackLogError, match=r"data row 2 \(line 3\), column 'cmd': 'jump' is no command"):
        bad = [r + [c] for r, c in zip(_readings(4), ["forward", "jump", "4", "left"])]
        import_tracks(_csv(tmp_path, bad, header=HEADER + ",cmd"), demonstrator="x", columns={"command": "cmd"})


def test_what_needs_the_commands_sent_refuses_a_log_without_them(tmp_path, recognizer):
    write_tracks(polymimic.record("poor", configuration=1, n=2, seed=1), tmp_path / "log.csv", include=())
    demos = import_tracks(tmp_path / "log.csv", demonstrator="poor", rate_hz=30).demonstrations
    for needs_commands in (lambda: primitives_sent(demos[0]), lambda: command_labels(demos),
                           lambda: steps_of(demos[0], actions="commands"),
                           lambda: recognition.segment_table(recognizer, demos)):
        with pytest.raises(ValueError, match="has no recorded commands"):
            needs_commands()
    assert len(steps_of(demos[0], recognizer=recognizer).actions) > 0  # learning from observation still works
    with pytest.raises(ValueError, match="leave 'command' out of include"):
        write_tracks(demos, tmp_path / "again.csv")


def test_column_names_are_mapped_and_defaults_follow_the_units(tmp_path):
    rows = [[r[0] * 1000, r[1] / 10, r[2] / 10, math.degrees(r[3]), r[4] / 10, r[5] / 10] for r in _readings(4)]
    path = _csv(tmp_path, rows, header="time,x,y,heading,bx,by")
    columns = {"t": "time", "robot_x": "x", "robot_y": "y", "robot_theta": "heading", "ball_x": "bx", "ball_y": "by"}
    demo = import_tracks(path, demonstrator="x", columns=columns,
                         units={"length": "cm", "angle": "deg", "time": "ms"}).demonstrations[0]
    assert demo.frames["robot_x_mm"][0] == pytest.approx(-170) and len(demo.frames) == 4


# Bad logs: each refused, naming the file, the row and the column.

def _refused(path, match, **options):
    with pytest.raises(TrackLogError, match=match) as error:
        import_tracks(path, demonstrator="x", **options)
    assert str(path) in str(error.value)
    return str(error.value)


def test_a_missing_column_lists_what_the_file_has(tmp_path):
    path = _csv(tmp_path, [r[:5] for r in _readings(3)], header=HEADER.rsplit(",", 1)[0])
    message = _refused(path, r"no column for ball_y \(as 'ball_y_mm'\); the file has 't_s', 'robot_x_mm'")
    assert "columns=" in message


def test_an_unknown_column_is_refused_unless_ignored(tmp_path):
    path = _csv(tmp_path, [r + ["sunny"] for r in _readings(3)], header=HEADER + ",weather")
    _refused(path, r"unknown column\(s\) 'weather'; a log has t_s, robot_x_mm, .*ignore=")
    assert import_tracks(path, demonstrator="x", ignore=["weather"]).episodes == 1
    _refused(path, r"ignore= names 'wind', which the file does not have", ignore=["weather", "wind"])


def test_time_going_back_or_repeating_is_refused_with_its_row(tmp_path):
    rows = _readings(5)
    rows[3][0] = rows[1][0]
    _refused(_csv(tmp_path, rows), r"data row 4 \(line 5\), column 't_s': time 0.0333333 s goes back|"
                                   r"data row 4 \(line 5\), column 't_s': time goes back from 0.0666667 s to 0.0333333")
    rows = _readings(5)
    rows[3][0] = rows[2][0]
    _refused(_csv(tmp_path, rows, name="dup.csv"), r"data row 4 \(line 5\), column 't_s': time 0.0666667 s again "
                                                   r"\(as in data row 3\); duplicated timestamps")
    episodes = [[0] + r for r in _readings(3)] + [[1] + r for r in _readings(3)]
    assert import_tracks(_csv(tmp_path, episodes, header="episode," + HEADER, name="e.csv"),
                         demonstrator="x").episodes == 2  # each episode's clock may start again


def test_readings_that_do_not_fit_the_field_suggest_the_unit(tmp_path):
    in_mm = _readings(5)
    _refused(_csv(tmp_path, in_mm), r"data row 1 \(line 2\), column 'robot_x_mm': -170 m is far outside the "
                                    r"1020 × 810 mm field .*did you mean units=\{'length': 'mm'\}\?",
             units={"length": "m"}, columns={"robot_x": "robot_x_mm", "robot_y": "robot_y_mm", "ball_x": "ball_x_mm",
                                             "ball_y": "ball_y_mm"})
    in_m = [[t, x / 1000, y / 1000, th, bx / 1000, by / 1000] for t, x, y, th, bx, by in in_mm]
    _refused(_csv(tmp_path, in_m, name="m.csv"),
             r"reach only 0.17 mm from the centre.*did you mean units=\{'length': 'm'\}\?")
    in_deg = [[t, x, y, 90.0, bx, by] for t, x, y, th, bx, by in in_mm]
    _refused(_csv(tmp_path, in_deg, name="deg.csv"),
             r"data row 1 \(line 2\), column 'robot_theta_rad': heading 90 rad is more than 8 full turns.*; "
             r"did you mean units=\{'angle': 'deg'\}")
    in_ms = [[t * 1000, x, y, th, bx, by] for t, x, y, th, bx, by in in_mm]
    _refused(_csv(tmp_path, in_ms, name="ms.csv"), r"column 't_s': readings are 33.3333 s apart .*did you mean "
                                                   r"units=\{'time': 'ms'\}\?")


def test_unwrapped_headings_read_as_the_angles_they_are(tmp_path):
    """An integrating tracker's headings (past ±180°) give the frames the wrapped log gives."""
    demo = polymimic.record("expert", configuration=2, n=1, seed=3)[0]
    wrapped_path = tmp_path / "wrapped.csv"
    write_tracks([demo], wrapped_path)
    wrapped = import_tracks(wrapped_path, demonstrator="x")
    with open(wrapped_path, newline="") as file:
        header, *rows = list(csv.reader(file))
    column = header.index("robot_theta_rad")
    theta = np.unwrap([float(r[column]) for r in rows]) + 4 * math.pi  # two turns on, never jumping
    assert theta.max() > 2 * math.pi + 1
    for r, value in zip(rows, theta):
        r[column] = repr(float(value))
    unwrapped_path = tmp_path / "unwrapped.csv"
    with open(unwrapped_path, "w", newline="") as file:
        csv.writer(file).writerows([header, *rows])
    unwrapped = import_tracks(unwrapped_path, demonstrator="x")
    a, b = wrapped.demonstrations[0].frames, unwrapped.demonstrations[0].frames
    assert np.array_equal(a["robot_x_mm"], b["robot_x_mm"])
    turn = np.angle(np.exp(1j * (a["robot_theta_rad"] - b["robot_theta_rad"])))
    assert np.abs(turn).max() < 1e-9 and np.abs(b["robot_theta_rad"]).max() <= math.pi


def test_degrees_declared_as_radians_are_refused_by_the_turn_they_would_mean(tmp_path):
    """A robot turning 3° a reading, logged in degrees read as radians, would turn 14 turns a second."""
    rows = [[t, x, y, 30.0 + 3 * i, bx, by] for i, (t, x, y, th, bx, by) in enumerate(_readings(5))]
    message = _refused(_csv(tmp_path, rows), r"data row 2 \(line 3\), column 'robot_theta_rad': heading 33 rad after "
                                             r"30 rad 0.0333 s before, a turn of 14.3 turns a second \(at most 2\)")
    assert message.endswith("did you mean units={'angle': 'deg'}?")
    # No hint where degrees would not fit either: 5000° is nearly 14 turns.
    far = [[t, x, y, 5000.0, bx, by] for t, x, y, th, bx, by in _readings(5)]
    assert "did you mean" not in _refused(_csv(tmp_path, far, name="far.csv"), r"heading 5000 rad is more than 8 full")
    degrees = import_tracks(_csv(tmp_path, rows, header=HEADER.replace("_rad", "_deg"), name="deg.csv"),
                            demonstrator="x", units={"angle": "deg"})
    assert degrees.demonstrations[0].frames["robot_theta_rad"][1] == pytest.approx(math.radians(33.0))


def test_unknown_units_and_bad_rates_are_refused(tmp_path):
    path = _csv(tmp_path, _readings(5))
    with pytest.raises(ValueError, match=r"units\['length'\] is 'inch'; expected one of mm, cm, m"):
        import_tracks(path, demonstrator="x", units={"length": "inch"})
    with pytest.raises(ValueError, match="units has quantity 'speed'"):
        import_tracks(path, demonstrator="x", units={"speed": "m/s"})
    for rate in (0, -30, float("nan"), True):
        with pytest.raises(ValueError, match="rate_hz must be a positive number"):
            import_tracks(path, demonstrator="x", rate_hz=rate)
    _refused(path, r"column 't_s': rate_hz=60 means a reading every 16.7 ms, but the readings are 33.3 ms apart",
             rate_hz=60)


def test_empty_unreadable_and_non_numeric_logs_are_refused(tmp_path):
    (tmp_path / "empty.csv").write_text("")
    _refused(tmp_path / "empty.csv", "is empty")
    _refused(_csv(tmp_path, [], name="header.csv"), "has columns but no data rows")
    (tmp_path / "junk.parquet").write_bytes(b"\x00not parquet at all")
    _refused(tmp_path / "junk.parquet", "is not a readable Parquet file")
    (tmp_path / "ragged.csv").write_text(HEADER + "\n0,1,2\n")
    _refused(tmp_path / "ragged.csv", "is not a readable CSV file")
    rows = _readings(5)
    rows[2][4] = "far"
    _refused(_csv(tmp_path, rows, name="words.csv"),
             r"data row 3 \(line 4\), column 'ball_x_mm': 'far' is not a number")
    rows[2][4] = "inf"
    _refused(_csv(tmp_path, rows, name="inf.csv"), r"data row 3 \(line 4\), column 'ball_x_mm': inf is not a finite")
    rows = _readings(5)
    rows[1][0] = ""
    _refused(_csv(tmp_path, rows, name="no_time.csv"), r"data row 2 \(line 3\), column 't_s': no time")
    with pytest.raises(FileNotFoundError):
        import_tracks(tmp_path / "absent.csv", demonstrator="x")
    _refused(tmp_path / "log.txt", "a tracker log is a .csv or a .parquet file, not .txt")


def test_a_bad_outcome_names_row_column_value_and_the_allowed(tmp_path):
    rows = [r + ["scored"] for r in _readings(3)]
    _refused(_csv(tmp_path, rows, header=HEADER + ",outcome"),
             r"data row 1 \(line 2\), column 'outcome': outcome 'scored' is not one of goal, own_goal, ball_out, "
             r"robot_out, time_up")
    rows = [r + [o] for r, o in zip(_readings(3), ["goal", "", "ball_out"])]
    _refused(_csv(tmp_path, rows, header=HEADER + ",outcome", name="two.csv"),
             r"data row 3 \(line 4\), column 'outcome': episode 0 has outcome 'ball_out' here but 'goal' at data row 1")


def test_parquet_logs_are_checked_the_same_way(tmp_path):
    table = pa.table({"t_s": [0.0, 1 / 30, 1 / 30], "robot_x_mm": [-170.0, -170, -170], "robot_y_mm": [0.0, 0, 0],
                      "robot_theta_rad": [0.0, 0, 0], "ball_x_mm": [170.0, None, 170], "ball_y_mm": ["0", "0", "x"]})
    pq.write_table(table, tmp_path / "log.parquet")
    _refused(tmp_path / "log.parquet", r"log.parquet: data row 3, column 'ball_y_mm': 'x' is not a number")


def test_review_cases_nan_ids_one_reading_episodes_ms_times_and_infinite_configurations(tmp_path):
    """A NaN episode id is no id; an episode of one reading is counted invalid, not kept; times
    written to the millisecond reach their last frame; an infinite configuration is named."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    import polymimic
    from polymimic.tracks import TrackLogError

    def log(rows, path, **extra):
        columns = {k: [r[i] for r in rows] for i, k in enumerate(
            ("t_s", "robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"))}
        pq.write_table(pa.table({**columns, **extra}), path)
        return path

    rows = [(0.0, -170.0, 0.0, 0.0, 170.0, 0.0), (0.0333, -169.0, 0.0, 0.0, 170.0, 0.0),
            (0.0667, -168.0, 0.0, 0.0, 170.0, 0.0)]
    with pytest.raises(TrackLogError, match="no episode id"):
        polymimic.import_tracks(log(rows, tmp_path / "nan.parquet", episode=[1.0, float("nan"), 1.0]),
                                demonstrator="x")
    with pytest.warns(polymimic.tracks.LostTrackingWarning):
        short = polymimic.import_tracks(log(rows, tmp_path / "short.parquet", episode=[1.0, 1.0, 2.0]),
                                        demonstrator="x")
    assert [len(d.frames) for d in short.demonstrations] == [2]
    assert short.invalid == [(2.0, "1 reading: too short to be an attempt")]
    whole = polymimic.import_tracks(log(rows, tmp_path / "ms.parquet"), demonstrator="x")
    assert [len(d.frames) for d in whole.demonstrations] == [3], "0.0667 s is the frame at 2/30 s"
    with pytest.raises(TrackLogError, match=r"configuration inf; expected 1 or 2"):
        polymimic.import_tracks(log(rows, tmp_path / "inf.parquet", configuration=[float("inf")] * 3),
                                demonstrator="x")
