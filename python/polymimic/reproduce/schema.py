"""The shape of ``results.json``, as types: what :func:`~polymimic.reproduce.results.gather`
builds and what the report and the figures read. Shares are fractions; ``None`` stands where a
number does not exist (a share of nothing, the sd of no trials). docs/formats.md ("Results of a
reproduction") describes each key. ``MeanSd`` (a mean and its sample sd over trials, sd 0 for one
trial) is the plots' own, so that the summaries go to the bar charts as they are.
"""

from __future__ import annotations

from typing import NotRequired, TypedDict

from polymimic.plots import MeanSd

__all__ = ["AppendixB", "BehaviourRow", "ExperimentResults", "ExperimentSummary", "ImitatorScore", "LpClimb",
           "LpOverTime", "MeanSd", "Outcomes", "PrimitiveStats", "Results", "SegmentRow", "Sizes"]


class PrimitiveStats(TypedDict):
    """One primitive's row of Table 3.1."""

    distance_mean_mm: float
    distance_sd_mm: float
    rotation_mean_deg: float
    rotation_sd_deg: float
    count: int


class SegmentRow(TypedDict):
    """One demonstrator's row of Table 4.5."""

    command_match: float | None
    gaps: float | None
    segments: int
    classifiable: int


class Outcomes(TypedDict):
    """Goals and own goals over a number of attempts (Tables 4.6, 4.9)."""

    goals: int
    own_goals: int
    attempts: int


class LpClimb(TypedDict):
    """The LP changes a model took to cover ``share`` of the way to its final LP."""

    share: float
    changes: MeanSd


class LpOverTime(TypedDict):
    """Every ``stride``-th LP of every trial, by model."""

    stride: int
    trials: dict[str, list[list[float]]]


class ImitatorScore(TypedDict):
    """Goals and own goals of the evaluated imitators, mean and sd over imitators (Tables 4.8,
    4.11)."""

    goals: float | None
    own_goals: float | None
    attempts: int
    goals_sd: float | None
    own_goals_sd: float | None
    imitators: int
    control: str | None


class ExperimentSummary(TypedDict):
    """An experiment's trials summarised, by model."""

    title: str
    ordering: list[str]
    phase_one: str
    trials: int
    match_rate: dict[str, MeanSd]
    behaviours: dict[str, dict[str, MeanSd]]
    final_lp: dict[str, MeanSd]
    lp_order_hits: int | None
    lp_climb: dict[str, LpClimb]
    lp_over_time: LpOverTime


class ExperimentResults(ExperimentSummary):
    """An experiment's trials and its imitators' scores under both controls."""

    imitator: ImitatorScore
    imitator_thesis_control: ImitatorScore


class BehaviourRow(TypedDict):
    """One behaviour of Appendix B: in how many models it was found, permanent, predicting the ball."""

    primitives: str
    count: int
    permanent: int
    predicting_ball: int


class AppendixB(TypedDict):
    """The behaviours found, made permanent and predicting the ball in most models."""

    models: int
    created: list[BehaviourRow]
    permanent: list[BehaviourRow]
    predicting_ball: list[BehaviourRow]


class Sizes(TypedDict):
    """How large the run was."""

    train_per_primitive: int
    test_per_primitive: int
    codebook_size: int
    demonstrations_per_configuration: int
    trials: int
    evaluated_imitators: int
    attempts_per_configuration: int


class Results(TypedDict):
    """The whole of ``results.json``."""

    format: str
    version: int
    polymimic_version: str
    imitator: NotRequired[str]
    """The imitator's body (the Lego robot's, the thesis's, where absent)."""
    sizes: Sizes
    primitive_stats: dict[str, PrimitiveStats]
    hmm_accuracy: dict[str, float | None]
    hmm_log_likelihood: dict[str, dict[str, float | None]]
    segments: dict[str, SegmentRow]
    demonstrators: dict[str, Outcomes]
    experiments: dict[str, ExperimentResults]
    appendix_b: AppendixB
