"""results.json, the figures and the report of a tiny run."""

import json
import re

import pytest

from polymimic.reproduce import report as reports
from polymimic.reproduce import thesis
from polymimic.reproduce.figures import FIGURES
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.stages import Context, reproduce
from polymimic.runs import markdown, stats
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import RunConfig

PRIMITIVES = {"forward", "backward", "left", "right", "stop"}
MOVING = {"forward", "backward", "left", "right"}
COUNTS = {"created", "deleted", "permanent", "candidates", "duplicates", "candidates_permanent"}


@pytest.fixture(scope="module")
def run(tiny_run_toml, tmp_path_factory):
    run = RunDir(tmp_path_factory.mktemp("run") / "tiny")
    config = run.open(RunConfig.from_toml(tiny_run_toml(extra="lp_stride = 50\n")))
    reproduce(Context(run=run, config=config, runner=TaskRunner(workers=1), quiet=True))
    return run


@pytest.fixture(scope="module")
def results(run):
    return json.loads(run.results_path.read_text())


def _share(value):
    return isinstance(value, float) and 0.0 <= value <= 1.0


def _mean_sd(cell):
    return set(cell) == {"mean", "sd"} and all(isinstance(v, float) for v in cell.values()) and cell["sd"] >= 0


def test_results_schema(results):
    assert set(results["primitive_stats"]) == PRIMITIVES
    for row in results["primitive_stats"].values():
        assert {"distance_mean_mm", "distance_sd_mm", "rotation_mean_deg", "rotation_sd_deg"} <= set(row)
    assert set(results["hmm_accuracy"]) == MOVING and all(map(_share, results["hmm_accuracy"].values()))
    assert set(results["segments"]) == {"expert", "poor", "tiny", "humanoid", "average", "imitator"}
    for row in results["segments"].values():
        assert _share(row["command_match"]) and _share(row["gaps"])
    assert set(results["demonstrators"]) == {"expert", "poor", "tiny", "humanoid", "average"}
    for row in results["demonstrators"].values():
        assert row["attempts"] == 16 and 0 <= row["goals"] + row["own_goals"] <= row["attempts"]
    assert set(results["experiments"]) == {"heterogeneous_rcb", "heterogeneous_bcr", "varying_skill"}


@pytest.mark.parametrize("name, demonstrators", [
    ("heterogeneous_rcb", ["expert", "tiny", "humanoid"]),
    ("heterogeneous_bcr", ["humanoid", "tiny", "expert"]),
    ("varying_skill", ["poor", "average", "expert"]),
])
def test_experiment_schema(results, name, demonstrators):
    e = results["experiments"][name]
    assert e["trials"] == 3 and e["ordering"] == demonstrators
    assert list(e["match_rate"]) == ["imitator", *demonstrators]
    assert all(_mean_sd(c) and _share(c["mean"]) for c in e["match_rate"].values())
    for model in ["imitator", *demonstrators]:
        assert set(e["behaviours"][model]) == COUNTS and all(map(_mean_sd, e["behaviours"][model].values()))
    assert list(e["final_lp"]) == demonstrators and all(_mean_sd(c) for c in e["final_lp"].values())
    if name == "varying_skill":
        assert isinstance(e["lp_order_hits"], int) and 0 <= e["lp_order_hits"] <= 3
    else:
        assert e["lp_order_hits"] is None
    assert all(len(trials) == 3 for trials in e["lp_over_time"]["trials"].values())
    for key in ("imitator", "imitator_thesis_control"):
        cell = e[key]
        assert cell["attempts"] == 6 and cell["imitators"] == 2
        assert 0 <= cell["goals"] <= 6 and 0 <= cell["own_goals"] <= 6
        assert cell["goals_sd"] >= 0 and cell["own_goals_sd"] >= 0


def test_results_are_strict_json(run):
    json.loads(run.results_path.read_text(), parse_constant=lambda c: pytest.fail(f"{c} in results.json"))


def test_appendix_b_rows(results):
    table = results["appendix_b"]
    assert table["models"] == 3 * 3 * 4
    for key in ("created", "permanent", "predicting_ball"):
        rows = table[key]
        assert 0 < len(rows) <= 30
        counts = [r[key if key != "created" else "count"] for r in rows]
        assert counts == sorted(counts, reverse=True)
        assert all(re.fullmatch(r"[FBLRS](,[FBLRS])+", r["primitives"]) for r in rows)
        assert all(r["permanent"] <= r["count"] <= table["models"] for r in rows)


def test_every_figure_is_drawn(run):
    for number in FIGURES:
        assert (run.path / f"plots/fig_{number.replace('.', '_')}.png").stat().st_size > 1000


def test_the_report_sets_every_item_beside_the_thesis(run):
    text = run.report_md_path.read_text()
    items = ["Table 3.1", "Fig 4.5", "Table 4.3", "Table 4.5", "Tables 4.6 and 4.9", "Table 4.7", "Table 4.8",
             "Table 4.10", "Table 4.11", "Table B.1", "Table B.2", "Table B.3",
             *(f"Fig {n}" for n in FIGURES)]
    for item in items:
        assert re.search(rf"^#+ .*{re.escape(item)}\b", text, re.M) or f"![{item}:" in text, item
    # The thesis's own numbers are there, beside ours.
    assert "91.24 %" in text and "42.25 (12.98)" in text and "F,F,R,B" in text
    assert text.count("**Shape:**") >= 25
    summary = re.search(r"## Shape checks: (\d+) of (\d+) hold", text)
    assert summary and int(summary.group(1)) <= int(summary.group(2))


def test_the_html_report_stands_alone(run):
    page = run.report_html_path.read_text()
    assert page.startswith("<!DOCTYPE html>") and "<table>" in page
    assert page.count("src=\"data:image/png;base64,") == len(FIGURES) + 1
    assert "src=\"plots/" not in page


def test_verdicts_and_formatting():
    assert reports.verdict("Expert first", None).endswith("— **n/a (too little data)**")
    assert stats.msd({"mean": 0.914, "sd": 0.012}, share=True) == "91.4 % (1.2 %)"
    assert stats.msd(None) == "—"
    assert thesis.IMITATOR_GOALS["heterogeneous_bcr"] == {"goals": 7, "own_goals": 13, "attempts": 50}


def test_markdown_converter(tmp_path):
    (tmp_path / "plots").mkdir()
    (tmp_path / "plots" / "a.png").write_bytes(b"\x89PNG fake")
    body = markdown.to_html_body("## A & B\n\ntext with `x<y>` and **bold**\nsame paragraph\n\n- one\n- two\n\n"
                                 "![Fig 1: a](plots/a.png)\n\n![gone](plots/missing.png)\n| a | b |\n| 1 | 2 |\n",
                                 images_from=tmp_path)
    assert '<h2 id="a-b">A &amp; B</h2>' in body
    assert "<p>text with <code>x&lt;y&gt;</code> and <strong>bold</strong> same paragraph</p>" in body
    assert "<ul>\n<li>one</li>\n<li>two</li>\n</ul>" in body
    assert 'src="data:image/png;base64,iVBORyBmYWtl"' in body
    assert 'src="plots/missing.png"' in body
    assert "<tr><td>a</td><td>b</td></tr>" in body and "<thead>" not in body  # no separator: no header


def test_table_3_1_holds_within_the_thesiss_spreads_and_our_standard_errors():
    backward = thesis.TABLE_3_1["backward"]
    _like_table_3_1 = reports._like_table_3_1

    def row(**change):
        base = {"distance_mean_mm": backward["distance_mean_mm"], "distance_sd_mm": backward["distance_sd_mm"],
                "rotation_mean_deg": backward["rotation_mean_deg"], "rotation_sd_deg": backward["rotation_sd_deg"],
                "count": 1000}
        return {**base, **change}

    assert _like_table_3_1(row(), backward)
    # Two standard errors of a 12.6° spread over 1000 sequences: 0.797°, more than 10 % of 2.29°.
    assert _like_table_3_1(row(rotation_mean_deg=backward["rotation_mean_deg"] + 0.79), backward)
    assert not _like_table_3_1(row(rotation_mean_deg=backward["rotation_mean_deg"] + 0.80), backward)
    assert not _like_table_3_1(row(rotation_mean_deg=backward["rotation_mean_deg"] + 0.79, count=4000), backward)
    # A spread 36 % too wide, as the default tracker's forward turn is sevenfold.
    assert not _like_table_3_1(row(rotation_sd_deg=1.36 * backward["rotation_sd_deg"]), backward)
    assert not _like_table_3_1(row(distance_mean_mm=0.85 * backward["distance_mean_mm"]), backward)
