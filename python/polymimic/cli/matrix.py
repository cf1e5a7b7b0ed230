"""`polymimic matrix`: every imitator body against every set of demonstrators."""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import pathlib
import sys
from typing import Any

from polymimic.cli.run_options import asked_config, run_options
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError
from polymimic.runs.rundir import new_run_path


def add(commands: Any) -> None:
    """The ``matrix`` command."""
    text = ("who learns what from whom: imitator bodies (rows) learning from sets of demonstrators (columns), "
            "polymimic and bco in every cell, with transfer ratios; resumable (starts a run)")
    matrix = commands.add_parser("matrix", parents=[run_options(tasks=True)], help=text, description=text)
    matrix.add_argument("--imitators", nargs="+", metavar="BODY",
                        help="only these rows (built in: lego tiny humanoid wagon; more in --config's "
                             "[bodies.<name>])")
    matrix.add_argument("--columns", nargs="+", metavar="COLUMN",
                        help="only these columns (built in: expert tiny humanoid own_body mixed_bodies; more in "
                             "--config's [demonstrators.<name>])")
    matrix.set_defaults(handler=_matrix)


def _matrix(args: argparse.Namespace) -> int:
    # bco needs the optional scikit-learn: the rest of the command must not.
    if importlib.util.find_spec("sklearn") is None:
        raise ConfigError("polymimic matrix compares with bco, which needs scikit-learn: "
                          "pip install \"polymimic[baselines]\"")
    from polymimic.matrix.config import MatrixConfig
    from polymimic.matrix.driver import run_matrix
    from polymimic.matrix.rundir import MatrixDir

    run = MatrixDir(args.run_dir if args.run_dir is not None else new_run_path(pathlib.Path("runs") / "matrix"))
    requested = asked_config(args, MatrixConfig)  # read before the run directory is touched
    if args.imitators is not None:
        requested = requested or MatrixConfig()
        requested = dataclasses.replace(requested, matrix=dataclasses.replace(requested.matrix,
                                                                              imitators=tuple(args.imitators)))
    if args.columns is not None:
        requested = _only_columns(requested or MatrixConfig(), args.columns)
    with TaskRunner(backend=args.backend, workers=args.workers, address=args.address) as runner:
        with run.lock("polymimic matrix"):
            config = run.open(requested)
        seconds = run_matrix(run, config, runner, quiet=args.quiet)
        if not args.quiet:
            print(f"matrix in {seconds:.1f} s", file=sys.stderr)
    print(run.report_html_path)
    return 0


def _only_columns(config: Any, columns: list[str]) -> Any:
    """``config`` (a MatrixConfig) with only ``columns``: built-in ones and its demonstrators'."""
    from polymimic.matrix.config import COLUMNS

    own = config.run.demonstrators
    unknown = [c for c in columns if c not in COLUMNS and c not in own]
    if unknown or len(set(columns)) != len(columns):
        raise ConfigError(f"--columns {' '.join(columns)}: each once, one of {', '.join(COLUMNS)}"
                          + (f" or of --config's [demonstrators] ({', '.join(own)})" if own else
                             " (a --config's [demonstrators.<name>] adds more)"))
    return dataclasses.replace(config, matrix=dataclasses.replace(config.matrix, columns=tuple(
        c for c in columns if c in COLUMNS)), run=dataclasses.replace(config.run, demonstrators={
            c: own[c] for c in columns if c in own}))
