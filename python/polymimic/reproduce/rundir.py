"""A run directory: where every stage of a reproduction reads its inputs and writes its outputs.

::

    manifest.json            version, config, seeds, start and finish of every stage
    datasets/                self-observation, demonstrations, segments, imitator attempts (Parquet)
    models/recognizer.json   the HMM bank
    models/experiments/<experiment>/trial_<seed>.json            one learning trial each
    models/experiments/<experiment>/evaluation_<seed>_<control>.json
    results.json, plots/*.png, report.md, report.html

>>> import tempfile
>>> run = RunDir(tempfile.mkdtemp())
>>> config = run.open(RunConfig.quick())
>>> run.trial_path("varying_skill", 3).name
'trial_3.json'
>>> run.require(run.recognizer_path, "train")
Traceback (most recent call last):
...
polymimic.runs.rundir.MissingInputError: .../models/recognizer.json is missing: run `polymimic train ...` first
"""

from __future__ import annotations

import os
import pathlib

from polymimic.runs.config import RunConfig
from polymimic.runs.rundir import RunHouse

__all__ = ["MANIFEST_FORMAT", "RunDir"]

MANIFEST_FORMAT = "polymimic.run"


class RunDir(RunHouse[RunConfig]):
    """A reproduction's run directory: the thesis's datasets, trials, evaluations and report."""

    manifest_format = MANIFEST_FORMAT
    config_type = RunConfig
    results_name, report_name = "results", "report"

    def __init__(self, path: str | os.PathLike[str]) -> None:
        super().__init__(path)
        self.average_trial_path = self.models / "average_trial.json"

    def demonstrations_path(self, demonstrator: str) -> pathlib.Path:
        """A demonstrator's recordings (Parquet)."""
        return self.datasets / f"demonstrations_{demonstrator}.parquet"

    def segments_path(self, demonstrator: str) -> pathlib.Path:
        """A demonstrator's segments (Parquet)."""
        return self.datasets / f"segments_{demonstrator}.parquet"

    def attempts_path(self, experiment: str, control: str) -> pathlib.Path:
        """The attempts of an experiment's first evaluated imitator, driven by ``control``."""
        return self.datasets / f"attempts_{experiment}_{control}.parquet"

    def experiment_dir(self, experiment: str) -> pathlib.Path:
        """The folder of an experiment's trials and evaluations."""
        return self.models / "experiments" / experiment

    def trial_path(self, experiment: str, seed: int) -> pathlib.Path:
        """One learning trial of an experiment."""
        return self.experiment_dir(experiment) / f"trial_{seed}.json"

    def evaluation_path(self, experiment: str, seed: int, control: str) -> pathlib.Path:
        """One trained imitator's evaluation under a control (``thesis`` or ``improved``)."""
        return self.experiment_dir(experiment) / f"evaluation_{seed}_{control}.json"
