"""``polymimic matrix``: each imitator's own recogniser, each set of demonstrators recorded once,
polymimic and bco in every cell, and the summary and report.

Steps, each resumable (every result is written to the run directory, atomically, as it
arrives, and a rerun redoes only what is missing or damaged):

1. **recognise** — each row's self-observation on its own body and field, and its recogniser
   (the rows side by side);
2. **record** — each set's pool of demonstrations: for every trial (and bco fit) 25 valid ones
   per member and configuration of its own (the ``mixed_bodies`` crowd as the benchmark records
   it), a log's every episode, each trial resampling them (:mod:`polymimic.matrix.draws`);
3. **weigh** — polymimic's tuning, with bco's effort: in every cell of more than one
   demonstrator, each of its weightings of the members (``[matrix] weightings``) learns one trial
   under the first trial's seed and plays bco's validation attempts; the best by net goals, then
   goals (the first of equals) is the cell's;
4. **polymimic** — every cell's trials, each imitator learning on its own setting and played by
   the improved control on the evaluation attempts of its own field;
5. **attempts** — each row's first trial in the pictured column (the Expert's, else the first)
   played again, checked against its saved evaluation, and its first attempt saved to be drawn
   (:mod:`polymimic.matrix.pictures`);
6. **tune** — bco's hyperparameters in every cell, on validation attempts; the chosen fit is
   evaluated there and then;
7. **bco** — the other bco fits of every cell, evaluated;
8. **report** — ``matrix.json``, ``matrix.md``, ``matrix.html``, the heat map, and the pictures
   of every set's demonstration and every row's attempt, each on its own field.

A built-in body's own-body cell is the cell of its own controller's column (the same
demonstrations and imitator): it is computed once.
"""

from __future__ import annotations

import dataclasses
import functools
import json
import pathlib
import time
from typing import Any

from polymimic._atomic import atomic_write_text
from polymimic._native import PrimitiveRecognizer
from polymimic.crowds import member_seed
from polymimic.datasets import load_demonstrations, save_demonstrations, save_self_observation
from polymimic.field import Demonstration, record
from polymimic.matrix.cell_files import load_cell_evaluation, load_cell_tuning, load_cell_weighing
from polymimic.matrix.config import DemonstratorSet, MatrixConfig, demonstrator_sets, stored_column
from polymimic.matrix.draws import pool_size
from polymimic.matrix.pictures import draw_pictures, one_attempt, pictured_attempt_path, pictured_trial
from polymimic.matrix.report import matrix_html, matrix_markdown
from polymimic.matrix.rundir import MatrixDir
from polymimic.matrix.summary import draw_heat_map, gather
from polymimic.matrix.tasks import (
    Shared,
    attempt_task,
    bco_task,
    dumps,
    polymimic_task,
    recognise_task,
    tuning_task,
    weighing_task,
)
from polymimic.matrix.weighing import chosen_weighting, is_weighed
from polymimic.runs.backends import TaskRunner
from polymimic.runs.progress import progress
from polymimic.runs.roster_config import demonstrations_expected, record_demonstrator
from polymimic.runs.stages import Staged, each_member_recorded

__all__ = ["Matrix"]


@dataclasses.dataclass
class Matrix(Staged):
    """One matrix run: its directory, config, where tasks run, and whether to keep quiet."""

    run: MatrixDir
    config: MatrixConfig
    runner: TaskRunner
    quiet: bool = False

    def run_all(self) -> float:
        """Every step, in order; the seconds they took."""
        started = time.perf_counter()
        self._stage("recognise", self.recognise)
        self._stage("record", self.record)
        shared = self.shared()
        self._stage("weigh", lambda: self.weigh(shared))
        self._stage("polymimic", lambda: self.polymimic(shared))
        self._stage("attempts", lambda: self.attempts(shared))
        self._stage("tune", lambda: self.tune(shared))
        self._stage("bco", lambda: self.bco(shared))
        self._stage("report", self.report)
        return time.perf_counter() - started

    def rows(self) -> tuple[str, ...]:
        """The imitator bodies, one row each."""
        return self.config.matrix.imitators

    def sets(self) -> dict[str, dict[str, DemonstratorSet]]:
        """Each row's demonstrator set per column."""
        return {row: demonstrator_sets(row, self.config.run.demonstrators) for row in self.rows()}

    def cells(self) -> list[tuple[str, str]]:
        """The cells computed: each row's columns, a built-in body's own-body cell being another's."""
        cells = [(row, stored_column(sets, column)) for row, sets in self.sets().items()
                 for column in self.config.columns()]
        return list(dict.fromkeys(cells))

    # 1. Each imitator's recogniser.

    def recognise(self) -> int:
        """Stage: each row's self-observation and recogniser; returns the rows done now."""
        rows = [row for row in self.rows()
                if not self.run.finished(self.run.recognizer_of(row), PrimitiveRecognizer.load)]
        with progress(total=len(rows), desc="recognise", quiet=self.quiet) as bar:
            for row, (sequences, recognizer) in self.runner.map(recognise_task, self.config, rows):
                # The self-observation first: a recogniser on disk is done.
                save_self_observation(sequences, self.run.own_self_observation_path(row))
                recognizer.save(self.run.recognizer_of(row))
                bar.update(1)
        return len(rows)

    # 2. The demonstrations.

    def _unique_sets(self) -> dict[str, DemonstratorSet]:
        return {s.name: s for sets in self.sets().values() for s in sets.values()}

    def record(self) -> int:
        """Stage: every demonstrator set recorded; returns the sets recorded now."""
        settings = self.config.matrix
        sizes = settings.sizes
        made, n = 0, pool_size(sizes.demonstrations_per_configuration, max(sizes.trials, settings.bco_fits))
        unique = self._unique_sets()
        with progress(total=len(unique), desc="record", quiet=self.quiet) as bar:
            for name, chosen in unique.items():
                path = self.run.set_path(name)
                bodies = self.config.run.bodies
                whole = (functools.partial(each_member_recorded, names=chosen.names, n=n, bodies=bodies)
                         if chosen.spec is None or demonstrations_expected(chosen.spec, n) is not None
                         else functools.partial(load_demonstrations, bodies=bodies))
                if not self.run.finished(path, whole):
                    save_demonstrations(self._recorded(chosen, n), path)
                    made += 1
                bar.update(1)
        return made

    def _recorded(self, chosen: DemonstratorSet, n: int) -> list[Demonstration]:
        """Every member's ``n`` demonstrations per configuration, member by member, each member
        under its own seed (as :func:`polymimic.crowds.record_crowd` seeds a crowd's); a column of
        yours as a reproduction records it (a log's every valid episode)."""
        if chosen.spec is not None:
            demos, said = record_demonstrator(chosen.spec, n=n, seed=member_seed(self.config.seeds.demonstrations, 0),
                                              field_config=self.config.run.field, bodies=self.config.run.bodies)
            self.say(f"record: {said}")
            return demos
        out: list[Demonstration] = []
        for index, (name, controller, body, lapse) in enumerate(chosen.members):
            for configuration in (1, 2):
                demos = record(controller, configuration=configuration, n=n,
                               seed=member_seed(self.config.seeds.demonstrations, index), lapse=lapse,
                               config=self.config.run.field, body=self.config.body(body))
                out += [dataclasses.replace(d, demonstrator=name) for d in demos]
        return out

    def shared(self) -> Shared:
        """What every task reads: the rows' recognisers, the sets' demonstrations, the sets."""
        recognizers = {row: PrimitiveRecognizer.load(self.run.require(self.run.recognizer_of(row), "matrix"))
                       for row in self.rows()}
        demonstrations = {name: load_demonstrations(self.run.require(self.run.set_path(name), "matrix"),
                                                    bodies=self.config.run.bodies)
                          for name in self._unique_sets()}
        return Shared(self.config, recognizers, demonstrations, self.sets())

    # 3-7. polymimic and bco in every cell, and the pictured attempts.

    def _weighed_cells(self) -> list[tuple[str, str]]:
        """The cells where polymimic chooses how to weigh the members: those of a crowd."""
        return [(row, column) for row, column in self.cells() if is_weighed(self.config, row, column)]

    def weigh(self, shared: Shared) -> int:
        """Stage: polymimic's weighting of a crowd's members chosen on validation; returns the trials run."""
        jobs = [(row, column, weighting) for row, column in self._weighed_cells()
                for weighting in self.config.matrix.weightings
                if not self.run.finished(self.run.weighing_path(row, column, weighting), load_cell_weighing)]
        with progress(total=len(jobs), desc="weigh", quiet=self.quiet) as bar:
            for _, result in self.runner.map(weighing_task, shared, jobs):
                _write_in_cell(self.run.weighing_path(result["row"], result["column"], result["weighting"]), result)
                bar.update(1)
        return len(jobs)

    def _done(self, row: str, column: str, method: str, seed: int, weighting: str | None = None) -> bool:
        saved = self.run.loaded(self.run.evaluation_path(row, column, method, seed), load_cell_evaluation)
        attempts = self.config.evaluation_attempts()
        return saved is not None and (saved["attempts"], saved["evaluation_seed"], saved["weighting"]) == (
            attempts.count, attempts.seed, weighting)

    def _write(self, result: dict[str, Any]) -> None:
        _write_in_cell(self.run.evaluation_path(result["row"], result["column"], result["method"], result["seed"]),
                       result)

    def polymimic(self, shared: Shared) -> int:
        """Stage: polymimic's trials and evaluations in every cell; returns those run now."""
        weighting = {(row, column): chosen_weighting(self.run, self.config, row, column)[0]
                     for row, column in self.cells()}
        jobs = [(row, column, seed, weighting[row, column]) for row, column in self.cells()
                for seed in self.config.trial_seeds()
                if not self._done(row, column, "polymimic", seed, weighting[row, column])]
        # The mixed crowd's cells are the longest: first, so that no worker idles at the end.
        jobs.sort(key=lambda job: job[1] != "mixed_bodies")
        with progress(total=len(jobs), desc="polymimic", quiet=self.quiet) as bar:
            for _, result in self.runner.map(polymimic_task, shared, jobs):
                self._write(result)
                bar.update(1)
        return len(jobs)

    def attempts(self, shared: Shared) -> int:
        """Stage: each row's pictured attempt, played again and saved; returns those played now."""
        jobs = [(row, *pictured_trial(self.run, self.config, row)) for row in self.rows()
                if not self.run.finished(pictured_attempt_path(self.run, self.config, row),
                                         functools.partial(one_attempt, bodies=self.config.run.bodies))]
        with progress(total=len(jobs), desc="attempts", quiet=self.quiet) as bar:
            for _, result in self.runner.map(attempt_task, shared, jobs):
                row, column, seed = result["row"], result["column"], result["seed"]
                saved = load_cell_evaluation(self.run.require(self.run.evaluation_path(row, column, "polymimic", seed),
                                                              "matrix"))
                if (saved["weighting"], saved["outcomes"]) != (result["weighting"], result["outcomes"]):
                    raise RuntimeError(f"{row} ← {column}: trial {seed} played again is not its saved evaluation")
                save_demonstrations([result["attempt"]], pictured_attempt_path(self.run, self.config, row))
                bar.update(1)
        return len(jobs)

    def tune(self, shared: Shared) -> int:
        """Stage: ``bco`` tuned in every cell; returns the tunings run."""
        jobs = [(row, column) for row, column in self.cells()
                if not self.run.finished(self.run.tuning_path(row, column), load_cell_tuning)]
        jobs.sort(key=lambda job: job[1] != "mixed_bodies")
        with progress(total=len(jobs), desc="tune bco", quiet=self.quiet) as bar:
            for _, result in self.runner.map(tuning_task, shared, jobs):
                # The evaluation first: a tuning on disk is done, and a lost evaluation is redone.
                self._write(result.pop("evaluation"))
                _write_in_cell(self.run.tuning_path(result["row"], result["column"]), result)
                bar.update(1)
        return len(jobs)

    def bco(self, shared: Shared) -> int:
        """Stage: ``bco``'s fits evaluated in every cell; returns the fits run."""
        jobs = []
        for row, column in self.cells():
            tuned = load_cell_tuning(self.run.require(self.run.tuning_path(row, column), "matrix"))["hyperparameters"]
            jobs += [(row, column, seed, tuned) for seed in self.config.fit_seeds()
                     if not self._done(row, column, "bco", seed)]
        jobs.sort(key=lambda job: job[1] != "mixed_bodies")
        with progress(total=len(jobs), desc="bco", quiet=self.quiet) as bar:
            for _, result in self.runner.map(bco_task, shared, jobs):
                self._write(result)
                bar.update(1)
        return len(jobs)

    # 8. The summary, the pictures and the report.

    def report(self) -> int:
        """Stage: ``matrix.json``, the heat map, the pictures and the report; returns the files
        written."""
        summary = gather(self.run, self.config)
        atomic_write_text(self.run.results_path, json.dumps(summary, indent=1) + "\n")
        draw_heat_map(summary, self.run.plots)
        pictures = draw_pictures(self.run, self.config)
        stages = self.run.manifest()["stages"]
        seconds = {name: float(stages[name]["seconds"])
                   for name in ("recognise", "record", "weigh", "polymimic", "attempts", "tune", "bco")
                   if isinstance(stages.get(name, {}).get("seconds"), (int, float))}
        markdown = matrix_markdown(summary, seconds=seconds, pictures=pictures)
        atomic_write_text(self.run.report_md_path, markdown + "\n")
        atomic_write_text(self.run.report_html_path, matrix_html(markdown, images_from=str(self.run.path)))
        return 4 + len(pictures)


def _write_in_cell(path: pathlib.Path, result: dict[str, Any]) -> None:
    """``result`` to its file in a cell's folder, made on first use, atomically."""
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write_text(path, dumps(result))


def run_matrix(run: MatrixDir, config: MatrixConfig, runner: TaskRunner, *, quiet: bool = False) -> float:
    """Every step of a matrix run in ``run`` (opened with ``config``); the seconds it took."""
    with run.lock("polymimic matrix"):
        matrix = Matrix(run=run, config=config, runner=runner, quiet=quiet)
        return matrix.run_all()
