"""Each trial of a matrix cell learns from demonstrations of its own: its own recording seeds, or
a resample of a log's episodes, so a cell's spread measures what was demonstrated too."""

import pytest

import polymimic
from polymimic.matrix.config import MatrixConfig, demonstrator_sets
from polymimic.matrix.draws import drawn, resampled
from polymimic.matrix.tasks import Shared
from polymimic.runs.roster_config import LogDemonstrator


def _pool(n_total):
    return [d for configuration in (1, 2)
            for d in polymimic.record("tiny", configuration=configuration, n=n_total, seed=5)]


def test_each_draw_is_a_run_of_its_own_and_the_first_is_one_recording():
    pool = _pool(6)
    first = drawn(pool, names=("tiny",), per_configuration=2, draw=0, seed=0)
    second = drawn(pool, names=("tiny",), per_configuration=2, draw=1, seed=0)
    alone = [d for c in (1, 2) for d in polymimic.record("tiny", configuration=c, n=2, seed=5)]
    assert [d.frames.tobytes() for d in first] == [d.frames.tobytes() for d in alone]
    assert [(d.configuration, d.seed) for d in second] == [(d.configuration, d.seed) for d in pool[2:4] + pool[8:10]]
    assert not {d.seed for d in first if d.configuration == 1} & {d.seed for d in second if d.configuration == 1}
    with pytest.raises(ValueError, match="the pool holds 6 demonstrations of 'tiny' in configuration 1, too few for "
                                         "draw 3 of 2"):
        drawn(pool, names=("tiny",), per_configuration=2, draw=3, seed=0)


def test_a_logs_episodes_are_resampled_with_replacement_per_draw():
    pool = _pool(4)
    spec = LogDemonstrator(name="logged", log="log.csv", body="tiny")
    draws = [drawn(pool, names=("logged",), per_configuration=2, draw=i, seed=9, spec=spec) for i in range(4)]
    assert all(len(d) == len(pool) for d in draws)
    picked = [resampled(len(pool), draw=i, seed=9).tolist() for i in range(4)]
    assert [[pool.index(d) for d in draw] for draw in draws] == picked
    assert len({tuple(p) for p in picked}) == 4  # each draw its own
    assert any(len(set(p)) < len(p) for p in picked)  # with replacement


def test_every_trial_of_a_cell_gets_its_draw():
    config = MatrixConfig.from_toml('[matrix]\nimitators = ["lego"]\ncolumns = ["tiny"]\ntrials = 3\n'
                                    'demonstrations_per_configuration = 2\n[seeds]\nfirst_trial = 10\n')
    sets = {"lego": demonstrator_sets("lego")}
    shared = Shared(config, {}, {"tiny": _pool(6)}, sets)
    seeds = {shared.draw_of(seed): {d.seed for d in shared.cell("lego", "tiny", shared.draw_of(seed))[1]}
             for seed in config.trial_seeds()}
    assert sorted(seeds) == [0, 1, 2]
    assert seeds[0].isdisjoint(seeds[1]) and seeds[1].isdisjoint(seeds[2])
