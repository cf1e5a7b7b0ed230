"""The field a picture draws: a body's own field (its length, width, goal mouths and ball) and the
body's footprint, to scale, and the pitch drawn into matplotlib axes.

>>> scene_of("tiny").field_length_mm, scene_of("tiny").robot_length_mm
(560.0, 15.0)
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

from polymimic.bodies import BodySpec, as_body

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["HUMANOID_FOOTPRINT_MM", "Scene", "draw_field", "scene_of"]

HUMANOID_FOOTPRINT_MM = (70.0, 110.0)
"""The humanoid drawn from above: 70 mm front to back, 110 mm shoulder to shoulder."""
TARGET_COLOUR, OWN_COLOUR = "tab:blue", "tab:red"


@dataclasses.dataclass(frozen=True)
class Scene:
    """Sizes, mm: the field, its goal mouths, the ball and the robot's footprint (length along its
    heading)."""

    field_length_mm: float
    field_width_mm: float
    goal_mouth_mm: float
    ball_diameter_mm: float
    robot_length_mm: float
    robot_width_mm: float


def scene_of(body: BodySpec) -> Scene:
    """The field ``body`` plays on and its footprint: a :class:`polymimic.Body`, a built-in body
    by its name, or a :class:`~polymimic.bodies.WheeledBody`."""
    known = as_body(body)
    field, wheeled = known.field, known.description
    length_mm, width_mm = (wheeled.length_mm, wheeled.width_mm) if wheeled is not None else HUMANOID_FOOTPRINT_MM
    return Scene(field.length_mm, field.width_mm, float(field.goal_mouth_mm or 0.0), field.ball_diameter_mm,
                 float(length_mm), float(width_mm))


def draw_field(ax: Axes, scene: Scene) -> None:
    """The pitch, its centre line and circle, and both goals behind their lines, the axes' limits
    the field and a margin around it (a tenth of its length beyond the goal lines, a twentieth of
    its width beyond the side lines)."""
    from matplotlib.patches import Circle, Rectangle

    half_l, half_w = scene.field_length_mm / 2, scene.field_width_mm / 2
    mouth, depth = scene.goal_mouth_mm / 2, 0.06 * scene.field_length_mm
    ax.add_patch(Rectangle((-half_l, -half_w), 2 * half_l, 2 * half_w, facecolor="#eef6ea", edgecolor="0.15",
                           linewidth=1.5, zorder=0))
    ax.plot([0, 0], [-half_w, half_w], color="0.55", linewidth=1.0, linestyle=":", zorder=1)
    ax.add_patch(Circle((0, 0), 0.1 * scene.field_length_mm, fill=False, edgecolor="0.55", linewidth=1.0,
                        linestyle=":", zorder=1))
    for sign, colour, name in ((1, TARGET_COLOUR, "target goal"), (-1, OWN_COLOUR, "own goal")):
        x0 = half_l if sign > 0 else -half_l - depth
        ax.add_patch(Rectangle((x0, -mouth), depth, 2 * mouth, facecolor=colour, alpha=0.25, edgecolor=colour,
                               linewidth=1.5, zorder=1))
        ax.plot([sign * half_l] * 2, [-mouth, mouth], color=colour, linewidth=3.0, zorder=2)
        ax.text(sign * half_l, mouth + 0.02 * scene.field_width_mm, name, color=colour, ha="center",
                va="bottom", fontsize="small")
    margin = 0.1 * scene.field_length_mm
    ax.set_xlim(-half_l - margin, half_l + margin)
    ax.set_ylim(-half_w - 0.05 * scene.field_width_mm, half_w + 0.05 * scene.field_width_mm)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
