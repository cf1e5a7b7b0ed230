"""``bc`` against the plain cloner of ``benches/plain_cloner_vs_bc.py`` on a small mixed-body
crowd, as ``benches/plain_cloner_small_crowd.py`` runs them: the same demonstrations,
validation attempts and evaluation attempts, the benchmark's tuning budget, three fits each.
``bc`` must not be beaten by more than its own spread over fits."""

import importlib.util
import pathlib
import statistics

import pytest

pytest.importorskip("sklearn")

BENCH = pathlib.Path(__file__).parents[2] / "benches" / "plain_cloner_small_crowd.py"


def test_bc_is_not_beaten_by_the_plain_cloner_by_more_than_its_spread_over_fits():
    spec = importlib.util.spec_from_file_location("plain_cloner_small_crowd", BENCH)
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    plain_nets, bc_nets, chosen = bench.compare()
    assert statistics.mean(bc_nets) >= statistics.mean(plain_nets) - statistics.stdev(bc_nets), (
        bc_nets, plain_nets, chosen)
