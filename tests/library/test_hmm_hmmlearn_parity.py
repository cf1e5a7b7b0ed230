"""DiscreteHMM against hmmlearn's CategoricalHMM started from the same parameters."""

import numpy as np
import pytest

import polymimic

hmm = pytest.importorskip("hmmlearn.hmm")

N_ITER = 10


def training_sequences(rng, stochastic, n_symbols):
    truth = polymimic.DiscreteHMM.from_params(
        [1.0, 0.0, 0.0],
        [[0.7, 0.2, 0.1], [0.0, 0.8, 0.2], [0.0, 0.0, 1.0]],
        stochastic(3, n_symbols),
    )
    seqs = []
    for length in rng.integers(5, 31, size=60):
        symbols, _ = truth.sample(1, int(length), seed=int(rng.integers(1 << 31)))
        seqs.append(symbols[0])
    return seqs


def peer_fit(start, trans, emit, seqs):
    peer = hmm.CategoricalHMM(
        n_components=len(start),
        n_features=emit.shape[1],
        implementation="scaling",
        init_params="",
        params="ste",
        n_iter=N_ITER,
        tol=-np.inf,
    )
    peer.startprob_, peer.transmat_, peer.emissionprob_ = start.copy(), trans.copy(), emit.copy()
    peer.fit(np.concatenate(seqs)[:, None], lengths=[len(s) for s in seqs])
    return peer


@pytest.mark.parametrize("topology", ["left-right", "ergodic"])
def test_baum_welch_matches_hmmlearn(rng, stochastic, left_right_mask, topology):
    n_states, n_symbols = 5, 7
    seqs = training_sequences(rng, stochastic, n_symbols)
    if topology == "left-right":
        start = np.eye(n_states)[0]
        trans = stochastic(n_states, n_states, left_right_mask(n_states, 2))
    else:
        start = stochastic(1, n_states)[0]
        trans = stochastic(n_states, n_states)
    emit = stochastic(n_states, n_symbols)

    ours = polymimic.DiscreteHMM.from_params(
        start, trans, emit, topology=topology, max_iter=N_ITER, tol=float("-inf")
    ).fit(seqs, init="given")
    peer = peer_fit(start, trans, emit, seqs)

    np.testing.assert_allclose(ours.history_, list(peer.monitor_.history), rtol=1e-9, atol=0)
    assert len(ours.history_) == N_ITER
    np.testing.assert_allclose(ours.startprob_, peer.startprob_, rtol=0, atol=1e-10)
    np.testing.assert_allclose(ours.transmat_, peer.transmat_, rtol=0, atol=1e-10)
    np.testing.assert_allclose(ours.emissionprob_, peer.emissionprob_, rtol=0, atol=1e-10)
    if topology == "left-right":
        outside = ~left_right_mask(n_states, 2)
        assert np.all(ours.transmat_[outside] == 0.0)
        assert np.all(ours.startprob_[1:] == 0.0)


def test_scores_match_hmmlearn(rng, stochastic):
    start = stochastic(1, 4)[0]
    trans = stochastic(4, 4)
    emit = stochastic(4, 9)
    ours = polymimic.DiscreteHMM.from_params(start, trans, emit, topology="ergodic")
    peer = hmm.CategoricalHMM(n_components=4, n_features=9, implementation="scaling")
    peer.startprob_, peer.transmat_, peer.emissionprob_ = start, trans, emit
    for length in (1, 2, 17, 300):
        seq = rng.integers(0, 9, size=length)
        assert ours.score(seq) == pytest.approx(peer.score(seq[:, None]), rel=1e-12)
        path, log_p = ours.decode(seq)
        peer_log_p, peer_path = peer.decode(seq[:, None], algorithm="viterbi")
        assert log_p == pytest.approx(peer_log_p, rel=1e-12)
        np.testing.assert_array_equal(path, peer_path)
