"""What the correspondence between settings buys: each imitator body learning from each built-in
demonstrator, with the robot's distance from the ball mapped by the bodies' reach (the learner's
rule, :func:`polymimic.bodies.onto_field`) and with it kept in millimetres (the demonstrations'
reach marked unknown), the ball mapped the same way in both.

For each imitator body (lego, tiny, humanoid) a recogniser is trained on its own
self-observation (200 sequences per primitive, seed 1); for each demonstrator (the Expert on the
Lego, the Tiny controller on the tiny, the Humanoid controller) and each of ``--trials`` trials t,
25 demonstrations per configuration (seed 100 + t) teach one trial (seed t) on the imitator's
setting, and the improved control plays the same 50 evaluation attempts (seed 1000). Prints one
JSON line per (imitator, demonstrator): net goals per trial under each rule.
Run: ``python studies/what_the_reach_correspondence_buys.py [--trials 3]`` (about 30 s a trial).
"""

import argparse
import json
import statistics

import polymimic
from polymimic import learning, recognition
from polymimic._native import SegmentedDemonstrations

BODIES = ("lego", "tiny", "humanoid")
DEMONSTRATORS = ("expert", "tiny", "humanoid")


def reach_unknown(batch: SegmentedDemonstrations) -> SegmentedDemonstrations:
    return SegmentedDemonstrations([dict(d, reach_mm=None) for d in batch])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--trials", type=int, default=3)
    args = parser.parse_args()
    for imitator in BODIES:
        recognizer = recognition.train_recognizer(polymimic.self_observation(200, seed=1, body=imitator))
        for who in DEMONSTRATORS:
            net: dict[str, list[int]] = {"reach": [], "millimetres": []}
            for t in range(args.trials):
                demos = [d for c in (1, 2) for d in polymimic.record(who, configuration=c, n=25, seed=100 + t)]
                batch = learning.segmented(demos, recognizer)
                for rule, items in (("reach", batch), ("millimetres", reach_unknown(batch))):
                    trial = learning.run_trial(items, recognizer=recognizer, ordering=[who], seed=t, body=imitator)
                    policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved",
                                                     demonstrations=items, body=imitator)
                    played = learning.evaluate(policy, attempts_per_configuration=25, seed=1000)
                    net[rule].append(played.goals - played.own_goals)
            print(json.dumps({"imitator": imitator, "demonstrator": who,
                              **{rule: {"mean": round(statistics.mean(v), 1), "per_trial": v}
                                 for rule, v in net.items()}}), flush=True)


if __name__ == "__main__":
    main()
