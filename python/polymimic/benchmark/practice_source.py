"""What a benchmark run offers practice (:class:`~polymimic.runs.practising.PracticeSource`):
polymimic's imitator of each profile, practising on the profile's crowd as the run recorded it."""

from __future__ import annotations

import dataclasses
import pathlib
from collections.abc import Sequence

from polymimic._native import PrimitiveRecognizer
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.learning import segmented
from polymimic.runs.practising import PracticeInputs, PracticeSource, RunPractice, chosen_groups

__all__ = ["PRACTICE_SOURCE"]


def _practice(path: pathlib.Path, only: Sequence[str] | None, steps: int, method: str) -> RunPractice:
    """The benchmark at ``path`` ready to practise: the profiles ``only`` names (all for None),
    each one's crowd segmented by the run's recogniser."""
    from polymimic.datasets import load_demonstrations

    run = BenchmarkDir(path)
    config = run.open(None)
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "benchmark"))
    segmenter = dataclasses.asdict(config.segmenter)
    groups = chosen_groups(list(config.benchmark.profiles), only, "profile")
    demos = {g: segmented(load_demonstrations(run.require(run.crowd_path(g), "benchmark"), bodies=config.run.bodies),
                          recognizer, **segmenter)
             for g in groups}
    inputs = PracticeInputs(recognizer=recognizer, learning=config.learning, demonstrations=demos,
                            body=config.imitator_body(), field=config.field, segmenter=segmenter, steps=steps,
                            attempts=config.evaluation_attempts(), method=method)
    return RunPractice(run=run, groups=groups, trial_seeds=config.trial_seeds(), inputs=inputs,
                       trial_path=run.trial_path)


PRACTICE_SOURCE = PracticeSource(manifest_format=BenchmarkDir.manifest_format, command="benchmark", kind="benchmark",
                                 group="profile", practice=_practice)
"""The benchmark's practice: ``polymimic practice --run-dir`` a benchmark run."""
