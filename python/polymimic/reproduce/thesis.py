"""The thesis's published numbers, to set beside ours in the report (Chapter 4, Appendix B).

The thesis's demonstrators are named here as in polymimic: its RC2004 robot (the
ExpertDemonstrator) is ``expert``, the Citizen ``tiny``, the Bioloid ``humanoid``, its
PoorDemonstrator and AverageDemonstrator ``poor`` and ``average``, and its trained imitators
(VaryingSkillTrained among them) ``imitator``. Shares are fractions, like ours.

>>> DEMONSTRATOR_GOALS["expert"]
{'goals': 27, 'own_goals': 4, 'attempts': 50}
>>> MATCH_RATE["heterogeneous_bcr"]["humanoid"]
{'mean': 0.809, 'sd': 0.013}
>>> len(APPENDIX_B["predicting_ball"]), APPENDIX_B["models"]
(30, 1200)
"""

from __future__ import annotations

from typing import Any

from polymimic._native import thesis_table_3_1
from polymimic.reproduce.schema import MeanSd

__all__ = ["ACCURACY", "APPENDIX_B", "DEMONSTRATOR_GOALS", "IMITATOR_GOALS", "MATCH_RATE", "SEGMENTS",
           "TABLE_3_1"]

TABLE_3_1: dict[str, dict[str, float]] = thesis_table_3_1()
"""Table 3.1: distance (mm) and rotation (deg) of each moving primitive, mean and sd."""

ACCURACY = {"forward": 0.9800, "backward": 0.9869, "left": 0.9684, "right": 0.9124}
"""Table 4.3: held-out accuracy of each primitive's HMM."""

SEGMENTS = {
    "tiny": {"command_match": 0.314, "gaps": 0.027},
    "expert": {"command_match": 0.355, "gaps": 0.013},
    "humanoid": {"command_match": 0.116, "gaps": 0.028},
    "poor": {"command_match": 0.501, "gaps": 0.012},
    "average": {"command_match": 0.362, "gaps": 0.026},
    "imitator": {"command_match": 0.626, "gaps": 0.020},
}
"""Table 4.5: segments whose label matched the commands sent, and gaps; ``imitator`` is the
thesis's VaryingSkillTrained imitator."""


def _goals(goals: int, own_goals: int) -> dict[str, int]:
    return {"goals": goals, "own_goals": own_goals, "attempts": 50}


DEMONSTRATOR_GOALS = {
    "expert": _goals(27, 4), "tiny": _goals(15, 3), "humanoid": _goals(12, 1),  # Table 4.6
    "poor": _goals(13, 23), "average": _goals(11, 9),                           # Table 4.9
}
"""Tables 4.6 and 4.9: goals and own goals of each demonstrator over its 50 demonstrations."""


def _share(mean_percent: float, sd_percent: float) -> MeanSd:
    return {"mean": round(mean_percent / 100, 6), "sd": round(sd_percent / 100, 6)}


MATCH_RATE = {
    "heterogeneous_rcb": {"imitator": _share(91.4, 1.2), "expert": _share(89.4, 0.6), "tiny": _share(91.6, 1.7),
                          "humanoid": _share(81.3, 1.1)},
    "heterogeneous_bcr": {"imitator": _share(91.3, 0.9), "expert": _share(89.4, 0.6), "tiny": _share(91.5, 1.1),
                          "humanoid": _share(80.9, 1.3)},
    "varying_skill": {"imitator": _share(85.9, 4.14), "poor": _share(81.3, 0.07), "average": _share(79.1, 0.04),
                      "expert": _share(87.2, 2.74)},
}
"""Tables 4.7 and 4.10: prediction rounds with a match, per forward model, mean (sd) over 100 trials."""

IMITATOR_GOALS = {
    "heterogeneous_rcb": _goals(11, 9), "heterogeneous_bcr": _goals(7, 13),  # Table 4.8
    "varying_skill": _goals(11, 13),                                         # Table 4.11
}
"""Tables 4.8 and 4.11: goals and own goals of one trained imitator per experiment, 50 attempts."""

TRIALS = 100
"""Trials per experiment."""


def _rows(text: str) -> list[dict[str, Any]]:
    rows = []
    for line in text.strip().splitlines():
        count, permanent, ball, primitives = line.split()
        rows.append({"primitives": primitives, "count": int(count), "permanent": int(permanent),
                     "predicting_ball": int(ball)})
    return rows


APPENDIX_B: dict[str, Any] = {
    "models": 1200,  # 300 trials, four forward models each
    "created": _rows("""
        1200 1200 73 F,F
        1200 1200 0 B,B
        1200 1200 65 F,F,F
        1199 1199 76 F,F,F,F
        1187 1165 0 B,B,B
        1182 1106 74 F,F,F,F,F
        1175 1165 5 L,B
        1168 1062 69 F,F,F,F,F,F
        1139 1100 24 F,L
        1107 1002 0 L,L
        1103 1024 16 R,F
        1091 1000 7 R,B
        1079 923 21 L,F
        1058 929 2 B,B,B,B
        1015 859 0 R,R
        1005 489 0 B,L
        975 577 1 B,R
        970 477 22 F,F,F,F,F,F,F
        965 206 5 B,F
        964 683 7 F,F,L
        952 840 30 F,L,B
        949 765 20 F,R,F
        941 729 6 F,L,F
        924 524 1 B,L,B
        915 823 0 L,L,L,L
        878 53 2 F,B
        872 409 1 B,B,B,B,B
        868 639 75 F,R
        837 656 2 L,B,B
        816 571 23 L,F,F
    """),
    "permanent": _rows("""
        1200 1200 73 F,F
        1200 1200 0 B,B
        1200 1200 65 F,F,F
        1199 1199 76 F,F,F,F
        1187 1165 0 B,B,B
        1175 1165 5 L,B
        1182 1106 74 F,F,F,F,F
        1139 1100 24 F,L
        1168 1062 69 F,F,F,F,F,F
        1103 1024 16 R,F
        1107 1002 0 L,L
        1091 1000 7 R,B
        1058 929 2 B,B,B,B
        1079 923 21 L,F
        1015 859 0 R,R
        952 840 30 F,L,B
        915 823 0 L,L,L,L
        949 765 20 F,R,F
        941 729 6 F,L,F
        964 683 7 F,F,L
        837 656 2 L,B,B
        868 639 75 F,R
        731 632 85 F,R,B
        725 621 0 L,L,L
        724 609 0 L,L,L,L,L,L
        700 580 0 R,B,B
        975 577 1 B,R
        816 571 23 L,F,F
        756 558 11 L,B,B,B
        753 554 0 L,L,B
    """),
    "predicting_ball": _rows("""
        502 390 95 F,F,R,B
        731 632 85 F,R,B
        1199 1199 76 F,F,F,F
        868 639 75 F,R
        1182 1106 74 F,F,F,F,F
        1200 1200 73 F,F
        1168 1062 69 F,F,F,F,F,F
        1200 1200 65 F,F,F
        805 314 57 B,R,F
        186 83 37 F,F,F,R,B
        629 405 32 R,F,F
        952 840 30 F,L,B
        137 57 26 L,F,R
        186 90 25 F,F,R,B,B
        1139 1100 24 F,L
        816 571 23 L,F,F
        970 477 22 F,F,F,F,F,F,F
        1079 923 21 L,F
        949 765 20 F,R,F
        741 192 18 F,F,F,F,F,F,F,F
        1103 1024 16 R,F
        480 136 15 F,F,R
        479 66 15 L,B,R,F
        756 558 11 L,B,B,B
        383 173 11 R,F,L
        397 154 10 F,R,B,B
        114 76 10 R,F,F,L,B
        95 65 10 B,R,F,F
        595 181 9 F,F,R,F
        34 18 9 F,F,L,L,L,L,F,L,L,L,L,L
    """),
}
"""Appendix B, Tables B.1–B.3: the 30 behaviours created in most forward models, made permanent
in most, and predicting the ball in most, over the thesis's 1200 forward models."""
