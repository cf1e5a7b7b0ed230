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


def test_distils_check_is_the_one_the_validation_study_puts_first(monkeypatch):
    """Of the checks that never fell more than 1 below the teacher, the highest mean after 50 000
    steps is distil's default check (its practice attempts and its standard errors)."""
    import inspect

    from polymimic.practice.distil import distil
    from polymimic.practice.teacher import Gate

    monkeypatch.syspath_prepend(str(ROOT / "studies"))
    spec = importlib.util.spec_from_file_location("checks_study", ROOT / "studies" / "which_check_keeps_distil_safe.py")
    assert spec is not None and spec.loader is not None
    study = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(study)
    curves = MODULE.study_curves(MODULE.CHECK_STUDY)
    safe = {check: mean for check, mean in MODULE._means_after(curves).items()
            if min(min(p[2] for p in c) - c[0][2] for c in curves[check].values()) >= -1}
    winner = max(safe, key=safe.__getitem__)
    assert study.CHECKS[winner] == (Gate().attempts, inspect.signature(distil).parameters["confidence_z"].default)
