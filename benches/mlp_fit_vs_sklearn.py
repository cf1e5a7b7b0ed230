"""Fits per minute of a cloned policy's MLP: QuickFitMLP (flat Adam, scikit-learn's arithmetic)
against scikit-learn's MLPClassifier, on the same weighted samples, in one run, alternating.
The tuning grid's two shapes, (64,) and (64, 64), on a fit's full 20 000 decision samples of
five features and five primitives; each fit runs a fixed number of epochs, so both do the same
work, and the two must end with the same weights. Run: ``python benches/mlp_fit_vs_sklearn.py``.
"""

import argparse
import time
import warnings

import numpy as np
from sklearn.exceptions import ConvergenceWarning
from sklearn.neural_network import MLPClassifier
from threadpoolctl import threadpool_limits

from _rounds import alternate
from polymimic.baselines.mlp import QuickFitMLP


def fits_per_minute(model_class, params, X, y, weights):
    start = time.perf_counter()
    model_class(**params).fit(X, y, sample_weight=weights)
    return 60.0 / (time.perf_counter() - start)


def compare(hidden, X, y, weights, *, epochs, rounds):
    """Both MLPs of ``hidden`` layers on the same samples: the same weights, then their rates."""
    params = {"hidden_layer_sizes": hidden, "alpha": 1e-4, "max_iter": epochs, "tol": 0.0, "random_state": 0}
    ours, theirs = QuickFitMLP(**params).fit(X, y, weights), MLPClassifier(**params).fit(X, y, weights)
    assert all(np.array_equal(a, b) for a, b in zip(ours.coefs_, theirs.coefs_, strict=True))
    print(f"hidden layers {hidden}, {len(X)} samples, {epochs} epochs a fit:")
    ours_rate, theirs_rate, ratio = alternate(
        rounds, lambda _: fits_per_minute(QuickFitMLP, params, X, y, weights),
        lambda _: fits_per_minute(MLPClassifier, params, X, y, weights),
        names=("QuickFitMLP", "scikit-learn"), unit="fits/min")
    print(f"QuickFitMLP {ours_rate:.1f} fits/min, scikit-learn {theirs_rate:.1f}; median ratio {ratio:.2f}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=20_000)
    parser.add_argument("--epochs", type=int, default=20)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    X = rng.normal(size=(args.samples, 5))
    y = np.digitize(X[:, 0] + 0.5 * X[:, 1] + rng.normal(scale=0.5, size=args.samples), [-1.0, -0.3, 0.3, 1.0])
    weights = rng.uniform(0.2, 2.0, size=args.samples)
    warnings.simplefilter("ignore", ConvergenceWarning)  # a fixed number of epochs, on purpose
    with threadpool_limits(limits=1):  # as a benchmark worker fits
        for hidden in ((64,), (64, 64)):
            compare(hidden, X, y, weights, epochs=args.epochs, rounds=args.rounds)


if __name__ == "__main__":
    main()
