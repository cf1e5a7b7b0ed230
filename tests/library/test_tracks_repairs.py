"""What an import says it did: single readings the tracker dropped and gaps bridged, counted per
demonstration and in the summary; readings off the field name the field and how to give another."""

import pytest

from polymimic import cli
from polymimic.bodies import Field, WheeledBody
from polymimic.tracks import TrackLogError, import_tracks

HEADER = "episode,t_s,robot_x_mm,robot_y_mm,robot_theta_rad,ball_x_mm,ball_y_mm"


def _episode(episode, n, *, drop=(), blind=()):
    """``n`` readings 1/30 s apart of a robot creeping toward the ball, readings ``drop`` left
    out and readings ``blind`` without the ball."""
    rows = []
    for i in range(n):
        if i in drop:
            continue
        ball = ("", "") if i in blind else (170.0, 0.0)
        rows.append([episode, i / 30, -170.0 + 2 * i, 0.0, 0.0, *ball])
    return rows


def _csv(tmp_path, rows, name="log.csv"):
    path = tmp_path / name
    path.write_text(HEADER + "\n" + "".join(",".join(map(str, row)) + "\n" for row in rows))
    return path


def test_single_dropped_readings_are_counted_per_demonstration_and_in_the_summary(tmp_path):
    # Episode 3 misses readings 5, 12 and 20 (three single drops); episode 4 none.
    path = _csv(tmp_path, _episode(3, 40, drop=(5, 12, 20)) + _episode(4, 40))
    imported = import_tracks(path, demonstrator="x")
    assert imported.dropped_readings == [3, 0] and imported.gaps_bridged == [0, 0]
    assert imported.episode_ids == ["3", "4"]
    assert repr(imported) == "2 episodes from log.csv: 2 demonstrations (3 dropped readings filled in), 0 invalid"
    assert imported.repaired() == ["episode 3: 3 dropped readings filled in"]
    # Filled in on the line between the readings either side: reading 5 is where it would have been.
    assert imported.demonstrations[0].frames["robot_x_mm"][5] == pytest.approx(-160.0)


def test_dropped_readings_and_a_bridged_gap_are_told_apart(tmp_path):
    # 30 Hz, one reading dropped twice, and 0.3 s with no ball (readings 20–28): the SSL log's lapses.
    rows = _episode(0, 60, drop=(4, 40), blind=range(20, 29))
    imported = import_tracks(_csv(tmp_path, rows), demonstrator="x", max_gap_s=0.35)
    assert imported.dropped_readings == [2] and imported.gaps_bridged == [1]
    assert repr(imported) == ("1 episode from log.csv: 1 demonstration (2 dropped readings filled in, 1 gap bridged), "
                              "0 invalid")
    assert imported.repaired() == ["episode 0: 2 dropped readings filled in, 1 gap bridged"]


def test_a_log_read_whole_says_nothing_was_repaired(tmp_path):
    imported = import_tracks(_csv(tmp_path, _episode(0, 30) + _episode(1, 30)), demonstrator="x")
    assert imported.dropped_readings == [0, 0] and imported.repaired() == []
    assert repr(imported) == "2 episodes from log.csv: 2 demonstrations, 0 invalid"


def test_import_tracks_prints_each_repaired_episode(tmp_path, capsys):
    path = _csv(tmp_path, _episode(0, 40, drop=(7,)) + _episode(1, 40))
    out = tmp_path / "x.parquet"
    assert cli.main(["import-tracks", str(path), "--as", "x", "--out", str(out)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        f"2 episodes from log.csv: 2 demonstrations (1 dropped reading filled in), 0 invalid; written to {out}",
        "  episode 0: 1 dropped reading filled in"]


def _ssl_rows(n=30):
    """A robot 3 m from the centre of a 9 × 6 m field, in mm."""
    return [[0, i / 30, -3000.0 + 5 * i, 0.0, 0.0, 1500.0, 0.0] for i in range(n)]


SSL_BOT = WheeledBody("ssl_bot_repairs", length_mm=180, width_mm=180, wheel_base_mm=160, top_wheel_speed_mm_s=2000,
                      field=Field(9000, 6000, goal_mouth_mm=1000, ball_diameter_mm=43))


def test_readings_off_the_field_name_the_field_and_how_to_give_another(tmp_path):
    path = _csv(tmp_path, _ssl_rows())
    with pytest.raises(TrackLogError) as error:
        import_tracks(path, demonstrator="x")
    message = str(error.value)
    assert "column 'robot_x_mm': -3000 mm is far outside the 1020 × 810 mm field of body 'lego'" in message
    assert "did you mean" not in message  # no unit makes -3000 fit: the field is the fix
    for fix in ("body=WheeledBody(..., field=Field(length_mm, width_mm))", "--body FILE.toml",
                "a [bodies.<name>] table named by the demonstrator's body = in a run config"):
        assert fix in message
    imported = import_tracks(path, demonstrator="x", body=SSL_BOT)  # on its own field it reads
    assert len(imported.demonstrations) == 1 and imported.demonstrations[0].body.name == "ssl_bot_repairs"


def test_readings_too_small_for_the_field_name_it_too(tmp_path):
    rows = [[0, i / 30, -170.0, 0.0, 0.0, 170.0, 0.0] for i in range(10)]  # the Lego's start, read on a 9 m field
    with pytest.raises(TrackLogError, match=r"too little for the 9000 × 6000 mm field of body 'ssl_bot_repairs', on "
                                            r"which they start 1500 mm from it; did you mean units=\{'length': "
                                            r"'cm'\}\?; or, if the log is of another field, give a body that plays "
                                            r"on it: body=WheeledBody"):
        import_tracks(_csv(tmp_path, rows), demonstrator="x", body=SSL_BOT)
