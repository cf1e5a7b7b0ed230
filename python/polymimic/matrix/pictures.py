"""The matrix's pictures, each on the right field: for every set of demonstrators a column stands
for, its first demonstration on its demonstrator's own field (a log of a 9 × 6 m field on a 9 × 6 m
field); for every row, the first evaluation attempt of its imitator after the first trial, learning
from the pictured column (the Expert's, else the first), on the row's own field.

Each picture is drawn from files of the run (a set's recordings, a row's saved attempt), so that
drawing it again gives the same file; none of them moves a figure of ``matrix.json``.

>>> set_picture("own_wagon"), attempt_picture("lego")
('matrix_set_own_wagon.png', 'matrix_attempt_lego.png')
>>> from polymimic.matrix.config import MatrixConfig
>>> config = MatrixConfig.from_toml('[matrix]\\nimitators = ["lego", "wagon"]\\n')
>>> sets = pictured_sets(config)
>>> pictured_column(config), list(sets)
('expert', ['expert', 'tiny', 'humanoid', 'own_wagon', 'mixed_bodies'])
>>> sets["expert"], sets["own_wagon"]
(['expert', 'own body (lego)'], ['own body (wagon)'])
"""

from __future__ import annotations

import dataclasses
import pathlib
from typing import TYPE_CHECKING

from polymimic._drawn_field import scene_of
from polymimic.bodies import BodiesGiven
from polymimic.datasets import load_demonstrations
from polymimic.field import Demonstration
from polymimic.matrix.config import MatrixConfig, demonstrator_sets, stored_column
from polymimic.matrix.rundir import MatrixDir
from polymimic.matrix.weighing import chosen_weighting
from polymimic.plots import plot_demonstration, save_figure
from polymimic.runs.stages import counted

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["Picture", "attempt_figure", "attempt_picture", "draw_pictures", "one_attempt", "pictured_attempt_path",
           "pictured_column", "pictured_sets", "pictured_trial", "set_figure", "set_picture"]

PICTURE_DPI = 100
"""The pictures' resolution: a 7.5 × 5.6 inch figure, 750 × 560 pixels."""


@dataclasses.dataclass(frozen=True)
class Picture:
    """One picture of the report: its section (``"demonstrators"`` or ``"attempts"``), what it
    shows, and its file relative to the run."""

    section: str
    caption: str
    file: str


def set_picture(name: str) -> str:
    """The file, in ``plots/``, of the set ``name``'s demonstration."""
    return f"matrix_set_{name}.png"


def attempt_picture(row: str) -> str:
    """The file, in ``plots/``, of the row's imitator's attempt."""
    return f"matrix_attempt_{row}.png"


def pictured_column(config: MatrixConfig) -> str:
    """The column whose cell the rows' attempts are played in: the Expert's, else the first."""
    columns = config.columns()
    return "expert" if "expert" in columns else columns[0]


def pictured_sets(config: MatrixConfig) -> dict[str, list[str]]:
    """Every set of demonstrators the columns stand for, in the columns' order and then the rows',
    each with the columns it is the set of (``own body (wagon)`` where a row's own body is a set
    of its own)."""
    sets: dict[str, list[str]] = {}
    for column in config.columns():
        for row in config.matrix.imitators:
            name = demonstrator_sets(row, config.run.demonstrators)[column].name
            label = f"own body ({row})" if column == "own_body" else column.replace("_", " ")
            if label not in sets.setdefault(name, []):
                sets[name].append(label)
    return sets


def pictured_trial(run: MatrixDir, config: MatrixConfig, row: str) -> tuple[str, int, str]:
    """The trial whose first attempt pictures the row: its computed cell's column (the pictured
    column's), the first trial's seed, and the weighting that trial learned with."""
    column = stored_column(demonstrator_sets(row, config.run.demonstrators), pictured_column(config))
    weighting, _ = chosen_weighting(run, config, row, column)
    return column, config.trial_seeds()[0], weighting


def pictured_attempt_path(run: MatrixDir, config: MatrixConfig, row: str) -> pathlib.Path:
    """Where the row's pictured attempt is saved: in its cell, under the trial's seed and weighting
    (another weighting chosen, another file)."""
    return run.attempt_path(row, *pictured_trial(run, config, row))


def one_attempt(path: pathlib.Path, *, bodies: BodiesGiven = ()) -> Demonstration:
    """The one attempt saved at ``path`` (a body of one's own read as ``bodies`` describes it)."""
    return counted(load_demonstrations(path, bodies=bodies), 1)[0]


def set_figure(run: MatrixDir, config: MatrixConfig, name: str) -> tuple[Figure, str]:
    """The set ``name``'s first demonstration (from its recordings in the run) drawn on its
    demonstrator's own field, and words saying whose it is and which field."""
    demo = load_demonstrations(run.require(run.set_path(name), "matrix"), bodies=config.run.bodies)[0]
    columns = ", ".join(pictured_sets(config)[name])
    figure, field = _drawn(demo, config, f"{columns}: {demo.demonstrator}, configuration {demo.configuration}")
    return figure, f"{columns}: {demo.demonstrator} ({demo.outcome.replace('_', ' ')}), {field}"


def attempt_figure(run: MatrixDir, config: MatrixConfig, row: str) -> tuple[Figure, str]:
    """The row's pictured attempt (saved by the run's ``attempts`` step) drawn on the row's own
    field, and words saying whose it is and which field."""
    attempt = one_attempt(run.require(pictured_attempt_path(run, config, row), "matrix"), bodies=config.run.bodies)
    label = f"{row} learning from {pictured_column(config).replace('_', ' ')}, trial seed {config.trial_seeds()[0]}"
    figure, field = _drawn(attempt, config, f"{label}: configuration {attempt.configuration}")
    return figure, f"{label} ({attempt.outcome.replace('_', ' ')}), {field}"


def draw_pictures(run: MatrixDir, config: MatrixConfig) -> list[Picture]:
    """Every set's picture and every row's, from the run's files, into ``plots/``; what each shows."""
    pictures = []
    for section, file, (figure, caption) in [
            *(("demonstrators", set_picture(name), set_figure(run, config, name)) for name in pictured_sets(config)),
            *(("attempts", attempt_picture(row), attempt_figure(run, config, row)) for row in config.matrix.imitators)]:
        save_figure(figure, run.plots / file, dpi=PICTURE_DPI)
        pictures.append(Picture(section, caption, f"plots/{file}"))
    return pictures


def _drawn(demo: Demonstration, config: MatrixConfig, title: str) -> tuple[Figure, str]:
    """``demo`` drawn on its body's own field, titled ``title`` and its outcome; the words that say
    which field."""
    figure = plot_demonstration(demo)
    figure.axes[0].set_title(f"{title}: {demo.outcome.replace('_', ' ')}\n{len(demo.frames)} frames, "
                             f"{demo.frames['t_s'][-1]:.1f} s, on the {demo.body.name}'s field", fontsize="medium")
    scene = scene_of(demo.body)
    return figure, f"on the {demo.body.name}'s {scene.field_length_mm:g} × {scene.field_width_mm:g} mm field"
