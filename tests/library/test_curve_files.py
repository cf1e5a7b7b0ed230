"""The two learning-curve files a run keeps (a practice's, a ppo curve's) are read through one
check of their checkpoints: a curve that nets below zero loads, and each way of damaging one is
refused naming the file, the checkpoint and what disagrees."""

import json

import pytest

from polymimic import ModelFileError
from polymimic.benchmark.task_files import load_ppo_curve
from polymimic.runs.practising import load_practice


def _practice(checkpoints):
    return {"group": "half", "trial_seed": 0, "evaluation_seed": 1000, "attempts": 50, "budget": 100,
            "steps": 100, "method": "distil", "attempts_learned": 0, "attempts_lost": 0, "checkpoints": checkpoints}


def _point(checkpoint, steps, goals, own, net=None):
    return {"checkpoint": checkpoint, "steps": steps, "goals": goals, "own_goals": own,
            "net_goals": goals - own if net is None else net, "attempts_learned": 0, "attempts_lost": 0}


def _ppo(checkpoints):
    return {"seed": 0, "evaluation_seed": 1000, "attempts": 50, "total_timesteps": 100, "eval_every": 50,
            "checkpoints": checkpoints}


def _written(tmp_path, data):
    path = tmp_path / "curve.json"
    path.write_text(json.dumps(data))
    return path


def test_a_practice_netting_below_zero_loads(tmp_path):
    saved = load_practice(_written(tmp_path, _practice([_point(0, 0, 2, 9), _point(100, 100, 5, 7)])))
    assert [p["net_goals"] for p in saved["checkpoints"]] == [-7, -2]


@pytest.mark.parametrize(("checkpoints", "message"), [
    ([], "key 'checkpoints' must list objects"),
    ([_point(0, 0, 2, 1, net=3), _point(100, 100, 2, 1)], "checkpoint 0: its goals, own goals and net goals disagree"),
    ([_point(0, 0, 2, 1), _point(100, 100, 40, 20)], "checkpoint 1: its goals, own goals and net goals disagree"),
    ([_point(0, 0, 2, 1), _point(100, 100, 2, 1, net=1.0)], "checkpoint 1: its goals, own goals and net goals"),
    ([_point(0, 0, 2, 1), _point(100, 120, 2, 1)], "checkpoint 1: it played 120 steps, beyond its checkpoint 100"),
    ([_point(0, 0, 2, 1), _point(90, 90, 2, 1)], "the checkpoints must rise from 0 to the budget 100"),
])
def test_a_damaged_practice_is_refused_by_name(tmp_path, checkpoints, message):
    path = _written(tmp_path, _practice(checkpoints))
    with pytest.raises(ModelFileError, match=message) as error:
        load_practice(path)
    assert str(path) in str(error.value)


def test_a_practice_by_a_retired_method_reads_and_an_unknown_one_is_refused(tmp_path):
    points = [_point(0, 0, 2, 1), _point(100, 100, 3, 1)]
    older = {k: v for k, v in _practice(points).items() if k != "method"}
    assert load_practice(_written(tmp_path, older))["method"] == "refine"  # before there was a choice
    assert load_practice(_written(tmp_path, {**older, "method": "refine"}))["method"] == "refine"
    with pytest.raises(ModelFileError, match="key 'method' must be one of explore, jsrl, distil, got 'refin'"):
        load_practice(_written(tmp_path, {**older, "method": "refin"}))


def _ppo_point(steps, goals, own, attempts=50):
    return {"env_steps": steps, "goals": goals, "own_goals": own, "net_goals": goals - own, "attempts": attempts}


def test_a_ppo_curve_netting_below_zero_loads(tmp_path):
    saved = load_ppo_curve(_written(tmp_path, _ppo([_ppo_point(0, 0, 12), _ppo_point(128, 3, 4)])))
    assert [p["net_goals"] for p in saved["checkpoints"]] == [-12, -1]


@pytest.mark.parametrize(("checkpoints", "message"), [
    ("none", "key 'checkpoints' must list objects"),
    ([_ppo_point(0, 0, 12), _ppo_point(128, 30, 30)], "checkpoint 1: its goals, own goals and net goals disagree"),
    ([_ppo_point(0, 0, 12), _ppo_point(128, 3, 4, attempts=10)], "checkpoint 1: key 'attempts' must be the curve's 50"),
    ([_ppo_point(0, 0, 12), _ppo_point(64, 3, 4)], "env_steps must rise from 0 to at least 100"),
])
def test_a_damaged_ppo_curve_is_refused_by_name(tmp_path, checkpoints, message):
    path = _written(tmp_path, _ppo(checkpoints))
    with pytest.raises(ModelFileError, match=message):
        load_ppo_curve(path)
