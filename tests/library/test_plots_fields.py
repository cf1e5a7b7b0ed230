"""Pictures on the right field: each demonstration drawn on its own body's field, a 9 × 6 m log's on
a 9 × 6 m field, a crowd member's and an imitator's attempts on theirs."""

import numpy as np
import pytest
from matplotlib.patches import Rectangle

import polymimic
from polymimic.bodies import Field, WheeledBody
from polymimic.field import FRAME_DTYPE, Demonstration
from polymimic.plots import plot_demonstration, state_image

SSL_BOT = WheeledBody("ssl_bot_plots", length_mm=180, width_mm=180, wheel_base_mm=160, top_wheel_speed_mm_s=2000,
                      field=Field(9000, 6000, goal_mouth_mm=1000, ball_diameter_mm=43))


def _pitch(ax):
    """The drawn field: the rectangle at the bottom of the picture."""
    return next(p for p in ax.patches if isinstance(p, Rectangle) and p.get_zorder() == 0)


def _field_of(ax):
    pitch = _pitch(ax)
    return pitch.get_width(), pitch.get_height()


def _limits_match(ax, length_mm, width_mm):
    """The axes are the field, a tenth of its length beyond each goal line and a twentieth of its
    width beyond each side line."""
    assert ax.get_xlim() == pytest.approx((-0.6 * length_mm, 0.6 * length_mm))
    assert ax.get_ylim() == pytest.approx((-0.55 * width_mm, 0.55 * width_mm))


def _log_demo():
    frames = np.zeros(31, dtype=FRAME_DTYPE)
    frames["t_s"] = np.arange(31) / 30
    frames["robot_x_mm"] = np.linspace(-3000, -1600, 31)
    frames["ball_x_mm"] = 1500.0
    return Demonstration(frames, "time_up", "ssl_log", 1, 0, body=SSL_BOT)


def test_a_log_of_a_9_by_6_m_field_is_drawn_on_a_9_by_6_m_field():
    ax = plot_demonstration(_log_demo()).axes[0]
    assert _field_of(ax) == (9000.0, 6000.0)
    _limits_match(ax, 9000.0, 6000.0)
    mouths = [p for p in ax.patches if isinstance(p, Rectangle) and p.get_zorder() == 1]
    assert [m.get_height() for m in mouths] == [1000.0, 1000.0]  # its own goal mouths


@pytest.mark.parametrize("who, body, size", [("tiny", "tiny", (560.0, 345.0)), ("expert", "lego", (1020.0, 810.0)),
                                             ("humanoid", "humanoid", (1020.0, 810.0))])
def test_every_built_in_body_is_drawn_on_its_own_field(who, body, size):
    demo = polymimic.record(who, configuration=1, n=1, seed=2)[0]
    assert demo.body.name == body
    ax = plot_demonstration(demo).axes[0]
    assert _field_of(ax) == size
    _limits_match(ax, *size)


def test_a_crowd_member_and_an_imitators_attempts_are_drawn_on_their_bodys_field():
    member = polymimic.record("tiny", configuration=1, n=1, seed=2)[0]
    renamed = Demonstration(member.frames, member.outcome, "tiny_03", 1, 0, body="tiny")  # not a built-in's name
    assert _field_of(plot_demonstration(renamed).axes[0]) == (560.0, 345.0)
    attempt = Demonstration(member.frames, member.outcome, "imitator", 1, 0, body="tiny")
    assert _field_of(plot_demonstration(attempt).axes[0]) == (560.0, 345.0)


def test_a_demonstration_brings_its_own_body_to_the_picture():
    frames = _log_demo().frames
    with pytest.raises(ValueError, match='unknown body "ssl_bot_plots": the built-in bodies are'):
        Demonstration(frames, "time_up", "x", 1, 0, body="ssl_bot_plots")  # a name alone: no field to draw
    again = Demonstration(frames, "time_up", "x", 1, 0, body=polymimic.Body(SSL_BOT))
    assert _field_of(plot_demonstration(again).axes[0]) == (9000.0, 6000.0)


def test_the_environments_picture_is_its_bodys_field():
    wide = state_image(SSL_BOT, (-3000.0, 0.0, 0.0), (1500.0, 0.0), "ssl")
    lego = state_image("lego", (-170.0, 0.0, 0.0), (170.0, 0.0), "lego")
    assert wide.shape[1] == lego.shape[1] and wide.shape[0] < lego.shape[0]  # 9 × 6 is wider than 1020 × 810
