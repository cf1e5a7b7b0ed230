"""The roster a run config adds to the thesis's (docs/guides/own-data.md): bodies, demonstrators and
experiments of your own, as TOML tables, recorded, segmented, learned from, evaluated and
reported like the thesis's.

::

    [bodies.rover]                 # a wheeled body (see polymimic.bodies.WheeledBody)
    length_mm = 180
    width_mm = 170
    wheel_base_mm = 150
    top_wheel_speed_mm_s = 140

    [demonstrators.poor_rover]     # a built-in controller, on any body it can drive
    controller = "poor"
    body = "rover"
    lapse = 0.1

    [demonstrators.chaser]         # a Python policy: "module:name" or "file.py:name" (a class is
    policy = "my_policies.py:Chaser"   # made once per recording; a file is found beside the config)
    body = "rover"
    decision_hz = 5

    [demonstrators.logged]         # a tracker log, with any option of polymimic.import_tracks
    log = "logs/overhead.csv"
    body = "lego"
    rate_hz = 15
    units = { length = "m", angle = "deg" }
    columns = { t = "time" }
    max_gap_s = 0.35
    ignore = ["camera"]

    [demonstrators.alice]          # what `polymimic import-tracks FILE --as alice` put in the run
    imported = true

    [experiments.mine]             # an experiment: whose demonstrations, in which phase-one order
    demonstrators = ["expert", "chaser", "logged"]
    ordering = ["chaser", "logged", "expert"]   # default: as listed
    phase_one = "by-model"                      # or "interleaved"
    skill_order = ["expert", "chaser", "logged"]  # optional: most skilled first

>>> from polymimic._toml import loads
>>> tables = loads('[demonstrators.slow_poor]\\ncontroller = "poor"\\nlapse = 0.3\\n')["demonstrators"]
>>> demonstrators_from_tables(tables, bodies={}, base_dir=".")["slow_poor"]
ControllerDemonstrator(name='slow_poor', controller='poor', body='lego', lapse=0.3)
"""

from __future__ import annotations

import dataclasses
import hashlib
import importlib
import importlib.util
import os
import pathlib
import sys
from collections.abc import Mapping, Sequence
from typing import Any, Union

from polymimic import field, tracks
from polymimic.bodies import THESIS_BODY_FIELDS, BodySpec, WheeledBody, bodies_from_tables
from polymimic.policies import DECISION_RATES_HZ
from polymimic.runs.log_table import check_log_table
from polymimic.runs.roster import DEMONSTRATORS, EXPERIMENTS, Experiment
from polymimic.tracks.outcomes import LINE_TOLERANCE_MM

__all__ = ["ControllerDemonstrator", "DemonstratorSpec", "ImportedDemonstrator", "LogDemonstrator",
           "PolicyDemonstrator", "RosterError", "demonstrators_from_tables", "experiments_from_tables", "read_bodies",
           "demonstrations_expected", "file_digest", "record_demonstrator", "source_file", "spec_table"]


class RosterError(ValueError):
    """A body, demonstrator or experiment table that cannot be used."""


@dataclasses.dataclass(frozen=True)
class ControllerDemonstrator:
    """A built-in controller (``expert``, ``poor``, ``tiny``, ``humanoid``) on a body, lapsing at ε."""

    name: str
    controller: str
    body: str
    lapse: float = 0.0


@dataclasses.dataclass(frozen=True)
class PolicyDemonstrator:
    """A Python policy, found by ``module:name`` or ``file.py:name``."""

    name: str
    policy: str
    body: str
    decision_hz: int | None = None


@dataclasses.dataclass(frozen=True)
class LogDemonstrator:
    """A tracker log's valid episodes, imported with :func:`polymimic.import_tracks`'s options
    (``log`` is its ``path``; :data:`polymimic.runs.log_table.LOG_OPTIONS`)."""

    name: str
    log: str
    body: str
    rate_hz: float | None = None
    units: Mapping[str, str] = dataclasses.field(default_factory=dict)
    columns: Mapping[str, str] = dataclasses.field(default_factory=dict)
    configuration: int | None = None
    ignore: tuple[str, ...] = ()
    line_tolerance_mm: float = LINE_TOLERANCE_MM
    max_gap_s: float | None = None

    def import_options(self) -> dict[str, Any]:
        """The keywords of :func:`polymimic.import_tracks` this table gives (``body`` aside)."""
        return {"rate_hz": self.rate_hz, "units": dict(self.units) or None, "columns": dict(self.columns) or None,
                "configuration": self.configuration, "ignore": self.ignore,
                "line_tolerance_mm": self.line_tolerance_mm, "max_gap_s": self.max_gap_s}


@dataclasses.dataclass(frozen=True)
class ImportedDemonstrator:
    """Demonstrations brought into the run with ``polymimic import-tracks FILE --as <name>``
    (``imported = true``): the record stage finds them in the run's datasets."""

    name: str
    imported: bool
    body: str


DemonstratorSpec = Union[ControllerDemonstrator, PolicyDemonstrator, LogDemonstrator, ImportedDemonstrator]

_KINDS: dict[str, type[ControllerDemonstrator] | type[PolicyDemonstrator] | type[LogDemonstrator]
             | type[ImportedDemonstrator]] = {
    "controller": ControllerDemonstrator, "policy": PolicyDemonstrator, "log": LogDemonstrator,
    "imported": ImportedDemonstrator}


def demonstrators_from_tables(tables: Mapping[str, Any], *, bodies: Mapping[str, WheeledBody],
                              base_dir: str | os.PathLike[str]) -> dict[str, DemonstratorSpec]:
    """Every ``[demonstrators.<name>]`` table: exactly one of ``controller``, ``policy`` or
    ``log`` says what it is; ``body`` names a thesis body or one of ``bodies`` (default
    ``lego``). A log's path is taken relative to ``base_dir`` (the config's folder)."""
    if not isinstance(tables, Mapping):
        raise RosterError(f"[demonstrators] must hold one table per demonstrator, got {tables!r}")
    return {name: _demonstrator(name, table, bodies, pathlib.Path(base_dir)) for name, table in tables.items()}


def _demonstrator(name: str, table: Any, bodies: Mapping[str, WheeledBody], base_dir: pathlib.Path) -> DemonstratorSpec:
    where = f"[demonstrators.{name}]"
    if not isinstance(table, Mapping):
        raise RosterError(f"{where} must be a table, got {table!r}")
    if not name.isidentifier() or name in DEMONSTRATORS or name == "imitator":
        raise RosterError(f"{where}: a demonstrator's name must be a word of its own, not one of the thesis's "
                          f"({', '.join(DEMONSTRATORS)}) or 'imitator'")
    kinds = [k for k in _KINDS if k in table]
    if len(kinds) != 1:
        raise RosterError(f"{where} needs exactly one of controller, policy, log or imported; got "
                          f"{', '.join(kinds) if kinds else 'none'}")
    kind = _KINDS[kinds[0]]
    known = [f.name for f in dataclasses.fields(kind) if f.name != "name"]
    for key in table:
        if key not in known:
            raise RosterError(f"{where}: unknown key {key!r} for a {kinds[0]} demonstrator; known keys: "
                              f"{', '.join(known)}")
    # A built-in controller drives its own body unless told otherwise; anything else the Lego.
    own_body = field.BODIES.get(table.get("controller", ""), "lego") if kinds[0] == "controller" else "lego"
    values = {"body": own_body, **table}
    body = values["body"]
    if body not in THESIS_BODY_FIELDS and body not in bodies:
        raise RosterError(f"{where}: body {body!r} is neither a thesis body ({', '.join(THESIS_BODY_FIELDS)}) nor one "
                          f"of [bodies] ({', '.join(bodies) or 'none given'})")
    _check_kind(where, kinds[0], values, bodies)
    if kinds[0] == "log":
        values["log"] = os.fspath((base_dir / values["log"]).resolve())
    if kinds[0] == "policy" and values["policy"].rsplit(":", 1)[0].endswith(".py"):
        file, attribute = values["policy"].rsplit(":", 1)
        values["policy"] = f"{os.fspath((base_dir / file).resolve())}:{attribute}"
    made: DemonstratorSpec = kind(name=name, **values)
    return made


def _check_kind(where: str, kind: str, values: dict[str, Any], bodies: Mapping[str, WheeledBody]) -> None:
    def text(key: str) -> None:
        if not isinstance(values[key], str) or not values[key]:
            raise RosterError(f"{where}: {key} must be a non-empty string, got {values[key]!r}")
    if kind == "controller":
        text("controller")
        if values["controller"] not in field.DEMONSTRATORS:
            raise RosterError(f"{where}: controller {values['controller']!r} is not one of "
                              f"{', '.join(field.DEMONSTRATORS)}")
        if not _can_drive(values["controller"], values["body"], bodies):
            raise RosterError(f"{where}: the {values['controller']} controller cannot drive the {values['body']} body "
                              f"(the humanoid's drives only the humanoid, the Expert's a wheeled body that takes its "
                              f"wheel speeds, Poor's and Tiny's any wheeled body)")
        lapse = values.get("lapse", 0.0)
        if isinstance(lapse, bool) or not isinstance(lapse, (int, float)) or not 0.0 <= lapse <= 1.0:
            raise RosterError(f"{where}: lapse must be a number in [0, 1], got {lapse!r}")
        values["lapse"] = float(lapse)
    elif kind == "policy":
        text("policy")
        if ":" not in values["policy"]:
            raise RosterError(f"{where}: policy must be \"module:name\" or \"file.py:name\", got {values['policy']!r}")
        rate = values.get("decision_hz")
        if rate is not None and (isinstance(rate, bool) or rate not in DECISION_RATES_HZ):
            raise RosterError(f"{where}: decision_hz must be one of {', '.join(map(str, DECISION_RATES_HZ))}, "
                              f"got {rate!r}")
    elif kind == "imported":
        if values["imported"] is not True:
            raise RosterError(f"{where}: imported must be true (the demonstrations polymimic import-tracks put in "
                              f"the run), got {values['imported']!r}")
    else:
        try:
            check_log_table(where, values)
        except ValueError as error:
            raise RosterError(str(error)) from None


def _can_drive(controller: str, body: str, bodies: Mapping[str, WheeledBody]) -> bool:
    """Whether a built-in controller has commands for the body (as the field decides it)."""
    if controller == "humanoid" or body == "humanoid":
        return controller == body
    if controller == "expert":
        return body == "lego" or (body in bodies and bodies[body].expert_commands)
    return True


def experiments_from_tables(tables: Mapping[str, Any], *, demonstrators: Sequence[str]) -> dict[str, Experiment]:
    """Every ``[experiments.<name>]`` table as an :class:`Experiment`; its demonstrators are the
    thesis's or of ``demonstrators``."""
    out = {}
    for name, table in tables.items():
        where = f"[experiments.{name}]"
        if name in EXPERIMENTS or not name.isidentifier():
            raise RosterError(f"{where}: an experiment's name must be a word of its own, not one of the thesis's "
                              f"({', '.join(EXPERIMENTS)})")
        known = ("title", "demonstrators", "ordering", "phase_one", "skill_order")
        for key in table:
            if key not in known:
                raise RosterError(f"{where}: unknown key {key!r}; known keys: {', '.join(known)}")
        who = _names(where, "demonstrators", table.get("demonstrators"))
        allowed = (*DEMONSTRATORS, *demonstrators)
        for w in who:
            if w not in allowed:
                raise RosterError(f"{where}: demonstrator {w!r} is neither the thesis's nor one of [demonstrators] "
                                  f"({', '.join(demonstrators) or 'none given'})")
        ordering = _names(where, "ordering", table.get("ordering", list(who)))
        if sorted(ordering) != sorted(who):
            raise RosterError(f"{where}: ordering {ordering} must list the experiment's demonstrators {who}, "
                              f"each once")
        skill = table.get("skill_order")
        skill_order = None if skill is None else tuple(_names(where, "skill_order", skill))
        if skill_order is not None and sorted(skill_order) != sorted(who):
            raise RosterError(f"{where}: skill_order must list the experiment's demonstrators, each once")
        phase_one = table.get("phase_one", "by-model")
        if phase_one not in ("by-model", "interleaved"):
            raise RosterError(f"{where}: phase_one must be \"by-model\" or \"interleaved\", got {phase_one!r}")
        title = table.get("title", name.replace("_", " "))
        if not isinstance(title, str):
            raise RosterError(f"{where}: title must be a string, got {title!r}")
        out[name] = Experiment(name, title, tuple(who), tuple(ordering), phase_one, skill_order)
    return out


def _names(where: str, key: str, value: Any) -> list[str]:
    if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value) or \
            len(set(value)) != len(value):
        raise RosterError(f"{where}: {key} must be a list of distinct demonstrator names, got {value!r}")
    return list(value)


def read_bodies(tables: Any) -> dict[str, WheeledBody]:
    """``[bodies]``, each table a :class:`WheeledBody`."""
    try:
        return bodies_from_tables(tables)
    except ValueError as error:
        raise RosterError(str(error)) from None


def spec_table(spec: DemonstratorSpec) -> dict[str, Any]:
    """A demonstrator's table as the config holds it (:func:`demonstrators_from_tables` reads it
    back)."""
    return {k: (dict(v) if isinstance(v, Mapping) else list(v) if isinstance(v, tuple) else v)
            for k, v in dataclasses.asdict(spec).items() if k != "name" and v is not None}


def record_demonstrator(spec: DemonstratorSpec, *, n: int, seed: int, field_config: Mapping[str, Any],
                        bodies: Mapping[str, WheeledBody]) -> tuple[list[field.Demonstration], str]:
    """A demonstrator's demonstrations (``n`` per configuration, a log's every valid episode) and
    a line saying what was done."""
    if isinstance(spec, ImportedDemonstrator):
        raise RosterError(f"[demonstrators.{spec.name}] is imported: bring its log in with `polymimic import-tracks "
                          f"FILE --as {spec.name} --run-dir <this run>` before recording")
    body: BodySpec = bodies.get(spec.body, spec.body)
    if isinstance(spec, LogDemonstrator):
        imported = tracks.import_tracks(spec.log, demonstrator=spec.name, body=body, **spec.import_options())
        return imported.demonstrations, imported.summary()
    who: Any = spec.controller if isinstance(spec, ControllerDemonstrator) else _policy(spec)
    extra: dict[str, Any] = ({"lapse": spec.lapse} if isinstance(spec, ControllerDemonstrator)
                             else {"decision_hz": spec.decision_hz})
    demos = [d for configuration in (1, 2)
             for d in field.record(who, configuration=configuration, n=n, seed=seed, config=dict(field_config),
                                   body=body, name=spec.name, **extra)]
    return demos, f"{spec.name}: {len(demos)} demonstrations"


def demonstrations_expected(spec: DemonstratorSpec | None, per_configuration: int) -> int | None:
    """How many demonstrations a demonstrator has: ``per_configuration`` from each field
    configuration where it is recorded (a thesis demonstrator, for None, too), or, for a log or
    an import, as many as its file held (None)."""
    if isinstance(spec, (LogDemonstrator, ImportedDemonstrator)):
        return None
    return 2 * per_configuration


def source_file(spec: DemonstratorSpec) -> pathlib.Path | None:
    """The file a demonstrator's demonstrations come from, where it has one: a log, or a
    policy's ``.py`` file (a module on the path is not followed)."""
    if isinstance(spec, LogDemonstrator):
        return pathlib.Path(spec.log)
    if isinstance(spec, PolicyDemonstrator) and spec.policy.rsplit(":", 1)[0].endswith(".py"):
        return pathlib.Path(spec.policy.rsplit(":", 1)[0])
    return None


def file_digest(path: pathlib.Path) -> str:
    """The SHA-256 of a file's bytes, hex."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _policy(spec: PolicyDemonstrator) -> Any:
    """The policy ``module:name`` or ``file.py:name`` names (a class made once). A file is
    loaded afresh for each demonstrator, so that two share no module-level state; whatever
    loading it raises (a syntax error, an exception at import) is named with the file."""
    where, attribute = spec.policy.rsplit(":", 1)
    try:
        if where.endswith(".py"):
            # Registered while it runs, as an import would be: dataclasses and pickling look it up.
            module_name = f"polymimic_policy_{spec.name}"
            location = importlib.util.spec_from_file_location(module_name, where)
            if location is None or location.loader is None:
                raise ImportError(f"no Python file at {where}")
            module = importlib.util.module_from_spec(location)
            sys.modules[module_name] = module
            location.loader.exec_module(module)
        else:
            module = importlib.import_module(where)
        found = getattr(module, attribute)
        return found() if isinstance(found, type) else found
    except Exception as error:  # the user's code: anything it raises is named, not a traceback
        raise RosterError(f"[demonstrators.{spec.name}] policy {spec.policy!r}: {type(error).__name__}: "
                          f"{error}") from error
