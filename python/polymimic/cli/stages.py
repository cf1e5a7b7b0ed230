"""`polymimic config` and the reproduction's stages, one command each (`reproduce` runs them all)."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from polymimic.cli.run_options import existing, positive, requested_config, run_options, run_path
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.stages import Context, reproduce, run_stage
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import RunConfig
from polymimic.runs.roster import EXPERIMENTS

_STAGE_HELP = {
    "self-observe": "record the imitator's own primitives, to learn from and to test on (starts a run)",
    "record": "record every demonstrator's attempts from both field configurations",
    "train": "train the primitive recogniser (codebooks and HMMs) on self-observation",
    "segment": "cut every demonstration into named segments (records the Average demonstrator first)",
    "learn": "run the experiments' learning trials; finished trials are kept, so a rerun resumes",
    "evaluate": "drive the robot with the trained imitators and count their goals",
    "report": "write results.json, plots/, report.md and report.html",
    "reproduce": "every stage in turn: the thesis end to end (starts a run)",
}
_STARTS_A_RUN = ("self-observe", "reproduce")


def add(commands: Any) -> None:
    """``config`` and a command for every stage."""
    config = commands.add_parser("config", parents=[run_options(tasks=False)],
                                 help="print every parameter as TOML: the thesis's, --quick's, a file's or a run's")
    config.set_defaults(handler=_config)
    for stage, text in _STAGE_HELP.items():
        sub = commands.add_parser(stage, parents=[run_options(tasks=True)], help=text, description=text)
        if stage in ("learn", "evaluate"):
            sub.add_argument("--experiment", action="append", metavar="NAME",
                             help=f"only this experiment (repeatable; default: all): {', '.join(EXPERIMENTS)} or "
                                  "one of the run config's [experiments.<name>]")
        if stage == "learn":
            sub.add_argument("--limit", type=positive, help="run at most this many new trials per experiment")
        sub.set_defaults(handler=_stage, stage=stage)


def _config(args: argparse.Namespace) -> int:
    if args.run_dir is not None and (args.run_dir / "manifest.json").exists():
        config = RunDir(args.run_dir).open(requested_config(args))
    else:
        config = requested_config(args) or RunConfig()
    sys.stdout.write(config.to_toml())
    return 0


def _stage(args: argparse.Namespace) -> int:
    new = args.stage in _STARTS_A_RUN
    run = RunDir(run_path(args, new=new))
    if not new:
        existing(run)
    requested = requested_config(args)  # read before the run directory is touched
    with run.lock(f"polymimic {args.stage}"):
        return _run_stages(run, run.open(requested), args)


def _run_stages(run: RunDir, config: RunConfig, args: argparse.Namespace) -> int:
    with TaskRunner(backend=args.backend, workers=args.workers, address=args.address) as runner:
        ctx = Context(run=run, config=config, runner=runner, quiet=args.quiet)
        ctx.say(f"run directory: {run.path}")
        if args.stage == "reproduce":
            seconds = reproduce(ctx)
            ctx.say(f"reproduced in {seconds:.1f} s")
        else:
            options = {}
            if args.stage in ("learn", "evaluate"):
                options["experiments"] = args.experiment
            if args.stage == "learn":
                options["limit"] = args.limit
            run_stage(ctx, args.stage, **options)
    if args.stage in ("report", "reproduce"):
        print(run.report_html_path)
    return 0
