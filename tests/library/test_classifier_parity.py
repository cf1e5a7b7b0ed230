"""The baselines' fast classifiers against the scikit-learn estimators they stand in for: the same
predictions, and for the MLP the same training, to the bit."""

import pickle

import numpy as np
import pytest
from threadpoolctl import threadpool_limits


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    """Small fits on a shared node: threads only add contention."""
    with threadpool_limits(limits=1):
        yield


def test_the_small_batch_forest_predicts_as_scikit_learns_forest_to_the_bit():
    from sklearn.ensemble import RandomForestClassifier

    from polymimic.baselines.classifiers import SmallBatchForest

    rng = np.random.default_rng(0)
    X = rng.normal(size=(2000, 6))
    y = (X[:, 0] + rng.normal(size=2000) > 0).astype(int) + 2 * (X[:, 1] > 1)
    for params in ({"max_features": "sqrt", "min_samples_leaf": 1}, {"max_features": None, "min_samples_leaf": 10}):
        theirs = RandomForestClassifier(n_estimators=50, random_state=4, n_jobs=1, **params).fit(X, y)
        ours = SmallBatchForest(n_estimators=50, random_state=4, n_jobs=1, **params).fit(X, y)
        for rows in (1, 5, 500):
            query = rng.normal(size=(rows, 6))
            assert np.array_equal(ours.predict_proba(query), theirs.predict_proba(query))
            assert np.array_equal(ours.predict(query), theirs.predict(query))


def test_the_small_batch_boosting_predicts_as_scikit_learns_boosting_to_the_bit():
    from sklearn.ensemble import HistGradientBoostingClassifier

    from polymimic.baselines.classifiers import SmallBatchBoosting

    rng = np.random.default_rng(1)
    X = rng.normal(size=(1500, 5))
    X[rng.random(X.shape) < 0.05] = np.nan  # missing values take the side each split learned for them
    multiclass = (X[:, 0] > 0).astype(int) + 2 * (X[:, 1] > 0.5) + (np.nan_to_num(X[:, 2]) > 1)
    for y in (multiclass, (X[:, 3] > 0).astype(int)):
        params = {"max_iter": 40, "max_leaf_nodes": 15, "learning_rate": 0.1, "early_stopping": False}
        theirs = HistGradientBoostingClassifier(random_state=2, **params).fit(X, y)
        ours = SmallBatchBoosting(random_state=2, **params).fit(X, y)
        # Rows right on the thresholds, too, where ≤ and < part ways.
        splits = [node for iteration in theirs._predictors for tree in iteration for node in tree.nodes
                  if not node["is_leaf"]]
        on_thresholds = np.full((len(splits), 5), 0.0)
        on_thresholds[np.arange(len(splits)), [s["feature_idx"] for s in splits]] = [s["num_threshold"] for s in splits]
        for rows in (1, 7, 400):
            query = rng.normal(size=(rows, 5))
            query[rng.random(query.shape) < 0.1] = np.nan
            query = np.vstack([query, on_thresholds[rng.integers(len(splits), size=rows)]])
            assert np.array_equal(ours.predict_proba(query), theirs.predict_proba(query))
            assert np.array_equal(ours.predict(query), theirs.predict(query))
    # A saved model leaves its flat trees out and builds them again on loading.
    saved = pickle.dumps(ours)
    loaded = pickle.loads(saved)
    assert len(saved) < len(pickle.dumps(theirs)) + 1000
    assert "_flat_trees_" in vars(loaded) and "_flat_trees_" in vars(ours)
    assert np.array_equal(loaded.predict_proba(query), theirs.predict_proba(query))


def _same_fit(ours, theirs):
    """Whether two fitted MLPs hold the same weights, loss curve, stopping state and optimizer."""
    arrays = list(zip(ours.coefs_ + ours.intercepts_, theirs.coefs_ + theirs.intercepts_, strict=True))
    moments = list(zip(ours._optimizer.ms + ours._optimizer.vs, theirs._optimizer.ms + theirs._optimizer.vs,
                       strict=True))
    return (all(np.array_equal(a, b) for a, b in arrays + moments) and ours.loss_curve_ == theirs.loss_curve_
            and (ours.n_iter_, ours.t_, ours.best_loss_, ours._no_improvement_count, ours._optimizer.t)
            == (theirs.n_iter_, theirs.t_, theirs.best_loss_, theirs._no_improvement_count, theirs._optimizer.t))


def test_the_quick_fit_mlp_trains_as_scikit_learns_mlp_to_the_bit():
    import warnings

    from sklearn.exceptions import ConvergenceWarning
    from sklearn.neural_network import MLPClassifier

    from polymimic.baselines.mlp import QuickFitMLP

    rng = np.random.default_rng(5)
    X = rng.normal(size=(530, 4))  # 530: the last batch of each epoch is a short one
    multiclass = (X[:, 0] > 0).astype(int) + 2 * (X[:, 1] > 0.5) + (X[:, 2] > 1)
    binary = (X[:, 3] + 0.3 * X[:, 0] > 0).astype(int)  # a logistic output and its own loss
    weights = rng.uniform(0.1, 3.0, size=len(X))
    cases = [({"hidden_layer_sizes": (16, 16), "max_iter": 12}, multiclass, weights),
             ({"hidden_layer_sizes": (8,), "max_iter": 12, "alpha": 1e-2}, multiclass, None),
             ({"hidden_layer_sizes": (8,), "max_iter": 12, "batch_size": 64}, binary, weights),
             ({"hidden_layer_sizes": (8,), "max_iter": 12, "activation": "tanh"}, multiclass, weights),
             # A loose tolerance: the loss stalls, and the fit stops before its last epoch.
             ({"hidden_layer_sizes": (8,), "max_iter": 200, "tol": 0.05, "n_iter_no_change": 2}, multiclass, weights)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        # float32 samples, which this loop would round differently, are left to scikit-learn.
        for params, y, w, samples in [(*case, X) for case in cases] + [(*cases[0], X.astype(np.float32))]:
            theirs = MLPClassifier(random_state=3, **params).fit(samples, y, sample_weight=w)
            ours = QuickFitMLP(random_state=3, **params).fit(samples, y, sample_weight=w)
            assert _same_fit(ours, theirs), params
            assert np.array_equal(ours.predict_proba(samples), theirs.predict_proba(samples))
            # Carrying on from there, scikit-learn's partial_fit takes up the same optimizer state.
            assert _same_fit(ours.partial_fit(samples, y, sample_weight=w),
                             theirs.partial_fit(samples, y, sample_weight=w))
        assert cases[-1][0]["max_iter"] > QuickFitMLP(random_state=3, **cases[-1][0]).fit(X, multiclass).n_iter_
