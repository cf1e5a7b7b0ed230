"""Rank correlations against scipy's on fixed and random vectors, ties included."""

import pytest
from scipy import stats

from polymimic.ranking import kendall, ranks, spearman

FIXED = [
    ([1, 2, 3, 4, 5], [5, 6, 7, 8, 7]),
    ([0.05, 0.9, 0.9, 0.9, 0.9], [0.8, 0.3, 0.2, 0.4, 0.3]),  # one_good's shape: nine tied
    ([1, 2, 2, 3, 3, 3], [3, 1, 2, 2, 1, 3]),
    ([10, 9, 8, 7], [1, 2, 3, 4]),
]


@pytest.mark.parametrize(("x", "y"), FIXED)
def test_spearman_and_kendall_equal_scipys(x, y):
    assert spearman(x, y) == pytest.approx(stats.spearmanr(x, y).statistic, abs=1e-12)
    assert kendall(x, y) == pytest.approx(stats.kendalltau(x, y, variant="b").statistic, abs=1e-12)


def test_random_vectors_with_ties_agree_with_scipy(rng):
    for _ in range(50):
        n = int(rng.integers(2, 15))
        x, y = rng.integers(0, 4, n).astype(float), rng.normal(size=n).round(1)
        if len(set(x)) < 2 or len(set(y)) < 2:
            continue
        assert spearman(x, y) == pytest.approx(stats.spearmanr(x, y).statistic, abs=1e-12)
        assert kendall(x, y) == pytest.approx(stats.kendalltau(x, y).statistic, abs=1e-12)


def test_ranks_share_ties():
    assert ranks([3.0, 1.0, 3.0, 2.0]).tolist() == [3.5, 1.0, 3.5, 2.0]


def test_a_constant_side_has_no_correlation():
    assert spearman([0.5] * 4, [1, 2, 3, 4]) is None
    assert kendall([1, 2, 3], [7, 7, 7]) is None


@pytest.mark.parametrize(("x", "y", "match"), [
    ([1, 2], [1, 2, 3], "same length"),
    ([1], [1], "at least two"),
    ([1, float("nan")], [1, 2], "finite"),
])
def test_bad_input_is_named(x, y, match):
    with pytest.raises(ValueError, match=match):
        spearman(x, y)
