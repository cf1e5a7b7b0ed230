"""The practice curve: net goals on the evaluation attempts against environment steps of practice
(one step is one second of play, as in ``PenaltyKick-v0``), as CSV, JSON and a plot on the axes of
PPO's learning curve.
"""

from __future__ import annotations

import dataclasses
import json
import os
from collections.abc import Sequence
from typing import Any

from polymimic._atomic import atomic_write_text

__all__ = ["DEFAULT_CHECKPOINTS", "CurvePoint", "curve_csv", "curve_json", "plot_curves"]

DEFAULT_CHECKPOINTS = (0, 1_000, 2_500, 5_000, 10_000, 25_000, 50_000)
"""Steps of practice at which the policy is scored, within the budget."""

CSV_COLUMNS = ("steps", "net_goals", "goals", "own_goals", "attempts_learned", "attempts_lost")


@dataclasses.dataclass(frozen=True)
class CurvePoint:
    """The policy after ``steps`` environment steps of practice (at most the checkpoint's), scored
    on the evaluation attempts; ``attempts_learned`` of its own attempts refine it, and
    ``attempts_lost`` more were played but lost by the tracker (§3.2.1: left out, counted)."""

    checkpoint: int
    steps: int
    net_goals: int
    goals: int
    own_goals: int
    attempts_learned: int
    attempts_lost: int

    def to_dict(self) -> dict[str, int]:
        """The point as plain JSON values."""
        return dataclasses.asdict(self)


def curve_csv(points: Sequence[CurvePoint]) -> str:
    """One row a checkpoint: ``checkpoint`` and the columns of :data:`CSV_COLUMNS`.

    >>> print(curve_csv([CurvePoint(0, 0, 40, 41, 1, 0, 0)]), end="")
    checkpoint,steps,net_goals,goals,own_goals,attempts_learned,attempts_lost
    0,0,40,41,1,0,0
    """
    rows = [",".join(("checkpoint", *CSV_COLUMNS))]
    rows += [",".join(str(getattr(p, c)) for c in ("checkpoint", *CSV_COLUMNS)) for p in points]
    return "\n".join(rows) + "\n"


def curve_json(points: Sequence[CurvePoint], **about: Any) -> str:
    """``{"points": [...], **about}``: the points and what they are of (seeds, budget, body)."""
    return json.dumps({**about, "points": [p.to_dict() for p in points]}, indent=2) + "\n"


def plot_curves(path: str | os.PathLike[str], curves: dict[str, Sequence[tuple[float, float]]], *,
                title: str = "Net goals on the evaluation attempts") -> None:
    """Curves of (environment steps, net goals) per name on one plot, written as PNG; steps on a
    scale linear to 1 000 and logarithmic beyond, so a practice budget of thousands and ppo's
    million share it."""
    from matplotlib.figure import Figure
    from matplotlib.ticker import StrMethodFormatter

    from polymimic.plots import save_figure

    figure = Figure(figsize=(7.0, 4.0), layout="constrained")
    axes = figure.add_subplot()
    for name, points in curves.items():
        axes.plot([p[0] for p in points], [p[1] for p in points], marker="o", markersize=3, label=name)
    axes.set_xscale("symlog", linthresh=1_000)
    axes.xaxis.set_major_formatter(StrMethodFormatter("{x:,.0f}"))
    axes.set_xlabel("environment steps (one second of play each)")
    axes.set_ylabel("net goals on the evaluation attempts")
    axes.set_title(title, fontsize="medium")
    axes.grid(alpha=0.3)
    axes.legend(fontsize="x-small")
    save_figure(figure, path)


def write_curve(directory: str | os.PathLike[str], points: Sequence[CurvePoint], **about: Any) -> None:
    """``practice_curve.csv`` and ``practice_curve.json`` in ``directory``."""
    atomic_write_text(os.path.join(directory, "practice_curve.csv"), curve_csv(points))
    atomic_write_text(os.path.join(directory, "practice_curve.json"), curve_json(points, **about))
