"""A run's demonstrations as Minari datasets (``polymimic export``): one dataset for each
demonstrator of the body ``PenaltyKick-v0`` simulates, read as the run's recogniser reads them
(or by the commands they sent)."""

from __future__ import annotations

import dataclasses
from typing import Any

from polymimic import export
from polymimic._native import PrimitiveRecognizer
from polymimic.datasets import load_demonstrations
from polymimic.field import body_of
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.config import RunConfig
from polymimic.runs.roster import DEMONSTRATORS

__all__ = ["export_run"]


def export_run(run: RunDir, config: RunConfig, *, prefix: str, actions: str = "recognizer", labels: str = "steps",
               overwrite: bool = False, **minari_info: Any) -> list[str]:
    """Write ``<prefix>-<demonstrator>-v0`` for every Lego-bodied demonstrator of the run (the
    Expert, the Poor, the Average); return the dataset ids written."""
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train")) if actions == "recognizer" \
        else None
    written = []
    for who in (w for w in DEMONSTRATORS if body_of(w) == "lego"):
        demos = load_demonstrations(run.require(run.demonstrations_path(who), "record" if who != "average"
                                                else "segment"), bodies=config.bodies)
        dataset_id = f"{prefix}-{who}-v0"
        export.to_minari(demos, dataset_id, actions=actions, recognizer=recognizer, labels=labels,
                         segmenter=dataclasses.asdict(config.segmenter), overwrite=overwrite, **minari_info)
        written.append(dataset_id)
    return written
