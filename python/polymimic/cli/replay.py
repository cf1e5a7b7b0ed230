"""`polymimic replay`: an episode of a run as an animated GIF."""

from __future__ import annotations

import argparse
import pathlib
from typing import Any

from polymimic.cli.run_options import existing, positive, requested_config, run_options, run_path
from polymimic.datasets import load_demonstrations
from polymimic.plots import animate_demonstration
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.config import ConfigError
from polymimic.runs.roster import CONTROLS, DEMONSTRATORS
from polymimic.runs.rundir import RunError


def add(commands: Any) -> None:
    """The ``replay`` command."""
    replay = commands.add_parser("replay", parents=[run_options(tasks=False)],
                                 help="an episode as an animated GIF: a demonstration, or an imitator's attempt")
    replay.add_argument("who", help=f"{', '.join(DEMONSTRATORS)}, one of the run config's [demonstrators], or "
                                    "imitator")
    replay.add_argument("--episode", type=int, default=0, help="which episode, from 0 (default 0)")
    replay.add_argument("--experiment", default="varying_skill",
                        help="whose imitator, for `imitator` (its first evaluated one)")
    replay.add_argument("--control", choices=CONTROLS, default="improved", help="for `imitator`")
    replay.add_argument("--out", type=pathlib.Path, help="the GIF (default: plots/replay_<who>_<episode>.gif)")
    replay.add_argument("--fps", type=positive, default=10)
    replay.add_argument("--stride", type=positive, default=3,
                        help="every stride-th tracker frame (3 at 10 fps: real time)")
    replay.set_defaults(handler=_replay)


def _replay(args: argparse.Namespace) -> int:
    run = existing(RunDir(run_path(args, new=False)))
    config = run.open(requested_config(args))
    known = [*DEMONSTRATORS, *config.demonstrators, "imitator"]
    if args.who not in known:
        raise ConfigError(f"unknown demonstrator {args.who!r}; expected one of {', '.join(known)}")
    if args.experiment not in config.all_experiments():
        raise ConfigError(f"unknown experiment {args.experiment!r}; expected one of "
                          f"{', '.join(config.all_experiments())}")
    if args.who == "imitator":
        source = run.require(run.attempts_path(args.experiment, args.control), "evaluate")
    else:
        source = run.require(run.demonstrations_path(args.who), "record" if args.who != "average" else "segment")
    episodes = load_demonstrations(source, bodies=config.bodies)
    if not 0 <= args.episode < len(episodes):
        raise RunError(f"{source} holds episodes 0 to {len(episodes) - 1}; there is no episode {args.episode}")
    out = args.out or run.plots / f"replay_{args.who}_{args.episode}.gif"
    out.parent.mkdir(parents=True, exist_ok=True)
    animate_demonstration(episodes[args.episode], out, fps=args.fps, stride=args.stride)
    print(out)
    return 0
