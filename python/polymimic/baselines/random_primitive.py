"""``random``: a uniformly random primitive every step, seeded (the floor; learns nothing).

The module is not named ``random``, which would shadow the standard library's wherever this
folder is on ``sys.path``.

>>> import numpy as np
>>> from polymimic.baselines import random_primitive
>>> policy = random_primitive.fit(seed=1)
>>> policy.predict(np.zeros((3, 5))).tolist() == random_primitive.fit(seed=1).predict(np.zeros((3, 5))).tolist()
True
"""

from __future__ import annotations

from collections.abc import Sequence

from polymimic.baselines.policy import RandomPolicy
from polymimic.field import Demonstration

__all__ = ["fit"]


def fit(demonstrations: Sequence[Demonstration] | None = None, *, seed: int = 0,
        frames_per_action: int = 30) -> RandomPolicy:
    """A :class:`~polymimic.baselines.policy.RandomPolicy` (``demonstrations`` are ignored: taken
    so that every method is called alike)."""
    return RandomPolicy(seed=seed, frames_per_action=frames_per_action)
