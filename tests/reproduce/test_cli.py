"""The command line."""

import pathlib
import subprocess
import sys

import pytest

from polymimic import cli, demo


def test_demo_recognises_the_primitives_it_was_shown(capsys):
    assert cli.main(["demo", "--train", "60", "--test", "30", "--codebook-size", "32"]) == 0
    out = capsys.readouterr().out
    assert "accuracy" in out and "forward" in out


def test_demo_accuracy_is_high_and_reproducible():
    a = demo.run(n_train=60, n_test=40, codebook_size=32, seed=3)
    b = demo.run(n_train=60, n_test=40, codebook_size=32, seed=3)
    # Chance is 0.25; "left" is the hardest, its turn rate spreading as widely as the thesis's.
    assert min(a.accuracy.values()) > 0.7 and a.accuracy["forward"] > 0.95
    assert a.accuracy == b.accuracy and (a.confusion == b.confusion).all()


def test_module_entry_point_and_version():
    out = subprocess.run([sys.executable, "-m", "polymimic", "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.startswith("polymimic ")


def _tracker_log(path, **options):
    import polymimic

    demos = polymimic.record("poor", configuration=1, n=3, seed=2)
    polymimic.write_tracks(demos, path, **options)
    return demos


def test_import_tracks_writes_the_runs_demonstrations_and_says_how_many(tmp_path, capsys, monkeypatch):
    from polymimic.datasets import load_demonstrations

    log = tmp_path / "log.csv"
    demos = _tracker_log(log, units={"length": "m", "angle": "deg"}, rate_hz=60, include=())
    from polymimic.reproduce.rundir import RunDir
    from polymimic.runs.config import RunConfig

    run = tmp_path / "runs" / "20260101-000000"
    RunDir(run).open(RunConfig.from_toml('[demonstrators.alice]\nimported = true\n'))
    monkeypatch.chdir(tmp_path)  # the newest run under runs/ is the default
    argv = ["import-tracks", str(log), "--as", "alice", "--length-unit", "m", "--angle-unit", "deg", "--rate-hz", "60"]
    assert cli.main(argv) == 0
    out = capsys.readouterr().out.strip().splitlines()
    assert out == [f"3 episodes from log.csv: 3 demonstrations, 0 invalid; written to "
                   f"{pathlib.Path('runs/20260101-000000/datasets/demonstrations_alice.parquet')}"]
    imported = load_demonstrations(run / "datasets" / "demonstrations_alice.parquet")
    assert [d.outcome for d in imported] == [d.outcome for d in demos]
    assert {d.demonstrator for d in imported} == {"alice"}


def test_import_tracks_counts_invalid_episodes_and_maps_columns(tmp_path, capsys):
    log = tmp_path / "log.csv"
    _tracker_log(log)
    lines = log.read_text().splitlines()
    header = lines[0].replace("robot_x_mm", "x")
    cells = lines[40].split(",")
    cells[5] = ""  # no ball x: lost tracking in episode 0
    log.write_text("\n".join([header, *lines[1:40], ",".join(cells), *lines[41:]]) + "\n")
    out = tmp_path / "alice.parquet"
    argv = ["import-tracks", str(log), "--as", "alice", "--column", "robot_x=x", "--out", str(out)]
    assert cli.main(argv) == 0
    assert capsys.readouterr().out.startswith("3 episodes from log.csv: 2 demonstrations, 1 invalid (episode 0: "
                                              "lost tracking at 1.30 s")
    assert out.exists()


def test_import_tracks_refuses_bad_logs_in_one_line(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    log = tmp_path / "log.csv"
    _tracker_log(log, units={"length": "m"})
    cases = [
        (["import-tracks", str(log), "--as", "alice", "--out", str(tmp_path / "a.parquet")], "did you mean units="),
        (["import-tracks", str(log), "--as", "alice", "--length-unit", "m"], "no run under runs/"),
        (["import-tracks", str(log), "--as", "alice", "--length-unit", "m", "--rate-hz", "0", "--out",
          str(tmp_path / "a.parquet")], "rate_hz must be a positive number"),
        (["import-tracks", str(tmp_path / "absent.csv"), "--as", "alice", "--out", str(tmp_path / "a.parquet")],
         "no such tracker log"),
        (["import-tracks", str(log), "--as", "al/ice", "--out", str(tmp_path / "a.parquet")], "letters, digits"),
        (["import-tracks", str(log), "--as", "alice", "--column", "robot_x", "--out", str(tmp_path / "a.parquet")],
         "expected polymimic_name=file_column"),
        (["import-tracks", str(log), "--as", "alice", "--length-unit", "m", "--max-gap-s", "-1", "--out",
          str(tmp_path / "a.parquet")], "max_gap_s must be a finite number"),
        (["import-tracks", str(log), "--as", "alice", "--length-unit", "m", "--max-gap-s", "nan", "--out",
          str(tmp_path / "a.parquet")], "max_gap_s must be a finite number"),
    ]
    for argv, message in cases:
        assert cli.main(argv) == 2
        captured = capsys.readouterr()
        assert captured.out == "" and len(captured.err.strip().splitlines()) == 1, captured.err
        assert captured.err.startswith("polymimic import-tracks: error: ") and message in captured.err
        assert "Traceback" not in captured.err
    assert not (tmp_path / "a.parquet").exists()


def test_the_command_needs_no_optional_extra(tmp_path):
    """`pip install .` then `polymimic reproduce`: without scikit-learn, gymnasium or minari the
    command runs; only `polymimic benchmark` asks for the baselines extra, in one line."""
    blocked = ("import sys\n"
               "for name in ('sklearn', 'gymnasium', 'minari', 'ray', 'stable_baselines3', 'torch'):\n"
               "    sys.modules[name] = None\n"
               "from polymimic import cli\n"
               "sys.exit(cli.main(sys.argv[1:]))\n")
    script = tmp_path / "bare.py"
    script.write_text(blocked)
    config = subprocess.run([sys.executable, str(script), "config", "--quick"], capture_output=True, text=True,
                            check=False)
    assert config.returncode == 0, config.stderr
    assert "[experiments]" in config.stdout
    bench = subprocess.run([sys.executable, str(script), "benchmark", "--quick", "--run-dir", str(tmp_path / "b")],
                           capture_output=True, text=True, check=False)
    assert bench.returncode == 2
    assert bench.stderr.strip().splitlines()[-1].endswith("pip install \"polymimic[baselines]\"")


@pytest.mark.parametrize(("argv", "message"), [
    (["practice", "--run-dir", "r", "--method", "refine"], "polymimic practice: error: argument --method: invalid "
                                                           "choice: 'refine'"),
    (["practice"], "polymimic practice: error: the following arguments are required: --run-dir"),
    (["benchmark", "--workers", "0"], "polymimic benchmark: error: argument --workers"),
    (["nope"], "polymimic: error: argument command: invalid choice: 'nope'"),
])
def test_argument_errors_are_one_line_with_exit_code_2(argv, message, capsys):
    with pytest.raises(SystemExit) as exit_:
        cli.main(argv)
    err = capsys.readouterr().err
    assert exit_.value.code == 2 and err.startswith(message) and len(err.strip().splitlines()) == 1, err
    assert err.strip().endswith("--help)")


def test_an_address_without_ray_is_one_line_naming_the_command(capsys):
    assert cli.main(["practice", "--run-dir", "r", "--address", "auto"]) == 2
    err = capsys.readouterr().err
    assert err == "polymimic practice: error: --address is for the Ray backend: add --backend ray\n"
