"""Rank correlations, for judging how well an estimate ranks demonstrators by skill.

Spearman's ρ is Pearson's correlation of the ranks (ties take their mean rank); Kendall's τ is
τ-b, which corrects for ties on either side. Both are ``None`` where a side is constant (no
ranking to agree with), never NaN.

>>> spearman([1, 2, 3, 4], [10, 20, 30, 40]), kendall([1, 2, 3], [3, 2, 1])
(1.0, -1.0)
>>> spearman([1, 1, 1], [1, 2, 3]) is None
True
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["kendall", "ranks", "spearman"]


def _pair(x: Sequence[float], y: Sequence[float]) -> tuple[np.ndarray, np.ndarray]:
    a, b = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if a.ndim != 1 or a.shape != b.shape:
        raise ValueError(f"x and y must be two sequences of the same length, got shapes {a.shape} and {b.shape}")
    if len(a) < 2:
        raise ValueError(f"a rank correlation needs at least two pairs, got {len(a)}")
    if not (np.isfinite(a).all() and np.isfinite(b).all()):
        raise ValueError("x and y must be finite numbers")
    return a, b


def ranks(values: Sequence[float] | np.ndarray) -> np.ndarray:
    """1-based ranks, ascending, ties sharing their mean rank."""
    a = np.asarray(values, dtype=float)
    order = np.argsort(a, kind="stable")
    out = np.empty(len(a))
    sorted_values = a[order]
    start = 0
    while start < len(a):
        stop = start + 1
        while stop < len(a) and sorted_values[stop] == sorted_values[start]:
            stop += 1
        out[order[start:stop]] = (start + stop + 1) / 2.0  # mean of ranks start+1 … stop
        start = stop
    return out


def spearman(x: Sequence[float], y: Sequence[float]) -> float | None:
    """Spearman's ρ between ``x`` and ``y``."""
    a, b = _pair(x, y)
    ra, rb = ranks(a) - (len(a) + 1) / 2.0, ranks(b) - (len(b) + 1) / 2.0
    norm = float(np.sqrt((ra * ra).sum() * (rb * rb).sum()))
    return None if norm == 0.0 else float((ra * rb).sum() / norm)


def kendall(x: Sequence[float], y: Sequence[float]) -> float | None:
    """Kendall's τ-b between ``x`` and ``y``."""
    a, b = _pair(x, y)
    i, j = np.triu_indices(len(a), k=1)
    sa, sb = np.sign(a[i] - a[j]), np.sign(b[i] - b[j])
    untied_a, untied_b = float(np.count_nonzero(sa)), float(np.count_nonzero(sb))
    if untied_a == 0.0 or untied_b == 0.0:
        return None
    return float((sa * sb).sum() / np.sqrt(untied_a * untied_b))
