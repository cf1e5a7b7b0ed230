"""Who takes part in a reproduction: the demonstrators a run records, the thesis's three
experiments (§4.4) and the two controls that drive their imitators. Plain data, imported by
every stage, the results and the report.

>>> DEMONSTRATORS
('expert', 'poor', 'tiny', 'humanoid', 'average')
>>> EXPERIMENTS["varying_skill"].ordering
('poor', 'average', 'expert')
>>> [e.name for e in EXPERIMENTS.values() if e.skill_order is None]
['heterogeneous_rcb', 'heterogeneous_bcr']
"""

from __future__ import annotations

import dataclasses

from polymimic import field

__all__ = ["CONTROLS", "DEMONSTRATORS", "EXPERIMENTS", "HETEROGENEOUS", "RECORDED", "VARYING_SKILL", "Experiment"]

RECORDED = field.DEMONSTRATORS
"""The built-in demonstrators, recorded by the ``record`` stage."""

DEMONSTRATORS = (*RECORDED, "average")
"""Every demonstrator of a run: the built-in ones and the Average, an imitator trained in the
heterogeneous experiment (§4.4.2)."""

HETEROGENEOUS = ("expert", "tiny", "humanoid")
"""The heterogeneous experiment's demonstrators, in its RCB ordering."""

VARYING_SKILL = ("poor", "average", "expert")
"""The varying-skill experiment's demonstrators, from least to most skilled."""

CONTROLS = ("improved", "thesis")
"""How an imitator's model drives the robot: polymimic's control, and the thesis's rule."""


@dataclasses.dataclass(frozen=True)
class Experiment:
    """One experiment: whose demonstrations, in which phase-one order, mixed or by model."""

    name: str
    title: str
    demonstrators: tuple[str, ...]
    """Whose demonstrations, in the order they are handed to every trial."""
    ordering: tuple[str, ...]
    """The demonstrators' models in phase-one order."""
    phase_one: str
    skill_order: tuple[str, ...] | None
    """The demonstrators from most to least skilled, where the experiment defines one."""


EXPERIMENTS = {e.name: e for e in (
    Experiment("heterogeneous_rcb", "heterogeneous bodies, RCB ordering", HETEROGENEOUS, HETEROGENEOUS,
               "by-model", None),
    Experiment("heterogeneous_bcr", "heterogeneous bodies, BCR ordering", HETEROGENEOUS, HETEROGENEOUS[::-1],
               "by-model", None),
    Experiment("varying_skill", "varying skill", VARYING_SKILL, VARYING_SKILL, "interleaved", VARYING_SKILL[::-1]),
)}
"""The thesis's three experiments, by name."""
