"""Fixtures shared by every test."""

import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(20260)


def _random_stochastic(rng, rows, cols, mask=None):
    """Random row-stochastic matrix, zero where ``mask`` is False."""
    values = rng.uniform(0.05, 1.0, size=(rows, cols))
    if mask is not None:
        values = np.where(mask, values, 0.0)
    return values / values.sum(axis=1, keepdims=True)


def _left_right_mask(n_states, links):
    i, j = np.indices((n_states, n_states))
    return (j >= i) & (j - i <= links)


@pytest.fixture
def stochastic(rng):
    """Makes a random row-stochastic matrix from ``rng``: ``stochastic(rows, cols, mask=None)``."""
    return lambda rows, cols, mask=None: _random_stochastic(rng, rows, cols, mask)


@pytest.fixture(scope="session")
def left_right_mask():
    """``left_right_mask(n_states, links)``: where a left-right HMM may have transitions."""
    return _left_right_mask


@pytest.fixture(scope="session")
def expert_imitator():
    """A small improved-control Lego imitator of three Expert demonstrations per configuration
    (a recogniser of 20 seconds per primitive): what the stepping, live and practice tests drive."""
    import polymimic
    from polymimic import recognition

    recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)
    demos = [d for c in (1, 2) for d in polymimic.record("expert", configuration=c, n=3, seed=0)]
    trial = polymimic.run_trial(demos, recognizer=recognizer, ordering=["expert"])
    return polymimic.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demos)
