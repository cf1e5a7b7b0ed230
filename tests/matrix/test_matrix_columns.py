"""Columns of your own in a matrix: a config's [demonstrators] (a tracker log, a Python policy)
beside the built-in columns, and a reproduction's config read as a matrix's."""

import json

import pytest

import polymimic
from polymimic import cli
from polymimic.matrix.config import COLUMNS, MatrixConfig
from polymimic.matrix.driver import run_matrix
from polymimic.matrix.rundir import MatrixDir
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError

pytest.importorskip("sklearn")

SIZES = """
[recognizer]
train_per_primitive = 40
test_per_primitive = 10
codebook_size = 32
[matrix]
imitators = ["lego"]
columns = ["expert"]
trials = 2
demonstrations_per_configuration = 2
attempts_per_configuration = 2
bco_fits = 1
tuning_budget = 1
validation_attempts_per_configuration = 1
max_decision_samples = 300
"""

POLICY = '''
def chase(reading):
    """Forward, whatever it sees."""
    return "forward"
'''


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    folder = tmp_path_factory.mktemp("columns")
    polymimic.write_tracks(polymimic.record("poor", configuration=2, n=3, seed=7), folder / "log.csv",
                           include=("episode",))
    (folder / "mine.py").write_text(POLICY)
    (folder / "matrix.toml").write_text(SIZES + '[demonstrators.logged]\nlog = "log.csv"\nbody = "lego"\n'
                                        '[demonstrators.pushing]\npolicy = "mine.py:chase"\n')
    run = MatrixDir(folder / "run")
    config = run.open(MatrixConfig.load(folder / "matrix.toml"))
    with TaskRunner(workers=1) as runner:
        run_matrix(run, config, runner, quiet=True)
    return run, config


def test_the_demonstrators_are_columns_after_the_built_in_ones(finished):
    run, config = finished
    summary = json.loads(run.results_path.read_text())
    assert config.columns() == ("expert", "logged", "pushing")
    assert summary["columns"] == ["expert", "logged", "pushing"]
    logged = summary["cells"]["lego"]["logged"]
    assert logged["demonstrators"] == ["logged"] and logged["polymimic"]["evaluated"] == 2
    assert logged["transfer"] == {"polymimic": None, "bco": None}  # no own-body column to compare with
    recorded = polymimic.load_demonstrations(run.set_path("logged"))
    assert len(recorded) == 3 and {d.demonstrator for d in recorded} == {"logged"}  # the log's every episode
    assert len(polymimic.load_demonstrations(run.set_path("pushing"))) == 8  # 2 per configuration for each trial
    assert "| lego |" in run.report_md_path.read_text()


def test_the_config_with_columns_of_yours_round_trips(tmp_path):
    (tmp_path / "log.csv").write_text("")
    config = MatrixConfig.from_toml(SIZES + '[demonstrators.logged]\nlog = "log.csv"\nmax_gap_s = 0.35\n',
                                    base_dir=tmp_path)
    assert MatrixConfig.from_toml(config.to_toml()) == config
    assert MatrixConfig.from_dict(json.loads(json.dumps(config.to_dict()))) == config


def test_a_reproductions_config_reads_as_a_matrixs():
    toml = ('[bodies.cart]\nlength_mm = 90\nwidth_mm = 80\nwheel_base_mm = 70\ntop_wheel_speed_mm_s = 60\n'
            '[imitator]\nbody = "cart"\n[experiments]\ntrials = 3\n[demonstrators.cart_poor]\ncontroller = "poor"\n'
            'body = "cart"\n[experiments.mine]\ndemonstrators = ["expert", "cart_poor"]\n')
    config = MatrixConfig.from_toml(toml)
    assert config.matrix.imitators == ("cart", "lego", "tiny", "humanoid", "wagon")  # its imitator first
    assert config.columns() == (*COLUMNS, "cart_poor")
    named = MatrixConfig.from_toml(toml + '[matrix]\nimitators = ["lego"]\n')
    assert named.matrix.imitators == ("lego",)


@pytest.mark.parametrize("toml, match", [
    ('[demonstrators.alice]\nimported = true\n', r"\[demonstrators.alice\] is imported into a reproduction's run"),
    ('[demonstrators.own_x]\ncontroller = "poor"\n', r"needs a name apart from its built-in columns"),
    ('[matrix]\ncolumns = ["expret"]\n', r"\[matrix\] columns must be a list of distinct built-in columns"),
    ('[matrix]\ncolumns = []\n', r"\[matrix\] columns is empty and there is no \[demonstrators.<name>\]"),
    ('[demonstrators.logged]\nlog = "x.csv"\nmax_gap_s = -1\n', r"max_gap_s must be a number of seconds"),
])
def test_a_bad_column_is_refused_naming_it(toml, match):
    with pytest.raises(ConfigError, match=match):
        MatrixConfig.from_toml(toml)


def test_the_command_chooses_columns_and_refuses_an_unknown_one(tmp_path, capsys):
    argv = ["matrix", "--quick", "--columns", "expert", "expret", "--run-dir", str(tmp_path / "m")]
    assert cli.main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--columns expert expret: each once, one of expert, tiny" in err
    assert not (tmp_path / "m").exists()
