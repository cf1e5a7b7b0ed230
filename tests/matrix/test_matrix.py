"""`polymimic matrix` on a run small enough for a test: its files, its schema, its resumption and
its refusals."""

import json

import pytest

from polymimic import cli
from polymimic.matrix.config import COLUMNS, WAGON, MatrixConfig, demonstrator_sets
from polymimic.matrix.driver import run_matrix
from polymimic.matrix.rundir import MatrixDir
from polymimic.matrix.summary import transfer
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError

pytest.importorskip("sklearn")

TINY = """
[recognizer]
train_per_primitive = 40
test_per_primitive = 10
codebook_size = 32
[matrix]
imitators = ["lego", "wagon"]
trials = 2
demonstrations_per_configuration = 2
attempts_per_configuration = 2
bco_fits = 2
tuning_budget = 1
validation_attempts_per_configuration = 1
max_decision_samples = 300
"""


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    folder = tmp_path_factory.mktemp("matrix")
    run = MatrixDir(folder / "run")
    config = run.open(MatrixConfig.from_toml(TINY))
    with TaskRunner(workers=1) as runner:
        run_matrix(run, config, runner, quiet=True)
    return run, config


def test_matrix_json_holds_every_cell_of_both_methods_with_its_transfer(finished):
    run, config = finished
    summary = json.loads(run.results_path.read_text())
    assert (summary["format"], summary["version"]) == ("polymimic.matrix", 1)
    assert list(summary["cells"]) == ["lego", "wagon"] and summary["columns"] == list(COLUMNS)
    for cells in summary["cells"].values():
        assert list(cells) == list(COLUMNS)
        for cell in cells.values():
            assert cell["polymimic"]["evaluated"] == 2 and cell["bco"]["evaluated"] == 2
            assert all(-4 <= net <= 4 for net in cell["polymimic"]["per_seed"] + cell["bco"]["per_seed"])
            own = cells["own_body"]["polymimic"]["net_goals"]["mean"]
            assert cell["transfer"]["polymimic"] == transfer(cell["polymimic"]["net_goals"]["mean"], own)
            assert set(cell["bco"]["hyperparameters"]) >= {"classifier", "frames_per_action"}
    # The Lego's own body is the Expert's column, the same cell; the wagon's its own set.
    assert summary["cells"]["lego"]["own_body"]["polymimic"] == summary["cells"]["lego"]["expert"]["polymimic"]
    assert summary["cells"]["wagon"]["own_body"]["set"] == "own_wagon"
    assert summary["imitators"]["wagon"]["field"]["goal_mouth_mm"] == 320.0
    assert summary["imitators"]["lego"]["reach_mm"] == 120.0
    assert run.report_html_path.exists() and (run.plots / "matrix_heat_map.png").stat().st_size > 0
    assert "| lego ← tiny: transfer ≥ 0.8 × the own-body cell |" in run.report_md_path.read_text()


def test_polymimic_weighs_a_crowds_members_as_its_validation_chose(finished):
    run, config = finished
    summary = json.loads(run.results_path.read_text())
    for row, cells in summary["cells"].items():
        for column, cell in cells.items():
            method = cell["polymimic"]
            if column != "mixed_bodies":
                # One demonstrator weighs 1 however it is weighed: no choice, the config's weighting.
                assert (method["weighting"], method["weighing"]) == ("lp", []), (row, column)
                continue
            tried = method["weighing"]
            assert [w["weighting"] for w in tried] == ["lp", "lp_gain"] and {w["attempts"] for w in tried} == {2}
            # The best by net goals, then goals; the first of equals.
            best = max(range(2), key=lambda i: (tried[i]["goals"] - tried[i]["own_goals"], tried[i]["goals"], -i))
            assert method["weighting"] == tried[best]["weighting"], (row, tried)
            saved = json.loads(run.evaluation_path(row, column, "polymimic", config.trial_seeds()[0]).read_text())
            assert saved["weighting"] == method["weighting"]
    assert "| lego ← mixed bodies |" in run.report_md_path.read_text()


def test_a_rerun_redoes_nothing_and_a_lost_cell_only(finished):
    run, config = finished
    before = run.results_path.read_bytes()
    lost = run.evaluation_path("wagon", "tiny", "polymimic", config.trial_seeds()[1])
    lost.write_text("{ damaged")
    run.weighing_path("lego", "mixed_bodies", "lp_gain").write_text('{"goals": -1}')
    # An evaluation made under a weighting the cell did not choose is redone too.
    other = run.evaluation_path("wagon", "mixed_bodies", "polymimic", config.trial_seeds()[0])
    saved = json.loads(other.read_text())
    other.write_text(json.dumps({**saved, "weighting": "even"}))
    with TaskRunner(workers=1) as runner:
        run_matrix(run, config, runner, quiet=True)
    stages = run.manifest()["stages"]
    assert stages["weigh"]["made"] == 1 and stages["polymimic"]["made"] == 2
    assert stages["tune"]["made"] == 0 and stages["bco"]["made"] == 0
    assert run.results_path.read_bytes() == before, "the same seed makes the same bits"


def test_each_row_learns_from_the_columns_demonstrators():
    sets = demonstrator_sets("tiny")
    assert sets["own_body"].members == sets["tiny"].members
    assert sets["mixed_bodies"].names[:3] == ("expert_00", "expert_01", "expert_02")
    assert len(sets["mixed_bodies"].names) == 9
    assert demonstrator_sets("wagon")["own_body"].members == (("tiny_wagon", "tiny", "wagon", 0.0),)
    assert MatrixConfig().body("wagon").description == WAGON


@pytest.mark.parametrize("toml, match", [
    ('[matrix]\nimitators = ["lego", "tinny"]\n', r"\[matrix\] imitators: 'tinny' is not a body"),
    ('[matrix]\nimitators = []\n', r"\[matrix\] imitators must be a non-empty list"),
    ('[matrix]\ntrials = 0\n', r"\[matrix\] trials"),
    ('[matrix]\ntrails = 3\n', r"unknown key in \[matrix\]: trails"),
    ('[matrix]\nweightings = ["lp", "lpp"]\n', r"\[matrix\] weightings must be .* one of even, lp, lp_gain; got"),
    ('[matrix]\nweightings = []\n', r"\[matrix\] weightings must be a non-empty list"),
    ('[matrix]\nweightings = [["lp"]]\n', r"\[matrix\] weightings must be a non-empty list"),
])
def test_a_bad_matrix_config_is_refused_naming_it(toml, match):
    with pytest.raises(ConfigError, match=match):
        MatrixConfig.from_toml(toml)


def test_the_command_answers_an_unknown_imitator_with_one_line(tmp_path, capsys):
    assert cli.main(["matrix", "--quick", "--imitators", "lego", "tinny", "--run-dir", str(tmp_path / "m")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "'tinny' is not a body" in err
    assert not (tmp_path / "m").exists(), "nothing is written for a refused config"


def test_the_config_round_trips():
    config = MatrixConfig.from_toml(TINY)
    assert MatrixConfig.from_toml(config.to_toml()) == config
    assert MatrixConfig.from_dict(json.loads(json.dumps(config.to_dict()))) == config


def test_the_described_body_in_docs_is_the_default_matrixs_own():
    import pathlib

    path = pathlib.Path(__file__).parents[2] / "docs" / "configs" / "matrix_wagon.toml"
    assert MatrixConfig.load(path) == MatrixConfig()


def test_without_a_choice_a_cell_takes_the_first_weighting(tmp_path):
    from polymimic.matrix.weighing import chosen_weighting, is_weighed

    one = MatrixConfig.from_toml('[matrix]\nweightings = ["lp_gain"]\n')
    run = MatrixDir(tmp_path / "never-written")
    assert not is_weighed(one, "lego", "mixed_bodies")
    assert chosen_weighting(run, one, "lego", "mixed_bodies") == ("lp_gain", [])
    two = MatrixConfig()
    assert is_weighed(two, "lego", "mixed_bodies") and not is_weighed(two, "lego", "expert")
    assert chosen_weighting(run, two, "tiny", "tiny") == ("lp", [])
