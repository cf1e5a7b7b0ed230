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
