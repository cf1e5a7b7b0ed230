"""What the demonstrations add: every method's floor (its net goals on the random crowd) and
its gain over it, in the summary and the report."""

import pytest

from polymimic.benchmark.report import benchmark_markdown
from polymimic.benchmark.summary import with_floors


def _method(net: float) -> dict:
    mean = {"mean": net, "sd": 0.0}
    return {"goals": mean, "own_goals": {"mean": 0.0, "sd": 0.0}, "net_goals": mean, "attempts": 50,
            "evaluated": 1, "hyperparameters": {}, "validation": None}


def _profile(nets: dict) -> dict:
    recovery = {"spearman": {"mean": None, "sd": None}, "kendall": {"mean": None, "sd": None}, "best_hits": None,
                "top_among_best": None}
    return {"methods": {m: _method(n) for m, n in nets.items()}, "demonstrators": {}, "trials": 1,
            "skill_recovery": recovery, "skill_by_outcomes": recovery}


def _summary(profiles: dict) -> dict:
    sizes = {"trials": 1, "demonstrations_per_configuration": 1, "attempts_per_configuration": 25,
             "validation_attempts_per_configuration": 50, "tuning_budget": 6, "max_decision_samples": 1,
             "lp_plugin_trials": 1, "baseline_fits": 1, "evaluation_seed": 0, "validation_seed": 0}
    return {"sizes": sizes, "controller_skill": {"expert": 0.98}, "profiles": profiles}


def test_each_method_gains_over_its_own_floor():
    profiles = {"one_good": _profile({"polymimic": 38.5, "bc": 20.0, "ppo": 44.0}),
                "random": _profile({"polymimic": 25.25, "bc": 1.5})}
    with_floors(profiles)
    ours = profiles["one_good"]["methods"]
    assert (ours["polymimic"]["floor"], ours["polymimic"]["gain_over_floor"]) == (25.25, 13.25)
    assert (ours["bc"]["floor"], ours["bc"]["gain_over_floor"]) == (1.5, 18.5)
    assert (ours["ppo"]["floor"], ours["ppo"]["gain_over_floor"]) == (None, None), "not run on the floor"
    assert profiles["random"]["methods"]["bc"]["gain_over_floor"] == 0.0
    text = benchmark_markdown(_summary(profiles))
    assert "## What the demonstrations add" in text
    assert "| polymimic | 25.2 | 38.5 (+13.2) |" in text and "| bc | 1.5 | 20.0 (+18.5) |" in text
    assert "| polymimic | 38.5 (0.0) | 0.0 (0.0) | 38.5 (0.0) | 25.2 | +13.2 |" in text


def test_without_the_random_crowd_there_is_no_floor():
    profiles = {"one_good": _profile({"polymimic": 38.0})}
    with_floors(profiles)
    assert profiles["one_good"]["methods"]["polymimic"]["floor"] is None
    text = benchmark_markdown(_summary(profiles))
    assert "## What the demonstrations add" not in text and "| n/a | n/a |" in text


@pytest.mark.parametrize(("ours", "uniform", "met"), [(40.0, 41.0, True), (39.9, 41.0, False), (45.0, 40.0, True)])
def test_the_lp_weighted_imitator_may_lose_at_most_one_net_goal_to_the_uniform_one(ours, uniform, met):
    from polymimic.benchmark.targets import check_targets

    summary = _summary({"half": _profile({"polymimic": ours, "polymimic_uniform_lp": uniform})})
    (target,) = [t for t in check_targets(summary) if "uniform_lp − 1" in t["statement"]]
    assert target["met"] is met
    (forty_five,) = [t for t in check_targets(summary) if "≥ 45" in t["statement"]]
    assert forty_five["met"] is (ours >= 45)
