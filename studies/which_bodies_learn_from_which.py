"""Imitators of other bodies than the Lego robot, a first look at who learns what from whom.

For each imitator body (lego, tiny, humanoid) a recogniser is trained on that body's own
self-observation (``--self-observation`` sequences per primitive, seed 1); then, for each
demonstrator, one learning trial (seed 0) on that body's setting from ``--demonstrations`` of its
demonstrations per configuration (seed 0; another field's brought onto the imitator's by
:func:`polymimic.bodies.onto_field`), and the trained
imitator plays the same 50 evaluation attempts (seed 1000) under the thesis's control and the
improved one. The humanoid takes no primitives: each is sent as the command that executes it
(``polymimic.field.primitive_command``). Prints one JSON line per (imitator, demonstrator):
goals and own goals under each control.
Run: ``python studies/which_bodies_learn_from_which.py [--demonstrations 25] [--self-observation 200]``.
"""

import argparse
import json

import polymimic
from polymimic import recognition
from polymimic.learning import ImitatorPolicy, evaluate, run_trial, segmented

IMITATORS = ("lego", "tiny", "humanoid")
DEMONSTRATORS = ("expert", "tiny", "humanoid")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--demonstrations", type=int, default=25, help="per configuration")
    parser.add_argument("--self-observation", type=int, default=200, help="sequences per primitive")
    args = parser.parse_args()
    for imitator in IMITATORS:
        recognizer = recognition.train_recognizer(polymimic.self_observation(args.self_observation, seed=1,
                                                                             body=imitator))
        for who in DEMONSTRATORS:
            demos = [d for c in (1, 2) for d in polymimic.record(who, configuration=c, n=args.demonstrations, seed=0)]
            batch = segmented(demos, recognizer)
            trial = run_trial(batch, recognizer=recognizer, ordering=[who], seed=0, body=imitator)
            scores = {}
            for control in ("thesis", "improved"):
                policy = ImitatorPolicy(trial, recognizer=recognizer, control=control, demonstrations=batch,
                                        body=imitator)
                played = evaluate(policy, attempts_per_configuration=25, seed=1000)
                scores[control] = {"goals": played.goals, "own_goals": played.own_goals}
            print(json.dumps({"imitator": imitator, "demonstrator": who, **scores}), flush=True)


if __name__ == "__main__":
    main()
