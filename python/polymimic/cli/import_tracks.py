"""`polymimic import-tracks`: a tracker log resampled into a run's demonstrations."""

from __future__ import annotations

import argparse
import pathlib
import sys
import warnings
from typing import Any

from polymimic.bodies import WheeledBody
from polymimic.cli.import_options import without_run
from polymimic.cli.run_options import existing
from polymimic.datasets import save_demonstrations
from polymimic.field import BODY_NAMES
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.config import RunConfig
from polymimic.runs.roster import CONTROLS, DEMONSTRATORS
from polymimic.runs.roster_config import ImportedDemonstrator
from polymimic.runs.rundir import MissingInputError, RunError, latest_run_path
from polymimic.tracks import LostTrackingWarning, TrackLogError, import_tracks
from polymimic.tracks.units import UNITS


def add(commands: Any) -> None:
    """The ``import-tracks`` command."""
    text = ("a tracker log (CSV or Parquet) resampled to 30 frames a second and saved as a run's demonstrations, "
            "datasets/demonstrations_<NAME>.parquet: the run's [demonstrators.<NAME>] with imported = true")
    tracks = commands.add_parser("import-tracks", help=text, description=text)
    tracks.add_argument("file", type=pathlib.Path, nargs="?",
                        help="the log: .csv or .parquet, one row per reading (default: --config's "
                             "[demonstrators.<NAME>] log)")
    tracks.add_argument("--as", dest="name", required=True, help="the demonstrator's name (letters, digits and _)")
    tracks.add_argument("--body", help=f"the demonstrator's body: {', '.join(BODY_NAMES)}, one of the run's (or "
                                       "--config's) [bodies], or a TOML file holding one [bodies.<name>] table "
                                       "(default: the body the config gives it, else lego)")
    tracks.add_argument("--config", type=pathlib.Path,
                        help="with --out: a run config whose [bodies] --body may name and whose [demonstrators.<NAME>] "
                             "log table gives the log and its options")
    for quantity, option in (("length", "--length-unit"), ("angle", "--angle-unit"), ("time", "--time-unit")):
        tracks.add_argument(option, dest=f"{quantity}_unit", choices=list(UNITS[quantity]),
                            help=f"the log's {quantity} unit (default {next(iter(UNITS[quantity]))})")
    tracks.add_argument("--rate-hz", type=float, help="the log's nominal rate, checked against its timestamps")
    tracks.add_argument("--max-gap-s", type=float, metavar="SECONDS",
                        help="the longest lapse in tracking (no reading, or NaN readings) bridged by interpolation "
                             "(default: a pause of three reading periods at most, and no NaN reading)")
    tracks.add_argument("--configuration", type=int, choices=(1, 2), help="every episode's field configuration "
                                                                          "(default: the log's, else inferred)")
    tracks.add_argument("--column", action="append", default=[], metavar="NAME=FILE_COLUMN",
                        help="the file's column for one of polymimic's (t, robot_x, ..., episode); repeatable")
    tracks.add_argument("--ignore", action="append", default=[], metavar="FILE_COLUMN",
                        help="a file column to skip; repeatable")
    tracks.add_argument("--run-dir", type=pathlib.Path, help="the run to add the demonstrations to (default: the "
                                                             "newest run under runs/)")
    tracks.add_argument("--out", type=pathlib.Path, help="write the demonstrations to this Parquet file instead")
    tracks.add_argument("--replace", action="store_true",
                        help="replace the run's demonstrations of this name, and what it made from them")
    tracks.set_defaults(handler=_import_tracks)


def _import_tracks(args: argparse.Namespace) -> int:
    if not args.name.isidentifier() or args.name in (*DEMONSTRATORS, "imitator"):
        raise RunError(f"--as {args.name!r}: a demonstrator's name is a word of letters, digits and _, not one of "
                       f"the thesis's ({', '.join(DEMONSTRATORS)})")
    columns = {}
    for item in args.column:
        name, sep, file_column = item.partition("=")
        if not sep or not name or not file_column:
            raise RunError(f"--column {item!r}: expected polymimic_name=file_column, e.g. --column t=time")
        columns[name] = file_column
    units = {q: u for q in UNITS if (u := getattr(args, f"{q}_unit")) is not None}
    given = {k: v for k, v in (("columns", columns), ("units", units), ("rate_hz", args.rate_hz),
                               ("configuration", args.configuration), ("ignore", tuple(args.ignore)),
                               ("max_gap_s", args.max_gap_s)) if v not in (None, {}, ())}
    body: str | WheeledBody
    if args.out is not None:
        out = pathlib.Path(args.out)
        if not out.parent.is_dir():
            raise RunError(f"--out {out}: directory {out.parent} does not exist")
        log, body, options = without_run(args, given)
    else:
        if args.config is not None:
            raise RunError("--config is for an import to a file (--out): a run's own config says what its "
                           "demonstrators are")
        if args.file is None:
            raise RunError("no log to import: give its FILE")
        log, options = args.file, given
        run = args.run_dir if args.run_dir is not None else latest_run_path()
        if run is None:
            raise MissingInputError("no run under runs/: name one with --run-dir, or write to a file with --out")
        if not pathlib.Path(run).is_dir():
            raise MissingInputError(f"--run-dir {run}: no such directory")
        target = existing(RunDir(run))
        config = target.open(None)
        out = target.demonstrations_path(args.name)
        body = _declared_body(config, args.name, args.body)
        if out.exists() and not args.replace:
            raise RunError(f"{out} exists: the run has {args.name}'s demonstrations already (and may have learned "
                           f"from them); import into a new run, or give --replace")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", LostTrackingWarning)  # the summary line says which were invalid
            imported = import_tracks(log, demonstrator=args.name, body=body, **options)
    except (TrackLogError, OSError, ValueError, TypeError) as error:  # the log or the options: bad input, named
        raise RunError(str(error)) from error
    if not imported.demonstrations:
        raise RunError(f"{imported.summary()}: no demonstration to write")
    out.parent.mkdir(exist_ok=True)
    if args.out is not None:
        save_demonstrations(imported.demonstrations, out)
    else:
        with target.lock(f"polymimic import-tracks --as {args.name}"):
            _replace_downstream(target, config, args.name)
            save_demonstrations(imported.demonstrations, out)
    print(f"{imported.summary()}; written to {out}")
    for line in imported.repaired():
        print(f"  {line}")
    return 0


def _replace_downstream(run: RunDir, config: RunConfig, name: str) -> None:
    """What the run made from ``name``'s earlier demonstrations: its segments, and the trials
    and evaluations of every experiment that learns from it, so that the next stages redo them."""
    run.segments_path(name).unlink(missing_ok=True)
    for experiment in config.all_experiments().values():
        if name in experiment.demonstrators:
            for made in run.experiment_dir(experiment.name).glob("*.json"):
                made.unlink()
            for control in CONTROLS:
                run.attempts_path(experiment.name, control).unlink(missing_ok=True)


def _declared_body(config: RunConfig, name: str, asked: str | None) -> str | WheeledBody:
    """The body the run's config gives demonstrator ``name`` (``[demonstrators.<name>]``), checked
    against ``--body``; without such a table, ``--body`` (a thesis body or one of the run's)."""
    spec = config.demonstrators.get(name)
    if spec is not None and not isinstance(spec, ImportedDemonstrator):
        raise RunError(f"--as {name}: the run's [demonstrators.{name}] is not imported (it says "
                       f"{type(spec).__name__}); choose another name")
    if spec is None:
        print(f"note: the run's config has no [demonstrators.{name}] with imported = true, so no experiment of the "
              f"run reads these demonstrations", file=sys.stderr)
    if spec is not None and asked is not None and asked != spec.body:
        raise RunError(f"--body {asked!r}: the run's [demonstrators.{name}] says body = {spec.body!r}")
    body = spec.body if spec is not None else (asked or "lego")
    if body not in BODY_NAMES and body not in config.bodies:
        known = dict.fromkeys([*BODY_NAMES, *config.bodies])
        raise RunError(f"--body {body!r}: one of {', '.join(known)} (the thesis's and the run's [bodies])")
    return config.bodies.get(body, body)
