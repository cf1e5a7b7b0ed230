"""What the commands share: the run options, the config asked for, and the run named."""

from __future__ import annotations

import argparse
import os
import pathlib
from typing import TYPE_CHECKING, Protocol, TypeVar

from polymimic.benchmark.config import BenchmarkConfig
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.backends import BACKENDS
from polymimic.runs.config import RunConfig
from polymimic.runs.rundir import MissingInputError, latest_run_path, new_run_path

if TYPE_CHECKING:
    from typing_extensions import Self


def positive(text: str) -> int:
    """``text`` as an integer of at least 1, for argparse."""
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {value}")
    return value


def run_options(*, tasks: bool) -> argparse.ArgumentParser:
    """The options every run command shares (``--run-dir``, ``--config``, ``--quiet``, and with
    ``tasks`` the workers and backend).
    """
    options = argparse.ArgumentParser(add_help=False)
    options.add_argument("--run-dir", type=pathlib.Path,
                         help="the run directory (default: a new runs/<timestamp> for self-observe and reproduce, "
                              "else the newest run under runs/)")
    options.add_argument("--config", type=pathlib.Path, help="a TOML file of parameters to change (see `polymimic "
                                                             "config`); a new run only")
    options.add_argument("--quick", action="store_true",
                         help="fewer trials, demonstrations and self-observation: seconds end to end")
    options.add_argument("--quiet", action="store_true", help="no progress bars or stage messages")
    if tasks:
        options.add_argument("--workers", type=positive, help="processes (or Ray CPUs) for trials and evaluations "
                                                               "(default: one per core)")
        options.add_argument("--backend", choices=BACKENDS, default="local",
                             help="local process pool (default) or Ray")
        options.add_argument("--address", help="a Ray cluster to join (e.g. ray://host:10001 or auto)")
    return options


class AskableConfig(Protocol):
    """A run's config as the command line asks for one: the defaults, ``quick()``, or a file
    read over either."""

    def __init__(self) -> None: ...

    @classmethod
    def quick(cls) -> Self:
        """The quick config: seconds end to end."""

    @classmethod
    def load(cls, path: str | os.PathLike[str], *, base: Self | None = None) -> Self:
        """A config from a TOML file, laid over ``base``."""


Asked = TypeVar("Asked", bound=AskableConfig)


def asked_config(args: argparse.Namespace, kind: type[Asked]) -> Asked | None:
    """The ``kind`` config ``--config`` and ``--quick`` ask for, or None when neither was given."""
    if args.config is None and not args.quick:
        return None
    base = kind.quick() if args.quick else kind()
    return kind.load(args.config, base=base) if args.config is not None else base


def requested_config(args: argparse.Namespace) -> RunConfig | None:
    """The reproduction's config asked for on the command line, or None when none was."""
    return asked_config(args, RunConfig)


def run_path(args: argparse.Namespace, *, new: bool) -> pathlib.Path:
    """The run directory: ``--run-dir``, else a new ``runs/<timestamp>`` (``new``), else the
    newest run under ``runs/``.
    """
    if args.run_dir is not None:
        return pathlib.Path(args.run_dir)
    if new:
        return new_run_path()
    latest = latest_run_path()
    if latest is None:
        raise MissingInputError("no run under runs/: start one with `polymimic reproduce` or `polymimic "
                                "self-observe`, or name one with --run-dir")
    return latest


def existing(run: RunDir) -> RunDir:
    """``run``, refused with a hint where it is not a run directory."""
    if not run.manifest_path.exists():
        raise MissingInputError(f"{run.path} is not a run directory (no manifest.json): start it with "
                                f"`polymimic self-observe --run-dir {run.path}` or `polymimic reproduce`")
    return run


def benchmark_config(args: argparse.Namespace) -> BenchmarkConfig | None:
    """The benchmark's config asked for on the command line, or None when none was."""
    return asked_config(args, BenchmarkConfig)
