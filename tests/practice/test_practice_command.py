"""`polymimic practice` on a finished reproduction and a finished benchmark: the curves beside
the run's results, resumption, the same bits on one worker or two, and bad input in one line."""

import json

import pytest

from polymimic import cli
from polymimic.reproduce.rundir import RunDir

TINY_REPRODUCTION = """
[recognizer]
train_per_primitive = 60
test_per_primitive = 20
codebook_size = 32
[experiments]
trials = 2
demonstrations_per_configuration = 8
attempts_per_configuration = 2
evaluated_imitators = 1
"""

TINY_BENCHMARK = """
[recognizer]
train_per_primitive = 40
codebook_size = 16
[benchmark]
profiles = ["pair"]
methods = ["polymimic"]
trials = 2
demonstrations_per_configuration = 2
attempts_per_configuration = 2
[profiles.pair]
members = [{ controller = "expert", lapse = 0.0, name = "good" }, { controller = "expert", lapse = 1.0, name = "bad" }]
"""


@pytest.fixture(scope="module")
def reproduced(tmp_path_factory):
    config = tmp_path_factory.mktemp("config") / "tiny.toml"
    config.write_text(TINY_REPRODUCTION)
    run = tmp_path_factory.mktemp("runs") / "tiny"
    assert cli.main(["reproduce", "--config", str(config), "--run-dir", str(run), "--quiet", "--workers", "1"]) == 0
    return run


@pytest.fixture(scope="module")
def benchmarked(tmp_path_factory):
    config = tmp_path_factory.mktemp("config") / "bench.toml"
    config.write_text(TINY_BENCHMARK)
    run = tmp_path_factory.mktemp("runs") / "bench"
    assert cli.main(["benchmark", "--config", str(config), "--run-dir", str(run), "--quiet", "--workers", "1"]) == 0
    return run


def _practise(run, *extra, workers="1"):
    return cli.main(["practice", "--run-dir", str(run), "--steps", "150", "--trials", "1", "--quiet",
                     "--workers", workers, *(extra or ("--method", "explore"))])


def test_a_reproductions_improved_imitators_practise_beside_its_results(reproduced, capsys):
    assert _practise(reproduced) == 0
    folder = reproduced / "practice" / "150_steps_explore"
    assert capsys.readouterr().out.strip() == str(folder / "practice.json")
    summary = json.loads((folder / "practice.json").read_text())
    assert (summary["format"], summary["version"], summary["run"], summary["steps"]) == (
        "polymimic.practice", 1, "reproduction", 150)
    run = RunDir(reproduced)
    for experiment, curve in summary["groups"].items():
        assert curve["checkpoints"] == [0, 150] and curve["trials"] == 1
        # Before practice: the improved imitator the reproduction evaluated, on the same attempts.
        evaluated = json.loads(run.evaluation_path(experiment, 0, "improved").read_text())
        assert curve["net_goals"][0]["mean"] == evaluated["goals"] - evaluated["own_goals"]
        saved = json.loads((folder / experiment / "practice_0.json").read_text())
        assert saved["checkpoints"][0]["net_goals"] == curve["net_goals"][0]["mean"]
    assert (folder / "practice.csv").read_text().startswith("group,checkpoint,steps_mean,net_goals_mean")
    assert (folder / "practice_curve.png").read_bytes()[:4] == b"\x89PNG"


def test_a_rerun_redoes_only_what_is_missing_or_damaged(reproduced, capsys):
    assert _practise(reproduced) == 0
    folder = reproduced / "practice" / "150_steps_explore"
    before = (folder / "practice.json").read_bytes()
    first = sorted(folder.glob("*/practice_0.json"))
    first[0].unlink()
    first[1].write_text(first[1].read_text()[:-20])
    capsys.readouterr()
    assert cli.main(["practice", "--run-dir", str(reproduced), "--steps", "150", "--trials", "1",
                     "--workers", "1", "--method", "explore"]) == 0
    err = capsys.readouterr().err
    assert "practised 2 imitators" in err and "is damaged" in err and "making it again" in err
    assert (folder / "practice.json").read_bytes() == before


def test_a_benchmarks_imitators_practise_and_two_workers_give_the_same_bits(benchmarked, tmp_path):
    assert _practise(benchmarked) == 0
    folder = benchmarked / "practice" / "150_steps_explore"
    one = (folder / "practice.json").read_bytes()
    assert json.loads(one)["run"] == "benchmark" and list(json.loads(one)["groups"]) == ["pair"]
    for path in folder.glob("*/practice_*.json"):
        path.unlink()
    assert _practise(benchmarked, workers="2") == 0
    assert (folder / "practice.json").read_bytes() == one


@pytest.mark.parametrize(("extra", "message"), [
    (["--only", "nope"], "--only: the run has no profile 'nope'; it has pair"),
    (["--trials", "3"], "--trials 3: the run has 2 trials per profile"),
])
def test_bad_input_is_one_line(benchmarked, capsys, extra, message):
    assert cli.main(["practice", "--run-dir", str(benchmarked), "--quiet", "--method", "explore", *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and len(err.splitlines()) == 1


def test_the_default_method_without_the_rl_extra_says_how_to_install_it(benchmarked, capsys, monkeypatch):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "stable_baselines3" else real(name, *a))
    assert cli.main(["practice", "--run-dir", str(benchmarked), "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.endswith('--method distil: practice by distil needs stable-baselines3 and torch: pip install '
                        '"polymimic[rl]" (explore needs neither)') and len(err.splitlines()) == 1
    assert not (benchmarked / "practice" / "25000_steps_distil").exists()  # refused before anything is made


def test_a_directory_that_is_no_run_is_refused(tmp_path, capsys):
    assert cli.main(["practice", "--run-dir", str(tmp_path)]) == 2
    assert "holds no manifest.json: not a run directory" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        cli.main(["practice", "--run-dir", str(tmp_path), "--steps", "-5"])


def test_a_run_of_another_kind_is_refused_naming_the_kinds_that_practise(tmp_path, capsys):
    (tmp_path / "manifest.json").write_text('{"format": "polymimic.matrix_run"}')
    assert cli.main(["practice", "--run-dir", str(tmp_path)]) == 2
    assert capsys.readouterr().err.strip().endswith(
        "is a polymimic.matrix_run; practice needs a reproduce or benchmark run")
