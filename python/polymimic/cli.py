"""The `polymimic` command: the demo, and the thesis reproduced stage by stage or end to end.

`polymimic reproduce` runs every stage into a run directory (runs/<timestamp> unless --run-dir
is given) and writes report.html beside results.json; `polymimic config` prints every parameter.
`polymimic benchmark` compares polymimic with the baselines on crowds of demonstrators and
writes benchmark.html beside benchmark.json (runs/benchmark/<timestamp> unless --run-dir).
`polymimic import-tracks` turns a tracker log into a run's demonstrations.
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import json
import pathlib
import sys
import time
import warnings
from typing import Any

from polymimic import __version__, demo
from polymimic._native import PolymimicError
from polymimic.benchmark.config import METHODS, BenchmarkConfig
from polymimic.benchmark.export import export_crowds
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.bodies import WheeledBody
from polymimic.datasets import load_demonstrations, save_demonstrations
from polymimic.export import ACTIONS, LABELS
from polymimic.field import BODY_NAMES
from polymimic.plots import animate_demonstration
from polymimic.reproduce.backends import TaskRunner
from polymimic.reproduce.config import ConfigError, RunConfig
from polymimic.reproduce.export import export_run
from polymimic.reproduce.roster import CONTROLS, DEMONSTRATORS, EXPERIMENTS
from polymimic.reproduce.roster_config import ImportedDemonstrator
from polymimic.reproduce.rundir import MissingInputError, RunDir, RunError, latest_run_path, new_run_path
from polymimic.reproduce.stages import Context, reproduce, run_stage
from polymimic.tracks import LostTrackingWarning, TrackLogError, import_tracks
from polymimic.tracks.units import UNITS

EXIT_USAGE = 2
"""Bad input: a missing stage input, a bad config, an unreadable file (as argparse's own errors)."""
EXIT_INTERRUPTED = 130

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


def _demo(args: argparse.Namespace) -> int:
    print(demo.report(demo.run(n_train=args.train, n_test=args.test, codebook_size=args.codebook_size,
                               n_states=args.states, seed=args.seed)))
    return 0


def _positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {value}")
    return value


def _run_options(*, tasks: bool) -> argparse.ArgumentParser:
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
        options.add_argument("--workers", type=_positive, help="processes (or Ray CPUs) for trials and evaluations "
                                                               "(default: one per core)")
        options.add_argument("--backend", choices=("local", "ray"), default="local",
                             help="local process pool (default) or Ray")
        options.add_argument("--address", help="a Ray cluster to join (e.g. ray://host:10001 or auto)")
    return options


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="polymimic", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"polymimic {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)
    demo = commands.add_parser("demo", help="train an HMM bank on synthetic motion primitives and recognise them")
    demo.add_argument("--train", type=int, default=200, help="training sequences per primitive")
    demo.add_argument("--test", type=int, default=100, help="held-out sequences per primitive")
    demo.add_argument("--codebook-size", type=int, default=64)
    demo.add_argument("--states", type=int, default=3)
    demo.add_argument("--seed", type=int, default=0)
    demo.set_defaults(handler=_demo)

    config = commands.add_parser("config", parents=[_run_options(tasks=False)],
                                 help="print every parameter as TOML: the thesis's, --quick's, a file's or a run's")
    config.set_defaults(handler=_config)
    for stage, text in _STAGE_HELP.items():
        sub = commands.add_parser(stage, parents=[_run_options(tasks=True)], help=text, description=text)
        if stage in ("learn", "evaluate"):
            sub.add_argument("--experiment", action="append", metavar="NAME",
                             help=f"only this experiment (repeatable; default: all): {', '.join(EXPERIMENTS)} or "
                                  "one of the run config's [experiments.<name>]")
        if stage == "learn":
            sub.add_argument("--limit", type=_positive, help="run at most this many new trials per experiment")
        sub.set_defaults(handler=_stage, stage=stage)

    replay = commands.add_parser("replay", parents=[_run_options(tasks=False)],
                                 help="an episode as an animated GIF: a demonstration, or an imitator's attempt")
    replay.add_argument("who", help=f"{', '.join(DEMONSTRATORS)}, one of the run config's [demonstrators], or "
                                    "imitator")
    replay.add_argument("--episode", type=int, default=0, help="which episode, from 0 (default 0)")
    replay.add_argument("--experiment", default="varying_skill",
                        help="whose imitator, for `imitator` (its first evaluated one)")
    replay.add_argument("--control", choices=CONTROLS, default="improved", help="for `imitator`")
    replay.add_argument("--out", type=pathlib.Path, help="the GIF (default: plots/replay_<who>_<episode>.gif)")
    replay.add_argument("--fps", type=_positive, default=10)
    replay.add_argument("--stride", type=_positive, default=3,
                        help="every stride-th tracker frame (3 at 10 fps: real time)")
    replay.set_defaults(handler=_replay)

    exporting = commands.add_parser("export", parents=[_run_options(tasks=False)],
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

    text = ("polymimic against behavioural cloning, cloning from observation and the rest on crowds of "
            "demonstrators of graded skill and mixed bodies; resumable (starts a run)")
    benchmark = commands.add_parser("benchmark", parents=[_run_options(tasks=True)], help=text, description=text)
    benchmark.add_argument("--profiles", nargs="+", metavar="PROFILE",
                           help="only these crowds (built in: one_good half equal linear mixed_bodies; more in "
                                "--config's [profiles.<name>])")
    benchmark.add_argument("--methods", nargs="+", metavar="METHOD",
                           help=f"only these methods (of {' '.join(METHODS)})")
    benchmark.set_defaults(handler=_benchmark)
    _add_import_tracks(commands)
    return parser


def _add_import_tracks(commands: Any) -> None:
    text = ("a tracker log (CSV or Parquet) resampled to 30 frames a second and saved as a run's demonstrations, "
            "datasets/demonstrations_<NAME>.parquet: the run's [demonstrators.<NAME>] with imported = true")
    tracks = commands.add_parser("import-tracks", help=text, description=text)
    tracks.add_argument("file", type=pathlib.Path, help="the log: .csv or .parquet, one row per reading")
    tracks.add_argument("--as", dest="name", required=True, help="the demonstrator's name (letters, digits and _)")
    tracks.add_argument("--body", help=f"the demonstrator's body: {', '.join(BODY_NAMES)} or one of the run's "
                                       "[bodies] (default: the body the run's config gives it, else lego)")
    for quantity, option in (("length", "--length-unit"), ("angle", "--angle-unit"), ("time", "--time-unit")):
        tracks.add_argument(option, dest=f"{quantity}_unit", choices=list(UNITS[quantity]),
                            help=f"the log's {quantity} unit (default {next(iter(UNITS[quantity]))})")
    tracks.add_argument("--rate-hz", type=float, help="the log's nominal rate, checked against its timestamps")
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


def _requested_config(args: argparse.Namespace) -> Any:
    """The config asked for on the command line, or None when none was."""

    if args.config is None and not args.quick:
        return None
    base = RunConfig.quick() if args.quick else RunConfig()
    return RunConfig.load(args.config, base=base) if args.config is not None else base


def _run_path(args: argparse.Namespace, *, new: bool) -> pathlib.Path:
    if args.run_dir is not None:
        return pathlib.Path(args.run_dir)
    if new:
        return new_run_path()
    latest = latest_run_path()
    if latest is None:
        raise MissingInputError("no run under runs/: start one with `polymimic reproduce` or `polymimic "
                                "self-observe`, or name one with --run-dir")
    return latest


def _existing(run: RunDir) -> RunDir:
    """``run``, refused with a hint where it is not a run directory."""
    if not run.manifest_path.exists():
        raise MissingInputError(f"{run.path} is not a run directory (no manifest.json): start it with "
                                f"`polymimic self-observe --run-dir {run.path}` or `polymimic reproduce`")
    return run


def _config(args: argparse.Namespace) -> int:
    if args.run_dir is not None and (args.run_dir / "manifest.json").exists():
        config = RunDir(args.run_dir).open(_requested_config(args))
    else:
        config = _requested_config(args) or RunConfig()
    sys.stdout.write(config.to_toml())
    return 0


def _stage(args: argparse.Namespace) -> int:
    new = args.stage in _STARTS_A_RUN
    run = RunDir(_run_path(args, new=new))
    if not new:
        _existing(run)
    requested = _requested_config(args)  # read before the run directory is touched
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


def _replay(args: argparse.Namespace) -> int:
    run = _existing(RunDir(_run_path(args, new=False)))
    config = run.open(_requested_config(args))
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
    episodes = load_demonstrations(source)
    if not 0 <= args.episode < len(episodes):
        raise RunError(f"{source} holds episodes 0 to {len(episodes) - 1}; there is no episode {args.episode}")
    out = args.out or run.plots / f"replay_{args.who}_{args.episode}.gif"
    out.parent.mkdir(parents=True, exist_ok=True)
    animate_demonstration(episodes[args.episode], out, fps=args.fps, stride=args.stride)
    print(out)
    return 0


def _export(args: argparse.Namespace) -> int:
    path = _run_path(args, new=False)
    minari_info = {"actions": args.actions, "labels": args.labels, "overwrite": args.overwrite, "author": args.author,
                   "author_email": args.author_email, "code_permalink": args.code_permalink}
    try:
        if _is_benchmark(path):
            bench = BenchmarkDir(path)
            exported = export_crowds(bench, bench.open(_benchmark_config(args)),
                                     prefix=args.prefix or "polymimic/benchmark", **minari_info)
            for profile, names in exported.left_out.items():
                print(f"{profile}: left out {', '.join(names)} (PenaltyKick-v0 simulates the Lego robot only)",
                      file=sys.stderr)
            written = exported.dataset_ids
        else:
            run = _existing(RunDir(path))
            written = export_run(run, run.open(_requested_config(args)), prefix=args.prefix or "polymimic/run",
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


def _benchmark_config(args: argparse.Namespace) -> BenchmarkConfig | None:
    """The benchmark config ``--config`` and ``--quick`` ask for, or None when neither was given."""
    if args.config is None and not args.quick:
        return None
    base = BenchmarkConfig.quick() if args.quick else BenchmarkConfig()
    return BenchmarkConfig.load(args.config, base=base) if args.config is not None else base


def _requested_benchmark(args: argparse.Namespace) -> BenchmarkConfig | None:
    """The benchmark config asked for on the command line, or None when none was."""
    config = _benchmark_config(args)
    if args.profiles is None and args.methods is None:
        return config
    config = config or BenchmarkConfig()
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
    body: str | WheeledBody = args.body or "lego"
    if args.out is not None:
        if body not in BODY_NAMES:
            raise RunError(f"--body {body!r}: without a run, one of {', '.join(BODY_NAMES)}")
        out = pathlib.Path(args.out)
        if not out.parent.is_dir():
            raise RunError(f"--out {out}: directory {out.parent} does not exist")
    else:
        run = args.run_dir if args.run_dir is not None else latest_run_path()
        if run is None:
            raise MissingInputError("no run under runs/: name one with --run-dir, or write to a file with --out")
        if not pathlib.Path(run).is_dir():
            raise MissingInputError(f"--run-dir {run}: no such directory")
        target = _existing(RunDir(run))
        config = target.open(None)
        out = target.demonstrations_path(args.name)
        body = _declared_body(config, args.name, args.body)
        if out.exists() and not args.replace:
            raise RunError(f"{out} exists: the run has {args.name}'s demonstrations already (and may have learned "
                           f"from them); import into a new run, or give --replace")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", LostTrackingWarning)  # the summary line says which were invalid
            imported = import_tracks(args.file, demonstrator=args.name, columns=columns, units=units,
                                     rate_hz=args.rate_hz, body=body, configuration=args.configuration,
                                     ignore=args.ignore)
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


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if getattr(args, "address", None) is not None and args.backend != "ray":
        parser.error("--address is for the Ray backend: add --backend ray")
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
