"""scikit-learn's MLP classifier, trained by a leaner loop that does the same arithmetic.

A cloned policy's MLP learns from some 20 000 decision samples in batches of 200 for up to 300
epochs: 30 000 Adam steps, each a few small products and some forty numpy calls. scikit-learn
spends most of a step's time outside those products: it rebuilds every moment estimate as a
new list of arrays, finds the ReLU's zeros by boolean indexing and indexes each batch through
its generic helpers. :class:`QuickFitMLP` keeps every parameter, gradient and moment estimate
in one flat array each (the layers are views into it), so Adam's update is a handful of calls
on one array, and masks the ReLU's derivative without boolean indexing. Every element is
computed by the same operations in the same order as scikit-learn's: the same weights, loss
curve and stopping epoch, to the bit (a test holds it to that). Whatever this loop does not
cover is left to scikit-learn: another solver, early stopping, no shuffling, ``partial_fit``,
``verbose``, and inputs other than dense float64 (float32 would round Adam's update where
scikit-learn does not). One difference is deliberate: an interrupt stops the fit with the
interrupt, where scikit-learn would warn and return a half-trained model as if fitted.
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np
from scipy.sparse import issparse  # type: ignore[import-untyped, unused-ignore]
from sklearn.exceptions import ConvergenceWarning  # type: ignore[import-untyped, unused-ignore]
from sklearn.neural_network import MLPClassifier  # type: ignore[import-untyped, unused-ignore]
from sklearn.neural_network._base import ACTIVATIONS, DERIVATIVES, LOSS_FUNCTIONS  # type: ignore[import-untyped, unused-ignore]
from sklearn.neural_network._stochastic_optimizers import AdamOptimizer  # type: ignore[import-untyped, unused-ignore]
from sklearn.utils import shuffle  # type: ignore[import-untyped, unused-ignore]

__all__ = ["QuickFitMLP"]


class QuickFitMLP(MLPClassifier):  # type: ignore[misc]
    """:class:`sklearn.neural_network.MLPClassifier`, fitted faster with the same result."""

    coefs_: list[np.ndarray]
    intercepts_: list[np.ndarray]

    def _fit_stochastic(self, X: np.ndarray, y: np.ndarray, sample_weight: np.ndarray | None,
                        activations: list[Any], deltas: list[Any], coef_grads: list[Any],
                        intercept_grads: list[Any], layer_units: list[int], incremental: bool) -> None:
        if incremental or self.solver != "adam" or self.early_stopping or not self.shuffle or self.verbose \
                or issparse(X) or X.dtype != np.float64:
            super()._fit_stochastic(X, y, sample_weight, activations, deltas, coef_grads, intercept_grads,
                                    layer_units, incremental)
            return
        layers = len(self.coefs_)
        flat, views = _flat_views(self.coefs_ + self.intercepts_)
        self.coefs_, self.intercepts_ = views[:layers], views[layers:]
        adam = _FlatAdam(flat, self.learning_rate_init, self.beta_1, self.beta_2, self.epsilon)
        try:
            self._epochs(X, y, sample_weight, adam)
        finally:
            # Separate arrays again, and an optimizer in scikit-learn's own state, so that a
            # later warm start or partial_fit carries on exactly as after scikit-learn's own fit
            # (and a fit stopped by an exception leaves a consistent model).
            self.coefs_ = [c.copy() for c in self.coefs_]
            self.intercepts_ = [b.copy() for b in self.intercepts_]
            self._optimizer = adam.to_sklearn(self.coefs_ + self.intercepts_)

    def _epochs(self, X: np.ndarray, y: np.ndarray, sample_weight: np.ndarray | None, adam: _FlatAdam) -> None:
        """Shuffled epochs of Adam steps until the training loss stalls or ``max_iter``."""
        layers = len(self.coefs_)
        grads_flat, grads = _flat_views(self.coefs_ + self.intercepts_)
        coef_grads, intercept_grads = grads[:layers], grads[layers:]
        n_samples = X.shape[0]
        if self.batch_size == "auto":
            batch_size = min(200, n_samples)
        else:
            if not 1 <= self.batch_size <= n_samples:
                warnings.warn("Got `batch_size` less than 1 or larger than sample size. It is going to be clipped",
                              stacklevel=3)
            batch_size = int(np.clip(self.batch_size, 1, n_samples))
        binary = self.loss == "log_loss" and self.out_activation_ == "logistic"
        loss_of = LOSS_FUNCTIONS["binary_log_loss" if binary else self.loss]
        order = np.arange(n_samples, dtype=int)
        self.n_iter_ = 0
        for _ in range(self.max_iter):
            order = shuffle(order, random_state=self._random_state)
            accumulated_loss = 0.0
            for start in range(0, n_samples, batch_size):
                stop = min(start + batch_size, n_samples)
                rows = order[start:stop]
                weights = None if sample_weight is None else sample_weight[rows]
                batch_loss = self._batch_gradients(X[rows], y[rows], weights, loss_of, coef_grads, intercept_grads)
                accumulated_loss += batch_loss * (stop - start)
                adam.step(grads_flat)
            self.n_iter_ += 1
            self.loss_ = accumulated_loss / n_samples
            self.t_ += n_samples
            self.loss_curve_.append(self.loss_)
            self._update_no_improvement_count(False, None, None, None)
            if self._no_improvement_count > self.n_iter_no_change:
                break  # Adam stops where the training loss has stalled
            if self.n_iter_ == self.max_iter:
                warnings.warn(f"Stochastic Optimizer: Maximum iterations ({self.max_iter}) reached and the "
                              f"optimization hasn't converged yet.", ConvergenceWarning, stacklevel=3)

    def _batch_gradients(self, X: np.ndarray, y: np.ndarray, sample_weight: np.ndarray | None, loss_of: Any,
                         coef_grads: list[np.ndarray], intercept_grads: list[np.ndarray]) -> float:
        """One batch forward and back: its loss (by ``loss_of``, scikit-learn's loss function
        for this output), with the gradients written into the views."""
        layers = len(self.coefs_)
        activations = [X]
        for i in range(layers):
            z = activations[i] @ self.coefs_[i]
            z += self.intercepts_[i]
            ACTIVATIONS[self.activation if i + 1 < layers else self.out_activation_](z)
            activations.append(z)
        loss = loss_of(y, activations[-1], sample_weight)
        values = 0
        for coef in self.coefs_:
            flat = coef.ravel()
            values += np.dot(flat, flat)
        sw_sum = X.shape[0] if sample_weight is None else sample_weight.sum()
        loss += (0.5 * self.alpha) * values / sw_sum
        delta = activations[-1] - y
        if sample_weight is not None:
            delta *= sample_weight.reshape(-1, 1)
        for i in range(layers - 1, -1, -1):
            np.matmul(activations[i].T, delta, out=coef_grads[i])
            coef_grads[i] += self.alpha * self.coefs_[i]
            coef_grads[i] /= sw_sum
            np.divide(np.sum(delta, axis=0), sw_sum, out=intercept_grads[i])
            if i > 0:
                delta = delta @ self.coefs_[i].T
                if self.activation == "relu":
                    delta = np.where(activations[i] == 0, 0.0, delta)
                else:
                    DERIVATIVES[self.activation](activations[i], delta)
        return float(loss)


class _FlatAdam:
    """Adam on one flat parameter array: the element-wise arithmetic of scikit-learn's
    ``AdamOptimizer``, in place."""

    def __init__(self, params: np.ndarray, learning_rate_init: float, beta_1: float, beta_2: float,
                 epsilon: float) -> None:
        self.params, self.learning_rate_init = params, learning_rate_init
        self.learning_rate = float(learning_rate_init)
        self.beta_1, self.beta_2, self.epsilon = beta_1, beta_2, epsilon
        self.t = 0
        self.m, self.v = np.zeros_like(params), np.zeros_like(params)
        self._scratch, self._update = np.empty_like(params), np.empty_like(params)

    def step(self, grads: np.ndarray) -> None:
        self.t += 1
        scratch, update = self._scratch, self._update
        self.m *= self.beta_1
        np.multiply(grads, 1 - self.beta_1, out=scratch)
        self.m += scratch
        self.v *= self.beta_2
        np.multiply(grads, grads, out=scratch)
        scratch *= 1 - self.beta_2
        self.v += scratch
        self.learning_rate = (self.learning_rate_init * np.sqrt(1 - self.beta_2**self.t)
                              / (1 - self.beta_1**self.t))
        np.multiply(self.m, -self.learning_rate, out=update)
        np.sqrt(self.v, out=scratch)
        scratch += self.epsilon
        update /= scratch
        self.params += update

    def to_sklearn(self, params: list[np.ndarray]) -> AdamOptimizer:
        """scikit-learn's optimizer for ``params`` (the layers, in order) in this one's state."""
        optimizer = AdamOptimizer(params, self.learning_rate_init, self.beta_1, self.beta_2, self.epsilon)
        optimizer.t, optimizer.learning_rate = self.t, self.learning_rate
        optimizer.ms = [m.copy() for m in _split(self.m, params)]
        optimizer.vs = [v.copy() for v in _split(self.v, params)]
        return optimizer


def _flat_views(arrays: list[np.ndarray]) -> tuple[np.ndarray, list[np.ndarray]]:
    """One flat array holding ``arrays``' values, and a view of it shaped as each."""
    flat = np.concatenate([a.ravel() for a in arrays])
    return flat, _split(flat, arrays)


def _split(flat: np.ndarray, like: list[np.ndarray]) -> list[np.ndarray]:
    ends = np.cumsum([a.size for a in like])
    return [part.reshape(a.shape) for part, a in zip(np.split(flat, ends[:-1]), like)]
