"""`polymimic export`: a run's demonstrations, or a benchmark's crowds, as Minari datasets."""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
from typing import Any

from polymimic.benchmark.export import export_crowds
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.cli.run_options import benchmark_config, existing, requested_config, run_options, run_path
from polymimic.export import ACTIONS, LABELS
from polymimic.reproduce.export import export_run
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.config import ConfigError
from polymimic.runs.rundir import RunError


def add(commands: Any) -> None:
    """The ``export`` command."""
    exporting = commands.add_parser("export", parents=[run_options(tasks=False)],
                                    help="write a run's demonstrations (or a benchmark's crowds) as Minari datasets of "
                                         "PenaltyKick-v0 episodes")
    exporting.add_argument("--prefix",
                           help="dataset ids are <prefix>-<demonstrator>-v0 for a run (default polymimic/run), "
                                "<prefix>-<profile>-v0 for a benchmark (default polymimic/benchmark)")
    exporting.add_argument("--actions", choices=ACTIONS, default="recognizer",
                           help="the recogniser's reading (learned from observation, default) or the commands sent")
    exporting.add_argument("--labels", choices=LABELS, default="steps",
                           help="how the recogniser names a step: the second of motion from it (default) or the "
                                "segments its frames lie in")
    exporting.add_argument("--overwrite", action="store_true", help="replace datasets of the same ids")
    exporting.add_argument("--author", help="the datasets' author (Minari asks for one)")
    exporting.add_argument("--author-email")
    exporting.add_argument("--code-permalink")
    exporting.set_defaults(handler=_export)


def _export(args: argparse.Namespace) -> int:
    path = run_path(args, new=False)
    minari_info = {"actions": args.actions, "labels": args.labels, "overwrite": args.overwrite, "author": args.author,
                   "author_email": args.author_email, "code_permalink": args.code_permalink}
    try:
        if _is_benchmark(path):
            bench = BenchmarkDir(path)
            exported = export_crowds(bench, bench.open(benchmark_config(args)),
                                     prefix=args.prefix or "polymimic/benchmark", **minari_info)
            for profile, names in exported.left_out.items():
                print(f"{profile}: left out {', '.join(names)} (PenaltyKick-v0 simulates the Lego robot only)",
                      file=sys.stderr)
            written = exported.dataset_ids
        else:
            run = existing(RunDir(path))
            written = export_run(run, run.open(requested_config(args)), prefix=args.prefix or "polymimic/run",
                                 **minari_info)
    except ValueError as error:  # an existing dataset id, or a bad prefix: bad input, named
        raise RunError(str(error)) from error
    except ModuleNotFoundError as error:  # Minari is an optional extra: the error says how to install it
        if error.name != "minari":
            raise
        raise ConfigError(str(error)) from error
    print("\n".join(written))
    return 0


def _is_benchmark(path: pathlib.Path) -> bool:
    """Whether ``path`` holds a benchmark's manifest (anything else is read as a run's, which
    names what is wrong with it)."""
    try:
        manifest = json.loads((path / "manifest.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(manifest, dict) and manifest.get("format") == BenchmarkDir.manifest_format
