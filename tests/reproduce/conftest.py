"""Fixtures shared by the tests of the reproduction: runs small enough for a test."""

import pytest


def _tiny_run_toml(*, trials=3, evaluated_imitators=2, attempts_per_configuration=3, extra=""):
    """The config of a run small enough for a test: a few trials on a few demonstrations."""
    return f"""
[recognizer]
train_per_primitive = 60
test_per_primitive = 20
codebook_size = 32
[experiments]
trials = {trials}
demonstrations_per_configuration = 8
attempts_per_configuration = {attempts_per_configuration}
evaluated_imitators = {evaluated_imitators}
{extra}"""


@pytest.fixture(scope="session")
def tiny_run_toml():
    """Makes the TOML config of a tiny run; keywords change its sizes, ``extra`` adds lines."""
    return _tiny_run_toml
