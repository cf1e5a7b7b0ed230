import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(20260)


def random_stochastic(rng, rows, cols, mask=None):
    """Random row-stochastic matrix, zero where ``mask`` is False."""
    values = rng.uniform(0.05, 1.0, size=(rows, cols))
    if mask is not None:
        values = np.where(mask, values, 0.0)
    return values / values.sum(axis=1, keepdims=True)


def left_right_mask(n_states, links):
    i, j = np.indices((n_states, n_states))
    return (j >= i) & (j - i <= links)

