"""The reproduction commands: config, the stages one by one, replay, and clear errors."""

import json

import pytest
import tomllib

from polymimic import cli
from polymimic.runs.config import RunConfig


@pytest.fixture(scope="module")
def tiny(tiny_run_toml):
    return tiny_run_toml(trials=2, evaluated_imitators=1, attempts_per_configuration=2)


@pytest.fixture(scope="module")
def tiny_toml(tiny, tmp_path_factory):
    path = tmp_path_factory.mktemp("config") / "tiny.toml"
    path.write_text(tiny)
    return path


@pytest.fixture(scope="module")
def reproduced(tiny_toml, tmp_path_factory):
    """A tiny run made stage by stage through the command line, as a user would."""
    run_dir = tmp_path_factory.mktemp("runs") / "tiny"
    common = ["--run-dir", str(run_dir), "--quiet", "--workers", "1"]
    assert cli.main(["self-observe", "--config", str(tiny_toml), *common]) == 0
    for stage in ("record", "train", "segment", "learn", "evaluate", "report"):
        assert cli.main([stage, *common]) == 0, stage
    return run_dir


def _error(capsys, argv):
    code = cli.main(argv)
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return code, err


def test_config_prints_every_parameter_with_the_thesis_defaults(capsys):
    assert cli.main(["config"]) == 0
    text = capsys.readouterr().out
    assert RunConfig.from_toml(text) == RunConfig()
    parsed = tomllib.loads(text)
    assert parsed["recognizer"]["codebook_size"] == 512 and parsed["experiments"]["trials"] == 100
    assert parsed["recognizer"]["test_per_primitive"] == 340 and parsed["learning"]["imitator_lp"] == 0.9
    assert cli.main(["config", "--quick"]) == 0
    assert RunConfig.from_toml(capsys.readouterr().out) == RunConfig.quick()


def test_config_of_a_file_and_of_a_run(capsys, tiny, tiny_toml, reproduced):
    assert cli.main(["config", "--config", str(tiny_toml)]) == 0
    assert tomllib.loads(capsys.readouterr().out)["experiments"]["trials"] == 2
    assert cli.main(["config", "--run-dir", str(reproduced)]) == 0
    assert RunConfig.from_toml(capsys.readouterr().out) == RunConfig.from_toml(tiny)


def test_the_stages_fill_the_run_directory(reproduced, capsys):
    manifest = json.loads((reproduced / "manifest.json").read_text())
    assert list(manifest["stages"]) == ["self-observe", "record", "train", "segment", "learn", "evaluate", "report"]
    assert manifest["config"]["experiments"]["trials"] == 2 and manifest["seeds"]["first_trial"] == 0
    assert {"polymimic_version", "created"} <= set(manifest)
    results = json.loads((reproduced / "results.json").read_text())
    assert results["experiments"]["varying_skill"]["trials"] == 2
    assert (reproduced / "report.html").stat().st_size > 10_000
    assert len(list((reproduced / "models" / "experiments").rglob("trial_*.json"))) == 3 * 2
    # Reproducing a finished run redoes nothing but the report, and says where it is.
    assert cli.main(["reproduce", "--run-dir", str(reproduced), "--quiet"]) == 0
    assert capsys.readouterr().out.strip().endswith("report.html")
    again = json.loads((reproduced / "manifest.json").read_text())["stages"]
    assert again["learn"]["finished"] == manifest["stages"]["learn"]["finished"] and "checked" in again["learn"]


def test_replay_writes_a_gif(reproduced, capsys):
    assert cli.main(["replay", "tiny", "--episode", "1", "--run-dir", str(reproduced), "--stride", "30"]) == 0
    assert capsys.readouterr().out.strip().endswith("replay_tiny_1.gif")
    assert (reproduced / "plots" / "replay_tiny_1.gif").stat().st_size > 0
    out = reproduced / "imitator.gif"
    assert cli.main(["replay", "imitator", "--experiment", "heterogeneous_bcr", "--control", "thesis", "--run-dir",
                     str(reproduced), "--stride", "30", "--out", str(out)]) == 0
    assert out.stat().st_size > 0
    code, err = _error(capsys, ["replay", "tiny", "--episode", "99", "--run-dir", str(reproduced)])
    assert code == 2 and "holds episodes 0 to 15; there is no episode 99" in err


def test_a_stage_without_its_inputs_says_which_stage_to_run(tmp_path, capsys, tiny_toml):
    code, err = _error(capsys, ["train", "--run-dir", str(tmp_path / "nowhere")])
    assert code == 2 and "nowhere is not a run directory (no manifest.json)" in err
    run_dir = tmp_path / "fresh"
    assert cli.main(["self-observe", "--run-dir", str(run_dir), "--config", str(tiny_toml), "--quiet"]) == 0
    code, err = _error(capsys, ["learn", "--run-dir", str(run_dir)])
    assert code == 2 and "recognizer.json is missing: run `polymimic train --run-dir" in err
    code, err = _error(capsys, ["report", "--run-dir", str(run_dir)])
    assert code == 2 and "is missing: run `polymimic train" in err


def test_a_run_keeps_its_config(reproduced, capsys):
    code, err = _error(capsys, ["learn", "--run-dir", str(reproduced), "--quick"])
    assert code == 2 and "was made with a different config" in err


def test_bad_configs_and_options_are_usage_errors(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("[recognizer]\ncodebok_size = 3\n")
    code, err = _error(capsys, ["reproduce", "--config", str(bad), "--run-dir", str(tmp_path / "r")])
    assert code == 2 and "bad.toml: unknown key in [recognizer]: codebok_size" in err
    assert not (tmp_path / "r").exists()
    code, err = _error(capsys, ["reproduce", "--config", str(tmp_path / "absent.toml"), "--run-dir",
                                str(tmp_path / "r")])
    assert code == 2 and "cannot read config" in err
    (tmp_path / "stuff").mkdir()
    (tmp_path / "stuff" / "notes.txt").write_text("mine")
    code, err = _error(capsys, ["self-observe", "--run-dir", str(tmp_path / "stuff")])
    assert code == 2 and "is not empty and holds no manifest.json" in err
    code, err = _error(capsys, ["learn", "--address", "auto"])
    assert code == 2 and err.strip() == "polymimic learn: error: --address is for the Ray backend: add --backend ray"
    for argv in (["learn", "--workers", "0"], ["learn", "--backend", "spark"]):
        with pytest.raises(SystemExit) as exit_:
            cli.main(argv)
        assert exit_.value.code == 2
        assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_export_writes_minari_datasets_of_the_runs_lego_demonstrators(reproduced, capsys, tmp_path, monkeypatch):
    minari = pytest.importorskip("minari")
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "minari"))
    who = ["--author", "tests", "--author-email", "tests@polymimic.invalid", "--code-permalink", "tests"]
    assert cli.main(["export", "--run-dir", str(reproduced), "--prefix", "polymimic/tiny", *who]) == 0
    written = capsys.readouterr().out.split()
    assert written == ["polymimic/tiny-expert-v0", "polymimic/tiny-poor-v0", "polymimic/tiny-average-v0"]
    expert = minari.load_dataset("polymimic/tiny-expert-v0")
    assert expert.total_episodes == 16 and expert.storage.metadata["learned_from_observation"] is True
    code, err = _error(capsys, ["export", "--run-dir", str(reproduced), "--prefix", "polymimic/tiny", *who])
    assert code == 2 and "exists already: pass overwrite=True" in err
    assert cli.main(["export", "--run-dir", str(reproduced), "--prefix", "polymimic/tiny", "--actions", "commands",
                     "--overwrite", *who]) == 0
    assert minari.load_dataset("polymimic/tiny-poor-v0").storage.metadata["polymimic_actions"] == "commands"
