"""Training: initialisation, convergence and the invariants of EM, by hypothesis."""

import os
import subprocess
import sys

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import polymimic

sequence_lists = st.lists(
    st.lists(st.integers(0, 5), min_size=1, max_size=25).map(np.array), min_size=1, max_size=30
)
topologies = st.sampled_from(["left-right", "ergodic"])


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seqs=sequence_lists, n_states=st.integers(1, 6), topology=topologies, seed=st.integers(0, 2**32))
def test_trained_rows_are_distributions_and_likelihood_never_falls(left_right_mask, seqs, n_states, topology, seed):
    model = polymimic.DiscreteHMM(n_states, 6, topology=topology, max_iter=25, tol=float("-inf"), seed=seed)
    model.fit(seqs)
    for table in (model.startprob_[None, :], model.transmat_, model.emissionprob_):
        assert np.all(np.isfinite(table)) and np.all(table >= 0)
        np.testing.assert_allclose(table.sum(axis=1), 1.0, atol=1e-12)
    history = model.history_
    assert np.all(np.isfinite(history))
    # Non-decreasing up to rounding: relative 1e-9, and 1e-9 nats where the likelihood is ~1.
    assert np.all(np.diff(history) >= -1e-9 * (np.abs(history[1:]) + 1.0)), history
    if topology == "left-right":
        assert np.all(model.transmat_[~left_right_mask(n_states, 2)] == 0.0)


THREAD_PROBE = """
import sys, numpy as np, polymimic
rng = np.random.default_rng(int(sys.argv[1]))
seqs = [rng.integers(0, 32, size=rng.integers(5, 40)) for _ in range(700)]
m = polymimic.DiscreteHMM(5, 32, max_iter=8, tol=float("-inf"), seed=3).fit(seqs)
c = polymimic.Codebook.fit(rng.normal(size=(9000, 3)), size=64, seed=2)
print(m.history_.tobytes().hex(), m.transmat_.tobytes().hex(), m.emissionprob_.tobytes().hex(),
      c.centroids.tobytes().hex())
"""


def run_with_threads(threads, data_seed):
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    out = subprocess.run([sys.executable, "-c", THREAD_PROBE, str(data_seed)], env=env, check=True,
                         capture_output=True, text=True)
    return out.stdout


@settings(max_examples=3, deadline=None)
@given(data_seed=st.integers(0, 2**32))
def test_results_are_bit_identical_for_any_thread_count(data_seed):
    assert run_with_threads(1, data_seed) == run_with_threads(3, data_seed)


def test_segment_initialisation_splits_each_sequence_in_time():
    # Two states, sequences of 4: the first half of every sequence teaches state 0.
    seqs = [np.array([0, 0, 1, 1]), np.array([0, 0, 1, 1])]
    model = polymimic.DiscreteHMM(2, 2, max_iter=0, emission_floor=0.0).fit(seqs)
    np.testing.assert_array_equal(model.emissionprob_, [[1.0, 0.0], [0.0, 1.0]])
    np.testing.assert_array_equal(model.startprob_, [1.0, 0.0])
    assert len(model.history_) == 0


def test_initial_floor_is_applied_then_rows_renormalised():
    model = polymimic.DiscreteHMM(1, 4, max_iter=0, emission_floor=1e-3).fit([np.array([0, 1])])
    expected = np.array([0.5, 0.5, 1e-3, 1e-3]) / 1.002
    np.testing.assert_allclose(model.emissionprob_[0], expected, rtol=1e-15)


def test_one_state_model_is_the_symbol_histogram():
    seqs = [np.array([0, 1, 1, 2]), np.array([1, 1])]
    model = polymimic.DiscreteHMM(1, 3, emission_floor=0.0).fit(seqs)
    np.testing.assert_allclose(model.emissionprob_[0], [1 / 6, 4 / 6, 1 / 6], rtol=1e-14)


def test_converges_and_stops_when_gain_is_below_tol(rng):
    seqs = [rng.integers(0, 8, size=20) for _ in range(50)]
    model = polymimic.DiscreteHMM(3, 8, max_iter=1000, tol=1e-2).fit(seqs)
    assert model.converged_
    assert np.diff(model.history_)[-1] < 1e-2
    assert len(model.history_) < 1000


def test_minus_infinity_tol_runs_exactly_max_iter(rng):
    seqs = [rng.integers(0, 8, size=20) for _ in range(10)]
    model = polymimic.DiscreteHMM(3, 8, max_iter=17, tol=float("-inf")).fit(seqs)
    assert len(model.history_) == 17 and not model.converged_


def test_same_seed_same_model_other_seed_other_start(rng):
    seqs = [rng.integers(0, 8, size=20) for _ in range(20)]
    a = polymimic.DiscreteHMM(4, 8, seed=1, max_iter=5).fit(seqs)
    b = polymimic.DiscreteHMM(4, 8, seed=1, max_iter=5).fit(seqs)
    c = polymimic.DiscreteHMM(4, 8, seed=2, max_iter=5).fit(seqs)
    np.testing.assert_array_equal(a.transmat_, b.transmat_)
    assert not np.array_equal(a.transmat_, c.transmat_)


def test_accepts_any_integer_dtype_and_lists(rng):
    seqs = [np.array([0, 1, 2], dtype=np.uint8), [2, 1, 0], np.array([1, 1], dtype=np.int32)]
    model = polymimic.DiscreteHMM(2, 3).fit(seqs)
    assert model.score(np.array([0, 1], dtype=np.int16)) == model.score([0, 1])


def test_fit_returns_the_model_for_chaining():
    model = polymimic.DiscreteHMM(2, 3)
    assert model.fit([[0, 1, 2]]) is model
