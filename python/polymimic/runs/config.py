"""Every parameter of a run, with the thesis's values as defaults; TOML in and out, and the
checks every application's config is read with.

Sections: ``[seeds]``, ``[field]`` (the simulated field), ``[imitator]`` (the learner's body),
``[recognizer]`` (self-observation sizes and the HMM bank), ``[segmenter]``, ``[learning]``
(:class:`~polymimic.LearningConfig`) and ``[experiments]`` (trials, demonstrations, attempts). A
file may give only some keys; the rest take their defaults. Unknown keys and values of the wrong type are refused.

>>> config = RunConfig()
>>> config.recognizer.codebook_size, config.experiments.sizes.trials
(512, 100)
>>> RunConfig.from_toml(config.to_toml()) == config
True
>>> RunConfig.from_toml("[experiments]\\ntrials = 8\\n").experiments.sizes.trials
8
>>> RunConfig.from_toml("[recognizer]\\ncodebok_size = 3\\n")
Traceback (most recent call last):
...
polymimic.runs.config.ConfigError: unknown key in [recognizer]: codebok_size
"""

from __future__ import annotations

import dataclasses
import json
import os
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, TypeVar

from polymimic import _arguments
from polymimic._native import PrimitiveRecognizer
from polymimic._tables import Path, merged
from polymimic._toml import documented as _doc
from polymimic._toml import loads, write_table
from polymimic.bodies import THESIS_BODIES, Body, WheeledBody
from polymimic.evaluation import Attempts
from polymimic.field import PrimitiveSequence, check_config, default_config, primitive_set_of
from polymimic.learning import LearningConfig
from polymimic.runs.roster import EXPERIMENTS, Experiment
from polymimic.runs.roster_config import (
    DemonstratorSpec,
    RosterError,
    demonstrators_from_tables,
    experiments_from_tables,
    read_bodies,
    spec_table,
)
from polymimic.runs.sizes import Sizes

if TYPE_CHECKING:
    from typing_extensions import Self

__all__ = ["IMITATOR_BODIES", "ConfigError", "ConfigFile", "ExperimentSettings", "ImitatorSettings",
           "RecognizerSettings", "RunConfig", "SeedSettings", "SegmenterSettings", "as_table", "checked_section",
           "in_range", "read_config", "replaced_section", "section_docs", "section_table", "toml_tables"]


Loaded = TypeVar("Loaded")


class ConfigError(ValueError):
    """A run configuration that cannot be used: an unknown key, a wrong type, a bad value."""


def in_range(section: str, name: str, value: float, low: float, high: float | None = None, *,
              exclusive_low: bool = False) -> None:
    """A :class:`ConfigError` naming ``[section] name`` unless ``value`` is a finite number in range."""
    try:
        _arguments.in_range(name, value, low, high, exclusive_low=exclusive_low)
    except ValueError as error:
        raise ConfigError(f"[{section}] {error}") from None


class ConfigFile:
    """How every application's config is read from TOML: its :meth:`from_dict` over the tables,
    laid over a base, with the paths a file names read from the file's folder."""

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, base: Self | None = None,
                  base_dir: str | os.PathLike[str] = ".") -> Self:
        """A config from plain tables laid over ``base``; paths in them are read from ``base_dir``."""
        raise NotImplementedError

    @classmethod
    def from_toml(cls, text: str, *, base: Self | None = None, base_dir: str | os.PathLike[str] = ".") -> Self:
        """A config from TOML text laid over ``base``; paths in it are read from ``base_dir``."""
        return cls.from_dict(toml_tables(text), base=base, base_dir=base_dir)

    @classmethod
    def load(cls, path: str | os.PathLike[str], *, base: Self | None = None) -> Self:
        """A config from a TOML file laid over ``base``; paths in it are read from the file's folder."""
        folder = os.path.dirname(os.path.abspath(path))
        return read_config(path, lambda text: cls.from_toml(text, base=base, base_dir=folder))


@dataclasses.dataclass(frozen=True)
class SeedSettings:
    """Where every random draw of the run starts; the same seeds give the same bits."""

    self_observation_train: int = _doc("self-observation sequences the recogniser learns from", 1)
    self_observation_test: int = _doc("held-out self-observation sequences (Table 4.3, Fig 4.5)", 2)
    demonstrations: int = _doc("every demonstrator's recorded attempts; the Average demonstrator's first trial", 0)
    first_trial: int = _doc("trial i of every experiment has seed first_trial + i", 0)
    evaluation: int = _doc("starting positions and noise of every imitator's attempts", 1000)

    def __post_init__(self) -> None:
        for f in dataclasses.fields(self):
            in_range("seeds", f.name, getattr(self, f.name), 0, 2**64 - 1)


@dataclasses.dataclass(frozen=True)
class RecognizerSettings:
    """Self-observation sizes and the HMM bank (thesis §3.1)."""

    train_per_primitive: int = _doc("self-observed sequences per primitive to learn from", 1000)
    test_per_primitive: int = _doc("held-out sequences per primitive", 340)
    n_states: int = _doc("HMM states (the thesis settled on one)", 1)
    codebook_size: int = _doc("LBG codewords per representation", 512)
    links: int = _doc("left-right links per state", 2)
    max_iter: int = _doc("Baum-Welch iterations at most", 100)
    tol: float = _doc("Baum-Welch stops when the log-likelihood gains less", 1e-4)
    representation: str = _doc("\"thesis\" (positional/rotational) or \"egocentric\"", "thesis")
    emissions: str = _doc("\"discrete\" (the thesis's) or \"gaussian\"", "discrete")
    emission_floor: float = _doc("smallest emission probability", 1e-8)
    min_variance: float = _doc("smallest variance of Gaussian emissions", 0.01)
    seed: int = _doc("codebook and HMM initialisation", 0)

    def __post_init__(self) -> None:
        for name in ("train_per_primitive", "test_per_primitive", "n_states", "codebook_size", "links", "max_iter"):
            in_range("recognizer", name, getattr(self, name), 1)
        in_range("recognizer", "n_states", self.n_states, 1, 20)
        in_range("recognizer", "tol", self.tol, 0.0, exclusive_low=True)
        # At most one over the codebook's size, so that an emission row can still sum to 1.
        in_range("recognizer", "emission_floor", self.emission_floor, 0.0, 1.0 / self.codebook_size)
        in_range("recognizer", "min_variance", self.min_variance, 0.0, exclusive_low=True)
        in_range("recognizer", "seed", self.seed, 0, 2**64 - 1)
        if self.representation not in ("thesis", "egocentric"):
            raise ConfigError(f"[recognizer] representation = {self.representation!r} must be \"thesis\" or "
                              "\"egocentric\"")
        if self.emissions not in ("discrete", "gaussian"):
            raise ConfigError(f"[recognizer] emissions = {self.emissions!r} must be \"discrete\" or \"gaussian\"")

    def train(self, sequences: Sequence[PrimitiveSequence]) -> PrimitiveRecognizer:
        """The recogniser these settings make from self-observed ``sequences`` (the
        reproduction's and the benchmark's alike)."""
        options = {k: v for k, v in dataclasses.asdict(self).items()
                   if k not in ("train_per_primitive", "test_per_primitive")}
        return PrimitiveRecognizer.train([s.frames for s in sequences], [s.primitive for s in sequences],
                                         primitives=primitive_set_of(sequences), **options)


@dataclasses.dataclass(frozen=True)
class SegmenterSettings:
    """How demonstrations are cut into segments and named (thesis §3.2.2)."""

    min_frames: int = _doc("shortest segment, frames", 10)
    stop_distance_mm: float = _doc("a segment moving less than this…", 1.0)
    stop_rotation_deg: float = _doc("…and turning less than this is a stop", 20.0)
    limit_sds: float = _doc("a segment ends when its motion leaves this many sds of a primitive's", 2.0)
    gap_margin: float = _doc("log-likelihood margin below which a segment is a gap", 2.0)

    def __post_init__(self) -> None:
        in_range("segmenter", "min_frames", self.min_frames, 2)
        in_range("segmenter", "stop_distance_mm", self.stop_distance_mm, 0.0)
        in_range("segmenter", "stop_rotation_deg", self.stop_rotation_deg, 0.0, 180.0)
        in_range("segmenter", "limit_sds", self.limit_sds, 0.0)
        in_range("segmenter", "gap_margin", self.gap_margin, 0.0)


@dataclasses.dataclass(frozen=True)
class ExperimentSettings:
    """The learning experiments and the evaluation of the imitators they train (thesis §4.4)."""

    sizes: Sizes = Sizes(trials=100)
    evaluated_imitators: int = _doc("imitators evaluated per experiment: the first trials'", 100)
    average_max_trials: int = _doc("heterogeneous imitators tried as the Average (the one whose net goals lie "
                                   "nearest the middle of the Poor's and the Expert's is chosen)", 10)
    lp_stride: int = _doc("LP-over-time plots keep every lp_stride-th LP change", 200)

    def __post_init__(self) -> None:
        for name in ("average_max_trials", "lp_stride"):
            in_range("experiments", name, getattr(self, name), 1)
        in_range("experiments", "evaluated_imitators", self.evaluated_imitators, 0)


IMITATOR_BODIES = ("lego", "tiny", "humanoid")
"""The built-in bodies an imitator may have; a ``[bodies.<name>]`` table of the run's adds its own."""


@dataclasses.dataclass(frozen=True)
class ImitatorSettings:
    """Who learns: the body that observes itself, learns and plays."""

    body: str = _doc("the imitator's body: lego (the thesis's), tiny, humanoid, or the name of a [bodies.<name>] "
                     "table", "lego")


_SECTIONS = {"seeds": SeedSettings, "imitator": ImitatorSettings, "recognizer": RecognizerSettings,
             "segmenter": SegmenterSettings, "experiments": ExperimentSettings}


@dataclasses.dataclass(frozen=True)
class RunConfig(ConfigFile):
    """The whole run. ``RunConfig()`` is the thesis's; :meth:`quick` a run of about a minute."""

    seeds: SeedSettings = dataclasses.field(default_factory=SeedSettings)
    field: dict[str, Any] = dataclasses.field(default_factory=default_config)
    imitator: ImitatorSettings = dataclasses.field(default_factory=ImitatorSettings)
    recognizer: RecognizerSettings = dataclasses.field(default_factory=RecognizerSettings)
    segmenter: SegmenterSettings = dataclasses.field(default_factory=SegmenterSettings)
    learning: LearningConfig = dataclasses.field(default_factory=LearningConfig)
    experiments: ExperimentSettings = dataclasses.field(default_factory=ExperimentSettings)
    bodies: dict[str, WheeledBody] = dataclasses.field(default_factory=lambda: dict(THESIS_BODIES))
    """``[bodies.<name>]``: the wheeled bodies, the thesis's ``lego`` and ``tiny`` (as the field
    was calibrated; a table of either must hold the same constants) and the user's (see
    :mod:`polymimic.runs.roster_config`)."""
    demonstrators: dict[str, DemonstratorSpec] = dataclasses.field(default_factory=dict)
    """``[demonstrators.<name>]``: demonstrators of the user's, recorded or imported with the thesis's."""
    own_experiments: dict[str, Experiment] = dataclasses.field(default_factory=dict)
    """``[experiments.<name>]``: experiments of the user's, run, evaluated and reported with the thesis's."""

    def __post_init__(self) -> None:
        name = self.imitator.body
        if name not in IMITATOR_BODIES and name not in self.bodies:
            own = [n for n in self.bodies if n not in IMITATOR_BODIES]
            raise ConfigError(f"[imitator] body = {name!r} is not a body: one of {', '.join(IMITATOR_BODIES)}"
                              + (f" or of the run's [bodies.<name>] tables ({', '.join(own)})" if own else
                                 ", or describe it in a [bodies.<name>] table"))

    def imitator_body(self) -> Body:
        """The imitator's :class:`polymimic.Body`: a built-in body, or the one the run's
        ``[bodies.<name>]`` table of that name describes.

        >>> RunConfig().imitator_body()
        Body('lego')
        """
        return self.body(self.imitator.body)

    def body(self, name: str) -> Body:
        """The body ``name`` names: a built-in one, or the run's ``[bodies.<name>]``."""
        return Body(name if name in IMITATOR_BODIES else self.bodies[name])

    @property
    def thesis_imitator(self) -> bool:
        """Whether the imitator is the thesis's, the Lego robot: only then do the thesis's figures
        compare."""
        return self.imitator.body == "lego"

    def evaluation_attempts(self) -> Attempts:
        """The attempts every evaluated imitator plays (``[experiments] attempts_per_configuration``
        from each configuration, under ``[seeds] evaluation``).

        >>> RunConfig().evaluation_attempts()
        Attempts(per_configuration=25, seed=1000, starts=None)
        """
        return self.experiments.sizes.evaluation_attempts(seed=self.seeds.evaluation)

    def all_experiments(self) -> dict[str, Experiment]:
        """The thesis's three experiments, then the user's."""
        return {**EXPERIMENTS, **self.own_experiments}

    @classmethod
    def quick(cls) -> RunConfig:
        """Fewer of everything: 8 trials, 10 demonstrations per configuration, 200 self-observed
        sequences per primitive, a 128-word codebook and two evaluated imitators per experiment.

        >>> RunConfig.quick().experiments.sizes.trials
        8
        """
        thesis = cls()
        return dataclasses.replace(
            thesis,
            recognizer=dataclasses.replace(thesis.recognizer, train_per_primitive=200, test_per_primitive=68,
                                           codebook_size=128),
            experiments=dataclasses.replace(thesis.experiments, evaluated_imitators=2,
                                            sizes=Sizes(trials=8, demonstrations_per_configuration=10)))

    def to_dict(self) -> dict[str, Any]:
        """Plain data, section by section (what ``manifest.json`` keeps); the user's
        demonstrators and experiments only where there are some."""
        data = {"seeds": section_table(self.seeds), "field": json.loads(json.dumps(self.field)),
                "imitator": section_table(self.imitator), "recognizer": section_table(self.recognizer),
                "segmenter": section_table(self.segmenter),
                "learning": self.learning.to_dict(),
                "experiments": {**section_table(self.experiments),
                                **{n: _experiment_table(e) for n, e in self.own_experiments.items()}}}
        data["bodies"] = {name: body.to_table() for name, body in self.bodies.items()}
        if self.demonstrators:
            data["demonstrators"] = {name: spec_table(spec) for name, spec in self.demonstrators.items()}
        return data

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, base: RunConfig | None = None,
                  base_dir: str | os.PathLike[str] = ".") -> RunConfig:
        """A config from plain data; what ``data`` leaves out comes from ``base`` (the thesis's).
        Files a demonstrator names (a log, a policy's file) are found relative to ``base_dir``."""
        base = base or cls()
        unknown = sorted(set(data) - {f.name for f in dataclasses.fields(cls) if f.name != "own_experiments"})
        if unknown:
            raise ConfigError(f"unknown section{'s' if len(unknown) > 1 else ''}: {', '.join(unknown)}")
        changes: dict[str, Any] = {}
        own_tables: dict[str, Any] = {}
        if "experiments" in data:
            table = as_table("experiments", data["experiments"])
            own_tables = {k: v for k, v in table.items() if isinstance(v, dict)}
            data = {**data, "experiments": {k: v for k, v in table.items() if k not in own_tables}}
        for name in _SECTIONS:
            if name in data:
                current = getattr(base, name)
                changes[name] = replaced_section(name, current, as_table(name, data[name]))
        try:
            bodies = {**base.bodies, **read_bodies(data["bodies"])} if "bodies" in data else base.bodies
            demonstrators = (demonstrators_from_tables(data["demonstrators"], bodies=bodies, base_dir=base_dir)
                             if "demonstrators" in data else base.demonstrators)
            own = (experiments_from_tables(own_tables, demonstrators=list(demonstrators)) if own_tables
                   else base.own_experiments)
        except RosterError as error:
            raise ConfigError(str(error)) from None
        changes.update(bodies=bodies, demonstrators=demonstrators, own_experiments=own)
        if "field" in data:
            field = _field_section(base.field, as_table("field", data["field"]))
            try:
                check_config(field)
            except (ValueError, TypeError) as error:
                raise ConfigError(f"[field] {str(error).removeprefix('field config: ')}") from error
            changes["field"] = field
        if "learning" in data:
            values = checked_section("learning", as_table("learning", data["learning"]), base.learning.to_dict())
            try:
                changes["learning"] = base.learning.replace(**values)
            except ValueError as error:
                raise ConfigError(f"[learning] {str(error).removeprefix('config: ')}") from error
        return dataclasses.replace(base, **changes)

    def to_toml(self) -> str:
        """Every parameter, one ``key = value`` line each, with what it means beside it."""
        lines = ["# polymimic run configuration: the thesis's values unless changed", ""]
        for name in ("seeds", "field", "imitator", "recognizer", "segmenter", "learning", "experiments"):
            section: Any = getattr(self, name)
            if isinstance(section, LearningConfig):
                write_table(lines, name, section.to_dict(), {})
            elif dataclasses.is_dataclass(section) and not isinstance(section, type):
                write_table(lines, name, section_table(section), section_docs(section, per="experiment"))
            else:
                lines.append("# The simulated field of self-observation and of every recorded demonstration.")
                write_table(lines, name, section, {})
        for name, experiment in self.own_experiments.items():
            write_table(lines, f"experiments.{name}", _experiment_table(experiment), {})
        for name, body in self.bodies.items():
            write_table(lines, f"bodies.{name}", body.to_table(), {})
        for name, spec in self.demonstrators.items():
            write_table(lines, f"demonstrators.{name}", spec_table(spec), {})
        return "\n".join(lines).rstrip() + "\n"


def _experiment_table(experiment: Experiment) -> dict[str, Any]:
    table: dict[str, Any] = {"title": experiment.title, "demonstrators": list(experiment.demonstrators),
                             "ordering": list(experiment.ordering), "phase_one": experiment.phase_one}
    if experiment.skill_order is not None:
        table["skill_order"] = list(experiment.skill_order)
    return table


def toml_tables(text: str) -> dict[str, Any]:
    """The tables of a config's TOML, a :class:`ConfigError` where it is not TOML."""
    try:
        return loads(text)
    except ValueError as error:
        raise ConfigError(str(error)) from error


def read_config(path: str | os.PathLike[str], parse: Callable[[str], Loaded]) -> Loaded:
    """The config ``parse`` makes of the file at ``path``; its errors name the file."""
    try:
        with open(path, encoding="utf-8") as file:
            text = file.read()
    except OSError as error:
        raise ConfigError(f"cannot read config {os.fspath(path)!r}: {error.strerror}") from error
    try:
        return parse(text)
    except ConfigError as error:
        raise ConfigError(f"{os.fspath(path)}: {error}") from error


def as_table(section: str, value: Any) -> dict[str, Any]:
    """``value`` if it is a table (a dict), else a ``ConfigError`` naming ``[section]``."""
    if not isinstance(value, dict):
        raise ConfigError(f"[{section}] must be a table, got {value!r}")
    return value


def checked_section(section: str, values: dict[str, Any], defaults: dict[str, Any]) -> dict[str, Any]:
    """``values`` with their types checked against ``defaults``' (ints are accepted as floats)."""
    unknown = sorted(set(values) - set(defaults))
    if unknown:
        raise ConfigError(f"unknown key{'s' if len(unknown) > 1 else ''} in [{section}]: {', '.join(unknown)}")
    return {key: _typed(f"[{section}] {key}", value, defaults[key]) for key, value in values.items()}


def section_table(settings: Any, *, order: Sequence[str] = ()) -> dict[str, Any]:
    """A section's keys and values as its file holds them: a block's (:class:`~polymimic.runs.sizes.Sizes`)
    flat among the section's own, lists for tuples, the keys of ``order`` first.

    >>> list(section_table(ExperimentSettings()))[:4]
    ['trials', 'demonstrations_per_configuration', 'attempts_per_configuration', 'evaluated_imitators']
    """
    table: dict[str, Any] = {}
    for field in dataclasses.fields(settings):
        value = getattr(settings, field.name)
        if dataclasses.is_dataclass(value):
            table.update(section_table(value))
        else:
            table[field.name] = list(value) if isinstance(value, tuple) else value
    return {**{key: table[key] for key in order}, **table}


def section_docs(settings: Any, *, per: str) -> dict[str, str]:
    """What each key of a section means (a field's ``metadata["doc"]``), a block's ``{per}`` said
    as ``per`` (what one learning trial belongs to)."""
    docs: dict[str, str] = {}
    for field in dataclasses.fields(settings):
        value = getattr(settings, field.name)
        if dataclasses.is_dataclass(value):
            docs.update(section_docs(value, per=per))
        else:
            docs[field.name] = field.metadata.get("doc", "").replace("{per}", per)
    return docs


def replaced_section(section: str, settings: Loaded, table: dict[str, Any]) -> Loaded:
    """``settings`` with the values of its file's ``[section]`` ``table``, each checked against
    its current one's type and a block's keys given to its block; a :class:`ConfigError` naming
    ``[section] key`` for an unknown key or a bad value."""
    values = checked_section(section, table, section_table(settings))
    changes: dict[str, Any] = {}
    for field in dataclasses.fields(settings):  # type: ignore[arg-type]
        current = getattr(settings, field.name)
        if dataclasses.is_dataclass(current):
            own = {key: values[key] for key in section_table(current) if key in values}
            try:
                changes[field.name] = dataclasses.replace(current, **own)  # type: ignore[type-var]
            except ValueError as error:
                raise ConfigError(f"[{section}] {error}") from None
        elif field.name in values:
            changes[field.name] = values[field.name]
    return dataclasses.replace(settings, **changes)  # type: ignore[type-var]


def _typed(where: str, value: Any, default: Any) -> Any:
    expected = type(default)
    if expected is float and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    if type(value) is not expected:
        raise ConfigError(f"{where} = {value!r} must be {_type_name(expected)}, like the default {default!r}")
    return value


def _type_name(kind: type) -> str:
    return {bool: "true or false", int: "an integer", float: "a number", str: "a string", dict: "a table"}.get(
        kind, kind.__name__)


def _field_section(defaults: dict[str, Any], values: dict[str, Any]) -> dict[str, Any]:
    """``[field]`` merged over the field's defaults, nested tables key by key, worded as a run
    config's sections are."""
    def unknown(path: Path, known: Sequence[str]) -> Exception:
        return ConfigError(f"unknown key in [{'.'.join(path[:-1])}]: {path[-1]}")

    def not_table(path: Path, value: Any) -> Exception:
        return ConfigError(f"[{'.'.join(path)}] must be a table, got {value!r}")

    def leaf(path: Path, value: Any, default: Any) -> Any:
        return _typed(f"[{'.'.join(path[:-1])}] {path[-1]}", value, default)

    return merged(defaults, values, unknown=unknown, not_table=not_table, leaf=leaf, path=("field",))
