"""Practice: the imitator keeps learning by playing (docs/guides/practice.md; the thesis's future work, thesis §5.4).

>>> from polymimic.practice import DEFAULT_CHECKPOINTS, PRACTICE_SEED_BASE
>>> DEFAULT_CHECKPOINTS[-1], PRACTICE_SEED_BASE == 2**63
(50000, True)
"""

from polymimic.practice.curve import DEFAULT_CHECKPOINTS, CurvePoint, curve_csv, curve_json, plot_curves, write_curve
from polymimic.practice.loop import Practice, practice, steps_of
from polymimic.practice.seeds import PRACTICE_SEED_BASE, round_seed

__all__ = ["DEFAULT_CHECKPOINTS", "PRACTICE_SEED_BASE", "CurvePoint", "Practice", "curve_csv", "curve_json",
           "plot_curves", "practice", "round_seed", "steps_of", "write_curve"]
