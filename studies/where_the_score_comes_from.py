"""Where the improved control's score comes from, and what weighing each part by the LP does.

The imitator's improved control learns four things from the demonstrations it watches: the
ball's response to each primitive (physics), where pushes toward the goal begin (the push
region), which states lead to goals or own goals (the states' values) and which behaviours to
chain (the imitator's forward model). Each row replaces some of them by what the imitator's own
self-observation alone would give it (no ball, no goal: the ball predicted to stay, no region to
route to, every state worth 0, its primitives unchained) and plays the benchmark's evaluation
attempts after the run's first trials; the weighting rows keep every part and change which parts
the LP weighs (``world_weighting``), or hold every LP at 0.5 (the uniform-LP trials).

Reads a ``polymimic benchmark`` run whose learn stage has finished for the profiles asked (its
recogniser, crowds and trials), and writes ``where_the_score_comes_from.json`` and ``.md`` beside
this file::

    polymimic benchmark --profiles one_good half_poor --methods polymimic polymimic_uniform_lp
    python studies/where_the_score_comes_from.py RUN_DIR --profiles one_good half_poor --trials 5
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import pathlib
from typing import Any

from polymimic import _native
from polymimic._native import PrimitiveRecognizer
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.datasets import load_demonstrations
from polymimic.learning import TrialResult, evaluate, segmented
from polymimic.runs.stats import mean_sd, msd

HERE = pathlib.Path(__file__).with_suffix("")

PARTS = ("ball_response", "push_region", "state_value", "behaviours")
ABLATIONS: dict[str, tuple[str, ...]] = {
    "every part from the demonstrations": (),
    "ball's response from self-observation": ("ball_response",),
    "push region from self-observation": ("push_region",),
    "states' values from self-observation": ("state_value",),
    "behaviours from self-observation": ("behaviours",),
    "intent (region, values, behaviours) from self-observation": ("push_region", "state_value", "behaviours"),
    "everything from self-observation": PARTS,
}
"""Each row: the parts learned from no demonstration."""

WEIGHTINGS = ("outcome", "intent", "every")


def _policy(trial: TrialResult, batch: Any, recognizer: PrimitiveRecognizer, config: Any, *,
            world_weighting: str, unlearned: tuple[str, ...] = (), uniform: bool = False) -> Any:
    learning = config.learning.replace(world_weighting=world_weighting)
    if uniform:
        learning = learning.replace(hold_lp=True)
    return _native.ImitatorPolicy(trial, recognizer=recognizer, config=learning, control="improved",
                                  demonstrations=batch, body=config.imitator_body(), unlearned=list(unlearned))


def _net(policy: Any, config: Any) -> int:
    played = evaluate(policy, attempts_per_configuration=config.benchmark.sizes.attempts_per_configuration,
                      seed=config.seeds.evaluation, field_config=config.field)
    return played.goals - played.own_goals


def measure(run: BenchmarkDir, profile: str, trials: int, world_weighting: str) -> dict[str, Any]:
    """Every row's net goals after each of the first ``trials`` trials of ``profile``."""
    config = run.open(None)
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "benchmark"))
    demos = load_demonstrations(run.require(run.crowd_path(profile), "benchmark"))
    batch = segmented(demos, recognizer, **dataclasses.asdict(config.segmenter))
    seeds = config.trial_seeds()[:trials]
    rows: dict[str, list[int]] = {name: [] for name in ABLATIONS}
    rows.update({f"world_weighting = {w}": [] for w in WEIGHTINGS})
    rows["every LP held at 0.5 (polymimic_uniform_lp)"] = []
    for seed in seeds:
        trial = TrialResult.load(run.require(run.trial_path(profile, seed), "benchmark"))
        for name, parts in ABLATIONS.items():
            policy = _policy(trial, batch, recognizer, config, world_weighting=world_weighting, unlearned=parts)
            rows[name].append(_net(policy, config))
        for weighting in WEIGHTINGS:
            policy = _policy(trial, batch, recognizer, config, world_weighting=weighting)
            rows[f"world_weighting = {weighting}"].append(_net(policy, config))
        held = TrialResult.load(run.require(run.trial_path(profile, seed, uniform_lp=True), "benchmark"))
        policy = _policy(held, batch, recognizer, config, world_weighting=world_weighting, uniform=True)
        rows["every LP held at 0.5 (polymimic_uniform_lp)"].append(_net(policy, config))
    return {"trial_seeds": seeds, "attempts": 2 * config.benchmark.sizes.attempts_per_configuration,
            "evaluation_seed": config.seeds.evaluation, "world_weighting": world_weighting,
            "net_goals": {name: {"per_trial": values, **mean_sd(values)} for name, values in rows.items()}}


def markdown(results: dict[str, Any]) -> str:
    profiles = list(results["profiles"])
    first = results["profiles"][profiles[0]]
    lines = ["# Where the improved control's score comes from", "",
             f"Net goals of {first['attempts']} on the benchmark's evaluation attempts (seed "
             f"{first['evaluation_seed']}), mean (sd) over the first {len(first['trial_seeds'])} trials; the "
             f"ablation rows weigh as `world_weighting = {first['world_weighting']}`.", "",
             "| imitator | " + " | ".join(f"`{p}`" for p in profiles) + " |",
             "| --- | " + " | ".join("---" for _ in profiles) + " |"]
    for row in first["net_goals"]:
        cells = [msd(results["profiles"][p]["net_goals"][row]) for p in profiles]
        lines.append(f"| {row} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a `polymimic benchmark` run whose learn stage has finished")
    parser.add_argument("--profiles", nargs="+", default=["one_good", "half_poor"])
    parser.add_argument("--trials", type=int, default=5, help="the run's first trials to play after")
    parser.add_argument("--world-weighting", default="outcome", choices=WEIGHTINGS,
                        help="how the ablation rows weigh")
    parser.add_argument("--out", default=str(HERE), help="output path without suffix")
    args = parser.parse_args()
    run = BenchmarkDir(args.run_dir)
    results = {"profiles": {p: measure(run, p, args.trials, args.world_weighting) for p in args.profiles}}
    out = pathlib.Path(args.out)
    out.with_suffix(".json").write_text(json.dumps(results, indent=1) + "\n", encoding="utf-8")
    out.with_suffix(".md").write_text(markdown(results), encoding="utf-8")
    print(markdown(results))


if __name__ == "__main__":
    main()
