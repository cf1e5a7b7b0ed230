"""The examples in the README, in every documentation page and in docstrings run, and say what they print."""

import doctest
import importlib
import pathlib
import pkgutil

import pytest

import polymimic

ROOT = pathlib.Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
PAGES = sorted((ROOT / "docs").rglob("*.md"))


def python_examples(page):
    """The page's ```python blocks with >>> prompts, one doctest in the page's order."""
    blocks = [block.split("```", 1)[0] for block in page.read_text().split("```python\n")[1:]]
    return [block for block in blocks if ">>> " in block]


def run_examples(page):
    parser = doctest.DocTestParser()
    test = parser.get_doctest("\n".join(python_examples(page)), {}, page.name, str(page), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    return runner


def test_readme_examples():
    assert python_examples(README), "the README has Python examples"
    runner = run_examples(README)
    assert runner.failures == 0


@pytest.mark.parametrize("page", [p for p in PAGES if python_examples(p)], ids=lambda p: str(p.relative_to(ROOT)))
def test_docs_page_examples(page):
    """Every example of every documentation page runs and prints what the page says."""
    runner = run_examples(page)
    assert runner.tries > 0 and runner.failures == 0


def test_every_python_block_in_the_docs_is_run():
    """A ```python block without prompts would be shown but never run: the pages have none."""
    for page in PAGES + [README]:
        blocks = [b.split("```", 1)[0] for b in page.read_text().split("```python\n")[1:]]
        assert all(">>> " in block for block in blocks), page


def test_readme_quick_start_is_what_ci_runs():
    ci = (README.parent / ".ci" / "run").read_text().strip().splitlines()[-1]
    quick_start = README.read_text().split("## Quick start", 1)[1].split("```sh\n", 1)[1].split("```", 1)[0]
    lines = quick_start.strip().splitlines()
    assert len(lines) == 2
    assert ci == lines[1]


MODULES = [polymimic] + [
    importlib.import_module(info.name)
    for info in pkgutil.walk_packages(polymimic.__path__, prefix="polymimic.")
    if not info.name.rsplit(".", 1)[-1].startswith("_")
]


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_docstring_examples(module):
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
    assert result.failed == 0


OWN_DATA = ROOT / "docs" / "guides" / "own-data.md"


def test_own_data_body_table_is_a_body():
    """The guide's [bodies.<name>] example reads as the body its comments describe."""
    from polymimic._toml import loads
    from polymimic.bodies import bodies_from_tables

    blocks = [b.split("```", 1)[0] for b in OWN_DATA.read_text().split("```toml\n")[1:]]
    tables = [loads(b) for b in blocks if "[bodies." in b and "[experiments." not in b]
    assert tables, "the guide shows a body table"
    for table in tables:
        for name, body in bodies_from_tables(table["bodies"]).items():
            assert body.primitives_mm_s["forward"] == (60.0, 58.0), name
            assert body.primitives_mm_s["backward"] == (-60.0, -60.0), "the others derived from the top speed"


def test_own_data_roster_is_a_run_config():
    """The guide's own-experiments example reads as a run config with those experiments."""
    from polymimic.runs.config import RunConfig

    blocks = [b.split("```", 1)[0] for b in OWN_DATA.read_text().split("```toml\n")[1:]]
    rosters = [b for b in blocks if "[experiments." in b]
    assert rosters, "the guide shows an own experiment"
    config = RunConfig.from_toml(rosters[0], base_dir=ROOT)
    assert list(config.demonstrators) == ["wanderer_poor", "chaser", "logged", "alice"]
    assert config.own_experiments["mine"].skill_order[0] == "expert"
    assert config.demonstrators["logged"].log == str(ROOT / "logs" / "overhead.csv")


def test_readme_is_a_front_page():
    """The README stays a front page: short, the headline comparison near the top, the citation
    and the API reference one link away."""
    lines = README.read_text().splitlines()
    assert len(lines) <= 250
    first_screen = "\n".join(lines[:60])
    assert "| `polymimic` |" in first_screen and "| `bc` |" in first_screen
    text = "\n".join(lines)
    assert "## Citing" in text and "CITATION.cff" in text
    assert "docs/api/index.md" in text
