"""`polymimic benchmark`: polymimic against the baselines on crowds of demonstrators."""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import pathlib
from typing import Any

from polymimic.benchmark.config import METHODS, OPTIONAL_METHODS, BenchmarkConfig
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.cli.run_options import benchmark_config, run_options
from polymimic.crowds import PROFILES
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError
from polymimic.runs.rundir import new_run_path


def add(commands: Any) -> None:
    """The ``benchmark`` command."""
    text = ("polymimic against behavioural cloning, cloning from observation and the rest on crowds of "
            "demonstrators of graded skill and mixed bodies; resumable (starts a run)")
    benchmark = commands.add_parser("benchmark", parents=[run_options(tasks=True)], help=text, description=text)
    benchmark.add_argument("--profiles", nargs="+", metavar="PROFILE",
                           help=f"only these crowds (built in: {' '.join(PROFILES)}; more in --config's "
                                "[profiles.<name>])")
    benchmark.add_argument("--methods", nargs="+", metavar="METHOD",
                           help=f"only these methods (of {' '.join(METHODS)}; or named, {' '.join(OPTIONAL_METHODS)})")
    benchmark.add_argument("--imitator", metavar="BODY",
                           help="the imitator's body: lego (the default), tiny, humanoid, or a [bodies.<name>] of "
                                "--config")
    benchmark.set_defaults(handler=_benchmark)


def _requested_benchmark(args: argparse.Namespace) -> BenchmarkConfig | None:
    """The benchmark config asked for on the command line, or None when none was."""
    config = benchmark_config(args)
    if args.profiles is None and args.methods is None and args.imitator is None:
        return config
    config = config or BenchmarkConfig()
    if args.imitator is not None:
        config = dataclasses.replace(config, run=dataclasses.replace(
            config.run, imitator=dataclasses.replace(config.run.imitator, body=args.imitator)))
    settings = config.benchmark
    if args.profiles is not None:
        settings = dataclasses.replace(settings, profiles=tuple(args.profiles))
    if args.methods is not None:
        settings = dataclasses.replace(settings, methods=tuple(args.methods))
    return dataclasses.replace(config, benchmark=settings)


def _benchmark(args: argparse.Namespace) -> int:
    # The baselines need the optional scikit-learn: the rest of the command must not.
    if importlib.util.find_spec("sklearn") is None:
        raise ConfigError("polymimic benchmark compares with baselines that need scikit-learn: "
                          "pip install \"polymimic[baselines]\"")
    from polymimic.benchmark.driver import Benchmark

    run = BenchmarkDir(args.run_dir if args.run_dir is not None else new_run_path(pathlib.Path("runs") / "benchmark"))
    requested = _requested_benchmark(args)  # read before the run directory is touched
    if requested is not None:
        Benchmark.check_extras(requested)
    with run.lock("polymimic benchmark"), TaskRunner(backend=args.backend, workers=args.workers,
                                                     address=args.address) as runner:
        bench = Benchmark(run=run, config=run.open(requested), runner=runner, quiet=args.quiet)
        bench.say(f"run directory: {run.path}")
        seconds = bench.run_all()
        bench.say(f"benchmarked in {seconds:.1f} s")
    print(run.report_html_path)
    return 0
