"""Predictions per second of a policy-sized batch: SmallBatchBoosting (every tree descends at
once, in numpy) against scikit-learn's HistGradientBoostingClassifier (a call per tree), both
fitted alike on the same samples, in one run, alternating. The largest candidate of the tuning
grid: 300 iterations of five classes, 31 leaves. Rows per call are what a policy asks about
(one per episode still running). Run: ``python benches/boosting_vs_sklearn.py``.
"""

import argparse
import statistics
import time

import numpy as np
from sklearn.ensemble import HistGradientBoostingClassifier
from threadpoolctl import threadpool_limits

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
    ours_rates, theirs_rates = [], []
    with threadpool_limits(limits=1):  # as a benchmark worker predicts
        for round_ in range(args.rounds):
            ours_rates.append(calls_per_second(ours, queries))
            theirs_rates.append(calls_per_second(theirs, queries))
            print(f"round {round_}: SmallBatchBoosting {ours_rates[-1]:7.0f}  scikit-learn {theirs_rates[-1]:7.0f} "
                  f"calls/s  ratio {ours_rates[-1] / theirs_rates[-1]:.2f}")
    ratio = statistics.median(a / b for a, b in zip(ours_rates, theirs_rates))
    print(f"\n{args.rows} rows per call: SmallBatchBoosting {statistics.median(ours_rates):.0f} calls/s, "
          f"scikit-learn {statistics.median(theirs_rates):.0f}; median ratio {ratio:.2f}")


if __name__ == "__main__":
    main()
