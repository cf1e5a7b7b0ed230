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

TWO_EACH = polymimic.Attempts(per_configuration=2)


@pytest.fixture(scope="module")
def teacher(expert_imitator):
    return expert_imitator


@pytest.fixture(scope="module")
def practised(teacher):
    from polymimic.practice.teacher import Gate, jsrl

    # A gate always open (no pair of returns is 10 apart): each check earns a stage.
    return jsrl(teacher, steps=600, checkpoints=[0, 600], evaluation=TWO_EACH, handover_start=4, stages=2,
                tolerance=10.0, gate=Gate(every=100, attempts=1), n_steps=64, batch_size=32)


def test_at_the_start_the_practised_policy_is_its_teacher_bit_for_bit(teacher, practised):
    # No stage is earned before the first check: the teacher plays every decision.
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


def test_a_stage_is_earned_only_when_a_check_shows_the_policy_no_worse_than_the_teacher_with_confidence():
    from polymimic.practice.teacher import TEACHER_ALONE, Curriculum

    teacher = (1, 0, 1, 0, 1, 0, 1, 0)
    curriculum = Curriculum.stepping_down(12, 3, reference=teacher, tolerance=0.1, confidence_z=2.0)
    assert curriculum.stages == (8, 4, 0) and curriculum.handover == 8
    # Differences (0, 0, -1, 0, 0, 0, 0, 0): mean -1/8, sd sqrt(1/8), lower bound -1/8 - 2 / 8 < -0.1.
    assert curriculum.lower_bound((1, 0, 0, 0, 1, 0, 1, 0)) == pytest.approx(-0.125 - 2 * (1 / 8) ** 0.5 / 8 ** 0.5)
    assert not curriculum.checked((1, 0, 0, 0, 1, 0, 1, 0)) and curriculum.earned == TEACHER_ALONE
    # The same mean as the teacher's, but by luck on two attempts: -0 - 2 * sd / sqrt(8) = -0.378.
    assert not curriculum.checked((0, 1, 1, 0, 1, 0, 1, 0)) and curriculum.earned == TEACHER_ALONE
    assert curriculum.checked(teacher) and (curriculum.earned, curriculum.handover) == (8, 4)
    assert curriculum.checked((1, 1, 1, 1, 1, 1, 1, 1)) and (curriculum.earned, curriculum.handover) == (4, 0)
    assert not curriculum.finished and curriculum.checked(teacher) and curriculum.finished
    assert (curriculum.earned, curriculum.handover, curriculum.best) == (0, 0, 0.5)
    # The learner alone, kept: a later policy must also net more on the check's attempts.
    assert not curriculum.checked(teacher) and curriculum.best == 0.5
    assert curriculum.checked((1, 1, 1, 1, 1, 1, 1, 1)) and curriculum.best == 1.0
    with pytest.raises(ValueError, match="stages must be decreasing handovers ≥ 0, got \\(2, 5\\)"):
        Curriculum(stages=(2, 5), reference=(0.5,))
    with pytest.raises(ValueError, match="a check plays the reference's 8 attempts, got 2 returns"):
        curriculum.checked((1, 1))
    for name, value, allowed in (("tolerance", float("inf"), "a finite number"),
                                 ("confidence_z", -0.5, "a finite number ≥ 0"),
                                 ("confidence_z", float("nan"), "a finite number ≥ 0"),
                                 ("confidence_z", True, "a finite number ≥ 0")):
        with pytest.raises(ValueError, match=f"{name} must be {allowed}, got {value!r}"):
            Curriculum(stages=(0,), reference=(0.5,), **{name: value})
    assert Curriculum(stages=(0,), reference=(0.5,), tolerance=-5.0).tolerance == -5.0  # must beat the teacher
    # No confidence asked: the mean alone decides, and the lucky check above passes.
    assert Curriculum(stages=(0,), reference=teacher, confidence_z=0.0).checked((0, 1, 1, 0, 1, 0, 1, 0))


def test_a_check_plays_practice_attempts_counts_their_steps_and_fits_before_the_checkpoint(teacher):
    from polymimic.practice.practised import PractisedPolicy
    from polymimic.practice.seeds import round_seed
    from polymimic.practice.teacher import TEACHER_ALONE, Curriculum, Gate, _Counter, _teacher_alone

    gate, counter = Gate(every=100, attempts=2), _Counter(steps=100, limit=339)
    assert not gate.due(counter)  # 239 steps left; four attempts may take 240
    counter.limit = 340
    assert gate.due(counter)
    played = evaluate(teacher, attempts_per_configuration=2, seed=round_seed(3, 10_000))
    returns = [{"goal": 1.0, "own_goal": -1.0}.get(a.outcome, 0.0) for a in played.attempts]
    curriculum = Curriculum(stages=(0,), reference=returns, tolerance=0.0)
    alone = PractisedPolicy(teacher, None, handover=TEACHER_ALONE)  # the teacher plays every decision
    gate.check(alone, curriculum, counter, seed=3, field_config=None)
    # The check replays the attempts the teacher's reference is measured on: the teacher passes.
    steps = sum(-(-len(a.frames) // 30) for a in played.attempts)
    assert counter.steps == 100 + steps and gate.last_step == counter.steps
    assert curriculum.finished and curriculum.best == sum(returns) / 4
    assert gate.scored(alone) is not alone  # a policy that passes is kept, as a copy
    assert _teacher_alone(teacher, 3, None, gate)[1] == returns


def test_practise_names_its_methods_and_refuses_others(teacher):
    from polymimic.practice.methods import practise

    taught = practise(teacher, method="jsrl", steps=300, evaluation=polymimic.Attempts(per_configuration=1))
    assert [p.checkpoint for p in taught.curve][-1] == 300 and taught.attempts == []
    with pytest.raises(ValueError, match="unknown practice method 'rl'; expected one of explore, jsrl, distil"):
        practise(teacher, method="rl", steps=10)
    with pytest.raises(ValueError, match=r"practice method 'refine' is retired .* explore=0, refines=None"):
        practise(teacher, method="refine", steps=10)
    for method in ("jsrl", "distil"):  # refused before any learning: a practised policy plays no starts of its own
        with pytest.raises(ValueError, match="evaluation must be attempts from the thesis's configurations"):
            practise(teacher, method=method, steps=10, evaluation=polymimic.Attempts(starts=[1]))


def test_the_practised_policy_saves_loads_and_plays_through_evaluate_predict_and_record(tmp_path, practised):
    from polymimic.practice.practised import PractisedPolicy

    policy = PractisedPolicy(practised.policy.guide, practised.policy.actor, handover=3)
    policy.save(tmp_path / "practised.zip")
    again = PractisedPolicy.load(tmp_path / "practised.zip")
    assert (again.handover, again.body.name, again.method) == (3, "lego", "jsrl")
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
    from polymimic.practice.teacher import Gate

    # A gate always open: the actor replaces the teacher at its first check.
    taught = distil(teacher, steps=900, checkpoints=[0, 300, 900], evaluation=TWO_EACH, dagger_rounds=1,
                    dagger_steps=300, warmup_steps=100, tolerance=10.0, gate=Gate(every=1, attempts=1),
                    n_steps=64, batch_size=32)
    alone = evaluate(teacher, attempts_per_configuration=2)
    # Before the actor's first check, the practised policy is the teacher itself.
    assert taught.curve[0].net_goals == alone.goals - alone.own_goals
    assert [(p.checkpoint, p.steps) for p in taught.curve] == [(0, 0), (300, 300), (900, 900)]
    assert taught.policy.handover == 0 and taught.policy.method == "distil"


def test_an_actor_that_never_earns_it_never_replaces_the_teacher(teacher):
    from polymimic.practice.distil import distil
    from polymimic.practice.teacher import TEACHER_ALONE, Gate

    # A gate never open (a check would have to beat the teacher by 5 per attempt).
    taught = distil(teacher, steps=500, checkpoints=[0, 250, 500], evaluation=TWO_EACH, dagger_rounds=2,
                    dagger_steps=150, warmup_steps=100, tolerance=-5.0, gate=Gate(every=1, attempts=1),
                    n_steps=64, batch_size=32)
    alone = evaluate(teacher, attempts_per_configuration=2)
    assert [p.net_goals for p in taught.curve] == [alone.goals - alone.own_goals] * 3
    assert taught.policy.handover == TEACHER_ALONE
