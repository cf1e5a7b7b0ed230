"""Predictions per second of a policy-sized batch: SmallBatchBoosting (every tree descends at
once, in numpy) against scikit-learn's HistGradientBoostingClassifier (a call per tree), both
fitted alike on the same samples, in one run, alternating. The largest candidate of the tuning
grid: 300 iterations of five classes, 31 leaves. Rows per call are what a policy asks about
(one per episode still running). Run: ``python benches/boosting_vs_sklearn.py``.
"""

import argparse
import time

import numpy as np
from sklearn.ensemble import HistGradientBoostingClassifier
from threadpoolctl import threadpool_limits

from _rounds import alternate
from polymimic.baselines.classifiers import SmallBatchBoosting


def calls_per_second(model, queries):
    start = time.perf_counter()
    for query in queries:
        model.predict(query)
    return len(queries) / (time.perf_counter() - start)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10, help="observations per predict call")
    parser.add_argument("--calls", type=int, default=200, help="predict calls per measurement")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    X = rng.normal(size=(3000, 12))
    y = np.digitize(X[:, 0] + 0.5 * X[:, 1] + rng.normal(scale=0.5, size=3000), [-1.0, -0.3, 0.3, 1.0])
    params = {"max_iter": 300, "max_leaf_nodes": 31, "learning_rate": 0.1, "early_stopping": False, "random_state": 0}
    ours, theirs = SmallBatchBoosting(**params).fit(X, y), HistGradientBoostingClassifier(**params).fit(X, y)
    queries = [rng.normal(size=(args.rows, 12)) for _ in range(args.calls)]
    assert all(np.array_equal(ours.predict_proba(q), theirs.predict_proba(q)) for q in queries[:20])
    with threadpool_limits(limits=1):  # as a benchmark worker predicts
        ours_rate, theirs_rate, ratio = alternate(
            args.rounds, lambda _: calls_per_second(ours, queries), lambda _: calls_per_second(theirs, queries),
            names=("SmallBatchBoosting", "scikit-learn"), unit="calls/s")
    print(f"\n{args.rows} rows per call: SmallBatchBoosting {ours_rate:.0f} calls/s, "
          f"scikit-learn {theirs_rate:.0f}; median ratio {ratio:.2f}")


if __name__ == "__main__":
    main()
