"""Mean ± sd over trials or fits, and how a report writes it.

>>> cell = mean_sd([34.0, 29.0, 38.0])
>>> msd(cell), msd(mean_sd([0.5, 0.7]), share=True), msd(mean_sd([]))
('33.7 (4.5)', '60.0 % (14.1 %)', '—')
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from polymimic.plots import MeanSd

__all__ = ["mean_sd", "msd", "num", "pct"]


def mean_sd(values: Iterable[float]) -> MeanSd:
    """Mean and sample standard deviation (0 for one value; both ``None`` for none)."""
    array = np.asarray(list(values), dtype=float)
    if array.size == 0:
        return {"mean": None, "sd": None}
    return {"mean": float(array.mean()), "sd": float(array.std(ddof=1)) if array.size > 1 else 0.0}


def pct(share: float | None, digits: int = 1) -> str:
    """A share as a percentage; ``—`` where there is none."""
    return "—" if share is None else f"{100 * share:.{digits}f} %"


def num(value: float | None, digits: int = 1) -> str:
    """``value`` with ``digits`` decimals, or an em dash for None."""
    return "—" if value is None else f"{value:.{digits}f}"


def msd(cell: MeanSd | None, *, share: bool = False, digits: int = 1) -> str:
    """``mean (sd)``, as a percentage for shares."""
    if not cell or cell["mean"] is None:
        return "—"
    if share:
        return f"{pct(cell['mean'], digits)} ({pct(cell['sd'], digits)})"
    return f"{cell['mean']:.{digits}f} ({num(cell['sd'], digits)})"
