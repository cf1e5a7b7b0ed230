"""The shipped type stubs match the compiled module."""

import subprocess
import sys

import pytest


def test_stubtest_finds_no_mismatch():
    pytest.importorskip("mypy")
    result = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "polymimic._native", "--ignore-missing-stub"],
        capture_output=True, text=True,
    )
    assert result.returncode == 0, result.stdout + result.stderr
