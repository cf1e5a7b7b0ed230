"""What a reproduction offers practice (:class:`~polymimic.runs.practising.PracticeSource`): the
improved imitator of each experiment, practising on the experiment's segmented demonstrations."""

from __future__ import annotations

import dataclasses
import pathlib
from collections.abc import Sequence

from polymimic._native import PrimitiveRecognizer
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.practising import PracticeInputs, PracticeSource, RunPractice, chosen_groups

__all__ = ["PRACTICE_SOURCE"]


def _practice(path: pathlib.Path, only: Sequence[str] | None, steps: int, method: str) -> RunPractice:
    """The reproduction at ``path`` ready to practise: the experiments ``only`` names (all for
    None), each one's demonstrations as the run segmented them."""
    from polymimic.reproduce.experiments import experiment_items, trial_seeds

    run = RunDir(path)
    config = run.open(None)
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    experiments = config.all_experiments()
    groups = chosen_groups(list(experiments), only, "experiment")
    inputs = PracticeInputs(recognizer=recognizer, learning=config.learning,
                            demonstrations={g: experiment_items(run, experiments[g]) for g in groups},
                            body=config.imitator_body(), field=config.field,
                            segmenter=dataclasses.asdict(config.segmenter), steps=steps,
                            attempts=config.evaluation_attempts(), method=method)
    return RunPractice(run=run, groups=groups, trial_seeds=trial_seeds(config), inputs=inputs,
                       trial_path=run.trial_path)


PRACTICE_SOURCE = PracticeSource(manifest_format=RunDir.manifest_format, command="reproduce", kind="reproduction",
                                 group="experiment", practice=_practice)
"""The reproduction's practice: ``polymimic practice --run-dir`` a reproduction's run."""
