"""Which boosted trees ``bc`` needs to clone as well as the plain cloner on few demonstrations.

On the small mixed-body crowd of ``studies/does_bc_match_a_plain_cloner_on_a_small_crowd.py`` (three demonstrations
per member and configuration, at most 3000 decision samples), ``bc``'s decision samples are
fitted under seeds 0 to 7 by three boosted-tree classifiers, each played at ten frames a step on
the same 50 evaluation attempts: histogram boosting with seven leaves of at least 20 samples
(``PLAIN_BOOSTING`` once), histogram boosting of depth 3 whose leaves may hold one sample
(``PLAIN_BOOSTING`` now), and scikit-learn's ``GradientBoostingClassifier`` with its defaults
(what the plain cloner fits). The plain cloner's own fits under the same seeds are printed
first. Prints one JSON line per way: net goals per fit, their mean and sd.
Run: ``python studies/which_trees_bc_needs_on_few_demonstrations.py``.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # batched predictions of ≤ 50 rows: threads only cost

import dataclasses  # noqa: E402
import json  # noqa: E402
import statistics  # noqa: E402

from sklearn.ensemble import GradientBoostingClassifier  # noqa: E402

import does_bc_match_a_plain_cloner_on_a_small_crowd as bench  # noqa: E402
from polymimic.baselines.classifiers import SmallBatchBoosting  # noqa: E402
from polymimic.baselines.evaluation import attempts_of  # noqa: E402
from polymimic.baselines.features import features  # noqa: E402
from polymimic.baselines.hyperparameters import PLAIN_BOOSTING  # noqa: E402
from polymimic.baselines.labels import command_labels  # noqa: E402
from polymimic.baselines.policy import ClonedPolicy  # noqa: E402
from polymimic.baselines.training import decision_samples  # noqa: E402
from polymimic.crowds import PROFILES, record_crowd  # noqa: E402

FITS, FRAMES = range(8), 10
CLASSIFIERS = {
    "seven_leaves_of_20": lambda seed: SmallBatchBoosting(random_state=seed, early_stopping=False, max_iter=100,
                                                          learning_rate=0.1, max_leaf_nodes=7),
    "depth_3_leaves_of_1": lambda seed: SmallBatchBoosting(random_state=seed, early_stopping=False, max_iter=100,
                                                           learning_rate=0.1, max_depth=3, min_samples_leaf=1),
    "sklearn_gradient_boosting": lambda seed: GradientBoostingClassifier(random_state=seed),
}


def line(way: str, nets: list[int]) -> str:
    return json.dumps({"way": way, "net": nets, "mean": statistics.mean(nets), "sd": statistics.stdev(nets)})


def main() -> None:
    demos = record_crowd(PROFILES["mixed_bodies"], n=3, seed=0)
    evaluation = attempts_of(25, seed=bench.EVALUATION_SEED)
    plain = bench.plain_cloner()
    print(line("plain_cloner", [bench.net(plain.fit(demos, FRAMES, max_samples=bench.MAX_SAMPLES, seed=seed),
                                          evaluation) for seed in FITS]), flush=True)
    items = command_labels(demos)
    step = dataclasses.replace(PLAIN_BOOSTING, frames_per_action=FRAMES)
    for way, make in CLASSIFIERS.items():
        nets = []
        for seed in FITS:
            X, y, w = decision_samples(items, max_samples=bench.MAX_SAMPLES, seed=seed)
            model = make(seed).fit(features(X, feature_set=step.feature_set), y, sample_weight=w)
            nets.append(bench.net(ClonedPolicy("bc", step, model), evaluation))
        print(line(way, nets), flush=True)


if __name__ == "__main__":
    main()
