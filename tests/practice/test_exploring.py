"""Practice that explores around the ball: the imitator's own attempts show pushes its policy
never chooses, learned as physics."""

import pytest

from polymimic import Attempts
from polymimic.learning import ImitatorPolicy, evaluate


@pytest.fixture(scope="module")
def teacher(expert_imitator):
    return expert_imitator


def test_exploring_practice_explores_near_the_ball_and_refines_only_what_it_is_told(teacher, tmp_path):
    from polymimic.practice.exploring import explored_attempts

    plain = evaluate(teacher, attempts_per_configuration=2, seed=6).attempts
    never = explored_attempts(teacher, attempts_per_configuration=2, seed=6, epsilon=0.0)
    assert [a.frames.tobytes() for a in never] == [a.frames.tobytes() for a in plain], "ε = 0 is the policy's play"
    wild = explored_attempts(teacher, attempts_per_configuration=2, seed=6, epsilon=1.0)
    assert [a.frames.tobytes() for a in wild] != [a.frames.tobytes() for a in plain]
    assert [a.frames.tobytes() for a in wild] == \
        [a.frames.tobytes() for a in explored_attempts(teacher, attempts_per_configuration=2, seed=6, epsilon=1.0)]
    with pytest.raises(ValueError, match=r"epsilon must be a number in \[0, 1\], got 1.5"):
        explored_attempts(teacher, attempts_per_configuration=1, seed=6, epsilon=1.5)
    from polymimic.practice import practice

    result = practice(teacher, steps=300, checkpoints=[0, 300], attempts_per_round=2,
                      evaluation=Attempts(per_configuration=2), explore=0.5, refines=["ball_response"])
    assert result.steps <= 300 and result.policy.made_from.practice_refines == ("ball_response",)
    result.policy.save(tmp_path / "explored.zip")
    assert ImitatorPolicy.load(tmp_path / "explored.zip").made_from.practice_refines == ("ball_response",)
