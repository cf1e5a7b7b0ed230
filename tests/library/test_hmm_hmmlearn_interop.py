"""hmmlearn in and out: CategoricalHMMs carried over exactly, the topology read from transmat,
and hmmlearn's own known answers for its CategoricalHMM, met by ours."""

import numpy as np
import pytest
from hmmlearn import hmm

import polymimic

# hmmlearn's CategoricalHMM test model (Wikipedia's "Viterbi algorithm" example): two states,
# three symbols, the sequence 0 1 2.
START, TRANS = np.array([0.6, 0.4]), np.array([[0.7, 0.3], [0.4, 0.6]])
EMIT = np.array([[0.1, 0.4, 0.5], [0.6, 0.3, 0.1]])
SEQUENCE = np.array([0, 1, 2])


@pytest.fixture
def wikipedia():
    return polymimic.DiscreteHMM.from_params(START, TRANS, EMIT)


def test_hmmlearns_known_answers(wikipedia):
    assert wikipedia.topology == "ergodic"
    assert np.exp(wikipedia.score(SEQUENCE)) == pytest.approx(0.033612, abs=1e-12)
    path, log_p = wikipedia.decode(SEQUENCE)
    assert path.tolist() == [1, 0, 0] and np.exp(log_p) == pytest.approx(0.01344, abs=1e-12)
    np.testing.assert_allclose(wikipedia.predict_proba(SEQUENCE), [[0.23170303, 0.76829697],
                                                                   [0.62406281, 0.37593719],
                                                                   [0.86397706, 0.13602294]], atol=1e-6)


def test_the_same_answers_as_hmmlearn_on_random_models(rng, stochastic):
    for n_states, n_symbols in ((1, 3), (3, 5), (5, 9)):
        ours = polymimic.DiscreteHMM.from_params(stochastic(1, n_states)[0], stochastic(n_states, n_states),
                                                 stochastic(n_states, n_symbols))
        peer = ours.to_hmmlearn()
        for length in (1, 7, 40):
            seq = rng.integers(0, n_symbols, size=length)
            assert ours.score(seq) == pytest.approx(peer.score(seq[:, None]), rel=1e-12)
            np.testing.assert_allclose(ours.predict_proba(seq), peer.predict_proba(seq[:, None]), atol=1e-12)
            peer_log_p, peer_path = peer.decode(seq[:, None], algorithm="viterbi")
            path, log_p = ours.decode(seq)
            assert log_p == pytest.approx(peer_log_p, rel=1e-12)
            if length <= 7:  # longer ones may hold paths within rounding of each other
                assert path.tolist() == peer_path.tolist()


def test_round_trips_carry_every_parameter_exactly(wikipedia):
    fitted = hmm.CategoricalHMM(2, n_iter=17, tol=1e-3, random_state=5, init_params="ste")
    fitted.fit(np.array([[0], [1], [2], [2], [1], [0], [0]]), lengths=[3, 4])
    ours = polymimic.DiscreteHMM.from_hmmlearn(fitted, seed=5)
    for name in ("startprob_", "transmat_", "emissionprob_"):
        assert np.array_equal(getattr(ours, name), getattr(fitted, name)), name
    assert (ours.max_iter, ours.tol, ours.seed) == (17, 1e-3, 5)
    back = ours.to_hmmlearn()
    for name in ("startprob_", "transmat_", "emissionprob_"):
        assert np.array_equal(getattr(back, name), getattr(fitted, name)), name
    assert (back.n_iter, back.tol, back.random_state, back.n_features) == (17, 1e-3, 5, 3)
    # hmmlearn trains on from the carried-over state, as ours does.
    seqs = [np.array([0, 1, 2, 2]), np.array([2, 1, 0])]
    peer = ours.to_hmmlearn()
    peer.n_iter, peer.tol = 5, -np.inf
    peer.fit(np.concatenate(seqs)[:, None], lengths=[len(s) for s in seqs])
    trained = polymimic.DiscreteHMM.from_params(ours.startprob_, ours.transmat_, ours.emissionprob_, max_iter=5,
                                                tol=float("-inf")).fit(seqs, init="given")
    np.testing.assert_allclose(trained.transmat_, peer.transmat_, atol=1e-10)


def test_a_model_hmmlearn_fitted_carries_over_without_a_seed():
    """Fitting leaves hmmlearn's random_state a RandomState: the seed is drawn from a copy of it,
    the same for the same state, and the model's own state is left as it was."""
    fitted = hmm.CategoricalHMM(2, n_iter=9, random_state=3, init_params="ste")
    fitted.fit(np.array([[0], [1], [2], [2], [1], [0], [0], [2]]), lengths=[3, 5])
    assert isinstance(fitted.random_state, np.random.RandomState)
    state = fitted.random_state.get_state()
    ours = polymimic.DiscreteHMM.from_hmmlearn(fitted)
    again = polymimic.DiscreteHMM.from_hmmlearn(fitted)
    assert ours.seed == again.seed >= 0
    after = fitted.random_state.get_state()
    assert after[0] == state[0] and np.array_equal(after[1], state[1]) and after[2:] == state[2:]
    for seq in ([0, 1, 2], [2, 2, 1, 0, 0], [1]):
        assert ours.score(np.array(seq)) == pytest.approx(fitted.score(np.array(seq)[:, None]), rel=1e-12)
    generator = hmm.CategoricalHMM(2, random_state=np.random.default_rng(11))
    generator.startprob_, generator.transmat_, generator.emissionprob_ = START, TRANS, EMIT
    first = polymimic.DiscreteHMM.from_hmmlearn(generator).seed
    assert first == polymimic.DiscreteHMM.from_hmmlearn(generator).seed == np.random.default_rng(11).integers(0, 2**62)
    generator.random_state = "seven"
    with pytest.raises(ValueError, match="random_state must be an int, None, a RandomState or a Generator to carry "
                                         "over, got seven: pass seed="):
        polymimic.DiscreteHMM.from_hmmlearn(generator)


def test_the_topology_is_the_one_transmat_implies():
    emit = np.full((4, 3), 1 / 3)
    band = [[0.5, 0.3, 0.2, 0.0], [0.0, 0.6, 0.4, 0.0], [0.0, 0.0, 0.7, 0.3], [0.0, 0.0, 0.0, 1.0]]
    left_right = polymimic.DiscreteHMM.from_params([1, 0, 0, 0], band, emit)
    assert (left_right.topology, left_right.links) == ("left-right", 2)
    chain = [[0.9, 0.1, 0, 0], [0, 0.9, 0.1, 0], [0, 0, 0.9, 0.1], [0, 0, 0, 1.0]]
    assert polymimic.DiscreteHMM.from_params([1, 0, 0, 0], chain, emit).links == 1
    # Starting elsewhere than state 0, or moving back, is ergodic; both are accepted as given.
    assert polymimic.DiscreteHMM.from_params([0.5, 0.5, 0, 0], chain, emit).topology == "ergodic"
    ergodic = np.full((4, 4), 0.25)
    assert polymimic.DiscreteHMM.from_params([1, 0, 0, 0], ergodic, emit).topology == "ergodic"
    # Named explicitly, a topology is checked as before.
    with pytest.raises(ValueError, match="left-right topology with links=2 allows only"):
        polymimic.DiscreteHMM.from_params([1, 0, 0, 0], ergodic, emit, topology="left-right")
    # Links are a left-right model's: giving them says so.
    assert polymimic.DiscreteHMM.from_params([1, 0, 0, 0], band, emit, links=3).links == 3
    with pytest.raises(ValueError, match="left-right topology with links=1 allows only"):
        polymimic.DiscreteHMM.from_params([1, 0, 0, 0], band, emit, links=1)


def test_foreign_and_unfitted_models_are_refused():
    with pytest.raises(polymimic.NotFittedError, match="not fitted: it has no startprob_"):
        polymimic.DiscreteHMM.from_hmmlearn(hmm.CategoricalHMM(2))
    with pytest.raises(TypeError, match="takes a fitted hmmlearn.hmm.CategoricalHMM, got a GaussianHMM"):
        polymimic.DiscreteHMM.from_hmmlearn(hmm.GaussianHMM(2))
    with pytest.raises(TypeError, match="got a dict"):
        polymimic.DiscreteHMM.from_hmmlearn({"startprob_": START})
    peer = hmm.CategoricalHMM(2, random_state=7)
    peer.startprob_, peer.transmat_, peer.emissionprob_ = START, TRANS, EMIT
    assert polymimic.DiscreteHMM.from_hmmlearn(peer).seed == 7
    peer.random_state = None
    assert polymimic.DiscreteHMM.from_hmmlearn(peer).seed == 0
