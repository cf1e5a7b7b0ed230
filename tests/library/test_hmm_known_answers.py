"""DiscreteHMM against answers known without it: textbook models and brute force."""

import itertools

import numpy as np
import pytest

import polymimic

WEATHER_START = [0.6, 0.4]
WEATHER_TRANS = [[0.7, 0.3], [0.4, 0.6]]


def weather(emissions):
    return polymimic.DiscreteHMM.from_params(WEATHER_START, WEATHER_TRANS, emissions, topology="ergodic")


def test_rainy_sunny_textbook_probability():
    model = weather([[0.1, 0.4, 0.5], [0.6, 0.3, 0.1]])
    assert np.exp(model.score([0, 1, 2])) == pytest.approx(0.033612, abs=5e-7)


def test_stamp_textbook_probability():
    model = weather([[0.1, 0.4, 0.5], [0.7, 0.2, 0.1]])
    assert np.exp(model.score([0, 1, 0, 2])) == pytest.approx(0.0096296, abs=5e-8)


def joint_probabilities(start, trans, emit, seq):
    """P(path, O) for every state path."""
    n = len(start)
    for path in itertools.product(range(n), repeat=len(seq)):
        p = start[path[0]] * emit[path[0], seq[0]]
        for t in range(1, len(seq)):
            p *= trans[path[t - 1], path[t]] * emit[path[t], seq[t]]
        yield path, p


@pytest.mark.parametrize("n_states,length", [(2, 7), (3, 6), (4, 5)])
def test_score_and_decode_match_enumeration_of_all_paths(rng, stochastic, n_states, length):
    start = stochastic(1, n_states)[0]
    trans = stochastic(n_states, n_states)
    emit = stochastic(n_states, 4)
    model = polymimic.DiscreteHMM.from_params(start, trans, emit, topology="ergodic")
    for _ in range(5):
        seq = rng.integers(0, 4, size=length)
        paths = list(joint_probabilities(start, trans, emit, seq))
        total = sum(p for _, p in paths)
        best_path, best_p = max(paths, key=lambda item: item[1])
        assert model.score(seq) == pytest.approx(np.log(total), rel=1e-12)
        path, log_p = model.decode(seq)
        assert tuple(path) == best_path
        assert log_p == pytest.approx(np.log(best_p), rel=1e-12)


def test_score_samples_equals_score_of_each(rng):
    model = weather([[0.1, 0.4, 0.5], [0.6, 0.3, 0.1]])
    seqs = [rng.integers(0, 3, size=n) for n in (1, 4, 9, 30)]
    np.testing.assert_allclose(model.score_samples(seqs), [model.score(s) for s in seqs], rtol=0, atol=0)


def test_long_sequences_do_not_underflow(rng):
    model = weather([[0.1, 0.4, 0.5], [0.6, 0.3, 0.1]])
    seq = rng.integers(0, 3, size=20_000)
    score = model.score(seq)
    assert np.isfinite(score) and score < -10_000
    _, log_p = model.decode(seq)
    assert np.isfinite(log_p) and log_p <= score


def test_samples_follow_the_start_and_emission_probabilities():
    model = weather([[0.1, 0.4, 0.5], [0.6, 0.3, 0.1]])
    symbols, states = model.sample(20_000, 2, seed=5)
    assert symbols.shape == states.shape == (20_000, 2)
    assert np.mean(states[:, 0] == 0) == pytest.approx(0.6, abs=0.015)
    rainy_then = states[states[:, 0] == 0, 1]
    assert np.mean(rainy_then == 0) == pytest.approx(0.7, abs=0.015)
    sunny_symbols = symbols[states[:, 0] == 1, 0]
    assert np.mean(sunny_symbols == 0) == pytest.approx(0.6, abs=0.02)
    again, _ = model.sample(20_000, 2, seed=5)
    np.testing.assert_array_equal(symbols, again)
