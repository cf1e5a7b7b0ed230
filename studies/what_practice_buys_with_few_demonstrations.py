"""Practice where demonstrations are few: imitators of one demonstrator's ``--n`` demonstrations
per field configuration (three trials), each practising for ``--steps`` environment steps and
scored on 50 evaluation attempts at every default checkpoint.

Prints one line per trial: the demonstrator, n, the trial's seed and its curve
``[(checkpoint, net goals), …]``. Run:
``python studies/what_practice_buys_with_few_demonstrations.py [--who expert] [--n 10] [--steps 10000]``.
"""

import argparse

import polymimic
from polymimic import learning, recognition
from polymimic.practice import practice


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--who", default="expert")
    parser.add_argument("--n", type=int, default=10)
    parser.add_argument("--steps", type=int, default=10_000)
    parser.add_argument("--trials", type=int, default=3)
    options = parser.parse_args()
    recognizer = recognition.train_recognizer(polymimic.self_observation(200, seed=1), codebook_size=64)
    demos = [d for c in (1, 2) for d in polymimic.record(options.who, configuration=c, n=options.n, seed=0)]
    batch = learning.segmented(demos, recognizer)
    for trial_seed in range(options.trials):
        trial = learning.run_trial(batch, recognizer=recognizer, ordering=[options.who], seed=trial_seed)
        policy = learning.ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=batch)
        # replaying its own play, refining the ball's response and the states' values: what this study measured
        result = practice(policy, steps=options.steps, seed=trial_seed, evaluation=polymimic.Attempts(),
                          explore=0.0, refines=None)
        print(options.who, options.n, trial_seed, [(p.checkpoint, p.net_goals) for p in result.curve], flush=True)


if __name__ == "__main__":
    main()
