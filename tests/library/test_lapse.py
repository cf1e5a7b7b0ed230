"""Lapsing demonstrators through the library (docs/guides/crowd.md) and 64-bit episode seeds."""

from __future__ import annotations

import math

import numpy as np
import pytest

import polymimic
from polymimic import _native
from polymimic._arguments import probability
from polymimic.field import DEMONSTRATORS, PRIMITIVES, command_primitives

# The humanoid's Walk Forward, Walk Backward, Turn Left, Turn Right and Wait: a lapse's commands
# on the body that takes no primitives.
HUMANOID_LAPSE_IDS = {211, 214, 215, 216, 200}


def same_frames(a: list[polymimic.Demonstration], b: list[polymimic.Demonstration]) -> bool:
    return len(a) == len(b) and all(
        x.seed == y.seed and x.outcome == y.outcome and x.frames.tobytes() == y.frames.tobytes() for x, y in zip(a, b))


@pytest.mark.parametrize("demonstrator", DEMONSTRATORS)
def test_no_lapse_is_the_demonstrators_own_recording(demonstrator):
    own = polymimic.record(demonstrator, configuration=1, n=3, seed=5)
    assert same_frames(polymimic.record(demonstrator, configuration=1, n=3, seed=5, lapse=0.0), own)
    assert same_frames(polymimic.record(demonstrator, configuration=1, n=3, seed=5, lapse=0), own)


@pytest.mark.parametrize("demonstrator", DEMONSTRATORS)
def test_a_full_lapse_sends_one_random_primitive_a_second(demonstrator):
    demos = polymimic.record(demonstrator, configuration=2, n=3, seed=5, lapse=1.0)
    allowed = HUMANOID_LAPSE_IDS if demonstrator == "humanoid" else {0, 1, 2, 3, 4}
    primitives = set()
    for d in demos:
        commands = d.frames["command"]
        assert set(commands.tolist()) <= allowed
        for start in range(0, len(commands), 30):
            assert len(set(commands[start:start + 30].tolist())) == 1
        primitives |= set(command_primitives()[commands].tolist())
    assert primitives == set(PRIMITIVES)


def test_a_lapse_changes_the_recording_and_repeats_under_its_seed():
    own = polymimic.record("expert", configuration=1, n=2, seed=5)
    half = polymimic.record("expert", configuration=1, n=2, seed=5, lapse=0.5)
    assert same_frames(polymimic.record("expert", configuration=1, n=2, seed=5, lapse=0.5), half)
    assert not same_frames(half, own)
    commands = np.concatenate([d.frames["command"] for d in half])
    assert (commands < 5).any() and (commands >= 100).any()  # some seconds lapsed, some the Expert's


@pytest.mark.parametrize("bad", [1.5, -0.1, math.nan, math.inf, True, "0.5", None, [0.5]])
def test_a_lapse_outside_the_unit_interval_is_refused_by_name(bad):
    with pytest.raises(ValueError, match=r"lapse must be a number in \[0, 1\], got") as error:
        polymimic.record("expert", configuration=1, n=1, lapse=bad)
    assert repr(bad) in str(error.value)


@pytest.mark.parametrize("bad", [1.5, math.nan, -0.25])
def test_the_native_recording_refuses_a_bad_lapse_too(bad):
    with pytest.raises(ValueError, match=r"lapse.*\[0, 1\]"):
        _native.record_demonstrations("expert", configuration=1, n=1, lapse=bad)


def test_probability_takes_numpy_numbers_and_the_ends():
    assert probability("lapse", np.float32(0.5)) == 0.5
    assert probability("lapse", 0) == 0.0 and probability("lapse", 1) == 1.0


@pytest.mark.parametrize("seed", [2**63, 2**64 - 1, np.uint64(2**64 - 1)])
def test_an_episode_takes_any_64_bit_seed(seed):
    episode = polymimic.Episode("lego", configuration=1, seed=seed)
    assert episode.frames.shape == (0, 7)


def test_the_top_bit_of_an_episode_seed_matters():
    def first(seed):
        episode = polymimic.Episode("lego", configuration=1, seed=seed)
        return episode.step("stop")[0].tolist()

    assert first(2**63 + 5) != first(5)


@pytest.mark.parametrize("seed", [2**64, -1, -(2**63) - 1])
def test_an_episode_seed_outside_64_bits_is_refused(seed):
    with pytest.raises(ValueError, match=r"seed must be in 0\.\.18446744073709551615") as error:
        polymimic.Episode("lego", configuration=1, seed=seed)
    assert str(seed) in str(error.value)


@pytest.mark.parametrize("seed", [True, 1.0, "1"])
def test_an_episode_seed_must_be_an_integer(seed):
    with pytest.raises(TypeError, match="seed must be an integer"):
        polymimic.Episode("lego", configuration=1, seed=seed)


def test_recordings_take_64_bit_seeds():
    demos = polymimic.record("poor", configuration=1, n=1, seed=2**64 - 1)
    assert len(demos) == 1
    assert len(polymimic.self_observation(1, seed=2**64 - 1)) == 5
    with pytest.raises(ValueError, match="seed"):
        polymimic.record("poor", configuration=1, n=1, seed=2**64)
