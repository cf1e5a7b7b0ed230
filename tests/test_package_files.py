"""The licence texts, the citation and the changelog ship and agree with the package's metadata."""

import pathlib
import sys

import yaml

if sys.version_info >= (3, 11):
    import tomllib
else:
    import tomli as tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent


def test_licence_files_are_the_declared_licences():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    workspace = tomllib.loads((ROOT / "Cargo.toml").read_text())["workspace"]["package"]
    assert project["license"] == workspace["license"] == "MIT OR Apache-2.0"
    assert project["license-files"] == ["LICENSE-MIT", "LICENSE-APACHE"]
    assert (ROOT / "LICENSE-MIT").read_text().startswith("MIT License\n")
    assert "Apache License\n" in (ROOT / "LICENSE-APACHE").read_text().splitlines(keepends=True)[0]


def test_citation_names_this_version_and_the_thesis():
    citation = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    workspace = tomllib.loads((ROOT / "Cargo.toml").read_text())["workspace"]["package"]
    assert citation["cff-version"] == "1.2.0"
    assert citation["version"] == workspace["version"]
    assert citation["repository-code"] == workspace["repository"]
    assert sorted(citation["license"]) == ["Apache-2.0", "MIT"]
    (thesis,) = [r for r in citation["references"] if r["type"] == "thesis"]
    assert thesis["title"] == "Imitation Learning from Multiple Demonstrators Using Global Vision"


def test_changelog_starts_at_this_version():
    workspace = tomllib.loads((ROOT / "Cargo.toml").read_text())["workspace"]["package"]
    headings = [line for line in (ROOT / "CHANGELOG.md").read_text().splitlines() if line.startswith("## ")]
    assert headings[0].startswith(f"## {workspace['version']} ")
