"""``[imitator] body``: a reproduction whose learner is another body than the thesis's Lego robot."""

import json

import pytest

from polymimic.bodies import Body
from polymimic.datasets import load_demonstrations, load_self_observation
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.stages import Context, reproduce
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError, RunConfig


@pytest.fixture(scope="module")
def tiny_imitator_run(tiny_run_toml, tmp_path_factory):
    folder = tmp_path_factory.mktemp("tiny_imitator")
    config = RunConfig.from_toml(tiny_run_toml(trials=2, evaluated_imitators=1) + '[imitator]\nbody = "tiny"\n')
    run = RunDir(folder / "run")
    config = run.open(config)
    reproduce(Context(run=run, config=config, runner=TaskRunner(workers=1), quiet=True))
    return run, config


def test_the_imitator_observes_itself_learns_and_plays_as_the_tiny(tiny_imitator_run):
    run, config = tiny_imitator_run
    assert {s.body.name for s in load_self_observation(run.self_observation_path("train"))} == {"tiny"}
    average = load_demonstrations(run.demonstrations_path("average"))
    assert {d.body.name for d in average} == {"tiny"}, "the Average is an imitator: it has the imitator's body"
    attempts = load_demonstrations(run.attempts_path("varying_skill", "improved"))
    assert {a.body.name for a in attempts} == {"tiny"}
    # The tiny's field is 560 mm long: every attempt's ball starts on it.
    assert all(abs(a.frames["ball_x_mm"][0]) < 280.0 for a in attempts)
    results = json.loads(run.results_path.read_text())
    assert results["imitator"] == "tiny"


def test_the_report_of_another_imitator_leaves_out_the_thesiss_columns_and_checks(tiny_imitator_run):
    run, _ = tiny_imitator_run
    report = run.report_md_path.read_text()
    assert "The imitator is the tiny, not the thesis's Lego robot" in report
    assert "thesis" not in report.split("left out.", 1)[1].replace("thesis control", "")
    assert "**Shape:**" not in report
    assert "## Experiment: " in report and "What each of the tiny's primitives does" in report


@pytest.mark.parametrize("toml, match", [
    ('[imitator]\nbody = "tinny"\n', r"\[imitator\] body = 'tinny' is not a body: one of lego, tiny, humanoid"),
    ('[imitator]\nbody = "wagon"\n', r"describe it in a \[bodies.<name>\] table"),
    ('[imitator]\nbody = 3\n', r"\[imitator\] body = 3 must be a string"),
    ('[imitator]\nbodi = "tiny"\n', r"unknown key in \[imitator\]: bodi"),
])
def test_an_imitator_no_body_has_is_refused_naming_it(toml, match):
    with pytest.raises(ConfigError, match=match):
        RunConfig.from_toml(toml)


def test_an_imitator_of_a_described_body_is_that_body():
    config = RunConfig.from_toml('[bodies.van]\nlength_mm = 160\nwidth_mm = 150\nwheel_base_mm = 140\n'
                                 'top_wheel_speed_mm_s = 140\n[imitator]\nbody = "van"\n')
    assert config.imitator_body() == Body(config.bodies["van"]) and not config.thesis_imitator
    assert config.imitator_body().description is config.bodies["van"]
    assert RunConfig.from_toml(config.to_toml()) == config


def test_the_command_line_takes_the_imitator_and_refuses_an_unknown_one(tmp_path, capsys):
    from polymimic import cli

    assert cli.main(["benchmark", "--quick", "--imitator", "tinny", "--run-dir", str(tmp_path / "b")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "'tinny' is not a body" in err
