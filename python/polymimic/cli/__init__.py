"""The `polymimic` command: the demo, and the thesis reproduced stage by stage or end to end.

`polymimic reproduce` runs every stage into a run directory (runs/<timestamp> unless --run-dir
is given) and writes report.html beside results.json; `polymimic config` prints every parameter.
`polymimic benchmark` compares polymimic with the baselines on crowds of demonstrators and
writes benchmark.html beside benchmark.json (runs/benchmark/<timestamp> unless --run-dir).
`polymimic matrix` shows who learns what from whom: imitator bodies against sets of demonstrators
(runs/matrix/<timestamp> unless --run-dir). `polymimic practice` lets a finished run's imitators
keep learning by playing, and writes their curves beside its results. `polymimic import-tracks`
turns a tracker log into a run's demonstrations. `polymimic live` lets a saved imitator drive a
robot from a live tracker stream.
"""

from __future__ import annotations

import argparse
import functools
import sys
import time
from typing import NoReturn

from polymimic import __version__
from polymimic._native import PolymimicError
from polymimic.benchmark.practice_source import PRACTICE_SOURCE as BENCHMARK_PRACTICE
from polymimic.cli import benchmark, demo, export, import_tracks, live, matrix, practice, replay, stages
from polymimic.reproduce.practice_source import PRACTICE_SOURCE as REPRODUCTION_PRACTICE
from polymimic.runs.config import ConfigError

__all__ = ["EXIT_INTERRUPTED", "EXIT_USAGE", "build_parser", "main"]

EXIT_USAGE = 2
"""Bad input: a missing stage input, a bad config, an unreadable file (as argparse's own errors)."""
EXIT_INTERRUPTED = 130


class _OneLineParser(argparse.ArgumentParser):
    """argparse's parser, answering bad arguments with one line and exit code 2 (its usage is a
    ``--help`` away); the subcommands' parsers are of the same class."""

    def error(self, message: str) -> NoReturn:
        self.exit(EXIT_USAGE, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    """The ``polymimic`` command's argument parser, one subcommand per module of :mod:`polymimic.cli`."""
    parser = _OneLineParser(prog="polymimic", description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"polymimic {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)
    practice_on_runs = functools.partial(practice.add, sources=(REPRODUCTION_PRACTICE, BENCHMARK_PRACTICE))
    for add in (demo.add, stages.add, replay.add, export.add, benchmark.add, matrix.add, practice_on_runs,
                import_tracks.add, live.add):
        add(commands)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Runs the ``polymimic`` command with ``argv`` (the process's arguments by default); returns
    the exit code (2 for a missing input or a refused config, naming it).
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    if getattr(args, "address", None) is not None and args.backend != "ray":
        print(f"polymimic {args.command}: error: --address is for the Ray backend: add --backend ray", file=sys.stderr)
        return EXIT_USAGE
    started = time.perf_counter()
    try:
        return int(args.handler(args))
    except (PolymimicError, ConfigError) as error:  # bad input: files, configs, runs; a bug still raises
        one_line = "; ".join(line.strip() for line in str(error).splitlines() if line.strip())
        print(f"polymimic {args.command}: error: {one_line}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print(f"\npolymimic {args.command}: interrupted after {time.perf_counter() - started:.0f} s; run the same "
              "command again to go on where it stopped", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
