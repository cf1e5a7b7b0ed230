"""The results pages' main tables are what ``docs/write_results.py`` writes from the result files
committed under ``docs/results/``: one source for every number they hold."""

import importlib.util
import json
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULTS = ROOT / "docs" / "results"


def write_results():
    spec = importlib.util.spec_from_file_location("write_results", ROOT / "docs" / "write_results.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


MODULE = write_results()


@pytest.mark.parametrize("name", sorted(MODULE.TABLES))
def test_page_table_is_written_from_its_result_file(name):
    path, text, new = MODULE.page_with_table(name)
    if new is None:
        pytest.skip(f"{name}: its result file is not committed yet")
    assert new == text, f"{path.name} is stale: run python docs/write_results.py"


def test_result_files_are_small_and_each_has_its_provenance():
    provenance = json.loads((RESULTS / "provenance.json").read_text())
    files = sorted(RESULTS.glob("*.json"))
    assert any(f.name == "results.json" for f in files)
    for path in files:
        assert path.stat().st_size < 300_000, path.name
        if path.name != "provenance.json":
            assert {"command", "world", "machine"} <= set(provenance[path.name]), path.name


def test_the_reproduction_table_reads_the_default_world_from_results_json():
    """The check can fail: a number changed in the file changes the table."""
    results = json.loads((RESULTS / "results.json").read_text())
    column = MODULE.reproduction_column(results)
    results["demonstrators"]["expert"]["goals"] += 1
    assert MODULE.reproduction_column(results)[6] != column[6]


def test_the_practice_default_is_the_method_the_validation_study_puts_first(tmp_path, monkeypatch):
    """The default of practice is the study's winner, and the table's bold follows the file."""
    from polymimic.practice.methods import DEFAULT_METHOD

    table = MODULE.practice_validation_table()
    assert f"| `{DEFAULT_METHOD}` |" in table and table.count("**") == 2
    assert next(line for line in table.splitlines() if "**" in line).startswith(f"| `{DEFAULT_METHOD}` |")
    study = json.loads(MODULE.PRACTICE_STUDY.read_text())
    for key, value in study.items():
        if not key.startswith(f"{DEFAULT_METHOD}/"):
            value["curve"][-1][2] += 50  # every other method ends far above
    moved = tmp_path / "study.json"
    moved.write_text(json.dumps(study))
    monkeypatch.setattr(MODULE, "PRACTICE_STUDY", moved)
    assert not next(line for line in MODULE.practice_validation_table().splitlines()
                    if "**" in line).startswith(f"| `{DEFAULT_METHOD}` |")
