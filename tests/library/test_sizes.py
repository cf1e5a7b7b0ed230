"""The sizes every application's config embeds are checked once, naming the key and the value."""

import numpy as np
import pytest

from polymimic.runs.sizes import Sizes, TuningSizes


def test_a_numpy_integer_is_kept_as_the_int_it_stands_for():
    sizes = Sizes(trials=np.int64(3))
    assert sizes.trials == 3 and type(sizes.trials) is int
    assert type(TuningSizes(validation_seed=np.int32(7)).validation_seed) is int


@pytest.mark.parametrize(("make", "error", "message"), [
    (lambda: Sizes(trials=2.5), TypeError, "trials must be an integer, got 2.5"),
    (lambda: Sizes(attempts_per_configuration=True), TypeError, "attempts_per_configuration must be an integer, "
                                                                "got True"),
    (lambda: Sizes(demonstrations_per_configuration=0), ValueError, "demonstrations_per_configuration = 0 must be "
                                                                    "at least 1"),
    (lambda: TuningSizes(validation_seed=-1), ValueError, "validation_seed = -1 must be at least 0"),
    (lambda: TuningSizes(tuning_budget="6"), TypeError, "tuning_budget must be an integer, got '6'"),
])
def test_bad_sizes_are_named(make, error, message):
    with pytest.raises(error, match=message):
        make()
