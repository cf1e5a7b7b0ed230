"""Practice through the teacher beside ``ppo`` and ``ppo_bc``, at equal environment steps.

On a finished benchmark run, for each of ``--profiles`` (default ``one_good`` and ``half``) and
each of ``--seeds`` RL seeds: trial 0's ``polymimic`` imitator practises (``--practice``, by
default ``distil``; the seed its RL seed and its practice attempts), PPO learns from scratch and
``ppo_bc`` from the crowd's demonstrations cloned (its tuned pretraining, the benchmark's
choice), each for ``--steps`` environment steps, all scored on the run's evaluation attempts at
the same checkpoints. Each finished (method, profile, seed) curve is written at once to its own
file in ``--out`` (a directory), so that a rerun skips what is there and goes on with the rest,
and two processes (one per profile) can share the directory. ``--summary FILE`` gathers every
curve into one JSON file and ``--plot PNG`` draws them (mean over seeds) as one picture.

Run: ``python benches/practice_vs_ppo.py RUN_DIR [--steps 500000] [--seeds 0 1 2] [--out DIR]
[--summary JSON] [--plot PNG]`` (needs ``polymimic[rl]``; about 35 minutes of one core per
profile and seed at full size).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import pathlib
import time
from typing import Any

from polymimic._atomic import atomic_write_text
from polymimic._native import PrimitiveRecognizer, TrialResult
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.datasets import load_demonstrations
from polymimic.learning import ImitatorPolicy, segmented

CHECKPOINTS = (0, 10_000, 25_000, 50_000, 100_000, 150_000, 250_000, 350_000, 500_000)


def curve_of(method: str, run: BenchmarkDir, config: Any, profile: str, seed: int, steps: int) -> list[list[float]]:
    """``[checkpoint, steps played, net goals]`` at each checkpoint up to ``steps``."""
    marks = [c for c in CHECKPOINTS if c <= steps] + ([steps] if steps not in CHECKPOINTS else [])
    demos = load_demonstrations(run.crowd_path(profile))
    if method in ("jsrl", "distil"):
        from polymimic.practice.distil import distil
        from polymimic.practice.teacher import jsrl

        recognizer = PrimitiveRecognizer.load(run.recognizer_path)
        batch = segmented(demos, recognizer, **dataclasses.asdict(config.segmenter))
        trial = TrialResult.from_json(run.trial_path(profile, 0).read_text())
        teacher = ImitatorPolicy(trial, recognizer=recognizer, config=config.learning, control="improved",
                                 demonstrations=batch, body=config.imitator_body())
        practise = jsrl if method == "jsrl" else distil
        result = practise(teacher, steps=steps, seed=seed, checkpoints=marks, evaluation=config.evaluation_attempts(),
                          field_config=config.field)
        return [[p.checkpoint, p.steps, p.net_goals] for p in result.curve]
    from polymimic.baselines import ppo, ppo_bc

    if method == "ppo":
        _, points, _ = ppo.learning_curve(total_timesteps=steps, eval_every=marks[1] if len(marks) > 1 else steps,
                                          evaluation=config.evaluation_attempts(), seed=seed,
                                          field_config=config.field)
    else:
        choice = ppo_bc.tune_pretraining(demos, validation_seed=0, evaluation=config.evaluation_attempts())
        _, points, _ = ppo_bc.learning_curve(demos, choice.chosen, total_timesteps=steps,
                                             eval_every=marks[1] if len(marks) > 1 else steps,
                                             evaluation=config.evaluation_attempts(), seed=seed,
                                             field_config=config.field)
    return [[p.env_steps, p.env_steps, p.net_goals] for p in points]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a finished `polymimic benchmark` run directory")
    parser.add_argument("--profiles", nargs="+", default=["one_good", "half"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2])
    parser.add_argument("--methods", nargs="+", default=["distil", "ppo_bc", "ppo"],
                        choices=["distil", "jsrl", "ppo_bc", "ppo"])
    parser.add_argument("--steps", type=int, default=500_000)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("practice_vs_ppo"))
    parser.add_argument("--summary", type=pathlib.Path, help="every curve in --out, gathered into one JSON file")
    parser.add_argument("--plot", type=pathlib.Path)
    parser.add_argument("--gather", action="store_true",
                        help="only gather the curves already in --out into --summary and --plot; run nothing")
    options = parser.parse_args()
    os.environ.setdefault("OMP_NUM_THREADS", "1")  # torch on a small machine: one thread learns fastest
    run = BenchmarkDir(options.run_dir)
    config = run.open(None)
    options.out.mkdir(parents=True, exist_ok=True)
    for profile in [] if options.gather else options.profiles:
        for seed in options.seeds:
            for method in options.methods:
                key = f"{method}/{profile}/{seed}/{options.steps}"
                path = options.out / (key.replace("/", "_") + ".json")
                if path.exists():
                    json.loads(path.read_text())  # a damaged file is an error, not a result
                    continue
                shared = _ppo_of_another_profile(options.out, method, seed, options.steps)
                started = time.perf_counter()
                curve = shared["curve"] if shared else curve_of(method, run, config, profile, seed, options.steps)
                finished = {"key": key, "curve": curve, "seconds": round(time.perf_counter() - started, 1)}
                if shared:  # ppo learns no crowd: one run per seed serves every profile, bit for bit
                    finished.update(seconds=shared["seconds"], shared_with=shared["key"])
                atomic_write_text(path, json.dumps(finished) + "\n")
                print(f"{key}: {curve[-1][2]:+.0f} net goals at {curve[-1][1]} steps "
                      f"({finished['seconds']:.0f} s)", flush=True)
    done = {v["key"]: {k: w for k, w in v.items() if k != "key"}
            for v in (json.loads(p.read_text()) for p in sorted(options.out.glob("*.json")))}
    if options.summary is not None:
        atomic_write_text(options.summary, json.dumps(done, indent=1) + "\n")
    if options.plot is not None:
        plot(done, options)


def _ppo_of_another_profile(out: pathlib.Path, method: str, seed: int, steps: int) -> dict[str, Any] | None:
    """A finished ``ppo`` curve of the same seed and budget on another profile (``ppo`` reads no
    crowd, so its run is the same on every profile), else None."""
    if method != "ppo":
        return None
    for path in sorted(out.glob(f"ppo_*_{seed}_{steps}.json")):
        found: dict[str, Any] = json.loads(path.read_text())
        if found["key"].startswith("ppo/") and "shared_with" not in found:
            return found
    return None


def plot(done: dict[str, Any], options: argparse.Namespace) -> None:
    """Mean net goals over seeds against environment steps, a panel per profile."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    figure, axes = plt.subplots(1, len(options.profiles), figsize=(5 * len(options.profiles), 3.6), squeeze=False)
    for ax, profile in zip(axes[0], options.profiles):
        for method in options.methods:
            curves = [done[k]["curve"] for k in done if k.startswith(f"{method}/{profile}/")]
            if not curves:
                continue
            steps = np.array([p[1] for p in curves[0]])
            mean = np.mean([[p[2] for p in c][: len(steps)] for c in curves], axis=0)
            ax.plot(steps, mean, marker="o", markersize=3, label=f"{method} ({len(curves)} seeds)")
        ax.set_title(profile)
        ax.set_xlabel("environment steps")
        ax.set_ylabel("net goals of 50")
        ax.legend()
    figure.tight_layout()
    figure.savefig(options.plot, dpi=120)


if __name__ == "__main__":
    main()
