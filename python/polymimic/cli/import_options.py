"""What `polymimic import-tracks` imports without a run: the log, its body and its options, from
the command line, a body file (``--body FILE.toml``) or a run config's log demonstrator
(``--config``), the three agreeing."""

from __future__ import annotations

import argparse
import os
import pathlib
from typing import Any

from polymimic._toml import loads
from polymimic.bodies import WheeledBody, bodies_from_tables
from polymimic.field import BODY_NAMES
from polymimic.runs.config import RunConfig
from polymimic.runs.roster_config import LogDemonstrator
from polymimic.runs.rundir import RunError

__all__ = ["body_file", "without_run"]


def body_file(path: str) -> WheeledBody:
    """The one ``[bodies.<name>]`` table of the TOML file at ``path``, as a body."""
    try:
        text = pathlib.Path(path).read_text(encoding="utf-8")
    except OSError as error:
        raise RunError(f"--body {path}: cannot read it ({error.strerror})") from error
    try:
        tables = loads(text).get("bodies")
        bodies = bodies_from_tables(tables if tables is not None else {})
    except ValueError as error:
        raise RunError(f"--body {path}: {error}") from error
    if len(bodies) != 1:
        held = f"{len(bodies)} ({', '.join(bodies)})" if bodies else "no [bodies.<name>] table"
        raise RunError(f"--body {path}: a body file holds one [bodies.<name>] table, this one {held}; with several, "
                       "give the file as --config and the body's name as --body")
    return next(iter(bodies.values()))


def _body(asked: str, config: RunConfig | None) -> str | WheeledBody:
    """``--body`` as the library takes it: a file's body, a built-in's name, or one of --config's."""
    if asked.endswith(".toml"):
        return body_file(asked)
    if asked in BODY_NAMES:
        return asked
    if config is not None and asked in config.bodies:
        return config.bodies[asked]
    own = [n for n in (config.bodies if config is not None else ()) if n not in BODY_NAMES]
    raise RunError(f"--body {asked!r}: one of {', '.join(BODY_NAMES)}"
                   + (f", of --config's [bodies] ({', '.join(own)})" if own else "")
                   + ", or a TOML file holding a [bodies.<name>] table (FILE.toml)")


def without_run(args: argparse.Namespace, given: dict[str, Any]) -> tuple[pathlib.Path, str | WheeledBody,
                                                                        dict[str, Any]]:
    """The log, the body and :func:`polymimic.import_tracks`'s options for an import to ``--out``:
    the command line's (``given``, the options it set), over ``--config``'s
    ``[demonstrators.<--as>]`` log table if it has one; a value both give must agree."""
    config = RunConfig.load(args.config) if args.config is not None else None
    spec = config.demonstrators.get(args.name) if config is not None else None
    where = f"--config's [demonstrators.{args.name}]"
    if spec is not None and not isinstance(spec, LogDemonstrator):
        raise RunError(f"--as {args.name}: {where} is not a tracker log (it is {type(spec).__name__}); name a "
                       "log demonstrator of the config, or leave --config out")
    table = {k: v for k, v in (spec.import_options() if spec is not None else {}).items() if v not in (None, ())}
    if spec is not None and spec.line_tolerance_mm == LogDemonstrator.line_tolerance_mm:
        del table["line_tolerance_mm"]  # the default: the command line has no option for it
    for key, value in given.items():
        if key in table and table[key] != value:
            raise RunError(f"--{key.replace('_', '-')} {value!r}: {where} says {key} = {table[key]!r}; give it in one "
                           "place")
    log = args.file if args.file is not None else (pathlib.Path(spec.log) if spec is not None else None)
    if log is None:
        raise RunError("no log to import: give its FILE, or --config with a [demonstrators.<name>] log = \"FILE\" "
                       "table for --as <name>")
    if spec is not None and os.path.abspath(log) != os.path.abspath(spec.log):
        raise RunError(f"{log}: {where} says log = {spec.log!r}; give it in one place")
    if spec is not None and args.body is not None and not _same_body(_body(args.body, config), spec.body, config):
        raise RunError(f"--body {args.body}: {where} says body = {spec.body!r}")
    body: str | WheeledBody
    if spec is not None:
        body = config.bodies.get(spec.body, spec.body) if config is not None else spec.body
    else:
        body = _body(args.body, config) if args.body is not None else "lego"
    return log, body, {**table, **given}


def _same_body(asked: str | WheeledBody, named: str, config: RunConfig | None) -> bool:
    """Whether ``--body`` is the body the config's table names (by name, and a file's by its constants)."""
    if (asked.name if isinstance(asked, WheeledBody) else asked) != named:
        return False
    return not isinstance(asked, WheeledBody) or config is None or config.bodies.get(named) in (None, asked)
