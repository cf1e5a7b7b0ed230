"""A log through every command: a config's log demonstrator takes every option import_tracks
takes, by the same names, and `polymimic import-tracks` reads a body file or a config without a run."""

import dataclasses
import inspect

import pytest

import polymimic
from polymimic import cli
from polymimic.cli.import_options import body_file
from polymimic.datasets import load_demonstrations
from polymimic.runs.config import ConfigError, RunConfig
from polymimic.runs.roster_config import LogDemonstrator, record_demonstrator
from polymimic.tracks import import_tracks

BODY = """
[bodies.pitch_bot]
length_mm = 180
width_mm = 180
wheel_base_mm = 160
top_wheel_speed_mm_s = 600
field = { length_mm = 3000, width_mm = 2000, goal_mouth_mm = 700, ball_diameter_mm = 43 }
"""


def test_a_log_demonstrator_takes_every_option_of_import_tracks_by_its_name():
    options = set(inspect.signature(import_tracks).parameters) - {"path", "demonstrator"}
    keys = {f.name for f in dataclasses.fields(LogDemonstrator)} - {"name", "log"}
    assert keys == options


def _gappy_log(folder):
    """Three Expert episodes in metres, with a camera column, two single readings dropped and a
    0.3 s blind spot (the ball unseen) in the first episode."""
    log = folder / "log.csv"
    polymimic.write_tracks(polymimic.record("expert", configuration=1, n=3, seed=1), log, units={"length": "m"},
                           include=("episode",))
    lines = log.read_text().splitlines()
    rows = [line + ",1" for line in lines[1:]]
    for i in range(30, 39):  # readings 30–38 of episode 0: no ball, 0.33 s between the readings either side
        cells = rows[i].split(",")
        cells[5] = cells[6] = ""
        rows[i] = ",".join(cells)
    del rows[50], rows[10]  # two single readings dropped
    log.write_text("\n".join([lines[0] + ",camera", *rows]) + "\n")
    return log


def test_the_configs_options_import_as_the_function_does(tmp_path):
    log = _gappy_log(tmp_path)
    config = RunConfig.from_toml('[demonstrators.logged]\nlog = "log.csv"\nunits = { length = "m" }\n'
                                 'ignore = ["camera"]\nmax_gap_s = 0.35\nconfiguration = 1\nline_tolerance_mm = 2\n'
                                 'rate_hz = 30\n', base_dir=tmp_path)
    spec = config.demonstrators["logged"]
    demos, said = record_demonstrator(spec, n=1, seed=0, field_config=config.field, bodies=config.bodies)
    direct = import_tracks(log, demonstrator="logged", units={"length": "m"}, ignore=["camera"], max_gap_s=0.35,
                           configuration=1, line_tolerance_mm=2, rate_hz=30)
    assert said == direct.summary() == ("3 episodes from log.csv: 3 demonstrations (2 dropped readings filled in, "
                                        "1 gap bridged), 0 invalid")
    assert [d.frames.tobytes() for d in demos] == [d.frames.tobytes() for d in direct.demonstrations]
    assert RunConfig.from_toml(config.to_toml(), base_dir=tmp_path) == config


@pytest.mark.parametrize("line, message", [
    ("max_gap_s = -1", "max_gap_s must be a number of seconds, at least 0, got -1"),
    ("max_gap_s = \"0.3\"", "max_gap_s must be a number of seconds"),
    ("configuration = 3", "configuration must be 1 or 2"),
    ("ignore = \"camera\"", "ignore must be a list of the log's column names"),
    ("line_tolerance_mm = nan", "line_tolerance_mm must be a number of mm"),
    ("max_gap = 0.3", "unknown key 'max_gap' for a log demonstrator; known keys: log, body, rate_hz, units, columns, "
                      "configuration, ignore, line_tolerance_mm, max_gap_s"),
])
def test_a_bad_log_option_is_refused_when_the_config_is_read(line, message):
    with pytest.raises(ConfigError, match=rf"\[demonstrators.logged\]: {message}"):
        RunConfig.from_toml(f'[demonstrators.logged]\nlog = "log.csv"\n{line}\n')


def test_import_tracks_takes_a_body_file_without_a_run(tmp_path, capsys):
    (tmp_path / "bot.toml").write_text(BODY)
    rows = [f"{i / 30},{-1000 + 5 * i},0,0,500,0" for i in range(40)]  # 1 m from the centre: off the Lego's field
    (tmp_path / "log.csv").write_text("t_s,robot_x_mm,robot_y_mm,robot_theta_rad,ball_x_mm,ball_y_mm\n"
                                      + "\n".join(rows) + "\n")
    out = tmp_path / "bot.parquet"
    argv = ["import-tracks", str(tmp_path / "log.csv"), "--as", "bot", "--out", str(out)]
    assert cli.main(argv) == 2
    assert "field of body 'lego'" in capsys.readouterr().err
    assert cli.main([*argv, "--body", str(tmp_path / "bot.toml")]) == 0
    assert capsys.readouterr().out.startswith("1 episode from log.csv: 1 demonstration, 0 invalid; written to")
    bot = body_file(str(tmp_path / "bot.toml"))
    assert {d.body.name for d in load_demonstrations(out, bodies=[bot])} == {"pitch_bot"}


def test_import_tracks_reads_a_configs_log_table_without_a_run(tmp_path, capsys):
    _gappy_log(tmp_path)
    config = tmp_path / "run.toml"
    config.write_text('[demonstrators.logged]\nlog = "log.csv"\nunits = { length = "m" }\nignore = ["camera"]\n'
                      'max_gap_s = 0.35\n')
    out = tmp_path / "logged.parquet"
    assert cli.main(["import-tracks", "--config", str(config), "--as", "logged", "--out", str(out)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        f"3 episodes from log.csv: 3 demonstrations (2 dropped readings filled in, 1 gap bridged), 0 invalid; "
        f"written to {out}", "  episode 0: 2 dropped readings filled in, 1 gap bridged"]
    refusals = [
        (["--max-gap-s", "0.5"], "--max-gap-s 0.5: --config's [demonstrators.logged] says max_gap_s = 0.35"),
        (["--body", "tiny"], "--body tiny: --config's [demonstrators.logged] says body = 'lego'"),
        ([str(tmp_path / "other.csv")], "says log = "),
    ]
    for extra, message in refusals:
        assert cli.main(["import-tracks", "--config", str(config), "--as", "logged", "--out", str(out), *extra]) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and message in err, err
    assert cli.main(["import-tracks", "--as", "logged", "--out", str(out)]) == 2
    assert "no log to import" in capsys.readouterr().err
    (tmp_path / "two.toml").write_text(BODY + BODY.replace("pitch_bot", "other_bot"))
    assert cli.main(["import-tracks", str(tmp_path / "log.csv"), "--as", "x", "--out", str(out), "--body",
                     str(tmp_path / "two.toml")]) == 2
    assert "a body file holds one [bodies.<name>] table, this one 2 (pitch_bot, other_bot)" in capsys.readouterr().err
