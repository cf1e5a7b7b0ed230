"""Codebook against scikit-learn's Lloyd k-means and brute-force search; bad input; files."""

import pickle

import numpy as np
import pytest

import polymimic

cluster = pytest.importorskip("sklearn.cluster")


def blobs(rng, n=3000, dim=3, centres=12):
    middles = rng.uniform(-100, 100, size=(centres, dim))
    return middles[rng.integers(0, centres, size=n)] + rng.normal(scale=8.0, size=(n, dim))


@pytest.mark.parametrize("max_iter", [1, 4, 300])
def test_lloyd_stage_matches_scikit_learn(rng, max_iter):
    points = blobs(rng)
    init = points[rng.choice(len(points), size=24, replace=False)]
    ours = polymimic.Codebook(init).refine(points, tol=0.0, max_iter=max_iter)
    peer = cluster.KMeans(24, init=init, n_init=1, algorithm="lloyd", max_iter=max_iter, tol=0.0).fit(points)
    np.testing.assert_allclose(ours.centroids, peer.cluster_centers_, rtol=0, atol=1e-10)
    np.testing.assert_array_equal(ours.encode(points), peer.predict(points))
    assert ours.distortion(points) == pytest.approx(peer.inertia_ / len(points), rel=1e-10)


def test_encode_finds_the_nearest_codeword_like_brute_force(rng):
    for dim in (1, 2, 3, 6):
        codebook = polymimic.Codebook.fit(rng.normal(size=(4000, dim)), size=64, seed=1)
        queries = rng.normal(scale=1.5, size=(2000, dim))
        distances = ((queries[:, None, :] - codebook.centroids[None, :, :]) ** 2).sum(axis=2)
        np.testing.assert_array_equal(codebook.encode(queries), distances.argmin(axis=1))
        assert codebook.distortion(queries) == pytest.approx(distances.min(axis=1).mean(), rel=1e-12)


@pytest.mark.parametrize("size", [1, 2, 5, 64, 100])
def test_fit_grows_exactly_the_size_asked_for(rng, size):
    points = blobs(rng, n=2000)
    codebook = polymimic.Codebook.fit(points, size=size)
    assert codebook.centroids.shape == (size, 3) and len(codebook) == size
    assert len(np.unique(codebook.encode(points))) == size, "no codeword is left without points"
    assert codebook.distortion_ == pytest.approx(codebook.distortion(points), rel=1e-12)


def test_one_codeword_is_the_mean(rng):
    points = rng.normal(size=(500, 3))
    codebook = polymimic.Codebook.fit(points, size=1)
    np.testing.assert_allclose(codebook.centroids[0], points.mean(axis=0), atol=1e-12)


def test_lbg_is_a_fixed_point_of_lloyd_when_run_to_convergence(rng):
    points = blobs(rng)
    codebook = polymimic.Codebook.fit(points, size=32, tol=0.0, max_iter=1000)
    again = codebook.refine(points, tol=0.0, max_iter=1000)
    np.testing.assert_allclose(again.centroids, codebook.centroids, atol=1e-9)


def test_distortion_is_close_to_scikit_learns_kmeans_plus_plus(rng):
    points = blobs(rng, n=6000, centres=40)
    ours = polymimic.Codebook.fit(points, size=64, tol=1e-6)
    peer = cluster.KMeans(64, n_init=1, random_state=0).fit(points)
    assert ours.distortion(points) <= 1.05 * peer.inertia_ / len(points)


def test_same_seed_same_codebook(rng):
    points = blobs(rng)
    a, b = (polymimic.Codebook.fit(points, size=20, seed=4) for _ in range(2))
    np.testing.assert_array_equal(a.centroids, b.centroids)


@pytest.mark.parametrize(
    "points, kwargs, error, match",
    [
        (np.zeros((0, 3)), {}, ValueError, "no points"),
        (np.zeros(10), {}, ValueError, r"points must be 2-D, got shape \(10,\)"),
        (np.zeros((2, 2, 2)), {}, ValueError, "must be 2-D"),
        (np.array([[0.0, np.nan], [1.0, 1.0]]), {"size": 1}, ValueError, "point 0 has a non-finite coordinate"),
        (np.array([[0.0, 1.0], [np.inf, 1.0]]), {"size": 1}, ValueError, "point 1 has a non-finite"),
        (np.ones((10, 2)), {"size": 0}, ValueError, "size must be at least 1"),
        (np.ones((10, 2)), {"size": 11}, ValueError, "cannot grow 11 codewords from 10 points"),
        (np.ones((10, 2)), {"size": 2, "tol": -1.0}, ValueError, "tol must be"),
        (np.ones((10, 2)), {"size": 2, "split_epsilon": 0.0}, ValueError, "split_epsilon"),
        (np.array([["a", "b"]]), {}, TypeError, "dtype"),
    ],
)
def test_bad_input_is_named(points, kwargs, error, match):
    with pytest.raises(error, match=match):
        polymimic.Codebook.fit(points, **kwargs)


def test_points_of_another_dimension_are_refused():
    codebook = polymimic.Codebook(np.eye(3))
    with pytest.raises(ValueError, match="points have 2 dimensions but the codebook has 3"):
        codebook.encode(np.zeros((4, 2)))


def test_identical_points_do_not_break_growth():
    codebook = polymimic.Codebook.fit(np.ones((50, 3)), size=4)
    assert np.all(np.isfinite(codebook.centroids))
    assert codebook.distortion(np.ones((5, 3))) == 0.0


def test_save_load_and_pickle_round_trip(tmp_path, rng):
    codebook = polymimic.Codebook.fit(rng.normal(size=(300, 3)), size=16)
    codebook.save(tmp_path / "c.json")
    loaded = polymimic.Codebook.load(tmp_path / "c.json")
    np.testing.assert_array_equal(loaded.centroids, codebook.centroids)
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(codebook)).centroids, codebook.centroids)
    polymimic.DiscreteHMM.from_params([1.0], [[1.0]], [[1.0]]).save(tmp_path / "hmm.json")
    with pytest.raises(polymimic.ModelFileError, match="expected format"):
        polymimic.Codebook.load(tmp_path / "hmm.json")
    (tmp_path / "bad.json").write_text('{"format":"polymimic.Codebook","version":1,"payload":{"dim":0}}')
    with pytest.raises(polymimic.ModelFileError):
        polymimic.Codebook.load(tmp_path / "bad.json")
