"""A run config's own bodies, demonstrators and experiments: recorded, segmented, learned from,
evaluated and reported like the thesis's, while the thesis's part of the run stays as it was."""

from __future__ import annotations

import json
import pathlib

import pytest

from polymimic import write_tracks
from polymimic.datasets import load_demonstrations
from polymimic.field import record
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.stages import Context, reproduce
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import ConfigError, RunConfig

POLICY = '''
import math


class Straight:
    """Drive at the ball."""

    decision_hz = 10

    def act(self, reading):
        bearing = math.atan2(reading.ball_y_mm - reading.robot_y_mm, reading.ball_x_mm - reading.robot_x_mm)
        error = math.remainder(bearing - reading.robot_theta_rad, math.tau)
        return "forward" if abs(error) < 0.3 else ("left" if error > 0 else "right")
'''

ROSTER = '''
[bodies.van]
length_mm = 160
width_mm = 150
wheel_base_mm = 140
top_wheel_speed_mm_s = 140

[demonstrators.cart_poor]
controller = "poor"
body = "van"
lapse = 0.2

[demonstrators.straight]
policy = "policies.py:Straight"
body = "van"

[demonstrators.logged]
log = "logs/overhead.csv"
rate_hz = 20
units = { length = "m", angle = "deg" }

[experiments.mine]
title = "the user's crowd"
demonstrators = ["expert", "cart_poor", "straight", "logged"]
ordering = ["straight", "logged", "cart_poor", "expert"]
skill_order = ["expert", "straight", "cart_poor", "logged"]
'''


@pytest.fixture(scope="module")
def own_run(tiny_run_toml, tmp_path_factory):
    folder = tmp_path_factory.mktemp("own")
    (folder / "policies.py").write_text(POLICY)
    (folder / "logs").mkdir()
    logged = [d for c in (1, 2) for d in record("poor", configuration=c, n=4, seed=9)]
    write_tracks(logged, folder / "logs" / "overhead.csv", units={"length": "m", "angle": "deg"}, rate_hz=20,
                 include=("episode",))
    (folder / "run.toml").write_text(tiny_run_toml(trials=2) + ROSTER)
    config = RunConfig.load(folder / "run.toml")
    run = RunDir(folder / "run")
    config = run.open(config)
    reproduce(Context(run=run, config=config, runner=TaskRunner(workers=1), quiet=True))
    return run, config, logged


def test_the_config_reads_and_round_trips(own_run):
    _, config, _ = own_run
    assert list(config.demonstrators) == ["cart_poor", "straight", "logged"]
    assert config.bodies["van"].primitives_mm_s["forward"] == (56.0, 56.0) and set(config.bodies) == {
        "lego", "tiny", "van"}
    assert config.own_experiments["mine"].ordering == ("straight", "logged", "cart_poor", "expert")
    assert RunConfig.from_toml(config.to_toml()) == config
    assert RunConfig.from_dict(json.loads(json.dumps(config.to_dict()))) == config


def test_every_own_demonstrator_is_recorded_and_segmented(own_run):
    run, config, logged = own_run
    n = config.experiments.sizes.demonstrations_per_configuration
    cart = load_demonstrations(run.demonstrations_path("cart_poor"), bodies=config.bodies)
    straight = load_demonstrations(run.demonstrations_path("straight"), bodies=config.bodies)
    imported = load_demonstrations(run.demonstrations_path("logged"), bodies=config.bodies)
    assert len(cart) == len(straight) == 2 * n and len(imported) == len(logged)
    assert {d.body.name for d in cart + straight} == {"van"} and {d.demonstrator for d in imported} == {"logged"}
    assert [d.outcome for d in imported] == [d.outcome for d in logged]
    for who in ("cart_poor", "straight", "logged"):
        assert run.segments_path(who).exists()


def test_the_own_experiment_is_learned_evaluated_and_reported(own_run):
    run, config, _ = own_run
    results = json.loads(run.results_path.read_text())
    mine = results["experiments"]["mine"]
    assert mine["trials"] == 2 and mine["ordering"] == ["straight", "logged", "cart_poor", "expert"]
    assert set(mine["final_lp"]) == {"straight", "logged", "cart_poor", "expert"}
    assert mine["lp_order_hits"] is not None and 0 <= mine["lp_order_hits"] <= 2
    assert mine["imitator"]["imitators"] == 2
    assert set(results["demonstrators"]) >= {"cart_poor", "straight", "logged"}
    # Table 4.5 measures segments against commands: the log recorded none, the others did.
    assert "logged" not in results["segments"] and "straight" in results["segments"]
    report = run.report_md_path.read_text()
    assert "## Your experiment: the user's crowd" in report
    section = report.split("## Your experiment: the user's crowd", 1)[1].split("\n## ", 1)[0]
    # No thesis columns: the thesis has no numbers for the user's experiment.
    assert "| demonstrator | goals | own goals | attempts | final LP | rounds matched |" in section
    assert ", thesis" not in section
    # The thesis's three experiments are all there as ever.
    assert {"heterogeneous_rcb", "heterogeneous_bcr", "varying_skill"} <= set(results["experiments"])


@pytest.mark.parametrize(("extra", "message"), [
    ('[demonstrators.expert]\ncontroller = "poor"\n', r"\[demonstrators.expert\]: a demonstrator's name must be"),
    ('[demonstrators.x]\ncontroller = "poor"\npolicy = "a:b"\n',
     r"needs exactly one of controller, policy, log or imported; got controller, policy"),
    ('[demonstrators.x]\ncontroller = "pooor"\n', r"controller 'pooor' is not one of expert, poor"),
    ('[demonstrators.x]\ncontroller = "poor"\nbody = "kart"\n', r"body 'kart' is neither a thesis body"),
    ('[demonstrators.x]\ncontroller = "poor"\nlapse = 2\n', r"lapse must be a number in \[0, 1\], got 2"),
    ('[demonstrators.x]\ncontroller = "poor"\ncolour = 1\n', r"unknown key 'colour' for a controller demonstrator"),
    ('[demonstrators.x]\npolicy = "nocolon"\n', r"policy must be \"module:name\""),
    ('[demonstrators.x]\npolicy = "a:b"\ndecision_hz = 7\n', r"decision_hz must be one of 30, 15"),
    ('[demonstrators.x]\nimported = false\n', r"imported must be true"),
    ('[demonstrators.x]\ncontroller = "humanoid"\nbody = "lego"\n', r"the humanoid controller cannot drive the lego"),
    ('[demonstrators.x]\ncontroller = "expert"\nbody = "tiny"\n', r"the expert controller cannot drive the tiny"),
    ('[demonstrators.x]\npolicy = "a:b"\ndecision_hz = true\n', r"decision_hz must be one of"),
    ('[demonstrators.x]\nlog = "a.csv"\nrate_hz = -3\n', r"rate_hz must be a positive number .* got -3"),
    ('[demonstrators.x]\nlog = "a.csv"\nunits = { length = "furlong" }\n', r"units.length = 'furlong' is not a unit"),
    ('[own_experiments]\nx = 1\n', r"unknown section: own_experiments"),
    ('[experiments.varying_skill]\ndemonstrators = ["expert"]\n', r"an experiment's name must be a word of its own"),
    ('[experiments.e]\ndemonstrators = ["expert", "nobody"]\n', r"demonstrator 'nobody' is neither the thesis's"),
    ('[experiments.e]\ndemonstrators = ["expert", "poor"]\nordering = ["poor"]\n', r"ordering .* must list"),
    ('[experiments.e]\ndemonstrators = ["expert"]\nphase_one = "mixed"\n', r"phase_one must be"),
    ('[experiments.e]\ndemonstrators = ["expert"]\ncolour = 1\n', r"unknown key 'colour'"),
    ('[bodies.b]\nlength_mm = 0\nwidth_mm = 1\nwheel_base_mm = 1\ntop_wheel_speed_mm_s = 1\n',
     r"\[bodies.b\]: body 'b': length_mm must be a positive number, got 0"),
])
def test_bad_roster_tables_are_refused_by_table_and_key(extra, message):
    with pytest.raises(ConfigError, match=message):
        RunConfig.from_toml(extra)


def test_the_thesis_bodies_are_two_entries_of_the_bodies_table():
    from polymimic.bodies import THESIS_BODIES

    thesis = RunConfig()
    assert set(thesis.to_dict()) == {"seeds", "field", "imitator", "recognizer", "segmenter", "learning", "experiments",
                                     "bodies"}
    assert thesis.bodies == THESIS_BODIES and set(thesis.bodies) == {"lego", "tiny"}
    assert "[bodies.lego]" in thesis.to_toml() and RunConfig.from_toml(thesis.to_toml()) == thesis
    # An older manifest, which had no [bodies], reads as the same config.
    older = {k: v for k, v in thesis.to_dict().items() if k != "bodies"}
    assert RunConfig.from_dict(older) == thesis
    with pytest.raises(ConfigError, match="body 'lego' is already described with other constants"):
        RunConfig.from_toml("[bodies.lego]\nlength_mm = 141\nwidth_mm = 150\nwheel_base_mm = 175\n"
                            "top_wheel_speed_mm_s = 130\n")
    assert RunConfig.from_toml("[experiments]\ntrials = 3\n").own_experiments == {}


def test_a_log_brought_in_with_import_tracks_is_the_runs_demonstrator(tiny_run_toml, tmp_path, capsys):
    from polymimic import cli
    from polymimic.runs.rundir import MissingInputError

    roster = ('[demonstrators.alice]\nimported = true\n\n[experiments.with_alice]\n'
              'demonstrators = ["alice", "expert"]\n')
    config = RunConfig.from_toml(tiny_run_toml(trials=1, evaluated_imitators=1) + roster)
    run = RunDir(tmp_path / "run")
    config = run.open(config)
    ctx = Context(run=run, config=config, runner=TaskRunner(workers=1), quiet=True)
    with pytest.raises(MissingInputError, match=r"\[demonstrators.alice\] is imported; bring its log in with "
                                                r"`polymimic import-tracks FILE --as alice"):
        reproduce(ctx)
    logged = [d for c in (1, 2) for d in record("poor", configuration=c, n=3, seed=4)]
    write_tracks(logged, tmp_path / "alice.csv", rate_hz=30, include=("episode",))
    assert cli.main(["import-tracks", str(tmp_path / "alice.csv"), "--as", "alice", "--run-dir", str(run.path)]) == 0
    assert "6 episodes from alice.csv: 6 demonstrations, 0 invalid" in capsys.readouterr().out
    reproduce(ctx)
    results = json.loads(run.results_path.read_text())
    assert results["demonstrators"]["alice"]["attempts"] == 6
    assert set(results["experiments"]["with_alice"]["final_lp"]) == {"alice", "expert"}
    assert cli.main(["import-tracks", str(tmp_path / "alice.csv"), "--as", "expert", "--run-dir", str(run.path)]) == 2
    assert "not one of the thesis's" in capsys.readouterr().err


def test_import_tracks_takes_the_body_the_runs_config_gives(tmp_path, capsys):
    from polymimic import cli

    roster = ('[bodies.van]\nlength_mm = 160\nwidth_mm = 150\nwheel_base_mm = 140\ntop_wheel_speed_mm_s = 140\n'
              '[demonstrators.bob]\nimported = true\nbody = "van"\n')
    run = RunDir(tmp_path / "run")
    run.open(RunConfig.from_toml(roster))
    write_tracks(record("poor", configuration=1, n=2, seed=3), tmp_path / "bob.csv", include=("episode",))
    base = ["import-tracks", str(tmp_path / "bob.csv"), "--run-dir", str(run.path)]
    assert cli.main([*base, "--as", "bob", "--body", "tiny"]) == 2
    assert "--body 'tiny': the run's [demonstrators.bob] says body = 'van'" in capsys.readouterr().err
    assert cli.main([*base, "--as", "bob"]) == 0
    bodies = RunConfig.from_toml(roster).bodies
    assert {d.body.name for d in load_demonstrations(run.demonstrations_path("bob"), bodies=bodies)} == {"van"}
    assert cli.main([*base, "--as", "carol", "--body", "kart"]) == 2
    error = capsys.readouterr().err
    assert "--body 'kart': one of lego, tiny, humanoid, van (the thesis's and the run's [bodies])" in error


def test_a_controller_drives_its_own_body_unless_told(tmp_path):
    config = RunConfig.from_toml('[demonstrators.small_tiny]\ncontroller = "tiny"\n'
                                 '[demonstrators.walker]\ncontroller = "humanoid"\n')
    assert config.demonstrators["small_tiny"].body == "tiny" and config.demonstrators["walker"].body == "humanoid"


def test_a_policy_file_that_fails_to_load_is_named(tmp_path):
    from polymimic.runs.roster_config import RosterError, record_demonstrator

    (tmp_path / "broken.py").write_text("def act(reading:\n")
    (tmp_path / "typed.py").write_text("from __future__ import annotations\nimport dataclasses\n\n"
                                       "@dataclasses.dataclass\nclass Still:\n    decision_hz: int = 10\n\n"
                                       "    def act(self, reading) -> str:\n        return 'stop'\n")
    config = RunConfig.from_toml('[demonstrators.broken]\npolicy = "broken.py:act"\n'
                                 '[demonstrators.typed]\npolicy = "typed.py:Still"\n', base_dir=tmp_path)
    with pytest.raises(RosterError, match=r"\[demonstrators.broken\] policy .*broken.py:act': SyntaxError"):
        record_demonstrator(config.demonstrators["broken"], n=1, seed=0, field_config=config.field, bodies={})
    demos, _ = record_demonstrator(config.demonstrators["typed"], n=1, seed=0, field_config=config.field, bodies={})
    assert {d.demonstrator for d in demos} == {"typed"}


def test_a_rerun_makes_nothing_new_and_a_changed_log_is_refused(own_run):
    from polymimic.runs.rundir import RunError

    run, config, logged = own_run
    ctx = Context(run=run, config=config, runner=TaskRunner(workers=1), quiet=True)
    made = {p: p.stat().st_mtime_ns for p in (run.demonstrations_path("logged"), run.demonstrations_path("straight"),
                                              run.trial_path("mine", config.seeds.first_trial))}
    before = run.results_path.read_bytes()
    reproduce(ctx)
    assert {p: p.stat().st_mtime_ns for p in made} == made
    assert run.results_path.read_bytes() == before
    log = pathlib.Path(config.demonstrators["logged"].log)
    original = log.read_bytes()
    try:
        log.write_bytes(original)  # rewritten with the same bytes: the content, not the time, counts
        reproduce(ctx)
        write_tracks(logged[:4], log, units={"length": "m", "angle": "deg"}, rate_hz=20, include=("episode",))
        with pytest.raises(RunError, match=r"overhead.csv has changed since demonstrations_logged.parquet was made"):
            reproduce(ctx)
    finally:
        log.write_bytes(original)


def test_import_tracks_again_needs_replace_and_redoes_what_was_made_from_it(tiny_run_toml, tmp_path, capsys):
    from polymimic import cli

    roster = '[demonstrators.dora]\nimported = true\n\n[experiments.with_dora]\ndemonstrators = ["dora", "expert"]\n'
    run = RunDir(tmp_path / "run")
    config = run.open(RunConfig.from_toml(tiny_run_toml(trials=1, evaluated_imitators=1) + roster))
    write_tracks([d for c in (1, 2) for d in record("poor", configuration=c, n=2, seed=5)], tmp_path / "dora.csv",
                 include=("episode",))
    base = ["import-tracks", str(tmp_path / "dora.csv"), "--as", "dora", "--run-dir", str(run.path)]
    assert cli.main(base) == 0
    reproduce(Context(run=run, config=config, runner=TaskRunner(workers=1), quiet=True))
    trial = run.trial_path("with_dora", config.seeds.first_trial)
    assert trial.exists() and run.segments_path("dora").exists()
    capsys.readouterr()
    assert cli.main(base) == 2
    assert "exists: the run has dora's demonstrations already" in capsys.readouterr().err
    assert cli.main([*base, "--replace"]) == 0
    assert not trial.exists() and not run.segments_path("dora").exists()
    assert run.trial_path("varying_skill", config.seeds.first_trial).exists(), "what did not learn from dora stays"
