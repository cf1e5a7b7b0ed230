"""`polymimic benchmark` end to end on a tiny crowd: its files, its summary's schema and sense,
resumption, damaged files, and the same bits on one worker or two."""

import json
import shutil
import statistics
import sys

import pytest

from polymimic import Attempts
from polymimic.benchmark.config import METHODS, BenchmarkConfig
from polymimic.benchmark.rundir import BenchmarkDir
from polymimic.cli import main
from polymimic.learning import TrialResult

# Every default method, and polymimic_practice, which runs only when named.
TINY_METHODS = ["polymimic", "polymimic_thesis_control", "polymimic_uniform_lp", "polymimic_practice", "bco", "bco_lp",
                "bc", "bc_best", "random"]
TINY = """
[recognizer]
train_per_primitive = 40
codebook_size = 16
[benchmark]
profiles = ["pair", "duo"]
trials = 2
demonstrations_per_configuration = 2
attempts_per_configuration = 2
validation_attempts_per_configuration = 1
tuning_budget = 1
methods = {methods}
practice_steps = 300
practice_trials = 1
practice_method = "explore"
[profiles.pair]
members = [{ controller = "expert", lapse = 0.0, name = "good" }, { controller = "expert", lapse = 1.0, name = "bad" }]
[profiles.duo]
members = [{ controller = "tiny", lapse = 0.1 }, { controller = "poor", lapse = 0.6 }]
""".replace("{methods}", json.dumps(TINY_METHODS))


def _polymimic_on_pair() -> str:
    """The tiny benchmark, polymimic alone on the pair."""
    return (TINY.replace('profiles = ["pair", "duo"]', 'profiles = ["pair"]')
            .replace(f"methods = {json.dumps(TINY_METHODS)}", 'methods = ["polymimic"]'))


def _tiny_naming_its_own_methods() -> str:
    """The tiny benchmark without its methods line, for a variant that names its own."""
    return TINY.replace(f"methods = {json.dumps(TINY_METHODS)}\n", "", 1)


@pytest.fixture(scope="module")
def tiny_toml(tmp_path_factory):
    path = tmp_path_factory.mktemp("config") / "tiny.toml"
    path.write_text(TINY)
    return path


@pytest.fixture(scope="module")
def benchmarked(tmp_path_factory, tiny_toml):
    run = tmp_path_factory.mktemp("runs") / "bench"
    assert main(["benchmark", "--config", str(tiny_toml), "--run-dir", str(run), "--quiet", "--workers", "1"]) == 0
    return run


def _summary(run):
    return json.loads((run / "benchmark.json").read_text())


def test_the_run_holds_every_file(benchmarked):
    names = {p.name for p in benchmarked.rglob("*") if p.is_file()}
    assert {"benchmark.json", "benchmark.md", "benchmark.html", "crowd_pair.parquet", "crowd_duo.parquet",
            "trial_0.json", "trial_1_uniform_lp.json", "tuning_bc.json", "evaluation_polymimic_1.json",
            "evaluation_bco_lp_1.json", "evaluation_bc_0.json", "benchmark_net_goals.png", "controller_skill.json",
            "weighing_intent.json", "weighing_every.json", "weighing_outcome.json"} <= names
    # bc learns the same data in every trial: fitted and evaluated under three fit seeds.
    assert {"evaluation_bc_1.json", "evaluation_bc_2.json"} <= names and "evaluation_bc_3.json" not in names


def test_the_summary_follows_its_schema(benchmarked):
    summary = _summary(benchmarked)
    assert (summary["format"], summary["version"]) == ("polymimic.benchmark", 1)
    assert set(summary["sizes"]) >= {"trials", "attempts_per_configuration", "tuning_budget", "max_decision_samples"}
    pair = summary["profiles"]["pair"]
    assert set(pair) == {"demonstrators", "trials", "skill_recovery", "skill_by_outcomes", "methods",
                         "lp_over_training", "practice"}
    assert pair["trials"] == 2
    assert set(pair["demonstrators"]["good"]) == {"controller", "body", "lapse", "goals", "own_goals", "attempts",
                                                  "final_lp", "true_skill"}
    assert pair["demonstrators"]["good"]["attempts"] == 4
    assert set(pair["skill_recovery"]) == {"spearman", "kendall", "best_hits", "top_among_best"}
    assert list(pair["methods"]) == TINY_METHODS
    assert "polymimic_practice" not in METHODS and set(TINY_METHODS) == {*METHODS, "polymimic_practice"}
    for method, entry in pair["methods"].items():
        assert set(entry) == {"goals", "own_goals", "net_goals", "attempts", "evaluated", "hyperparameters",
                              "validation", "floor", "gain_over_floor"}
        assert entry["floor"] is None and entry["gain_over_floor"] is None, "the run has no random crowd"
        assert entry["attempts"] == 4
        assert entry["evaluated"] == (3 if method in ("bc", "bco", "bc_best", "random") else
                                      1 if method == "polymimic_practice" else 2)
        assert (entry["validation"] is None) == (method.startswith("polymimic") and method != "polymimic")
        assert entry["net_goals"]["mean"] == pytest.approx(entry["goals"]["mean"] - entry["own_goals"]["mean"])
    assert pair["methods"]["bc"]["hyperparameters"]["classifier"]
    assert summary["sizes"]["baseline_fits"] == 3
    assert pair["methods"]["polymimic"]["hyperparameters"]["control"] == "improved"
    duo = summary["profiles"]["duo"]
    assert duo["demonstrators"]["tiny_00"]["body"] == "tiny"


def test_polymimic_weighs_its_world_model_as_its_validation_prefers(benchmarked):
    """Each world weighting is played after the first trial on the baselines' validation
    attempts; the best by net goals, then goals (the first of equals), is evaluated."""
    from polymimic.baselines.tuning import validation_rank

    run = BenchmarkDir(benchmarked)
    summary = _summary(benchmarked)
    for profile in ("pair", "duo"):
        scores = [json.loads(run.weighing_path(profile, w).read_text()) for w in ("outcome", "intent", "every")]
        assert {(s["attempts"], s["seed"], s["validation_seed"]) for s in scores} == {(2, 0, 0)}
        best = max(range(3), key=lambda i: (validation_rank(scores[i]), -i))
        entry = summary["profiles"][profile]["methods"]["polymimic"]
        assert entry["hyperparameters"]["world_weighting"] == scores[best]["weighting"]
        assert entry["validation"]["candidates"] == 3
        assert entry["validation"]["chosen"]["net_goals"] == scores[best]["goals"] - scores[best]["own_goals"]
        for seed in (0, 1):
            saved = json.loads(run.evaluation_path(profile, "polymimic", seed).read_text())
            assert saved["world_weighting"] == scores[best]["weighting"]


def test_one_world_weighting_is_used_untried(tmp_path):
    config = tmp_path / "every.toml"
    config.write_text(_polymimic_on_pair().replace('profiles = ["pair"]', 'profiles = ["pair"]\n'
                                                   'world_weightings = ["every"]'))
    run = tmp_path / "every"
    assert main(["benchmark", "--config", str(config), "--run-dir", str(run), "--quiet", "--workers", "1"]) == 0
    assert not list(run.rglob("weighing_*.json"))
    entry = _summary(run)["profiles"]["pair"]["methods"]["polymimic"]
    assert entry["hyperparameters"]["world_weighting"] == "every" and entry["validation"] is None
    saved = json.loads(BenchmarkDir(run).evaluation_path("pair", "polymimic", 0).read_text())
    assert saved["world_weighting"] == "every"


def test_members_rank_by_their_controllers_measured_skill(benchmarked):
    run = BenchmarkDir(benchmarked)
    skill = json.loads(run.controller_skill_path.read_text())
    assert set(skill) == {"expert", "tiny", "poor"}
    duo = _summary(benchmarked)["profiles"]["duo"]["demonstrators"]
    assert duo["tiny_00"]["true_skill"] == pytest.approx(skill["tiny"] * 0.9)
    assert duo["poor_01"]["true_skill"] == pytest.approx(skill["poor"] * 0.4)
    assert _summary(benchmarked)["controller_skill"] == skill


def test_practice_is_polymimics_imitator_after_the_first_trial_practising(benchmarked):
    run = BenchmarkDir(benchmarked)
    pair = _summary(benchmarked)["profiles"]["pair"]
    saved = json.loads(run.practice_path("pair", 0).read_text())
    assert not run.practice_path("pair", 1).exists()
    assert [c["checkpoint"] for c in saved["checkpoints"]] == pair["practice"]["checkpoints"] == [0, 300]
    assert saved["budget"] == 300 and 300 - 61 < saved["steps"] <= 300
    # Before practice it is polymimic's imitator after the same trial, on the same attempts.
    polymimic = json.loads(run.evaluation_path("pair", "polymimic", 0).read_text())
    assert saved["checkpoints"][0]["net_goals"] == polymimic["goals"] - polymimic["own_goals"]
    # After practice it is polymimic_practice's evaluation.
    practised = json.loads(run.evaluation_path("pair", "polymimic_practice", 0).read_text())
    assert saved["checkpoints"][-1]["net_goals"] == practised["goals"] - practised["own_goals"]
    assert pair["methods"]["polymimic_practice"]["net_goals"]["mean"] == saved["checkpoints"][-1]["net_goals"]
    assert pair["methods"]["polymimic_practice"]["hyperparameters"]["practice_steps"] == 300
    assert pair["methods"]["polymimic_practice"]["hyperparameters"]["practice_method"] == "explore"
    # The tiny config's recogniser learned from 40 one-second sequences of each of the 5 primitives.
    assert pair["practice"]["self_observation_steps"] == 200
    text = (benchmarked / "benchmark.md").read_text()
    assert "## Practice" in text and "practice never loses more than 1" in text
    assert (benchmarked / "plots" / "benchmark_practice_curve.png").read_bytes()[:4] == b"\x89PNG"


def test_a_baselines_figures_are_over_its_fits_and_its_validation_scores_its_tunings(benchmarked):
    """bc's mean and sd are those of its three fits' evaluations, each fit under its own seed;
    its validation score is its chosen candidate's."""
    run = BenchmarkDir(benchmarked)
    entry = _summary(benchmarked)["profiles"]["pair"]["methods"]["bc"]
    saved = [json.loads(run.evaluation_path("pair", "bc", seed).read_text()) for seed in (0, 1, 2)]
    nets = [e["goals"] - e["own_goals"] for e in saved]
    assert entry["net_goals"]["mean"] == pytest.approx(sum(nets) / 3)
    assert entry["net_goals"]["sd"] == pytest.approx(statistics.stdev(nets))
    assert [e["trial_seed"] for e in saved] == [0, 1, 2]
    tuning = json.loads(run.tuning_path("pair", "bc").read_text())
    (only,) = tuning["scores"]
    assert entry["validation"] == {"attempts": 2, "candidates": 1, "runner_up": None,
                                   "chosen": {"goals": only["goals"], "own_goals": only["own_goals"],
                                              "net_goals": only["goals"] - only["own_goals"]}}


def test_the_skill_statistics_are_the_members_own(benchmarked):
    pair = _summary(benchmarked)["profiles"]["pair"]
    run = BenchmarkDir(benchmarked)
    # Two members: ρ and τ are +1 in a trial where the ε = 0 member ends with the higher LP, −1
    # where with the lower; best_hits counts the former.
    trials = [TrialResult.load(run.trial_path("pair", s)) for s in (0, 1)]
    signs = [1.0 if t.models["good"].lp > t.models["bad"].lp else -1.0 for t in trials
             if t.models["good"].lp != t.models["bad"].lp]
    assert pair["skill_recovery"]["spearman"]["mean"] == pytest.approx(sum(signs) / len(signs))
    assert pair["skill_recovery"]["kendall"]["mean"] == pytest.approx(sum(signs) / len(signs))
    assert pair["skill_recovery"]["best_hits"] == signs.count(1.0)
    assert pair["demonstrators"]["good"]["final_lp"]["mean"] == pytest.approx(
        sum(t.models["good"].lp for t in trials) / 2)
    # The net-goal estimator ranks by the members' own outcomes, the same in every trial.
    good, bad = pair["demonstrators"]["good"], pair["demonstrators"]["bad"]
    good_net, bad_net = good["goals"] - good["own_goals"], bad["goals"] - bad["own_goals"]
    expected = None if good_net == bad_net else (1.0 if good_net > bad_net else -1.0)
    assert pair["skill_by_outcomes"]["spearman"]["mean"] == expected
    assert pair["skill_by_outcomes"]["spearman"]["sd"] == (None if expected is None else 0.0)


def test_a_rerun_redoes_nothing_and_a_lost_or_damaged_file_is_made_again(benchmarked, tiny_toml, capsys):
    run = BenchmarkDir(benchmarked)
    before = _summary(benchmarked)
    run.evaluation_path("pair", "polymimic", 1).unlink()
    # Evaluated by the tuning, with the policy it chose; now by a fresh fit in the evaluate stage.
    run.evaluation_path("pair", "bc", 0).unlink()
    run.tuning_path("duo", "bco").write_text('{"profile": "duo", "method": "bco", "chosen": {}')  # truncated
    practice = json.loads(run.practice_path("duo", 0).read_text())
    practice["checkpoints"][1]["steps"] = 301  # played past its checkpoint: damaged
    run.practice_path("duo", 0).write_text(json.dumps(practice))
    assert main(["benchmark", "--config", str(tiny_toml), "--run-dir", str(benchmarked), "--quiet",
                 "--workers", "1"]) == 0
    stages = run.manifest()["stages"]
    assert stages["learn"]["made"] == 0 and stages["record"]["made"] == 0
    # The tuning is made again, bit for bit, so its evaluations stand; the ones lost are redone.
    assert stages["tune"]["made"] == 1
    assert stages["evaluate"]["made"] == 2
    assert stages["practice"]["made"] == 1
    err = capsys.readouterr().err
    assert "tuning_bco.json is damaged" in err and "practice_0.json is damaged" in err
    assert _summary(benchmarked) == before


def test_one_worker_or_two_give_the_same_bits(benchmarked, tiny_toml, tmp_path):
    other = tmp_path / "two"
    assert main(["benchmark", "--config", str(tiny_toml), "--run-dir", str(other), "--quiet", "--workers", "2"]) == 0
    assert (other / "benchmark.json").read_bytes() == (benchmarked / "benchmark.json").read_bytes()


def test_the_config_round_trips_as_toml(tiny_toml):
    config = BenchmarkConfig.load(tiny_toml)
    assert BenchmarkConfig.from_toml(config.to_toml()) == config
    assert config.crowds()[0].names == ("good", "bad")
    assert BenchmarkConfig.from_toml(BenchmarkConfig.quick().to_toml()) == BenchmarkConfig.quick()


@pytest.mark.parametrize(("argv", "message"), [
    (["--profiles", "one_goood"], "unknown profile 'one_goood'"),
    (["--methods", "bcx"], "unknown method 'bcx'"),
    (["--profiles", "pair", "pair"], "names 'pair' twice"),
])
def test_bad_names_are_one_line_usage_errors(argv, message, tiny_toml, tmp_path, capsys):
    assert main(["benchmark", "--config", str(tiny_toml), "--run-dir", str(tmp_path / "r"), *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and len(err.splitlines()) == 1


@pytest.mark.parametrize(("extra", "message"), [
    ('[profiles.solo]\nmembers = [{ controller = "expert", lapse = 0.1 }]\n', "at least two"),
    ('[profiles.wild]\nmembers = [{ controller = "expert", lapse = 1.2 }, { controller = "poor", lapse = 0 }]\n',
     "lapse 1.2"),
    ("[benchmark]\ntrials = 0\n", "trials = 0"),
    ("[benchmark]\nmax_decision_samples = 0\n", "max_decision_samples = 0"),
    ("[benchmark]\nbaseline_fits = 0\n", "baseline_fits = 0"),
    ("[benchmark]\nrefit_baselines = true\n", "[benchmark] refit_baselines is no more: use baseline_fits"),
    ('[benchmark]\npractice_method = "refin"\n',
     "[benchmark] practice_method must be one of explore, jsrl, distil, got 'refin'"),
    ('[benchmark]\nmethods = ["polymimic", "polymimic_practice"]\npractice_method = "refine"\n',
     "[benchmark] practice_method 'refine' is retired"),
])
def test_bad_crowds_and_sizes_are_named(extra, message, tmp_path, capsys):
    path = tmp_path / "bad.toml"
    path.write_text(extra)
    assert main(["benchmark", "--config", str(path), "--run-dir", str(tmp_path / "r")]) == 2
    assert message in capsys.readouterr().err


def test_a_run_made_before_refine_retired_still_opens_where_it_does_not_practise():
    config = BenchmarkConfig.from_toml('[benchmark]\nmethods = ["polymimic", "bc"]\npractice_method = "refine"\n')
    assert config.benchmark.practice_method == "refine"


def test_the_report_states_every_choice(benchmarked):
    text = (benchmarked / "benchmark.md").read_text()
    assert "## Targets" in text and "chosen on validation" in text
    assert "classifier=" in text and "world_weighting=" in text


def test_the_report_names_the_improved_controls_choices_where_they_are_not_the_defaults(benchmarked, tmp_path):
    defaults = _summary(benchmarked)["profiles"]["pair"]["methods"]["polymimic"]["hyperparameters"]
    assert "prefer_sooner_goals" not in defaults and "push_heading_tail" not in defaults
    config = tmp_path / "sooner.toml"
    config.write_text(_polymimic_on_pair() + "[learning]\nprefer_sooner_goals = true\npush_heading_tail = 0.2\n")
    run = tmp_path / "sooner"
    assert main(["benchmark", "--config", str(config), "--run-dir", str(run), "--quiet", "--workers", "1"]) == 0
    chosen = _summary(run)["profiles"]["pair"]["methods"]["polymimic"]["hyperparameters"]
    assert chosen["prefer_sooner_goals"] is True and chosen["control"] == "improved"
    assert chosen["push_heading_tail"] == 0.2
    text = (run / "benchmark.md").read_text()
    assert "prefer_sooner_goals=True" in text and "push_heading_tail=0.2" in text


def test_ray_gives_the_same_bits(benchmarked, tiny_toml, tmp_path):
    pytest.importorskip("ray")
    other = tmp_path / "ray"
    methods = ["polymimic", "polymimic_practice", "bco_lp", "random"]
    assert main(["benchmark", "--config", str(tiny_toml), "--run-dir", str(other), "--quiet", "--backend", "ray",
                 "--workers", "2", "--methods", *methods]) == 0
    ours, theirs = _summary(benchmarked)["profiles"], _summary(other)["profiles"]
    for profile in ours:
        assert {m: ours[profile]["methods"][m] for m in methods} == theirs[profile]["methods"]
        assert ours[profile]["skill_recovery"] == theirs[profile]["skill_recovery"]
        assert ours[profile]["practice"] == theirs[profile]["practice"]


PPO = """
[benchmark]
methods = ["polymimic", "random", "ppo"]
ppo_timesteps = 4096
ppo_eval_every = 2048
ppo_runs = 2
"""


def test_ppo_learns_the_tiny_imitators_policy_as_the_library_does(tmp_path):
    pytest.importorskip("stable_baselines3")
    from polymimic.baselines import ppo

    path = tmp_path / "tiny_ppo.toml"
    settings = ('methods = ["polymimic", "ppo"]\nprofiles = ["pair"]\n'
                "ppo_timesteps = 2048\nppo_eval_every = 2048\nppo_runs = 1\n")
    config = _tiny_naming_its_own_methods().replace("[benchmark]\n", "[benchmark]\n" + settings, 1)
    path.write_text('[imitator]\nbody = "tiny"\n' + config.replace('profiles = ["pair", "duo"]\n', ""))
    run = tmp_path / "run"
    assert main(["benchmark", "--config", str(path), "--run-dir", str(run), "--quiet", "--workers", "1"]) == 0
    summary = _summary(run)
    assert summary["imitator"] == "tiny"
    (ran,) = summary["ppo"]["runs"]
    evaluation = Attempts(per_configuration=summary["sizes"]["attempts_per_configuration"],
                          seed=summary["sizes"]["evaluation_seed"])
    _, curve, _ = ppo.learning_curve(imitator="tiny", total_timesteps=2048, eval_every=2048, seed=0,
                                     evaluation=evaluation)
    assert ran["checkpoints"] == [{k: v for k, v in c.to_dict().items() if k != "wall_s"} for c in curve]


def test_ppo_runs_once_for_every_profile_and_reports_the_steps_it_took(tmp_path, capsys):
    pytest.importorskip("stable_baselines3")
    path = tmp_path / "ppo.toml"
    path.write_text(_tiny_naming_its_own_methods().replace("[benchmark]\n", PPO.strip() + "\n", 1))
    one, two = tmp_path / "one", tmp_path / "two"
    for run, workers in ((one, "1"), (two, "2")):
        assert main(["benchmark", "--config", str(path), "--run-dir", str(run), "--quiet", "--workers", workers]) == 0
    assert (one / "benchmark.json").read_bytes() == (two / "benchmark.json").read_bytes()
    summary = _summary(one)
    runs = summary["ppo"]["runs"]
    assert [r["seed"] for r in runs] == [0, 1]
    for r in runs:
        # Before training, then at each policy update (every 2048 × 2 steps here) past 2048, 4096, …
        assert [c["env_steps"] for c in r["checkpoints"]] == [0, 4096]
    for profile in summary["profiles"].values():
        ours, ppo = profile["methods"]["polymimic"]["net_goals"]["mean"], profile["methods"]["ppo"]
        assert ppo["evaluated"] == 2 and ppo["attempts"] == 4
        assert ppo["net_goals"]["mean"] == sum(r["checkpoints"][-1]["net_goals"] for r in runs) / 2
        expected = [next((c["env_steps"] for c in r["checkpoints"] if c["net_goals"] >= ours), None) for r in runs]
        assert ppo["env_steps_to_polymimic"] == expected
    text = (one / "benchmark.md").read_text()
    assert "## Reinforcement learning: ppo" in text and "ppo seed 1" in text
    assert (one / "plots" / "benchmark_ppo_curve.png").read_bytes()[:4] == b"\x89PNG"
    # A lost curve and a damaged one are the only things redone, to the same bits.
    run = BenchmarkDir(one)
    run.ppo_curve_path(1).unlink()
    damaged = json.loads(run.ppo_curve_path(0).read_text())
    damaged["checkpoints"][-1]["net_goals"] += 1
    run.ppo_curve_path(0).write_text(json.dumps(damaged))
    assert main(["benchmark", "--run-dir", str(one), "--quiet", "--workers", "1"]) == 0
    stages = run.manifest()["stages"]
    assert (stages["ppo"]["made"], stages["evaluate"]["made"], stages["tune"]["made"]) == (2, 0, 0)
    assert "curve_0.json is damaged" in capsys.readouterr().err
    assert _summary(one) == summary


def test_ppo_without_stable_baselines3_is_refused_before_the_run_starts(tiny_toml, tmp_path, capsys, monkeypatch):
    from polymimic.baselines import ppo

    monkeypatch.setattr(ppo, "available", lambda: False)
    run = tmp_path / "r"
    assert main(["benchmark", "--config", str(tiny_toml), "--run-dir", str(run), "--methods", "polymimic", "ppo"]) == 2
    err = capsys.readouterr().err.strip()
    assert 'pip install "polymimic[rl]"' in err and len(err.splitlines()) == 1
    assert not run.exists()


TWINS = """
[recognizer]
train_per_primitive = 40
codebook_size = 16
[benchmark]
profiles = ["twins"]
methods = ["polymimic", "bc", "bc_best"]
trials = 1
demonstrations_per_configuration = 2
attempts_per_configuration = 2
validation_attempts_per_configuration = 1
tuning_budget = 2
[profiles.twins]
members = [{ controller = "expert", lapse = 0.2, count = 2 }]
"""


def test_bc_best_is_bc_where_every_member_shares_the_lowest_lapse_and_is_copied_not_rerun(tmp_path, monkeypatch):
    from polymimic.benchmark import driver
    from polymimic.benchmark.tasks import tuning_task

    path = tmp_path / "twins.toml"
    path.write_text(TWINS)
    tuned = []
    monkeypatch.setattr(driver, "tuning_task", lambda shared, job: tuned.append(job[1]) or tuning_task(shared, job))
    copied, fitted = tmp_path / "copied", tmp_path / "fitted"
    assert main(["benchmark", "--config", str(path), "--run-dir", str(copied), "--quiet", "--workers", "1"]) == 0
    assert tuned == ["bc"]
    monkeypatch.setattr(driver.Benchmark, "_bc_best_is_bc", lambda self, crowd, skill: False)
    assert main(["benchmark", "--config", str(path), "--run-dir", str(fitted), "--quiet", "--workers", "1"]) == 0
    assert tuned == ["bc", "bc", "bc_best"]
    assert (copied / "benchmark.json").read_bytes() == (fitted / "benchmark.json").read_bytes()
    assert json.loads(BenchmarkDir(copied).tuning_path("twins", "bc_best").read_text())["method"] == "bc_best"


def test_export_writes_each_crowd_with_its_members_lapses(benchmarked, tmp_path, monkeypatch, capsys):
    minari = pytest.importorskip("minari")
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "minari"))
    who = ["--author", "tests", "--author-email", "tests@polymimic.invalid", "--code-permalink", "tests"]
    assert main(["export", "--run-dir", str(benchmarked), *who]) == 0
    out, err = capsys.readouterr()
    assert out.split() == ["polymimic/benchmark-pair-v0", "polymimic/benchmark-duo-v0"]
    assert "duo: left out tiny_00 (PenaltyKick-v0 simulates the Lego robot only)" in err
    for dataset_id, lapses in (("polymimic/benchmark-pair-v0", {"good": 0.0, "bad": 1.0}),
                               ("polymimic/benchmark-duo-v0", {"poor_01": 0.6})):
        dataset = minari.load_dataset(dataset_id)
        # Two demonstrations per configuration and member.
        assert dataset.total_episodes == 4 * len(lapses)
        meta = list(dataset.storage.get_episode_metadata(range(dataset.total_episodes)))
        assert {m["demonstrator"]: m["lapse"] for m in meta} == lapses
        assert dataset.storage.metadata["learned_from_observation"] is True
    assert main(["export", "--run-dir", str(benchmarked), "--actions", "commands", "--overwrite", *who]) == 0
    capsys.readouterr()
    assert minari.load_dataset("polymimic/benchmark-pair-v0").storage.metadata["polymimic_actions"] == "commands"
    assert main(["export", "--run-dir", str(benchmarked), *who]) == 2
    assert "exists already: pass overwrite=True" in capsys.readouterr().err


WHO = ["--author", "tests", "--author-email", "tests@polymimic.invalid", "--code-permalink", "tests"]


def test_export_with_a_crowd_missing_writes_no_dataset(benchmarked, tmp_path, monkeypatch, capsys):
    minari = pytest.importorskip("minari")
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "minari"))
    run = tmp_path / "bench"
    shutil.copytree(benchmarked, run)
    BenchmarkDir(run).crowd_path("duo").unlink()  # the second profile: the first's would be written first
    assert main(["export", "--run-dir", str(run), *WHO]) == 2
    err = capsys.readouterr().err.strip()
    assert "crowd_duo.parquet is missing: run `polymimic benchmark" in err and len(err.splitlines()) == 1
    assert not minari.list_local_datasets()


def test_export_without_minari_says_how_to_install_it(benchmarked, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "minari"))
    monkeypatch.setitem(sys.modules, "minari", None)  # as if it were not installed
    assert main(["export", "--run-dir", str(benchmarked), *WHO]) == 2
    err = capsys.readouterr().err.strip()
    assert err == 'polymimic export: error: Minari export needs minari: pip install "polymimic[minari]"'


def test_export_reads_the_config_asked_for_as_the_benchmark_does(benchmarked, tiny_toml, tmp_path, monkeypatch,
                                                                 capsys):
    pytest.importorskip("minari")
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "minari"))
    assert main(["export", "--run-dir", str(benchmarked), "--config", str(tiny_toml), *WHO]) == 0
    assert capsys.readouterr().out.split() == ["polymimic/benchmark-pair-v0", "polymimic/benchmark-duo-v0"]
    assert main(["export", "--run-dir", str(benchmarked), "--quick", *WHO]) == 2
    err = capsys.readouterr().err.strip()
    assert "was made with a different config" in err and len(err.splitlines()) == 1


PPO_BC = """
[benchmark]
methods = ["polymimic", "polymimic_practice", "ppo_bc"]
ppo_timesteps = 4096
ppo_eval_every = 4096
ppo_runs = 1
"""


def test_ppo_bc_clones_each_crowd_then_learns_and_stands_beside_practice(tmp_path, capsys):
    pytest.importorskip("stable_baselines3")
    path = tmp_path / "ppo_bc.toml"
    path.write_text(_tiny_naming_its_own_methods().replace("[benchmark]\n", PPO_BC.strip() + "\n", 1))
    run_dir = tmp_path / "run"
    assert main(["benchmark", "--config", str(path), "--run-dir", str(run_dir), "--quiet", "--workers", "2"]) == 0
    run, summary = BenchmarkDir(run_dir), _summary(run_dir)
    for name, profile in summary["profiles"].items():
        tuning = json.loads(run.ppo_bc_tuning_path(name).read_text())
        curve = json.loads(run.ppo_bc_curve_path(name, 0).read_text())
        # The cloning chosen on validation is the one the run cloned; the curve starts from it.
        assert curve["pretraining"] == tuning["chosen"] and len(tuning["scores"]) == 1
        assert [c["env_steps"] for c in curve["checkpoints"]] == [0, 4096]
        entry = profile["methods"]["ppo_bc"]
        assert entry["net_goals"]["mean"] == curve["checkpoints"][-1]["net_goals"]
        assert entry["hyperparameters"]["cloning_epochs"] == tuning["chosen"]["epochs"]
        practised = profile["practice"]["net_goals"][-1]["mean"]
        expected = next((c["env_steps"] for c in curve["checkpoints"] if c["net_goals"] >= practised), None)
        assert profile["practice"]["ppo_bc_steps_to_practice"] == [expected]
    assert "ppo_bc to practice's final" in (run_dir / "benchmark.md").read_text()
    # A lost curve is the only thing redone, to the same bits.
    before = summary
    run.ppo_bc_curve_path("pair", 0).unlink()
    assert main(["benchmark", "--run-dir", str(run_dir), "--quiet", "--workers", "1"]) == 0
    assert run.manifest()["stages"]["ppo_bc"]["made"] == 1
    assert _summary(run_dir) == before
