"""Every baseline of the benchmark (docs/results/benchmark.md) tuned on validation attempts, then
evaluated on the imitator's 50 attempts (25 per configuration).

The demonstrations are the Expert's 50 (25 per configuration), or with ``--mix`` the Expert's
and the Poor's (100); ``bc_best`` clones the Expert alone, and ``bco_lp`` weighs each member by
its final LP from one learning trial on the same demonstrations (varying-skill style: phase one
interleaved). Every method gets ``--budget`` candidates, scored on ``--validation`` attempts
per configuration under validation seed ``--validation-seed`` (disjoint from the evaluation's
by construction: see ``polymimic.baselines.tuning``). Prints one JSON object per method: its
chosen hyperparameters, its validation scores, and its goals and own goals on evaluation.
Run: ``python studies/how_each_tuned_baseline_scores.py [--mix]``.

Measured on a shared two-core node (budget 12, 10 validation attempts per configuration,
validation seed 0; goals / own goals over the 50 evaluation attempts, configuration 1 + 2):

============ ====================== ====================== ======================
method       Expert, seed 0         Expert, seed 1         Expert + Poor, seed 0
============ ====================== ====================== ======================
bc           35 / 2 (25+10 / 0+2)   33 / 0 (25+8 / 0+0)    24 / 9 (24+0 / 0+9)
bco          25 / 1 (25+0 / 0+1)    23 / 10 (23+0 / 0+10)  25 / 23 (25+0 / 0+23)
bco_lp       = bco (one member)                            25 / 11 (25+0 / 0+11)
bc_best      = bc (one member)                             35 / 2 (25+10 / 0+2)
random       0 / 1                  0 / 0                  0 / 1
============ ====================== ====================== ======================

(The Expert's own demonstrations: 48 goals, 0 own goals.) Configuration 2 is where cloning
falls short: the Expert goes round the ball in arcs, and the primitive equivalent of every arc
is forward, so neither the commands (``bc``) nor the recogniser (``bco``) ever label the turn
that takes it round.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")  # batched predictions of ≤ 50 rows: threads only cost

import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402

import polymimic  # noqa: E402
from polymimic import baselines, recognition  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mix", action="store_true", help="Expert and Poor demonstrations instead of the Expert's")
    parser.add_argument("--budget", type=int, default=12)
    parser.add_argument("--validation", type=int, default=10, help="validation attempts per configuration")
    parser.add_argument("--validation-seed", type=int, default=0)
    parser.add_argument("--seed", type=int, default=0, help="demonstrations, evaluation and fits")
    parser.add_argument("--methods", nargs="+", default=list(baselines.METHODS))
    args = parser.parse_args()

    members = ("expert", "poor") if args.mix else ("expert",)
    demos = [d for who in members for c in (1, 2) for d in polymimic.record(who, configuration=c, n=25, seed=args.seed)]
    recognizer = recognition.train_recognizer(polymimic.self_observation(300, seed=args.seed + 1), codebook_size=256,
                                              seed=args.seed)
    if len(members) > 1:
        trial = polymimic.run_trial(demos, recognizer=recognizer, ordering=list(members), phase_one="interleaved",
                                    seed=args.seed)
        weights = {name: model.lp for name, model in trial.models.items()}
    else:
        weights = {"expert": 1.0}
    needs = {"bco": {"recognizer": recognizer}, "bco_lp": {"recognizer": recognizer, "weights": weights},
             "bc_best": {"member": "expert"}}
    for method in args.methods:
        started = time.perf_counter()
        tuning = baselines.tune(method, demos, budget=args.budget, validation_seed=args.validation_seed,
                                attempts_per_configuration=args.validation,
                                evaluation=polymimic.Attempts(seed=args.seed), seed=args.seed,
                                **needs.get(method, {}))
        result = baselines.evaluate_policy(tuning.policy, attempts_per_configuration=25, seed=args.seed)
        by_configuration = {c: {o: sum(a.outcome == o for a in result.attempts if a.configuration == c)
                                for o in ("goal", "own_goal")} for c in (1, 2)}
        print(json.dumps({"method": method, "demonstrators": list(members), "goals": result.goals,
                          "own_goals": result.own_goals, "by_configuration": by_configuration,
                          "chosen": tuning.chosen, "weights": weights if method == "bco_lp" else None,
                          "validation": tuning.scores, "seconds": round(time.perf_counter() - started, 1)}), flush=True)


if __name__ == "__main__":
    main()
