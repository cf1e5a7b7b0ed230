"""`polymimic practice`: a finished run's imitators keep learning by playing (docs/guides/practice.md).

On a benchmark run, polymimic's imitator of each profile; on a reproduction, the improved
imitator of each experiment: those of the first ``--trials`` trials practise for ``--steps``
environment steps each and are scored on the run's evaluation attempts at every checkpoint. The
curves are written beside the run's results, under ``practice/<steps>_steps_<method>/``.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys
from collections.abc import Sequence
from typing import Any

from polymimic.cli.run_options import positive
from polymimic.practice.methods import DEFAULT_METHOD, METHODS, needs_rl_extra
from polymimic.runs.backends import BACKENDS, TaskRunner
from polymimic.runs.config import ConfigError
from polymimic.runs.practising import PracticeSource, practise_run


def add(commands: Any, *, sources: Sequence[PracticeSource]) -> None:
    """The ``practice`` command, on the kinds of run ``sources`` name."""
    text = ("a finished reproduce or benchmark run's imitators practise on the field and are scored at every "
            "checkpoint; the curves go beside the run's results (resumable)")
    practice = commands.add_parser("practice", help=text, description=text)
    practice.add_argument("--run-dir", type=pathlib.Path, required=True,
                          help="a finished `polymimic reproduce` or `polymimic benchmark` run directory")
    practice.add_argument("--steps", type=positive, default=25_000,
                          help="environment steps (seconds of play) each imitator practises for (default 25000)")
    practice.add_argument("--method", choices=METHODS, default=DEFAULT_METHOD,
                          help="distil: distil the imitator into an RL actor and fine-tune it, the actor replacing "
                               "it only once a check shows it no worse (default; needs polymimic[rl]); jsrl: guide "
                               "an RL learner (needs polymimic[rl]); explore: play exploring around the ball, learn "
                               "its physics (needs neither)")
    practice.add_argument("--trials", type=positive, default=5,
                          help="how many trials' imitators practise, the first ones (default 5)")
    practice.add_argument("--only", nargs="+", metavar="NAME",
                          help="only these profiles (benchmark) or experiments (reproduction)")
    practice.add_argument("--quiet", action="store_true", help="no progress bars")
    practice.add_argument("--workers", type=positive, help="processes (or Ray CPUs) (default: one per core)")
    practice.add_argument("--backend", choices=BACKENDS, default="local", help="local process pool (default) or Ray")
    practice.add_argument("--address", help="a Ray cluster to join (e.g. ray://host:10001 or auto)")
    practice.set_defaults(handler=lambda args: _practice(args, sources))


def _source(path: pathlib.Path, sources: Sequence[PracticeSource]) -> PracticeSource:
    """The kind of run at ``path``, from its manifest."""
    try:
        manifest = json.loads((path / "manifest.json").read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ConfigError(f"{path} holds no manifest.json: not a run directory") from None
    except (OSError, ValueError) as error:
        raise ConfigError(f"{path}/manifest.json cannot be read ({error})") from None
    found = manifest.get("format") if isinstance(manifest, dict) else None
    kinds = {source.manifest_format: source for source in sources}
    if found not in kinds:
        raise ConfigError(f"{path} is a {found or 'run of no known format'}; practice needs a "
                          f"{' or '.join(source.command for source in sources)} run")
    return kinds[found]


def _practice(args: argparse.Namespace, sources: Sequence[PracticeSource]) -> int:
    source = _source(args.run_dir, sources)
    try:
        needs_rl_extra(args.method)
    except ModuleNotFoundError as error:
        raise ConfigError(f"--method {args.method}: {error}") from None
    ready = source.practice(args.run_dir, args.only, args.steps, args.method)
    run, seeds = ready.run, ready.trial_seeds
    if args.trials > len(seeds):
        raise ConfigError(f"--trials {args.trials}: the run has {len(seeds)} trials per {source.group}")
    seeds = seeds[:args.trials]

    def trial_json(group: str, seed: int) -> str:
        path = run.require(ready.trial_path(group, seed), "learn")
        return str(path.read_text(encoding="utf-8"))

    folder = run.path / "practice" / f"{args.steps}_steps_{args.method}"
    with run.lock("polymimic practice"), TaskRunner(backend=args.backend, workers=args.workers,
                                                    address=args.address) as runner:
        summary, ran = practise_run(run, folder, ready.inputs, [(g, s) for g in ready.groups for s in seeds],
                                    trial_json, runner, kind=source.kind, quiet=args.quiet)
    if not args.quiet:
        print(f"practised {ran} imitators", file=sys.stderr)
    print(summary)
    return 0
