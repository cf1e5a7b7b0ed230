"""The scikit-learn classifier families a cloned policy may use, built from plain parameters.

Every family takes per-sample weights (a demonstrator's weight times its class's balancing
weight); k-nearest neighbours, which scikit-learn fits without weights, votes with them instead
(:class:`WeightedKNeighbors`). Features are standardised for the families that measure
distances or follow gradients (k-NN, logistic regression, MLP).

The MLP trains on every sample until its loss stops falling, for at most 300 epochs, with
scikit-learn's arithmetic in a leaner loop (:class:`~polymimic.baselines.mlp.QuickFitMLP`: the
same weights to the bit, in less time). Stopping on a held-out tenth instead took a fifth of
the time on a crowd's 30 000 samples, but in the full benchmark ``bc_best`` then lost 8 to 10
net goals on three of the five profiles and ``bc`` lost 3 on two (gaining 3 on one): a weaker
baseline, so not the choice.

>>> import numpy as np
>>> model = make_classifier("knn", {"n_neighbors": 3}, seed=0)
>>> X, y = np.array([[0.0], [0.1], [0.2], [1.0], [1.1], [1.2]]), np.array([0, 0, 0, 1, 1, 1])
>>> fit_weighted(model, X, y, np.ones(6)).predict(np.array([[0.05], [1.15]])).tolist()
[0, 1]
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Mapping
from typing import Any

import numpy as np
from sklearn.base import BaseEstimator, ClassifierMixin  # type: ignore[import-untyped, unused-ignore]
from sklearn.dummy import DummyClassifier  # type: ignore[import-untyped, unused-ignore]
from sklearn.ensemble import HistGradientBoostingClassifier, RandomForestClassifier  # type: ignore[import-untyped, unused-ignore]
from sklearn.exceptions import ConvergenceWarning  # type: ignore[import-untyped, unused-ignore]
from sklearn.linear_model import LogisticRegression  # type: ignore[import-untyped, unused-ignore]
from sklearn.neighbors import NearestNeighbors  # type: ignore[import-untyped, unused-ignore]
from sklearn.pipeline import Pipeline  # type: ignore[import-untyped, unused-ignore]
from sklearn.preprocessing import StandardScaler  # type: ignore[import-untyped, unused-ignore]
from sklearn.utils.validation import check_is_fitted  # type: ignore[import-untyped, unused-ignore]

from polymimic.baselines.mlp import QuickFitMLP

__all__ = ["FAMILIES", "SmallBatchBoosting", "SmallBatchForest", "WeightedKNeighbors", "fit_weighted",
           "make_classifier"]

FAMILIES = ("hist_gradient_boosting", "random_forest", "knn", "logistic_regression", "mlp")


class SmallBatchForest(RandomForestClassifier):  # type: ignore[misc]
    """scikit-learn's random forest, predicting without joblib. A policy asks about a handful of
    observations at a time, and handing each of 100 trees to joblib costs some forty times the
    trees' own work. The same sums in the same order: the same probabilities, to the bit."""

    def predict_proba(self, X: np.ndarray) -> np.ndarray:
        """Class probabilities of shape ``(n, n_classes)``: the mean of the trees' leaf
        probabilities, scikit-learn's to the bit.
        """
        check_is_fitted(self)
        X = self._validate_X_predict(X)
        proba = np.zeros((X.shape[0], self.n_classes_), dtype=np.float64)
        for tree in self.estimators_:
            proba += tree.tree_.predict(X)[:, :self.n_classes_]
        proba /= len(self.estimators_)
        return proba


class SmallBatchBoosting(HistGradientBoostingClassifier):  # type: ignore[misc]
    """scikit-learn's histogram gradient boosting, predicting every tree at once. A policy asks
    about a handful of observations at a time, and scikit-learn walks its trees one at a time
    (300 iterations of five classes are 1500 calls, each some microseconds of overhead for a
    few rows); here all trees descend together, a level per step, in numpy. Leaf values are
    then added in scikit-learn's order: the same raw predictions, to the bit. Categorical
    splits, which no feature set makes, are left to scikit-learn."""

    def fit(self, X: np.ndarray, y: np.ndarray, sample_weight: np.ndarray | None = None) -> SmallBatchBoosting:
        """Fits as scikit-learn's ``HistGradientBoostingClassifier`` does, then flattens the trees
        for batched prediction; returns the classifier.
        """
        super().fit(X, y, sample_weight=sample_weight)
        self._flat_trees_ = _flat_trees(self._predictors)
        return self

    def __getstate__(self) -> dict[str, Any]:
        state = dict(super().__getstate__())  # a copy: the live estimator keeps its flat trees
        state.pop("_flat_trees_", None)  # derived from the trees, so rebuilt on loading, not saved
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        super().__setstate__(state)
        if hasattr(self, "_predictors"):
            self._flat_trees_ = _flat_trees(self._predictors)

    def _predict_iterations(self, X: np.ndarray, predictors: Any, raw_predictions: np.ndarray, is_binned: bool,
                            n_threads: int) -> None:
        flat = getattr(self, "_flat_trees_", None)
        if is_binned or flat is None or flat.categorical or predictors is not self._predictors:
            super()._predict_iterations(X, predictors, raw_predictions, is_binned, n_threads)
            return
        leaves = flat.leaf_values(np.asarray(X, dtype=np.float64))
        iterations, per_iteration = len(predictors), raw_predictions.shape[1]
        for step in leaves.reshape(len(X), iterations, per_iteration).transpose(1, 0, 2):
            raw_predictions += step


@dataclasses.dataclass(frozen=True)
class _FlatTrees:
    """Every tree's nodes in one array, trees in scikit-learn's order (iteration by iteration,
    class by class within one); ``roots[t]`` is tree t's first node. A leaf splits on feature 0
    at +∞ with the missing sent left, and both its children are itself, so a row that has
    reached its leaf stays there whatever it holds."""

    feature: np.ndarray
    threshold: np.ndarray
    missing_left: np.ndarray
    children: np.ndarray  # node n's left child at 2n, its right at 2n + 1
    leaf: np.ndarray
    value: np.ndarray
    roots: np.ndarray
    depth: int
    categorical: bool

    def leaf_values(self, X: np.ndarray) -> np.ndarray:
        """(rows, trees): the value of the leaf each row reaches in each tree."""
        rows, features = X.shape
        flat_X = np.ascontiguousarray(X).ravel()
        node = np.tile(self.roots, rows)
        # Only the (row, tree) pairs still above a leaf descend a level.
        walking, at, row_start = np.arange(len(node)), node, np.repeat(np.arange(rows) * features, len(self.roots))
        for _ in range(self.depth):
            x = flat_X[row_start + self.feature[at]]
            # As scikit-learn: a missing value goes where the split sent the missing, else x ≤ threshold goes left.
            left = np.where(np.isnan(x), self.missing_left[at], x <= self.threshold[at])
            at = self.children[2 * at + ~left]
            node[walking] = at
            still = ~self.leaf[at]
            walking, at, row_start = walking[still], at[still], row_start[still]
            if not len(walking):
                break
        return np.asarray(self.value[node].reshape(rows, len(self.roots)))


def _flat_trees(predictors: Any) -> _FlatTrees:
    trees = [predictor.nodes for iteration in predictors for predictor in iteration]
    sizes = [len(nodes) for nodes in trees]
    offsets = np.cumsum([0] + sizes[:-1]).astype(np.intp)
    nodes = np.concatenate(trees)
    shift = np.repeat(offsets, sizes)
    leaf = nodes["is_leaf"].astype(bool)
    own = np.arange(len(nodes))
    children = np.stack([np.where(leaf, own, nodes["left"].astype(np.intp) + shift),
                         np.where(leaf, own, nodes["right"].astype(np.intp) + shift)], axis=1).ravel()
    return _FlatTrees(feature=np.where(leaf, 0, nodes["feature_idx"]).astype(np.intp),
                      threshold=np.where(leaf, np.inf, nodes["num_threshold"]).astype(np.float64),
                      missing_left=np.where(leaf, True, nodes["missing_go_to_left"].astype(bool)),
                      children=children, leaf=leaf, value=nodes["value"].astype(np.float64), roots=offsets,
                      depth=int(nodes["depth"].max()), categorical=bool(nodes["is_categorical"].any()))


class WeightedKNeighbors(ClassifierMixin, BaseEstimator):  # type: ignore[misc]
    """k-nearest neighbours whose votes weigh by the neighbours' sample weights (and by
    inverse distance when ``weights="distance"``); a zero-weight sample never votes."""

    def __init__(self, n_neighbors: int = 5, weights: str = "uniform") -> None:
        self.n_neighbors = n_neighbors
        self.weights = weights

    def fit(self, X: np.ndarray, y: np.ndarray, sample_weight: np.ndarray | None = None) -> WeightedKNeighbors:
        """Indexes the samples of positive ``sample_weight`` (all weigh 1 without it); returns the
        classifier.
        """
        weight = np.ones(len(y)) if sample_weight is None else np.asarray(sample_weight, dtype=np.float64)
        keep = weight > 0
        self.classes_, self.y_ = np.unique(np.asarray(y)[keep], return_inverse=True)
        self.weight_ = weight[keep]
        self.index_ = NearestNeighbors(n_neighbors=min(self.n_neighbors, int(keep.sum()))).fit(X[keep])
        return self

    def predict_proba(self, X: np.ndarray) -> np.ndarray:
        """Class probabilities of shape ``(n, n_classes)``: the neighbours' weights (divided by their
        distance under ``weights="distance"``) summed per class and normalised.
        """
        distance, index = self.index_.kneighbors(X)
        vote = self.weight_[index]
        if self.weights == "distance":
            vote = vote / np.maximum(distance, 1e-9)
        proba = np.zeros((len(X), len(self.classes_)))
        np.add.at(proba, (np.arange(len(X))[:, None], self.y_[index]), vote)
        total = proba.sum(axis=1, keepdims=True)
        return np.asarray(proba / np.where(total > 0, total, 1.0))

    def predict(self, X: np.ndarray) -> np.ndarray:
        """The most probable class of each row."""
        return np.asarray(self.classes_[self.predict_proba(X).argmax(axis=1)])


def make_classifier(family: str, params: Mapping[str, Any], *, seed: int) -> Any:
    """An unfitted classifier of ``family`` (one of :data:`FAMILIES`) with ``params``, seeded."""
    params = dict(params)
    if family == "hist_gradient_boosting":
        return SmallBatchBoosting(random_state=seed, early_stopping=False, **params)
    if family == "random_forest":
        return SmallBatchForest(random_state=seed, n_jobs=1, **params)
    if family == "knn":
        return Pipeline([("scale", StandardScaler()), ("model", WeightedKNeighbors(**params))])
    if family == "logistic_regression":
        return Pipeline([("scale", StandardScaler()), ("model", LogisticRegression(max_iter=2000, **params))])
    if family == "mlp":
        return Pipeline([("scale", StandardScaler()),
                         ("model", QuickFitMLP(random_state=seed, max_iter=300, early_stopping=False, **params))])
    raise ValueError(f"unknown classifier family {family!r}; expected one of {', '.join(FAMILIES)}")


def fit_weighted(model: Any, X: np.ndarray, y: np.ndarray, sample_weight: np.ndarray) -> Any:
    """``model`` fitted on the samples of positive weight, with their weights; where they hold
    one class only, a constant classifier of that class instead (no family fits one class).
    An iterative fit that stops at its iteration cap is kept as it is (the cap is a
    hyperparameter, not a failure)."""
    keep = sample_weight > 0
    X, y, sample_weight = X[keep], y[keep], sample_weight[keep]
    if len(np.unique(y)) == 1:
        return DummyClassifier(strategy="most_frequent").fit(X, y)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        if isinstance(model, Pipeline):
            model.fit(X, y, model__sample_weight=sample_weight)
        else:
            model.fit(X, y, sample_weight=sample_weight)
    return model
