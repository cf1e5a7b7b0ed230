"""The matrix's pictures on the right field: a column of the bundled SSL log drawn on its 9 × 6 m
field, the Lego row's attempt on the Lego's 1020 × 810 mm field, both in the report, drawn again
to the same bytes, and made again when lost without moving ``matrix.json``."""

import dataclasses
import json
import pathlib
import shutil

import pytest
from matplotlib.patches import Rectangle

from polymimic.matrix.cell_files import load_cell_evaluation
from polymimic.matrix.config import MatrixConfig
from polymimic.matrix.driver import run_matrix
from polymimic.matrix.pictures import (
    attempt_figure,
    attempt_picture,
    one_attempt,
    pictured_attempt_path,
    set_figure,
    set_picture,
)
from polymimic.matrix.rundir import MatrixDir
from polymimic.runs.backends import TaskRunner

pytest.importorskip("sklearn")

SSL = pathlib.Path(__file__).resolve().parents[2] / "examples" / "ssl"

SIZES = """
[recognizer]
train_per_primitive = 40
test_per_primitive = 10
codebook_size = 32
[matrix]
imitators = ["lego"]
trials = 2
demonstrations_per_configuration = 2
attempts_per_configuration = 2
bco_fits = 1
tuning_budget = 1
validation_attempts_per_configuration = 1
max_decision_samples = 300
"""


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pictures")
    for name in ("ssl.toml", "ssl_vision.csv"):
        shutil.copy(SSL / name, folder / name)
    config = MatrixConfig.load(folder / "ssl.toml", base=MatrixConfig.from_toml(SIZES))
    # The config's [imitator] (the team's robot) is a row of its own: the Lego row alone here, and the
    # log's column alone.
    config = dataclasses.replace(config, matrix=dataclasses.replace(config.matrix, imitators=("lego",), columns=()))
    run = MatrixDir(folder / "run")
    config = run.open(config)
    with TaskRunner(workers=1) as runner:
        run_matrix(run, config, runner, quiet=True)
    return run, config


def _pitch_mm(ax):
    """The drawn field's length and width: the rectangle at the bottom of the picture."""
    pitch = next(p for p in ax.patches if isinstance(p, Rectangle) and p.get_zorder() == 0)
    return pitch.get_width(), pitch.get_height()


def _spans(ax, length_mm, width_mm):
    """The axes span the field, a tenth of its length beyond each goal line and a twentieth of its
    width beyond each side line."""
    return (ax.get_xlim() == pytest.approx((-0.6 * length_mm, 0.6 * length_mm))
            and ax.get_ylim() == pytest.approx((-0.55 * width_mm, 0.55 * width_mm)))


def test_the_logs_column_is_drawn_on_its_9_by_6_m_field(finished):
    run, config = finished
    assert config.columns() == ("ssl_log",)
    figure, words = set_figure(run, config, "ssl_log")
    ax = figure.axes[0]
    assert _pitch_mm(ax) == (9000.0, 6000.0)
    assert _spans(ax, 9000.0, 6000.0)  # ±5400 × ±3300 mm
    assert words.startswith("ssl log: ssl_log (") and words.endswith("on the ssl_bot's 9000 × 6000 mm field")


def test_the_lego_rows_attempt_is_drawn_on_the_legos_field(finished):
    run, config = finished
    figure, words = attempt_figure(run, config, "lego")
    ax = figure.axes[0]
    assert _pitch_mm(ax) == (1020.0, 810.0)
    assert _spans(ax, 1020.0, 810.0)  # ±612 × ±445.5 mm
    # The attempt is the first of the saved evaluation of the first trial, learning from the log.
    attempt = one_attempt(pictured_attempt_path(run, config, "lego"))
    saved = load_cell_evaluation(run.evaluation_path("lego", "ssl_log", "polymimic", config.trial_seeds()[0]))
    assert (attempt.body.name, attempt.configuration, attempt.outcome) == ("lego", 1, saved["outcomes"][0])
    assert words.startswith(f"lego learning from ssl log, trial seed {config.trial_seeds()[0]} ({attempt.outcome}")


def test_the_report_shows_both_pictures(finished):
    run, _ = finished
    markdown = run.report_md_path.read_text()
    for file in (set_picture("ssl_log"), attempt_picture("lego")):
        assert f"](plots/{file})" in markdown and (run.plots / file).stat().st_size > 0
    assert "on the ssl_bot's 9000 × 6000 mm field](plots/matrix_set_ssl_log.png)" in markdown
    assert "on the lego's 1020 × 810 mm field](plots/matrix_attempt_lego.png)" in markdown
    assert run.report_html_path.read_text().count('src="data:image/png;base64,') == 3  # and the heat map


def test_a_lost_attempt_is_played_again_to_the_same_picture_and_matrix_json(finished):
    run, config = finished
    pictures = {file: (run.plots / file).read_bytes() for file in (set_picture("ssl_log"), attempt_picture("lego"))}
    results = run.results_path.read_bytes()
    with TaskRunner(workers=1) as runner:
        run_matrix(run, config, runner, quiet=True)
    assert run.manifest()["stages"]["attempts"]["made"] == 0
    pictured_attempt_path(run, config, "lego").unlink()
    (run.plots / attempt_picture("lego")).unlink()
    with TaskRunner(workers=1) as runner:
        run_matrix(run, config, runner, quiet=True)
    stages = run.manifest()["stages"]
    assert stages["attempts"]["made"] == 1 and stages["polymimic"]["made"] == 0
    assert {file: (run.plots / file).read_bytes() for file in pictures} == pictures, "drawn again, the same file"
    assert run.results_path.read_bytes() == results
    assert json.loads(results)["cells"]["lego"]["ssl_log"]["polymimic"]["evaluated"] == 2
