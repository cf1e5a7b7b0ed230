"""Experiments: trials and evaluations give the same bits on any backend, resume where they
stopped, and summarise to known answers."""

import json
import re
import shutil

import pytest

from polymimic import ModelFileError
from polymimic.learning import ModelResult, TrialResult
from polymimic.reproduce import experiments, results
from polymimic.reproduce.rundir import RunDir
from polymimic.reproduce.stages import WORKER_MODULES, Context, run_stage
from polymimic.runs.backends import TaskRunner
from polymimic.runs.config import RunConfig
from polymimic.runs.roster import EXPERIMENTS
from polymimic.runs.rundir import MissingInputError


def _context(path, runner=None, config=None):
    run = RunDir(path)
    return Context(run=run, config=run.open(config), runner=runner or TaskRunner(workers=1), quiet=True)


@pytest.fixture(scope="module")
def segmented(tiny_run_toml, tmp_path_factory):
    """A tiny run, up to and including segmentation."""
    path = tmp_path_factory.mktemp("run") / "segmented"
    ctx = _context(path, config=RunConfig.from_toml(tiny_run_toml()))
    for stage in ("self-observe", "record", "train", "segment"):
        run_stage(ctx, stage)
    return path


def _copy(segmented, tmp_path, name):
    target = tmp_path / name
    shutil.copytree(segmented, target)
    return target


def _trial_files(path):
    return {p.relative_to(path).as_posix(): p.read_bytes()
            for p in sorted((path / "models" / "experiments").rglob("*.json"))}


def test_every_stage_wrote_its_outputs(segmented):
    run = RunDir(segmented)
    for who in ("expert", "poor", "tiny", "humanoid", "average"):
        assert run.demonstrations_path(who).exists() and run.segments_path(who).exists()
    assert run.recognizer_path.exists() and run.average_trial_path.exists()
    stages = run.manifest()["stages"]
    assert list(stages) == ["self-observe", "record", "train", "segment"]
    assert all(s["finished"] >= s["started"] for s in stages.values())


def test_same_bits_in_process_on_a_pool_and_on_ray(segmented, tmp_path):
    """Each trial depends on its seed alone: the backend and the number of workers change nothing."""
    ray = pytest.importorskip("ray")
    inline = _context(_copy(segmented, tmp_path, "inline"))
    pool = TaskRunner(workers=2)
    pool.start(WORKER_MODULES)  # workers forked from a server that imported the tasks' modules first
    pooled = _context(_copy(segmented, tmp_path, "pool"), pool)
    for ctx in (inline, pooled):
        run_stage(ctx, "learn")
        run_stage(ctx, "evaluate", experiments=["varying_skill"])
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        on_ray = _context(_copy(segmented, tmp_path, "ray"), TaskRunner(backend="ray", workers=2))
        run_stage(on_ray, "learn")
        run_stage(on_ray, "evaluate", experiments=["varying_skill"])
    finally:
        ray.shutdown()
    reference = _trial_files(inline.run.path)
    assert len([k for k in reference if "/trial_" in k]) == 3 * 3
    assert len([k for k in reference if "/evaluation_" in k]) == 2 * 2
    assert _trial_files(pooled.run.path) == reference
    assert _trial_files(on_ray.run.path) == reference


def test_an_interrupted_learn_resumes_without_redoing_trials(segmented, tmp_path):
    ctx = _context(_copy(segmented, tmp_path, "resume"))
    ran = experiments.learn(ctx.run, ctx.config, ctx.runner, limit=1, quiet=True)
    assert ran == {"heterogeneous_rcb": 1, "heterogeneous_bcr": 1, "varying_skill": 1}
    first = ctx.run.trial_path("varying_skill", 0)
    stamp = first.stat().st_mtime_ns
    ran = experiments.learn(ctx.run, ctx.config, ctx.runner, quiet=True)
    assert ran == {"heterogeneous_rcb": 2, "heterogeneous_bcr": 2, "varying_skill": 2}
    assert first.stat().st_mtime_ns == stamp
    # A lost trial is made again, identically, and nothing else is.
    lost = ctx.run.trial_path("heterogeneous_bcr", 1)
    before = lost.read_bytes()
    lost.unlink()
    assert experiments.learn(ctx.run, ctx.config, ctx.runner, quiet=True) == {
        "heterogeneous_rcb": 0, "heterogeneous_bcr": 1, "varying_skill": 0}
    assert lost.read_bytes() == before and first.stat().st_mtime_ns == stamp
    assert not list(ctx.run.models.rglob(".*.tmp*")), "no temporary file is left behind"


def test_evaluations_resume_and_need_their_trials(segmented, tmp_path):
    ctx = _context(_copy(segmented, tmp_path, "evaluate"))
    with pytest.raises(MissingInputError, match="trial_0.json is missing: run `polymimic learn"):
        experiments.evaluate_imitators(ctx.run, ctx.config, ctx.runner, quiet=True)
    experiments.learn(ctx.run, ctx.config, ctx.runner, experiments=["heterogeneous_rcb"], quiet=True)
    done = experiments.evaluate_imitators(ctx.run, ctx.config, ctx.runner, experiments=["heterogeneous_rcb"],
                                          quiet=True)
    assert done == {"heterogeneous_rcb": 2 * 2}
    assert ctx.run.attempts_path("heterogeneous_rcb", "thesis").exists()
    assert experiments.evaluate_imitators(ctx.run, ctx.config, ctx.runner, experiments=["heterogeneous_rcb"],
                                          quiet=True) == {"heterogeneous_rcb": 0}


def test_unknown_experiments_are_refused(segmented):
    ctx = _context(segmented)
    with pytest.raises(ValueError, match="unknown experiment 'mixed'"):
        experiments.learn(ctx.run, ctx.config, ctx.runner, experiments=["mixed"], quiet=True)


def test_the_policy_helper_drives_by_either_control(segmented):
    from polymimic import PrimitiveRecognizer

    run = RunDir(segmented)
    trial = TrialResult.load(run.average_trial_path)
    recognizer = PrimitiveRecognizer.load(run.recognizer_path)
    watched = experiments.experiment_items(run, EXPERIMENTS["heterogeneous_rcb"])
    for control in experiments.CONTROLS:
        policy = experiments.imitator_policy(trial, recognizer=recognizer, config=RunConfig().learning,
                                             control=control, demonstrations=watched)
        assert policy.control == control and len(policy) > 0
    with pytest.raises(ValueError, match="control must be one of"):
        experiments.imitator_policy(trial, recognizer=recognizer, config=RunConfig().learning, control="fast",
                                    demonstrations=watched)


# Summaries, on made-up trials with known answers.

def _model(name, *, lp, match_rate, created=0, history=(0.5,), behaviours=()):
    return ModelResult(name=name, lp=lp, lp_history=list(history), match_rate=match_rate, created=created,
                       deleted=0, permanent=0, candidates=0, duplicates=0, candidates_permanent=0, rounds=10,
                       rounds_matched=int(10 * match_rate), behaviours=list(behaviours))


def _trial(seed, lps, rates, created):
    models = {name: _model(name, lp=lp, match_rate=rate, created=c, history=[0.5, lp])
              for name, lp, rate, c in zip(("poor", "average", "expert"), lps, rates, created)}
    return TrialResult(models=models, imitator=_model("imitator", lp=0.9, match_rate=0.5), seed=seed)


def test_experiment_summary_known_answers():
    trials = [_trial(0, (0.2, 0.5, 0.9), (0.5, 0.6, 0.7), (10, 20, 30)),
              _trial(1, (0.6, 0.5, 0.9), (0.7, 0.6, 0.9), (12, 20, 34)),
              _trial(2, (0.1, 0.4, 0.95), (0.6, 0.6, 0.8), (14, 20, 32))]
    summary = results.summarize_experiment(EXPERIMENTS["varying_skill"], trials, lp_stride=1)
    assert summary["trials"] == 3
    assert summary["lp_order_hits"] == 2                      # trial 1 has Poor above Average
    assert summary["match_rate"]["expert"] == pytest.approx({"mean": 0.8, "sd": 0.1})
    assert summary["match_rate"]["imitator"] == {"mean": 0.5, "sd": 0.0}
    assert summary["behaviours"]["poor"]["created"] == {"mean": 12.0, "sd": 2.0}
    assert summary["final_lp"]["average"] == pytest.approx({"mean": 14 / 30, "sd": (1 / 300) ** 0.5})
    assert "imitator" not in summary["final_lp"]
    assert summary["lp_over_time"]["trials"]["expert"] == [[0.5, 0.9], [0.5, 0.9], [0.5, 0.95]]  # stride 1
    heterogeneous = results.summarize_experiment(
        EXPERIMENTS["heterogeneous_rcb"],
        [TrialResult(models={n: _model(n, lp=1.0, match_rate=1.0) for n in ("expert", "tiny", "humanoid")},
                     imitator=_model("imitator", lp=0.9, match_rate=1.0), seed=0)])
    assert heterogeneous["lp_order_hits"] is None


def test_lp_over_time_keeps_every_stride_th_change():
    assert results._sampled([0.0, 0.1, 0.2, 0.3, 0.4], 2) == [0.0, 0.2, 0.4]
    assert results._sampled([0.0, 0.1, 0.2, 0.3], 2) == [0.0, 0.2]


def test_appendix_b_counts_models_not_copies():
    def b(letters, permanent=False, samples=0, angle_sd=0.0):
        return {"primitives": letters, "permanency": 1.0 if permanent else 0.5, "permanent": permanent, "age": 0,
                "selected": 0, "ball_samples": samples, "ball_angle_deg": [0.0, angle_sd],
                "ball_distance_mm": [0.0, 0.0]}

    first = TrialResult(models={"expert": _model("expert", lp=1, match_rate=1, behaviours=[
        b("F"), b("FF", True, 9, 5.0), b("FF"), b("LR")])},
        imitator=_model("imitator", lp=0.9, match_rate=1, behaviours=[b("FF", True), b("LR", samples=9,
                                                                                          angle_sd=50.0)]), seed=0)
    table = results.appendix_b([first], RunConfig().learning)
    assert table["models"] == 2
    assert table["created"] == [{"primitives": "F,F", "count": 2, "permanent": 2, "predicting_ball": 1},
                                {"primitives": "L,R", "count": 2, "permanent": 0, "predicting_ball": 0}]
    assert [row["primitives"] for row in table["permanent"]] == ["F,F"]
    assert [row["primitives"] for row in table["predicting_ball"]] == ["F,F"]


def test_an_evaluation_counts_as_done_only_for_its_control_and_size(tmp_path, capsys):
    run = RunDir(tmp_path)
    path = tmp_path / "evaluation_0_improved.json"
    saved = {"trial_seed": 0, "control": "improved", "seed": 1000, "goals": 1, "own_goals": 0, "attempts": 2,
             "outcomes": ["goal", "ball_out"]}
    assert not experiments._evaluation_done(run, path, "improved", 2)
    path.write_text(json.dumps(saved))
    assert experiments._evaluation_done(run, path, "improved", 2)
    assert not experiments._evaluation_done(run, path, "thesis", 2)
    # Written by a build that could only drive by the thesis's rule.
    path.write_text(json.dumps({**saved, "control_used": "thesis"}))
    assert not experiments._evaluation_done(run, path, "improved", 2)
    assert path.exists(), "a whole file of another control is redone, not reported damaged"
    path.write_text("{not json")
    assert not experiments._evaluation_done(run, path, "improved", 2)
    assert "evaluation_0_improved.json is damaged" in capsys.readouterr().err and not path.exists()


@pytest.mark.parametrize("change, complaint", [
    ({"goals": 2}, "key 'goals' is 2 but its outcomes count 1"),
    ({"attempts": 0}, "key 'attempts' must be an integer at least 1, got 0"),
    ({"outcomes": ["goal", "own-goal"]}, "key 'outcomes' must list 2 outcomes"),
    ({"control": "improvd"}, "key 'control' must be one of improved, thesis, got 'improvd'"),
    ({"trial_seed": -1}, "key 'trial_seed' must be an integer at least 0"),
    ({"goals": True}, "key 'goals' must be an integer"),
])
def test_a_saved_evaluation_is_checked_key_by_key(tmp_path, change, complaint):
    path = tmp_path / "evaluation_0_improved.json"
    path.write_text(json.dumps({"trial_seed": 0, "control": "improved", "seed": 1000, "goals": 1, "own_goals": 0,
                                "attempts": 2, "outcomes": ["goal", "ball_out"], **change}))
    with pytest.raises(ModelFileError, match=re.escape(f"{path}: {complaint}")):
        experiments.load_evaluation(path)
