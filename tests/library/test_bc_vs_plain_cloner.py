"""``bc`` against the plain cloner of ``studies/does_bc_match_a_plain_cloner.py`` on a small mixed-body
crowd, as ``studies/does_bc_match_a_plain_cloner_on_a_small_crowd.py`` runs them: the same demonstrations,
validation attempts and evaluation attempts, the benchmark's tuning budget, three fits each.
``bc`` must not be beaten by more than its own spread over fits."""

import importlib.util
import pathlib
import statistics

import pytest

pytest.importorskip("sklearn")

STUDY = pathlib.Path(__file__).parents[2] / "studies" / "does_bc_match_a_plain_cloner_on_a_small_crowd.py"


def test_bc_is_not_beaten_by_the_plain_cloner_by_more_than_its_spread_over_fits():
    spec = importlib.util.spec_from_file_location("does_bc_match_a_plain_cloner_on_a_small_crowd", STUDY)
    assert spec is not None and spec.loader is not None
    study = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(study)
    plain_nets, bc_nets, chosen = study.compare()
    assert statistics.mean(bc_nets) >= statistics.mean(plain_nets) - statistics.stdev(bc_nets), (
        bc_nets, plain_nets, chosen)
