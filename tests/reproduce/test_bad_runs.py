"""Damaged, foreign and contended run directories: each refused in one line (exit 2) or found
damaged and made again, never a traceback, never a half-written file taken as finished."""

import json
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

from polymimic import cli
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.config import ConfigError, RunConfig
from polymimic.runs.rundir import RunError


@pytest.fixture(scope="module")
def tiny(tiny_run_toml):
    return tiny_run_toml(trials=2, evaluated_imitators=1, attempts_per_configuration=2)


@pytest.fixture(scope="module")
def finished_run(tiny, tmp_path_factory):
    """A whole tiny run, to be copied and damaged."""
    root = tmp_path_factory.mktemp("finished")
    (root / "tiny.toml").write_text(tiny)
    run_dir = root / "run"
    assert cli.main(["reproduce", "--config", str(root / "tiny.toml"), "--run-dir", str(run_dir), "--quiet",
                     "--workers", "1"]) == 0
    return run_dir


@pytest.fixture
def run_copy(finished_run, tmp_path):
    copy = tmp_path / "run"
    shutil.copytree(finished_run, copy)
    return copy


def _fails_in_one_line(capsys, argv, *expected):
    code = cli.main(argv)
    err = capsys.readouterr().err
    assert code == 2, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    for text in expected:
        assert text in err, err
    return err


def test_a_manifest_that_is_not_an_object(run_copy, capsys):
    (run_copy / "manifest.json").write_text("[1, 2]")
    _fails_in_one_line(capsys, ["report", "--run-dir", str(run_copy), "--quiet"], "manifest.json",
                       "a JSON object is expected, got list")


@pytest.mark.parametrize("damage", [
    lambda data: data[:100],                                 # truncated
    lambda data: data.replace(b'"lp": ', b'"lp": "high", "was": ', 1),  # retyped
    lambda data: b"\x00\xff\xfe not text",                  # binary
], ids=["truncated", "retyped", "binary"])
def test_a_damaged_trial_is_made_again_with_the_same_bits(run_copy, capsys, damage):
    trial = run_copy / "models" / "experiments" / "varying_skill" / "trial_1.json"
    original = trial.read_bytes()
    trial.write_bytes(damage(original))
    _fails_in_one_line(capsys, ["report", "--run-dir", str(run_copy), "--quiet"], "trial_1.json")
    assert cli.main(["learn", "--run-dir", str(run_copy), "--quiet", "--workers", "1"]) == 0
    err = capsys.readouterr().err
    assert "trial_1.json is damaged" in err and "making it again" in err
    assert trial.read_bytes() == original


def test_a_damaged_evaluation_is_made_again(run_copy, capsys):
    evaluation = run_copy / "models" / "experiments" / "heterogeneous_rcb" / "evaluation_0_improved.json"
    original = json.loads(evaluation.read_text())
    for damaged in ('{"goals": "x"', json.dumps({**original, "goals": original["attempts"] + 1}),
                    json.dumps({k: v for k, v in original.items() if k != "outcomes"})):
        evaluation.write_text(damaged)
        _fails_in_one_line(capsys, ["report", "--run-dir", str(run_copy), "--quiet"], "evaluation_0_improved.json")
        assert cli.main(["evaluate", "--run-dir", str(run_copy), "--quiet", "--workers", "1"]) == 0
        assert "evaluation_0_improved.json is damaged" in capsys.readouterr().err
        assert json.loads(evaluation.read_text()) == original


def test_a_damaged_dataset_is_made_again(run_copy, capsys):
    demos = run_copy / "datasets" / "demonstrations_poor.parquet"
    original = demos.read_bytes()
    demos.write_bytes(original[: len(original) // 2])
    assert cli.main(["record", "--run-dir", str(run_copy), "--quiet"]) == 0
    assert "demonstrations_poor.parquet is damaged" in capsys.readouterr().err
    assert demos.read_bytes() == original


def test_bad_values_are_refused_when_the_config_is_read(tmp_path, capsys):
    cases = {
        "[field.tracker]\nposition_sigma_mm = -1.0\n": "position_sigma_mm",
        "[field]\ntime_limt_s = 30.0\n": "unknown key in [field]: time_limt_s",
        "[segmenter]\nmin_frames = 0\n": "[segmenter] min_frames = 0 must be at least 2",
        "[segmenter]\ngap_margin = nan\n": "[segmenter] gap_margin = nan",
        "[segmenter]\nstop_rotation_deg = 400.0\n": "at most 180",
        "[recognizer]\ntol = -1e-4\n": "[recognizer] tol",
        "[seeds]\nevaluation = -3\n": "[seeds] evaluation = -3",
        "[learning]\ndecay_step = nan\n": "[learning]",
    }
    for text, expected in cases.items():
        path = tmp_path / "bad.toml"
        path.write_text(text)
        with pytest.raises(ConfigError, match=None) as refused:
            RunConfig.load(path)
        assert expected in str(refused.value), (text, refused.value)
        _fails_in_one_line(capsys, ["config", "--config", str(path)], expected)


def test_a_run_dir_that_is_a_file(tmp_path, capsys):
    (tmp_path / "afile").write_text("")
    _fails_in_one_line(capsys, ["report", "--run-dir", str(tmp_path / "afile")], "is a file, not a run directory")


def test_a_run_directory_in_use_is_refused_naming_its_holder(run_copy, capsys):
    with RunDir(run_copy).lock("polymimic learn"):
        holder = subprocess.run([sys.executable, "-m", "polymimic", "learn", "--run-dir", str(run_copy), "--quiet"],
                                capture_output=True, text=True, timeout=120)
    assert holder.returncode == 2 and "Traceback" not in holder.stderr
    assert f"is in use by pid {os.getpid()}" in holder.stderr and "polymimic learn" in holder.stderr
    # Free again, it runs (and finds nothing to do).
    assert cli.main(["learn", "--run-dir", str(run_copy), "--quiet"]) == 0


def test_the_lock_is_the_holders_to_take_again(tmp_path):
    run = RunDir(tmp_path / "r")
    with run.lock("polymimic reproduce"), run.lock("polymimic learn"):
        other = RunDir(tmp_path / "r")
        with pytest.raises(RunError, match="in use by pid"):
            with other.lock("polymimic report"):
                pass


def test_temporaries_of_an_interrupted_stage_are_removed(run_copy, capsys):
    stale = [run_copy / "plots" / ".fig_4_7.png.0123abcd.tmp.png",
             run_copy / "models" / "experiments" / "varying_skill" / ".trial_0.json.deadbeef.tmp.json"]
    for path in stale:
        path.write_bytes(b"half")
    keep = run_copy / "plots" / ".notes"
    keep.write_text("mine")
    assert cli.main(["report", "--run-dir", str(run_copy), "--quiet"]) == 0
    capsys.readouterr()
    assert not any(p.exists() for p in stale) and keep.exists()


def _partial_files(run_dir):
    return [p for p in run_dir.rglob(".*") if ".tmp" in p.name]


def test_killed_at_any_stage_and_rerun_gives_the_same_results(finished_run, tiny, tmp_path):
    """SIGKILL part way (several moments, so that different stages are hit), then the same
    command again: the same results.json as the uninterrupted run, and no partial file."""
    (tmp_path / "tiny.toml").write_text(tiny)
    argv = [sys.executable, "-m", "polymimic", "reproduce", "--config", str(tmp_path / "tiny.toml"), "--quiet",
            "--workers", "1"]
    expected = (finished_run / "results.json").read_bytes()
    for delay_s in (0.5, 2.0, 4.0, 7.0):
        run_dir = tmp_path / f"killed_{delay_s}"
        process = subprocess.Popen([*argv, "--run-dir", str(run_dir)], stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL, start_new_session=True)
        time.sleep(delay_s)
        os.killpg(process.pid, signal.SIGKILL)
        process.wait(timeout=60)
        rerun = subprocess.run([*argv, "--run-dir", str(run_dir)], capture_output=True, text=True, timeout=600)
        assert rerun.returncode == 0, rerun.stderr
        assert (run_dir / "results.json").read_bytes() == expected, delay_s
        assert not _partial_files(run_dir), _partial_files(run_dir)


def _config_tables():
    """Run configs as a careless hand writes them: known and misspelt sections and keys, values
    of every TOML type (NaN and infinities among the floats)."""
    from hypothesis import strategies as st

    defaults = RunConfig().to_dict()
    sections = st.sampled_from([*defaults, "experiment", "Seeds"])
    values = st.one_of(st.integers(-2**65, 2**65), st.floats(allow_nan=True, allow_infinity=True), st.booleans(),
                       st.text(max_size=6), st.lists(st.integers(), max_size=2),
                       st.dictionaries(st.text(max_size=4), st.integers(), max_size=2))

    def keys_of(section):
        known = list(defaults.get(section, {})) or ["x"]
        return st.dictionaries(st.sampled_from([*known, known[0] + "s"]), values, max_size=3)

    return sections.flatmap(lambda s: st.fixed_dictionaries({s: keys_of(s)}))


def test_any_config_is_refused_by_name_or_read_whole():
    from hypothesis import given, settings

    @settings(max_examples=int(os.environ.get("POLYMIMIC_BATTERY_EXAMPLES", "40")), deadline=None, derandomize=True)
    @given(data=_config_tables())
    def check(data):
        try:
            config = RunConfig.from_dict(data)
        except ConfigError as error:
            section = next(iter(data))
            assert section in str(error) or "unknown section" in str(error), (data, error)
            return
        assert RunConfig.from_toml(config.to_toml()) == config

    check()


def test_loaded_reads_a_whole_output_once_and_removes_a_damaged_one(tmp_path):
    run = RunDir(tmp_path / "run")
    whole, damaged = tmp_path / "whole.json", tmp_path / "damaged.json"
    whole.write_text('{"attempts": 50}')
    damaged.write_text('{"attempts": 5')
    reads: list[str] = []

    def load(path):
        reads.append(path.name)
        return json.loads(path.read_text())  # json.JSONDecodeError is a ValueError

    warnings: list[str] = []
    assert run.loaded(whole, load, say=warnings.append) == {"attempts": 50}
    assert reads == ["whole.json"]
    assert run.loaded(tmp_path / "missing.json", load) is None
    assert run.loaded(damaged, load, say=warnings.append) is None
    assert not damaged.exists() and len(warnings) == 1 and "damaged.json is damaged" in warnings[0]
    assert run.finished(whole, load) and not run.finished(damaged, load)
