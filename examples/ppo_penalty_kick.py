"""Reinforcement learning on the penalty kick: PPO (stable-baselines3) learns ``PenaltyKick-v0``
from its reward alone, and plays the imitator's evaluation attempts as it learns.

PPO is polymimic's ``ppo`` baseline (:func:`polymimic.baselines.ppo.fit`: two environments, one
per field configuration, one step = one primitive held for 30 tracker frames, reward +1 for a
goal and −1 for an own goal). At the start, at every checkpoint and at the end, the current
policy plays deterministically the attempts :func:`polymimic.evaluate` gives the imitator
(:func:`polymimic.baselines.evaluate_policy`: the same starts and noise at every checkpoint, so
the curve shows learning and not luck of the draw). PPO updates its policy once every
``n_steps × 2`` environment steps (4096 by default), so a checkpoint falls on the first update at
or past each multiple of ``--eval-every``; the files record the steps the policy had learned from.

Written to ``--out`` after every checkpoint (an interrupted run keeps its curve so far):

- ``curve.csv`` and ``curve.json``: env steps, goals, own goals, net goals, attempts, wall time;
- ``curve.png``: goals, own goals and net goals against environment steps;
- at the end, ``ppo.pmp`` (the final policy, for :func:`polymimic.baselines.load_policy`) and
  ``play.png`` (one of its evaluation attempts, a goal from configuration 2 if it scored one).

Run: ``pip install "polymimic[rl]"``, then
``python examples/ppo_penalty_kick.py [--timesteps N] [--eval-every N] [--attempts N] [--out DIR]``
(the default 200 000 steps take a few minutes on one core).
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import pathlib
import tempfile
from collections.abc import Sequence
from typing import Any

from polymimic import Attempts
from polymimic.baselines import ppo
from polymimic.baselines.ppo import Checkpoint
from polymimic.plots import plot_demonstration, save_figure
from polymimic.runs.config import SeedSettings

FEATURE_SET = "goal_relative"
FRAMES_PER_ACTION = 30
"""One step is one primitive held for a second, as the imitator executes them."""

COLUMNS = ("env_steps", "goals", "own_goals", "net_goals", "attempts", "wall_s")


def require_rl() -> None:
    """Stop with the install line when stable-baselines3 (and so torch) is missing."""
    if not ppo.available():
        raise SystemExit("this example needs stable-baselines3 and torch: pip install \"polymimic[rl]\"")


def write_curve(curve: Sequence[Checkpoint], folder: pathlib.Path, settings: dict[str, Any]) -> None:
    """``curve.csv``, ``curve.json`` and ``curve.png`` for the checkpoints so far."""
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(c.to_dict() for c in curve)
    (folder / "curve.csv").write_text(text.getvalue())
    (folder / "curve.json").write_text(json.dumps({"settings": settings, "checkpoints": [c.to_dict() for c in curve]},
                                                  indent=2) + "\n")
    plot_curve(curve, folder / "curve.png", attempts=curve[-1].attempts, seed=settings["seed"])


def plot_curve(curve: Sequence[Checkpoint], path: pathlib.Path, *, attempts: int, seed: int) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.ticker import StrMethodFormatter

    figure = Figure(figsize=(7.0, 4.2), layout="constrained")
    FigureCanvasAgg(figure)
    ax = figure.add_subplot()
    steps = [c.env_steps for c in curve]
    ax.plot(steps, [c.goals for c in curve], marker="o", markersize=3, label="goals")
    ax.plot(steps, [c.own_goals for c in curve], marker="o", markersize=3, color="tab:red", label="own goals")
    ax.plot(steps, [c.net_goals for c in curve], linestyle="--", color="0.3", label="net goals")
    ax.set_ylim(min(0, *(c.net_goals for c in curve)) - 1, attempts + 1)
    ax.xaxis.set_major_formatter(StrMethodFormatter("{x:,.0f}"))
    ax.set_xlabel("environment steps (one primitive each)")
    ax.set_ylabel(f"out of {attempts} attempts")
    ax.set_title(f"PPO on PenaltyKick-v0 (training seed {seed}), the imitator's evaluation attempts",
                 fontsize="medium")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize="small")
    save_figure(figure, path, dpi=110)


def main(argv: Sequence[str] | None = None) -> dict[str, Any]:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--timesteps", type=int, default=200_000, help="environment steps to learn from")
    parser.add_argument("--seed", type=int, default=0, help="PPO's and the training environments' seed")
    parser.add_argument("--eval-every", type=int, default=20_000, help="environment steps between checkpoints")
    parser.add_argument("--attempts", type=int, default=25,
                        help="evaluation attempts per field configuration (two configurations)")
    parser.add_argument("--eval-seed", type=int, default=SeedSettings().evaluation,
                        help="seed of the evaluation attempts (default: the imitator's, as polymimic reproduce)")
    parser.add_argument("--threads", type=int, default=1, help="torch threads")
    parser.add_argument("--out", type=pathlib.Path, default=None, help="folder for the curve, plot and policy")
    args = parser.parse_args(argv)
    for name in ("timesteps", "eval_every", "attempts", "threads"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')} must be at least 1")
    require_rl()
    import torch

    torch.set_num_threads(args.threads)
    folder = args.out or pathlib.Path(tempfile.mkdtemp(prefix="polymimic-ppo-"))
    folder.mkdir(parents=True, exist_ok=True)
    settings = {"timesteps": args.timesteps, "seed": args.seed, "eval_every": args.eval_every,
                "attempts_per_configuration": args.attempts, "eval_seed": args.eval_seed,
                "feature_set": FEATURE_SET, "frames_per_action": FRAMES_PER_ACTION, "torch_threads": args.threads}

    def report(curve: list[Checkpoint]) -> None:
        c = curve[-1]
        print(f"{c.env_steps:>9,} env steps: {c.goals:>2} goals, {c.own_goals:>2} own goals, net {c.net_goals:>3} "
              f"of {c.attempts} attempts ({c.wall_s:.0f} s)", flush=True)
        write_curve(curve, folder, settings)

    print(f"PPO on PenaltyKick-v0 for {args.timesteps:,} env steps, checkpoints every {args.eval_every:,}, "
          f"{2 * args.attempts} evaluation attempts (seed {args.eval_seed})", flush=True)
    policy, curve, final = ppo.learning_curve(total_timesteps=args.timesteps, eval_every=args.eval_every,
                                              evaluation=Attempts(per_configuration=args.attempts,
                                                                  seed=args.eval_seed), seed=args.seed,
                                              frames_per_action=FRAMES_PER_ACTION, feature_set=FEATURE_SET,
                                              on_checkpoint=report)
    policy.save(folder / "ppo.pmp")
    # A goal from configuration 2 if there is one: there the robot starts between the ball and the
    # target goal and has to come round behind the ball.
    goals = sorted((a for a in final.attempts if a.outcome == "goal"), key=lambda a: -a.configuration)
    shown = goals[0] if goals else final.attempts[0]
    plot_demonstration(shown, path=folder / "play.png")
    print(f"written to {folder}: curve.csv, curve.json, curve.png, ppo.pmp, play.png")
    result: dict[str, Any] = json.loads((folder / "curve.json").read_text())
    return result


if __name__ == "__main__":
    main()
