"""A matrix's run directory.

::

    manifest.json                                  version, config, start and finish of every step
    datasets/self_observation_<row>.parquet, models/recognizer_<row>.json   each imitator's own
    datasets/demonstrations_<set>.parquet          a set's demonstrations (load_demonstrations reads it)
    models/matrix/<row>/<column>/polymimic_<seed>.json   polymimic's evaluation after one trial
    models/matrix/<row>/<column>/polymimic_<seed>_<weighting>_attempt.parquet   its first attempt, pictured
    models/matrix/<row>/<column>/weighing_<weighting>.json   one of polymimic's weightings on validation
    models/matrix/<row>/<column>/bco_tuning.json   bco's candidates on validation, the choice
    models/matrix/<row>/<column>/bco_<seed>.json   one bco fit's evaluation
    matrix.json, matrix.md, matrix.html, plots/matrix_heat_map.png
    plots/matrix_set_<set>.png, plots/matrix_attempt_<row>.png   a set's demonstration, a row's attempt

>>> import tempfile
>>> run = MatrixDir(tempfile.mkdtemp())
>>> run.evaluation_path("tiny", "expert", "polymimic", 3).name
'polymimic_3.json'
"""

from __future__ import annotations

import pathlib

from polymimic.matrix.config import MatrixConfig
from polymimic.runs.rundir import RunHouse

__all__ = ["MatrixDir"]


class MatrixDir(RunHouse[MatrixConfig]):
    """Paths of a matrix's files."""

    manifest_format = "polymimic.matrix_run"
    config_type = MatrixConfig
    results_name = report_name = "matrix"

    def own_self_observation_path(self, row: str) -> pathlib.Path:
        """The row's own self-observation (Parquet)."""
        return self.datasets / f"self_observation_{row}.parquet"

    def recognizer_of(self, row: str) -> pathlib.Path:
        """The row's recogniser."""
        return self.models / f"recognizer_{row}.json"

    def set_path(self, name: str) -> pathlib.Path:
        """A demonstrator set's recordings (Parquet)."""
        return self.datasets / f"demonstrations_{name}.parquet"

    def cell_dir(self, row: str, column: str) -> pathlib.Path:
        """The folder of one cell's evaluations, weighings and tuning."""
        return self.models / "matrix" / row / column

    def evaluation_path(self, row: str, column: str, method: str, seed: int) -> pathlib.Path:
        """One evaluation of a method in a cell (a trial's or a fit's seed)."""
        return self.cell_dir(row, column) / f"{method}_{seed}.json"

    def attempt_path(self, row: str, column: str, seed: int, weighting: str) -> pathlib.Path:
        """The first evaluation attempt of polymimic's trial ``seed`` in a cell, learned with
        ``weighting`` (Parquet, one demonstration)."""
        return self.cell_dir(row, column) / f"polymimic_{seed}_{weighting}_attempt.parquet"

    def weighing_path(self, row: str, column: str, weighting: str) -> pathlib.Path:
        """One weighting's validation in a cell."""
        return self.cell_dir(row, column) / f"weighing_{weighting}.json"

    def tuning_path(self, row: str, column: str) -> pathlib.Path:
        """``bco``'s tuning in a cell."""
        return self.cell_dir(row, column) / "bco_tuning.json"
