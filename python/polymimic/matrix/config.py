"""Every parameter of a matrix run; TOML in and out.

The sections a reproduction has (``[seeds]``, ``[field]``, ``[recognizer]``, ``[segmenter]``,
``[learning]``, ``[bodies.<name>]``, read by :class:`~polymimic.runs.config.RunConfig`), then
``[matrix]``: the imitator bodies that make its rows, its built-in columns, its sizes, ``bco``'s
tuning effort and polymimic's (how it weighs a crowd's members). The
rows are the thesis's three bodies and ``wagon``, a wheeled body of its own field described in
``docs/configs/matrix_wagon.toml`` (the default config's own body, :data:`WAGON`); a
``[bodies.<name>]`` table adds another that ``imitators`` may name. Each ``[demonstrators.<name>]``
table (a tracker log, a Python policy, a built-in controller on a body; see
:mod:`polymimic.runs.roster_config`) adds a column after the built-in ones. A reproduction's
config reads as a matrix's too: its ``[imitator]`` body is the first row unless ``[matrix]
imitators`` names the rows, and its ``[experiments]`` are the reproduction's (checked, unused).

>>> config = MatrixConfig()
>>> config.matrix.imitators, config.matrix.sizes.trials
(('lego', 'tiny', 'humanoid', 'wagon'), 20)
>>> MatrixConfig.from_toml('[matrix]\\nimitators = ["lego", "tinny"]\\n')
Traceback (most recent call last):
...
polymimic.runs.config.ConfigError: [matrix] imitators: 'tinny' is not a body: one of lego, tiny, humanoid, wagon
"""

from __future__ import annotations

import dataclasses
import os
from typing import Any

from polymimic._toml import documented as _doc
from polymimic._toml import write_table
from polymimic.bodies import Body, Field, WheeledBody
from polymimic.crowds import PROFILES
from polymimic.evaluation import Attempts
from polymimic.runs.config import (
    IMITATOR_BODIES,
    ConfigError,
    ConfigFile,
    ExperimentSettings,
    ImitatorSettings,
    RunConfig,
    as_table,
    in_range,
    replaced_section,
    section_docs,
    section_table,
)
from polymimic.runs.roster_config import ControllerDemonstrator, DemonstratorSpec, ImportedDemonstrator, spec_table
from polymimic.runs.sizes import Sizes, TuningSizes

__all__ = ["COLUMNS", "WAGON", "WEIGHTINGS", "DemonstratorSet", "MatrixConfig", "MatrixSettings", "demonstrator_sets",
           "stored_column"]

COLUMNS = ("expert", "tiny", "humanoid", "own_body", "mixed_bodies")
"""The demonstrator sets, in the matrix's order: the Expert on the Lego, the Tiny controller on
the tiny, the Humanoid controller, the row's own body (a built-in controller on it) and the
benchmark's ``mixed_bodies`` crowd (three bodies at three skills)."""

WAGON = WheeledBody("wagon", length_mm=80, width_mm=80, wheel_base_mm=70, top_wheel_speed_mm_s=120,
                    field=Field(800, 560, goal_mouth_mm=320, ball_diameter_mm=60))
"""A wheeled body between the Lego and the tiny, on an 800 × 560 mm field of its own whose
mouths (320 mm) are not half its width: the matrix's described body."""

WEIGHTINGS = ("even", "lp", "lp_gain")
"""How polymimic may weigh a crowd's members (:class:`polymimic.LearningConfig`'s
``imitator_weighting``)."""

OWN_CONTROLLER = {"lego": "expert", "tiny": "tiny", "humanoid": "humanoid"}
"""The built-in controller that demonstrates on a built-in body; any other body's is the Tiny
controller's, which drives any wheeled body."""


@dataclasses.dataclass(frozen=True)
class MatrixSettings:
    """The rows, the sizes, and how hard ``bco`` is tuned in each cell: its candidates are plain
    boosted trees with each labelling, then the benchmark's others, chosen on the validation
    attempts that choose polymimic's weighting too."""

    imitators: tuple[str, ...] = _doc("the imitator bodies, one row each: lego, tiny, humanoid, or a "
                                      "[bodies.<name>]", ("lego", "tiny", "humanoid", "wagon"))
    columns: tuple[str, ...] = _doc("the built-in columns, of expert, tiny, humanoid, own_body, mixed_bodies; each "
                                    "[demonstrators.<name>] adds a column after them", COLUMNS)
    sizes: Sizes = Sizes(trials=20)
    bco_fits: int = _doc("fits of bco per cell, each evaluated, under seeds first_trial, first_trial + 1, …", 3)
    tuning: TuningSizes = TuningSizes(tuning_budget=2, validation_attempts_per_configuration=25)
    primitives: str = _doc("each row's primitives: own (its body's: the humanoid's eight, a wheeled body's five) "
                           "or wheeled (the five for every row, the humanoid walking, turning and waiting)", "own")
    weightings: tuple[str, ...] = _doc("polymimic's candidates for how it weighs a crowd's members "
                                       "([learning] imitator_weighting), chosen in every cell of more than one "
                                       "demonstrator on bco's validation attempts, one trial each under the first "
                                       "trial's seed; the first where there is no choice (one demonstrator or one "
                                       "candidate)", ("lp", "lp_gain"))

    def __post_init__(self) -> None:
        in_range("matrix", "bco_fits", self.bco_fits, 1)
        if self.primitives not in ("own", "wheeled"):
            raise ConfigError(f"[matrix] primitives must be 'own' or 'wheeled', got {self.primitives!r}")
        weightings = self.weightings
        if not isinstance(weightings, (list, tuple)) or not weightings \
                or not all(isinstance(w, str) and w in WEIGHTINGS for w in weightings) \
                or len(set(weightings)) != len(weightings):
            raise ConfigError(f"[matrix] weightings must be a non-empty list of distinct imitator weightings, each "
                              f"one of {', '.join(WEIGHTINGS)}; got {weightings!r}")
        object.__setattr__(self, "weightings", tuple(weightings))
        rows = self.imitators
        if not isinstance(rows, (list, tuple)) or not rows or not all(isinstance(r, str) for r in rows):
            raise ConfigError(f"[matrix] imitators must be a non-empty list of body names, got {rows!r}")
        if len(set(rows)) != len(rows):
            raise ConfigError(f"[matrix] imitators names {next(r for r in rows if rows.count(r) > 1)!r} twice")
        object.__setattr__(self, "imitators", tuple(rows))
        columns = self.columns
        if not isinstance(columns, (list, tuple)) or not all(isinstance(c, str) and c in COLUMNS for c in columns) \
                or len(set(columns)) != len(columns):
            raise ConfigError(f"[matrix] columns must be a list of distinct built-in columns, each one of "
                              f"{', '.join(COLUMNS)} (a [demonstrators.<name>] table adds one of yours); got "
                              f"{columns!r}")
        object.__setattr__(self, "columns", tuple(columns))


@dataclasses.dataclass(frozen=True)
class DemonstratorSet:
    """One column's demonstrators for one row: ``(name, controller, body, lapse)`` each; a column
    of the config's ``[demonstrators.<name>]`` has the one member it describes (``spec``; its
    controller is ``"log"`` or ``"policy"`` where it is not a built-in one)."""

    column: str
    name: str
    members: tuple[tuple[str, str, str, float], ...]
    spec: DemonstratorSpec | None = None

    @property
    def names(self) -> tuple[str, ...]:
        """The members' names, in order."""
        return tuple(m[0] for m in self.members)


def demonstrator_sets(row: str, demonstrators: dict[str, DemonstratorSpec] | None = None) -> dict[str, DemonstratorSet]:
    """Every column's demonstrators for the imitator ``row``: the built-in columns, then one per
    demonstrator of ``demonstrators`` (a config's ``[demonstrators]``). A built-in body's own-body
    column is the column of its own controller (the same set: its cells are one); another body's is
    the Tiny controller on that body, named ``own_<body>``."""
    sets = {"expert": DemonstratorSet("expert", "expert", (("expert", "expert", "lego", 0.0),)),
            "tiny": DemonstratorSet("tiny", "tiny", (("tiny", "tiny", "tiny", 0.0),)),
            "humanoid": DemonstratorSet("humanoid", "humanoid", (("humanoid", "humanoid", "humanoid", 0.0),)),
            "mixed_bodies": DemonstratorSet("mixed_bodies", "mixed_bodies", tuple(
                (m.name, m.controller, m.body, m.lapse) for m in PROFILES["mixed_bodies"].members))}
    if row in OWN_CONTROLLER:
        sets["own_body"] = dataclasses.replace(sets[OWN_CONTROLLER[row]], column="own_body")
    else:
        sets["own_body"] = DemonstratorSet("own_body", f"own_{row}", ((f"tiny_{row}", "tiny", row, 0.0),))
    yours = {name: DemonstratorSet(name, name, ((name, _kind(spec), spec.body,
                                                 spec.lapse if isinstance(spec, ControllerDemonstrator) else 0.0),),
                                   spec=spec) for name, spec in (demonstrators or {}).items()}
    return {**{column: sets[column] for column in COLUMNS}, **yours}


def stored_column(sets: dict[str, DemonstratorSet], column: str) -> str:
    """The column whose cell ``column``'s is, in a row of ``sets``: itself, but for a built-in
    body's own-body column, which is its own controller's."""
    own = sets["own_body"].name
    return own if column == "own_body" and not own.startswith("own_") else column


def _kind(spec: DemonstratorSpec) -> str:
    return spec.controller if isinstance(spec, ControllerDemonstrator) else type(spec).__name__.removesuffix(
        "Demonstrator").lower()


def _default_run() -> RunConfig:
    run = RunConfig()
    # The benchmark's polymimic: it learns more from members of higher LP (docs/results/benchmark.md).
    return dataclasses.replace(run, bodies={**run.bodies, "wagon": WAGON},
                               learning=run.learning.replace(imitator_weighting="lp"))


@dataclasses.dataclass(frozen=True)
class MatrixConfig(ConfigFile):
    """The whole matrix. ``MatrixConfig()`` is the full one; :meth:`quick` is small."""

    run: RunConfig = dataclasses.field(default_factory=_default_run)
    matrix: MatrixSettings = dataclasses.field(default_factory=MatrixSettings)

    def __post_init__(self) -> None:
        known = [*IMITATOR_BODIES, *(n for n in self.run.bodies if n not in IMITATOR_BODIES)]
        for row in self.matrix.imitators:
            if row not in known:
                raise ConfigError(f"[matrix] imitators: {row!r} is not a body: one of {', '.join(known)}")
        if not self.run.thesis_imitator:
            raise ConfigError("[imitator] has no place in a matrix config made in Python: its rows are [matrix] "
                              "imitators")
        for name, spec in self.run.demonstrators.items():
            if isinstance(spec, ImportedDemonstrator):
                raise ConfigError(f"[demonstrators.{name}] is imported into a reproduction's run; a matrix reads a log "
                                  f"itself: give its table log = \"FILE\" (and the import's options)")
            if name in COLUMNS or name.startswith("own_"):
                raise ConfigError(f"[demonstrators.{name}]: a matrix's column of yours needs a name apart from its "
                                  f"built-in columns ({', '.join(COLUMNS)}) and own_<body> sets")
        if not self.columns():
            raise ConfigError("[matrix] columns is empty and there is no [demonstrators.<name>]: a matrix needs a "
                              "column")

    def columns(self) -> tuple[str, ...]:
        """The columns: ``[matrix] columns``, then each ``[demonstrators.<name>]``."""
        return (*self.matrix.columns, *self.run.demonstrators)

    @property
    def seeds(self) -> Any:
        """The run's seeds (``[seeds]``)."""
        return self.run.seeds

    def body(self, row: str) -> Body:
        """The body named ``row``: a built-in one, or the config's ``[bodies.<row>]``."""
        return self.run.body(row)

    def evaluation_attempts(self) -> Attempts:
        """The attempts both methods play in every cell (``[matrix] attempts_per_configuration``
        from each configuration, under ``[seeds] evaluation``)."""
        return self.matrix.sizes.evaluation_attempts(seed=self.seeds.evaluation)

    def trial_seeds(self) -> list[int]:
        """The seeds of polymimic's trials in every cell."""
        return [self.seeds.first_trial + i for i in range(self.matrix.sizes.trials)]

    def fit_seeds(self) -> list[int]:
        """The seeds of ``bco``'s fits in every cell."""
        return [self.seeds.first_trial + i for i in range(self.matrix.bco_fits)]

    @classmethod
    def quick(cls) -> MatrixConfig:
        """A small matrix: 2 trials and 1 bco fit per cell, 5 demonstrations per member and
        configuration, 5 evaluation attempts per configuration, bco's 2 candidates on 3 validation
        attempts, fits of at most 1000 samples, the quick reproduction's recogniser."""
        full = cls()
        quick_run = RunConfig.quick()
        return dataclasses.replace(
            full, run=dataclasses.replace(full.run, recognizer=quick_run.recognizer),
            matrix=dataclasses.replace(full.matrix, sizes=Sizes(trials=2, demonstrations_per_configuration=5,
                                                                attempts_per_configuration=5), bco_fits=1,
                                       tuning=TuningSizes(tuning_budget=2, validation_attempts_per_configuration=3,
                                                          max_decision_samples=1000)))

    def to_dict(self) -> dict[str, Any]:
        """The whole config as plain tables (the run's and ``[matrix]``)."""
        run = self.run.to_dict()
        for section in ("experiments", "imitator"):
            del run[section]
        return {**run, "matrix": section_table(self.matrix)}

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, base: MatrixConfig | None = None,
                  base_dir: str | os.PathLike[str] = ".") -> MatrixConfig:
        """A config from tables such as :meth:`to_dict` gives, laid over ``base`` (the defaults);
        a demonstrator's files (a log, a policy's) are found relative to ``base_dir``.

        Raises
        ------
        ConfigError
            For an unknown key, a value out of range, or a table a matrix cannot use.
        """
        base = base or cls()
        run = RunConfig.from_dict({k: v for k, v in data.items() if k != "matrix"}, base=base.run, base_dir=base_dir)
        # The reproduction's sections: its imitator is a row; its experiments are checked above and kept out.
        imitator = run.imitator.body if "imitator" in data else None
        run = dataclasses.replace(run, imitator=ImitatorSettings(), experiments=ExperimentSettings(),
                                  own_experiments={})
        settings = base.matrix
        if "matrix" in data:
            settings = replaced_section("matrix", base.matrix, as_table("matrix", data["matrix"]))
        if imitator is not None and "imitators" not in as_table("matrix", data.get("matrix", {})):
            rows = (imitator, *(r for r in settings.imitators if r != imitator))
            settings = dataclasses.replace(settings, imitators=rows)
        return cls(run=run, matrix=settings)

    def to_toml(self) -> str:
        """The config as commented TOML."""
        lines = self.run.to_toml().split("\n[experiments]")[0].rstrip().split("\n")
        lines = [line for line in _without_table(lines, "imitator")]
        lines[0] = "# polymimic matrix configuration"
        lines.append("")
        write_table(lines, "matrix", section_table(self.matrix), section_docs(self.matrix, per="cell"))
        for name, body in self.run.bodies.items():
            write_table(lines, f"bodies.{name}", body.to_table(), {})
        for name, spec in self.run.demonstrators.items():
            write_table(lines, f"demonstrators.{name}", spec_table(spec), {})
        return "\n".join(lines).rstrip() + "\n"


def _without_table(lines: list[str], name: str) -> list[str]:
    """``lines`` of TOML without the table ``[name]``."""
    out, skipping = [], False
    for line in lines:
        if line.startswith("["):
            skipping = line.strip() == f"[{name}]"
        if not skipping:
            out.append(line)
    return out
