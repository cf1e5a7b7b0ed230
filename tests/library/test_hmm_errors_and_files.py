"""Bad input raises an exception that names the problem; saved models round-trip."""

import pickle

import numpy as np
import pytest

import polymimic

GOOD = dict(startprob=[1.0, 0.0], transmat=[[0.5, 0.5], [0.0, 1.0]], emissionprob=[[0.9, 0.1], [0.2, 0.8]])


@pytest.fixture
def model():
    return polymimic.DiscreteHMM.from_params(**GOOD, links=1)


@pytest.mark.parametrize(
    "sequences, error, match",
    [
        ([], ValueError, "sequences is empty"),
        ([np.array([], dtype=int)], ValueError, "sequence 0 is empty"),
        ([[0, 1], [0, -1]], ValueError, "sequence 1 holds symbol -1 at position 1"),
        ([[0, 2]], ValueError, r"symbol 2 at position 1; symbols must be in 0\.\.2"),
        ([np.array([0.0, 1.0])], TypeError, "dtype float64; symbols must be integers"),
        ([np.array([True, False])], TypeError, "dtype bool"),
        ([np.zeros((2, 3), dtype=int)], ValueError, r"must be a 1-D array of symbols, got shape \(2, 3\)"),
        (np.array([0, 1, 0]), TypeError, "got a single 1-D array"),
        (5, TypeError, "list of 1-D integer arrays"),
    ],
)
def test_bad_sequences_are_named(model, sequences, error, match):
    before = model.transmat_.copy()
    with pytest.raises(error, match=match):
        model.fit(sequences, init="given")
    np.testing.assert_array_equal(model.transmat_, before)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(n_states=0, n_symbols=3), "n_states must be at least 1"),
        (dict(n_states=2, n_symbols=0), "n_symbols must be at least 1"),
        (dict(n_states=-1, n_symbols=3), "n_states must be ≥ 0"),
        (dict(n_states=2, n_symbols=3, links=-1), "links must be ≥ 0"),
        (dict(n_states=2, n_symbols=3, topology="circular"), "topology must be"),
        (dict(n_states=2, n_symbols=3, tol=float("nan")), "tol must be a number"),
        (dict(n_states=2, n_symbols=3, emission_floor=0.5), "emission_floor must be in"),
        (dict(n_states=2, n_symbols=3, seed=-3), "seed must be ≥ 0"),
        (dict(n_states=2, n_symbols=3, max_iter=-1), "max_iter must be ≥ 0"),
    ],
)
def test_bad_parameters_are_named(kwargs, match):
    with pytest.raises(ValueError, match=match):
        polymimic.DiscreteHMM(**kwargs)


@pytest.mark.parametrize(
    "change, match",
    [
        (dict(transmat=[[0.5, 0.6], [0.0, 1.0]]), r"transmat row 0 sums to 1\.1"),
        (dict(startprob=[0.5, 0.4]), "startprob sums to 0.9"),
        (dict(emissionprob=[[1.2, -0.2], [0.2, 0.8]]), r"emissionprob\[0, 0\] = 1\.2 is not a probability"),
        (dict(emissionprob=[[np.nan, 1.0], [0.2, 0.8]]), "is not a probability"),
        (dict(transmat=[[0.5, 0.5], [0.5, 0.5]]), "left-right topology with links=1"),
        (dict(transmat=[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]), r"transmat has shape \[2, 3\]"),
        (dict(emissionprob=[[1.0], [1.0], [1.0]]), r"emissionprob has shape \[3, 1\]"),
        (dict(transmat=[0.5, 0.5]), "transmat must be 2-D"),
        (dict(startprob=["a", "b"]), "startprob has dtype"),
    ],
)
def test_bad_probability_tables_are_named(change, match):
    with pytest.raises((ValueError, TypeError), match=match):
        polymimic.DiscreteHMM.from_params(**{**GOOD, **change}, links=1)


def test_impossible_sequences_raise_or_score_minus_infinity(model):
    # State 1 cannot return to state 0 and neither state emits... everything is possible here,
    # so use a model where symbol 1 is never emitted.
    strict = polymimic.DiscreteHMM.from_params([1.0], [[1.0]], [[1.0, 0.0]])
    with pytest.raises(polymimic.ImpossibleSequenceError, match="position 2"):
        strict.score([0, 0, 1])
    with pytest.raises(polymimic.ImpossibleSequenceError, match="sequence 1 is impossible"):
        strict.score_samples([[0], [1]])
    scores = strict.score_samples([[0], [1]], impossible="-inf")
    assert scores[0] == 0.0 and scores[1] == -np.inf
    with pytest.raises(polymimic.ImpossibleSequenceError):
        strict.decode([1])
    with pytest.raises(polymimic.ImpossibleSequenceError, match="sequence 0"):
        strict.fit([[0, 1]], init="given")
    assert isinstance(polymimic.ImpossibleSequenceError("x"), polymimic.PolymimicError)


def test_unfitted_model_says_so():
    fresh = polymimic.DiscreteHMM(2, 3)
    for use in (lambda: fresh.transmat_, lambda: fresh.score([0]), lambda: fresh.sample(1, 2),
                lambda: fresh.fit([[0]], init="given")):
        with pytest.raises(polymimic.NotFittedError, match="not fitted"):
            use()
    assert "unfitted" in repr(fresh)


def test_unknown_init_and_sample_length(model):
    with pytest.raises(ValueError, match="init must be"):
        model.fit([[0]], init="kmeans")
    with pytest.raises(ValueError, match="length must be at least 1"):
        model.sample(2, 0)


def test_save_load_round_trip_is_exact(tmp_path, rng):
    seqs = [rng.integers(0, 5, size=15) for _ in range(20)]
    original = polymimic.DiscreteHMM(3, 5, tol=float("-inf"), max_iter=4, seed=9).fit(seqs)
    path = tmp_path / "model.json"
    original.save(path)
    loaded = polymimic.DiscreteHMM.load(str(path))
    for name in ("startprob_", "transmat_", "emissionprob_", "history_"):
        np.testing.assert_array_equal(getattr(loaded, name), getattr(original, name))
    assert (loaded.tol, loaded.seed, loaded.links, loaded.converged_) == (float("-inf"), 9, 2, False)
    assert not list(tmp_path.glob("*.partial"))
    clone = pickle.loads(pickle.dumps(original))
    np.testing.assert_array_equal(clone.emissionprob_, original.emissionprob_)


def test_corrupt_foreign_and_future_files_are_refused(tmp_path, model):
    path = tmp_path / "model.json"
    model.save(path)
    text = path.read_text()

    (tmp_path / "truncated.json").write_text(text[: len(text) // 2])
    (tmp_path / "future.json").write_text(text.replace('"version":1', '"version":7'))
    (tmp_path / "binary.bin").write_bytes(b"\x89PNG\x00\xff")
    polymimic.Codebook(np.eye(3)).save(tmp_path / "codebook.json")
    tampered = text.replace('"startprob":[1.0,0.0]', '"startprob":[0.7,0.0]')
    (tmp_path / "tampered.json").write_text(tampered)

    cases = {"truncated.json": "not a saved polymimic file", "future.json": "version 7 is not supported",
             "binary.bin": "not a polymimic file", "codebook.json": "expected format",
             "tampered.json": "startprob sums to 0.7"}
    for name, match in cases.items():
        with pytest.raises(polymimic.ModelFileError, match=match):
            polymimic.DiscreteHMM.load(tmp_path / name)
    for load in (polymimic.DiscreteHMM.load, polymimic.Codebook.load, polymimic.PrimitiveRecognizer.load):
        with pytest.raises(FileNotFoundError, match=r"No such file or directory.*missing\.json"):
            load(tmp_path / "missing.json")
    with pytest.raises(IsADirectoryError, match=str(tmp_path.name)):
        polymimic.DiscreteHMM.load(tmp_path)


def test_saves_leave_no_temporary_behind(tmp_path, model):
    model.save(tmp_path / "model.json")
    model.save(tmp_path / "model.json")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.json"]
    with pytest.raises(FileNotFoundError, match="nowhere"):
        model.save(tmp_path / "nowhere" / "model.json")
