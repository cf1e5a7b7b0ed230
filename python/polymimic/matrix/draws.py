"""Each trial of a matrix cell learns from demonstrations of its own, so that a cell's spread says
how much its answer depends on what was demonstrated, not only on the learner's seed.

A set is recorded once as a pool: every member ``n × draws`` times per field configuration (draw
``i`` is the ``i``-th run of ``n`` of them, recorded under seeds of its own: the pool's episodes
are seeded one by one, so draw 0 is what recording ``n`` would give). A tracker log has the
episodes it has: draw ``i`` resamples them, as many as there are, with replacement.

>>> import numpy as np
>>> resampled(5, draw=0, seed=0).tolist() == resampled(5, draw=0, seed=0).tolist()
True
>>> len(resampled(5, draw=1, seed=0))
5
"""

from __future__ import annotations

import numpy as np

from polymimic.field import Demonstration
from polymimic.runs.roster_config import LogDemonstrator

__all__ = ["drawn", "pool_size", "resampled"]


def pool_size(per_configuration: int, draws: int) -> int:
    """Demonstrations a member records per configuration for ``draws`` draws of ``per_configuration``."""
    return per_configuration * draws


def resampled(n: int, *, draw: int, seed: int) -> np.ndarray:
    """Indices of ``n`` episodes drawn from ``n`` with replacement, the same for the same draw and seed."""
    indices: np.ndarray = np.random.default_rng([seed, draw]).integers(0, n, size=n)
    return indices


def drawn(pool: list[Demonstration], *, names: tuple[str, ...], per_configuration: int, draw: int, seed: int,
          spec: object = None) -> list[Demonstration]:
    """Draw ``draw`` of a set's ``pool``: each member's ``draw``-th run of ``per_configuration``
    demonstrations per configuration, member by member (a log's episodes resampled under
    ``seed``)."""
    if isinstance(spec, LogDemonstrator):
        return [pool[i] for i in resampled(len(pool), draw=draw, seed=seed)]
    start, stop = draw * per_configuration, (draw + 1) * per_configuration
    out: list[Demonstration] = []
    for name in names:
        for configuration in (1, 2):
            mine = [d for d in pool if d.demonstrator == name and d.configuration == configuration]
            if len(mine) < stop:
                raise ValueError(f"the pool holds {len(mine)} demonstrations of {name!r} in configuration "
                                 f"{configuration}, too few for draw {draw} of {per_configuration}")
            out += mine[start:stop]
    return out
