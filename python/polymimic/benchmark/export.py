"""A benchmark's crowds as Minari datasets (``polymimic export --run-dir <benchmark run>``): one
dataset of ``PenaltyKick-v0`` episodes per profile, ``<prefix>-<profile>-v0``, read as the
benchmark's recogniser reads them (or by the commands sent), each episode with its member's
lapse in its metadata. The environment simulates the Lego robot only, so a member of another
body (``mixed_bodies``' Tiny and humanoid members) is left out of its profile's dataset, and
said to be."""

from __future__ import annotations

import dataclasses
from typing import Any

from polymimic import export
from polymimic._native import PrimitiveRecognizer
from polymimic.benchmark.config import BenchmarkConfig
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.datasets import load_demonstrations

__all__ = ["Exported", "export_crowds"]


@dataclasses.dataclass(frozen=True)
class Exported:
    """The dataset ids written, and for each profile the members left out (of another body)."""

    dataset_ids: list[str]
    left_out: dict[str, list[str]]


def export_crowds(run: BenchmarkDir, config: BenchmarkConfig, *, prefix: str, actions: str = "recognizer",
                  labels: str = "steps", overwrite: bool = False, **minari_info: Any) -> Exported:
    """Write ``<prefix>-<profile>-v0`` for every profile the benchmark recorded."""
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "benchmark")) \
        if actions == "recognizer" else None
    crowds = config.crowds()
    # Every crowd first: one missing must not leave the earlier profiles' datasets written.
    paths = [run.require(run.crowd_path(crowd.name), "benchmark") for crowd in crowds]
    written, left_out = [], {}
    for crowd, path in zip(crowds, paths):
        demos = load_demonstrations(path, bodies=config.run.bodies)
        simulated = [m for m in crowd.members if m.body in export.SIMULATED_BODIES]
        if len(simulated) < len(crowd.members):
            left_out[crowd.name] = [m.name for m in crowd.members if m not in simulated]
        kept = [d for d in demos if d.body.kind in export.SIMULATED_BODIES]
        if not kept:
            continue
        dataset_id = f"{prefix}-{crowd.name}-v0"
        export.to_minari(kept, dataset_id, actions=actions, recognizer=recognizer, labels=labels,
                         segmenter=dataclasses.asdict(config.segmenter),
                         lapses={m.name: m.lapse for m in simulated}, overwrite=overwrite, **minari_info)
        written.append(dataset_id)
    return Exported(written, left_out)
