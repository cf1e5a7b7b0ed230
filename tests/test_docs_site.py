"""The documentation site builds with `mkdocs build --strict`: a broken link, a missing anchor, a
page left out of the navigation or an API reference that does not resolve fails the build."""

import importlib.util
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent


@pytest.mark.skipif(importlib.util.find_spec("mkdocs") is None, reason="mkdocs is in the test extra")
def test_mkdocs_build_strict_is_clean(tmp_path):
    result = subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(tmp_path / "site")],
        cwd=ROOT, capture_output=True, text=True, timeout=600,
    )
    assert result.returncode == 0, result.stderr[-4000:]
    assert (tmp_path / "site" / "api" / "index.html").read_text().count("DiscreteHMM") > 0


def test_every_page_is_in_the_navigation():
    """mkdocs only warns about pages left out of `nav` when told to; the config tells it to."""
    config = (ROOT / "mkdocs.yml").read_text()
    assert "omitted_files: warn" in config and "strict: true" in config
