"""polymimic's tuning in a benchmark, with a baseline's effort: which parts of its world model
its LP weighting reaches (``[learning] world_weighting``), chosen among ``[benchmark]
world_weightings`` on the validation attempts the baselines are tuned on, one trial under the
first trial's seed per candidate. A benchmark of one candidate, or one without ``polymimic``,
makes no choice: it takes the first, untried."""

from __future__ import annotations

from typing import Any

from polymimic.baselines.tuning import validation_rank
from polymimic.benchmark.config import BenchmarkConfig
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.benchmark.task_files import load_weighing
from polymimic.benchmark.tasks import WEIGHED

__all__ = ["chosen_world_weighting", "is_weighed"]


def is_weighed(config: BenchmarkConfig) -> bool:
    """Does polymimic choose its world weighting in ``config``'s profiles?"""
    return WEIGHED in config.benchmark.methods and len(config.benchmark.world_weightings) > 1


def chosen_world_weighting(run: BenchmarkDir, config: BenchmarkConfig,
                           profile: str) -> tuple[str, list[dict[str, Any]]]:
    """polymimic's world weighting in ``profile`` and every candidate's validation score: the
    best by net goals, then goals (the first of equals), as a baseline's candidates are ranked;
    the first candidate, untried, where nothing is weighed."""
    weightings = config.benchmark.world_weightings
    if not is_weighed(config):
        return weightings[0], []
    scores = [load_weighing(run.require(run.weighing_path(profile, w), "benchmark")) for w in weightings]
    best = max(range(len(scores)), key=lambda i: (validation_rank(scores[i]), -i))
    return weightings[best], [{"world_weighting": s["weighting"], "goals": s["goals"], "own_goals": s["own_goals"],
                               "attempts": s["attempts"]} for s in scores]
