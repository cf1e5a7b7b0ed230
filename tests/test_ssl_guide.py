"""docs/guides/ssl.md end to end: the bundled SSL-Vision-style log and the team's robot through the
three commands of one config, and the log being what its generator makes."""

import json
import pathlib
import shutil

import pytest

from polymimic import cli
from polymimic.datasets import load_demonstrations
from polymimic.runs.config import RunConfig

pytest.importorskip("sklearn")

SSL = pathlib.Path(__file__).resolve().parent.parent / "examples" / "ssl"


def test_the_bundled_log_is_what_its_generator_makes(tmp_path, monkeypatch):
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_log", SSL / "make_log.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.write(tmp_path / "again.csv")
    assert (tmp_path / "again.csv").read_bytes() == (SSL / "ssl_vision.csv").read_bytes()


def test_one_config_and_three_commands(tmp_path, capsys, monkeypatch):
    for name in ("ssl.toml", "ssl_vision.csv"):
        shutil.copy(SSL / name, tmp_path / name)
    monkeypatch.chdir(tmp_path)

    assert cli.main(["import-tracks", "--config", "ssl.toml", "--as", "ssl_log", "--out", "ssl_log.parquet"]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "3 episodes from ssl_vision.csv: 3 demonstrations (2 dropped readings filled in, 1 gap bridged), 0 invalid; "
        "written to ssl_log.parquet", "  episode 0: 2 dropped readings filled in", "  episode 1: 1 gap bridged"]
    bodies = RunConfig.load(tmp_path / "ssl.toml").bodies
    assert {d.body.name for d in load_demonstrations(tmp_path / "ssl_log.parquet", bodies=bodies)} == {"ssl_bot"}

    assert cli.main(["reproduce", "--config", "ssl.toml", "--quick", "--run-dir", "runs/ssl", "--quiet"]) == 0
    results = json.loads((tmp_path / "runs" / "ssl" / "results.json").read_text())
    assert results["imitator"] == "ssl_bot"
    ssl = results["experiments"]["ssl"]
    assert ssl["ordering"] == ["ssl_log", "expert"] and ssl["imitator"]["attempts"] == 50

    assert cli.main(["matrix", "--config", "ssl.toml", "--quick", "--run-dir", "runs/ssl-matrix", "--imitators",
                     "ssl_bot", "lego", "--quiet"]) == 0
    matrix = json.loads((tmp_path / "runs" / "ssl-matrix" / "matrix.json").read_text())
    assert matrix["columns"][-1] == "ssl_log" and list(matrix["cells"]) == ["ssl_bot", "lego"]
    assert matrix["imitators"]["ssl_bot"]["field"]["length_mm"] == 9000
    for row in ("ssl_bot", "lego"):
        cell = matrix["cells"][row]["ssl_log"]
        assert cell["demonstrators"] == ["ssl_log"] and cell["polymimic"]["evaluated"] == 2
    # The pictures on the right fields: the log's and the team's robot's on 9 × 6 m, the Lego's on its own.
    report = (tmp_path / "runs" / "ssl-matrix" / "matrix.md").read_text()
    for field, picture in (("ssl_bot's 9000 × 6000", "set_ssl_log"), ("ssl_bot's 9000 × 6000", "attempt_ssl_bot"),
                           ("lego's 1020 × 810", "attempt_lego"), ("tiny's 560 × 345", "set_tiny")):
        assert f"on the {field} mm field](plots/matrix_{picture}.png)" in report
