"""`polymimic practice`: a finished run's imitators keep learning by playing (docs/guides/practice.md).

On a benchmark run, polymimic's imitator of each profile; on a reproduction, the improved
imitator of each experiment: those of the first ``--trials`` trials practise for ``--steps``
environment steps each and are scored on the run's evaluation attempts at every checkpoint. The
curves are written beside the run's results, under ``practice/<steps>_steps/``.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import pathlib
import sys
from typing import Any

from polymimic._native import PrimitiveRecognizer
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.cli.run_options import positive
from polymimic.learning import segmented
from polymimic.practice.methods import METHODS
from polymimic.reproduce.rundir import RunDir
from polymimic.runs.backends import BACKENDS, TaskRunner
from polymimic.runs.config import ConfigError
from polymimic.runs.practising import PracticeInputs, practise_run


def add(commands: Any) -> None:
    """The ``practice`` command."""
    text = ("a finished reproduce or benchmark run's imitators practise on the field and are scored at every "
            "checkpoint; the curves go beside the run's results (resumable)")
    practice = commands.add_parser("practice", help=text, description=text)
    practice.add_argument("--run-dir", type=pathlib.Path, required=True,
                          help="a finished `polymimic reproduce` or `polymimic benchmark` run directory")
    practice.add_argument("--steps", type=positive, default=25_000,
                          help="environment steps (seconds of play) each imitator practises for (default 25000)")
    practice.add_argument("--method", choices=METHODS, default="refine",
                          help="refine: replay its own play, refine its world model (default); explore: play "
                               "exploring around the ball, learn its physics; jsrl: guide an RL learner (needs "
                               "polymimic[rl])")
    practice.add_argument("--trials", type=positive, default=5,
                          help="how many trials' imitators practise, the first ones (default 5)")
    practice.add_argument("--only", nargs="+", metavar="NAME",
                          help="only these profiles (benchmark) or experiments (reproduction)")
    practice.add_argument("--quiet", action="store_true", help="no progress bars")
    practice.add_argument("--workers", type=positive, help="processes (or Ray CPUs) (default: one per core)")
    practice.add_argument("--backend", choices=BACKENDS, default="local", help="local process pool (default) or Ray")
    practice.add_argument("--address", help="a Ray cluster to join (e.g. ray://host:10001 or auto)")
    practice.set_defaults(handler=_practice)


def _kind(path: pathlib.Path) -> str:
    """``"benchmark"`` or ``"reproduction"``, from the run's manifest."""
    try:
        manifest = json.loads((path / "manifest.json").read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ConfigError(f"{path} holds no manifest.json: not a run directory") from None
    except (OSError, ValueError) as error:
        raise ConfigError(f"{path}/manifest.json cannot be read ({error})") from None
    found = manifest.get("format") if isinstance(manifest, dict) else None
    kinds = {BenchmarkDir.manifest_format: "benchmark", RunDir.manifest_format: "reproduction"}
    if found not in kinds:
        raise ConfigError(f"{path} is a {found or 'run of no known format'}; practice needs a reproduce or benchmark "
                          f"run")
    return kinds[found]


def _chosen(names: list[str], only: list[str] | None, what: str) -> list[str]:
    if only is None:
        return names
    unknown = [n for n in only if n not in names]
    if unknown:
        raise ConfigError(f"--only: the run has no {what} {unknown[0]!r}; it has {', '.join(names)}")
    return [n for n in names if n in only]


def _benchmark_inputs(path: pathlib.Path, args: argparse.Namespace) -> tuple[Any, PracticeInputs, list[str], list[int]]:
    from polymimic.datasets import load_demonstrations

    run = BenchmarkDir(path)
    config = run.open(None)
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "benchmark"))
    segmenter = dataclasses.asdict(config.segmenter)
    groups = _chosen(list(config.benchmark.profiles), args.only, "profile")
    demos = {g: segmented(load_demonstrations(run.require(run.crowd_path(g), "benchmark")), recognizer, **segmenter)
             for g in groups}
    inputs = PracticeInputs(recognizer=recognizer, learning=config.learning, demonstrations=demos,
                            body=config.imitator_body(), field=config.field, segmenter=segmenter, steps=args.steps,
                            evaluation_seed=config.seeds.evaluation,
                            attempts_per_configuration=config.benchmark.attempts_per_configuration,
                            method=args.method)
    return run, inputs, groups, config.trial_seeds()


def _reproduction_inputs(path: pathlib.Path,
                         args: argparse.Namespace) -> tuple[Any, PracticeInputs, list[str], list[int]]:
    from polymimic.reproduce.experiments import experiment_items, trial_seeds

    run = RunDir(path)
    config = run.open(None)
    recognizer = PrimitiveRecognizer.load(run.require(run.recognizer_path, "train"))
    experiments = config.all_experiments()
    groups = _chosen(list(experiments), args.only, "experiment")
    inputs = PracticeInputs(recognizer=recognizer, learning=config.learning,
                            demonstrations={g: experiment_items(run, experiments[g]) for g in groups},
                            body=config.imitator_body(), field=config.field,
                            segmenter=dataclasses.asdict(config.segmenter), steps=args.steps,
                            evaluation_seed=config.seeds.evaluation,
                            attempts_per_configuration=config.experiments.attempts_per_configuration,
                            method=args.method)
    return run, inputs, groups, trial_seeds(config)


def _practice(args: argparse.Namespace) -> int:
    kind = _kind(args.run_dir)
    make = _benchmark_inputs if kind == "benchmark" else _reproduction_inputs
    run, inputs, groups, seeds = make(args.run_dir, args)
    if args.trials > len(seeds):
        raise ConfigError(f"--trials {args.trials}: the run has {len(seeds)} trials per "
                          f"{'profile' if kind == 'benchmark' else 'experiment'}")
    seeds = seeds[:args.trials]

    def trial_json(group: str, seed: int) -> str:
        path = run.require(run.trial_path(group, seed), "learn")
        return str(path.read_text(encoding="utf-8"))

    folder = run.path / "practice" / (f"{args.steps}_steps" + ("" if args.method == "refine" else f"_{args.method}"))
    with run.lock("polymimic practice"), TaskRunner(backend=args.backend, workers=args.workers,
                                                    address=args.address) as runner:
        summary, ran = practise_run(run, folder, inputs, [(g, s) for g in groups for s in seeds], trial_json, runner,
                                    kind=kind, quiet=args.quiet)
    if not args.quiet:
        print(f"practised {ran} imitators", file=sys.stderr)
    print(summary)
    return 0
