"""Practice through the teacher (jump-start RL): the imitator guides a PPO learner; the practised
policy plays wherever an imitator plays. Needs the optional `rl` extra (stable-baselines3 and
torch), which the test line leaves out: its install is measured in the README."""

import importlib.util

import gymnasium
import pytest

import polymimic
from polymimic.learning import evaluate

pytestmark = pytest.mark.skipif(importlib.util.find_spec("stable_baselines3") is None,
                                reason="stable-baselines3 is the optional `rl` extra")


@pytest.fixture(scope="module")
def teacher(expert_imitator):
    return expert_imitator


@pytest.fixture(scope="module")
def practised(teacher):
    from polymimic.practice.teacher import jsrl

    # A gate always open (any return is within 2 of the teacher's): each stage is earned by one episode.
    return jsrl(teacher, steps=600, checkpoints=[0, 600], evaluation_attempts=2, handover_start=60, stages=2,
                tolerance=2.0, window=1, n_steps=64, batch_size=32)


def test_at_the_start_the_practised_policy_is_its_teacher_bit_for_bit(teacher, practised):
    # No stage is earned before the first practice episode: the teacher plays every decision.
    assert [p.checkpoint for p in practised.curve] == [0, 600]
    alone = evaluate(teacher, attempts_per_configuration=2)
    assert practised.curve[0].net_goals == alone.goals - alone.own_goals
    from polymimic.practice.practised import PractisedPolicy

    guided = evaluate(PractisedPolicy(teacher, practised.policy.actor, handover=60), attempts_per_configuration=2)
    assert [a.frames.tobytes() for a in guided.attempts] == [a.frames.tobytes() for a in alone.attempts]


def test_every_step_counts_the_teachers_roll_ins_too_and_the_budget_holds(practised):
    # No checkpoint is scored with more steps played than it names, the teacher's included.
    assert all(p.steps <= p.checkpoint for p in practised.curve)
    assert 590 <= practised.steps <= 600
    assert practised.policy.handover == 0  # both stages earned: the learner plays alone


def test_a_stage_is_earned_only_when_the_learners_returns_reach_the_teachers():
    from polymimic.practice.teacher import TEACHER_ALONE, Curriculum

    curriculum = Curriculum.stepping_down(12, 3, reference=0.8, tolerance=0.1, window=3)
    assert curriculum.stages == (8, 4, 0) and curriculum.handover == 8
    for episode_return in (1.0, 0.0, 1.0, 1.0):  # windows of mean 0.67 then 0.67: below 0.7
        curriculum.episode_ended(episode_return)
        assert curriculum.earned == TEACHER_ALONE
    curriculum.episode_ended(1.0)  # the last three return 1.0 on average
    assert (curriculum.earned, curriculum.handover) == (8, 4)
    for episode_return in (-1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0):  # 4 earned after the first full window at 1.0
        curriculum.episode_ended(episode_return)
    assert (curriculum.earned, curriculum.handover) == (0, 0)  # the last stage: the learner alone, kept
    with pytest.raises(ValueError, match="stages must be decreasing handovers ≥ 0, got \\(2, 5\\)"):
        Curriculum(stages=(2, 5), reference=0.5)


def test_practise_names_its_methods_and_refuses_others(teacher):
    from polymimic.practice.methods import practise

    taught = practise(teacher, method="jsrl", steps=300, evaluation_attempts=1)
    assert [p.checkpoint for p in taught.curve][-1] == 300 and taught.attempts == []
    with pytest.raises(ValueError, match="unknown practice method 'rl'; expected one of refine, explore, jsrl, distil"):
        practise(teacher, method="rl", steps=10)


def test_the_practised_policy_saves_loads_and_plays_through_evaluate_predict_and_record(tmp_path, practised):
    from polymimic.practice.practised import PractisedPolicy

    policy = PractisedPolicy(practised.policy.guide, practised.policy.actor, handover=3)
    policy.save(tmp_path / "practised.zip")
    again = PractisedPolicy.load(tmp_path / "practised.zip")
    assert (again.handover, again.body, again.method) == (3, "lego", "jsrl")
    played = [evaluate(p, attempts_per_configuration=2, seed=4).attempts for p in (policy, again)]
    assert [a.frames.tobytes() for a in played[0]] == [a.frames.tobytes() for a in played[1]]
    env = gymnasium.make("PenaltyKick-v0")
    observation, _ = env.reset(seed=1)
    action, state = again.predict(observation)
    assert env.action_space.contains(action) and len(state) == 1
    shown = polymimic.record(again.player(), configuration=1, n=1, seed=2, body="lego", name="practised")
    assert shown[0].demonstrator == "practised"
    (tmp_path / "bad.zip").write_text("no")
    with pytest.raises(polymimic.ModelFileError, match="not a practised policy"):
        PractisedPolicy.load(tmp_path / "bad.zip")



def test_distilling_clones_the_teacher_then_fine_tunes_within_the_budget(teacher):
    from polymimic.practice.distil import distil

    # A gate always open: the actor replaces the teacher after its first practice episode.
    taught = distil(teacher, steps=700, checkpoints=[0, 300, 700], evaluation_attempts=2, dagger_rounds=1,
                    dagger_steps=300, warmup_steps=200, tolerance=2.0, window=1, n_steps=64, batch_size=32)
    alone = evaluate(teacher, attempts_per_configuration=2)
    # Before the actor has played an episode, the practised policy is the teacher itself.
    assert taught.curve[0].net_goals == alone.goals - alone.own_goals
    assert [(p.checkpoint, p.steps) for p in taught.curve] == [(0, 0), (300, 300), (700, 700)]
    assert taught.policy.handover == 0 and taught.policy.method == "distil"


def test_an_actor_that_never_earns_it_never_replaces_the_teacher(teacher):
    from polymimic.practice.distil import distil
    from polymimic.practice.teacher import TEACHER_ALONE

    # A gate never open (returns would have to beat the teacher's by 5 per episode).
    taught = distil(teacher, steps=500, checkpoints=[0, 250, 500], evaluation_attempts=2, dagger_rounds=2,
                    dagger_steps=150, warmup_steps=100, tolerance=-5.0, window=1, n_steps=64, batch_size=32)
    alone = evaluate(teacher, attempts_per_configuration=2)
    assert [p.net_goals for p in taught.curve] == [alone.goals - alone.own_goals] * 3
    assert taught.policy.handover == TEACHER_ALONE
