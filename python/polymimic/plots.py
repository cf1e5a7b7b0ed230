"""Pictures of demonstrations: a still of the whole run and an animated GIF, both to scale.

The field is drawn in its own millimetres (origin at the centre, +x toward the target goal),
with the target goal at +x (blue) and the demonstrator's own goal at −x (red). matplotlib is
imported only when a picture is made, and only its object-oriented API is used (no pyplot,
no GUI backend), so these work headless and in threads.

>>> import pathlib, tempfile
>>> from polymimic.field import record
>>> demo = record("expert", configuration=1, n=1, seed=4)[0]
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> figure = plot_demonstration(demo, path=folder / "expert.png")
>>> sorted(p.name for p in folder.iterdir())
['expert.png']
>>> animate_demonstration(demo, folder / "expert.gif", stride=10)
>>> from PIL import Image
>>> with Image.open(folder / "expert.gif") as gif:
...     gif.n_frames == -(-(len(demo.frames) - 1) // 10) + 1
True
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypedDict, cast

import numpy as np

from polymimic._atomic import atomic_path
from polymimic._drawn_field import Scene, draw_field, scene_of
from polymimic.bodies import BodySpec
from polymimic.field import Demonstration

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = ["animate_demonstration", "plot_demonstration"]


class MeanSd(TypedDict):
    """A mean and its sd, as the bar charts take them; ``None`` where there is none."""

    mean: float | None
    sd: float | None


_BALL_COLOUR = "tab:orange"


def plot_demonstration(demo: Demonstration, *, ax: Axes | None = None,
                       path: str | os.PathLike[str] | None = None) -> Figure:
    """Draw a demonstration on its field: the robot's path coloured by time, its heading every
    second, the ball's path, and where both started (hollow) and ended (filled).

    Parameters
    ----------
    demo : Demonstration
        What to draw, on the field of its body (``demo.body``): the tiny's small field, the Lego's
        and the humanoid's large one, a described body's own (a log of a 9 × 6 m field on that
        field), with the robot's footprint and the ball to scale.
    ax : matplotlib.axes.Axes, optional
        Draw into these axes (a colour bar for time is added beside them); default: a new figure.
    path : str or path-like, optional
        Also save the figure there (format from the extension, e.g. ``.png``, ``.svg``),
        atomically.

    Returns
    -------
    matplotlib.figure.Figure
        The figure drawn on.

    Examples
    --------
    >>> from polymimic.field import record
    >>> demo = record("poor", configuration=2, n=1, seed=1)[0]
    >>> figure = plot_demonstration(demo)
    >>> figure.axes[0].get_title().startswith("poor, configuration 2")
    True
    """
    from matplotlib.collections import LineCollection

    scene = _scene(demo)
    frames = demo.frames
    figure, ax = _figure_and_axes(ax, (7.5, 5.6))
    draw_field(ax, scene)

    t_s, x, y, theta = frames["t_s"], frames["robot_x_mm"], frames["robot_y_mm"], frames["robot_theta_rad"]
    points = np.column_stack([x, y])
    segments = np.stack([points[:-1], points[1:]], axis=1)
    ok = np.isfinite(segments).all(axis=(1, 2))
    path_lines = LineCollection(segments[ok], array=t_s[:-1][ok], cmap="viridis", linewidths=3.0, capstyle="round",
                                zorder=3)
    path_lines.set_clim(t_s[0], max(t_s[-1], t_s[0] + 1e-9))
    ax.add_collection(path_lines)
    figure.colorbar(path_lines, ax=ax, label="time (s)", shrink=0.8)
    # Heading arrows, one a second, half a robot long.
    each_second = np.arange(0, len(frames), 30)
    tick_mm = 0.5 * scene.robot_length_mm
    ax.quiver(x[each_second], y[each_second], np.cos(theta[each_second]), np.sin(theta[each_second]),
              angles="xy", scale_units="xy", scale=1 / tick_mm, width=0.0025, color="0.2", alpha=0.6, zorder=4)
    ax.add_patch(_robot_patch(scene, x[0], y[0], theta[0], filled=False))
    ax.add_patch(_robot_patch(scene, x[-1], y[-1], theta[-1], filled=True))

    bx, by = frames["ball_x_mm"], frames["ball_y_mm"]
    ax.plot(bx, by, color=_BALL_COLOUR, linewidth=1.5, linestyle="--", zorder=3, label="ball")
    _ball_markers(ax, scene, bx, by)
    ax.plot([], [], color="0.3", linewidth=2, label="robot (hollow: start, filled: end)")
    ax.legend(loc="lower left", fontsize="small", framealpha=0.9)
    ax.set_title(f"{demo.demonstrator}, configuration {demo.configuration}: {demo.outcome.replace('_', ' ')}\n"
                 f"{len(frames)} frames, {t_s[-1]:.1f} s, seed {demo.seed}", fontsize="medium")
    save_figure(figure, path, dpi=120)
    return figure


def animate_demonstration(demo: Demonstration, path: str | os.PathLike[str], *, fps: int = 30,
                          stride: int = 1) -> None:
    """Write an animated GIF of a demonstration, atomically: the robot as an oriented box with
    its front marked, the ball as a circle, both to scale, trailing their paths.

    Parameters
    ----------
    demo : Demonstration
        What to animate.
    path : str or path-like
        The ``.gif`` file to write (replaced if it exists). Its directory must exist.
    fps : int, default 30
        GIF frames per second, 1 to 100. The tracker runs at 30 frames a second, so the GIF plays in real
        time when ``fps * stride == 30``.
    stride : int, default 1
        Draw every ``stride``-th tracker frame, and always the last one, where the outcome is
        shown: the GIF has ``ceil((len(frames) - 1) / stride) + 1`` frames.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from polymimic.field import record
    >>> demo = record("tiny", configuration=1, n=1, seed=2)[0]
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "tiny.gif"
    >>> animate_demonstration(demo, path, fps=15, stride=30)
    >>> path.stat().st_size > 0
    True
    """
    if not isinstance(stride, (int, np.integer)) or isinstance(stride, bool) or stride < 1:
        raise ValueError(f"stride must be an integer ≥ 1, got {stride!r}")
    if not isinstance(fps, (int, np.integer)) or isinstance(fps, bool) or not 1 <= fps <= 100:
        raise ValueError(f"fps must be an integer in 1..100, got {fps!r}")
    if not os.fspath(path).lower().endswith(".gif"):
        raise ValueError(f"animate_demonstration writes GIF files; {os.fspath(path)!r} does not end in .gif")
    from matplotlib.animation import PillowWriter
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.patches import Circle

    scene = _scene(demo)
    frames = demo.frames
    aspect = (1.1 * scene.field_width_mm) / (1.2 * scene.field_length_mm)
    figure = Figure(figsize=(6.0, 6.0 * aspect + 0.7), layout="constrained")
    FigureCanvasAgg(figure)
    ax = figure.add_subplot()
    draw_field(ax, scene)
    robot_trail, = ax.plot([], [], color="0.35", linewidth=1.0, zorder=3)
    ball_trail, = ax.plot([], [], color=_BALL_COLOUR, linewidth=1.0, linestyle="--", zorder=3)
    robot = _robot_patch(scene, frames["robot_x_mm"][0], frames["robot_y_mm"][0], frames["robot_theta_rad"][0],
                         filled=True)
    ax.add_patch(robot)
    ball = Circle((0.0, 0.0), scene.ball_diameter_mm / 2, facecolor=_BALL_COLOUR, edgecolor="black",
                  linewidth=0.8, zorder=5)
    ax.add_patch(ball)
    title = ax.set_title("", fontsize="medium")
    label = f"{demo.demonstrator}, configuration {demo.configuration}"

    writer = PillowWriter(fps=int(fps))
    with atomic_path(path) as temporary, writer.saving(figure, os.fspath(temporary), dpi=80):
        for i in _drawn_frames(len(frames), stride):
            f = frames[i]
            robot.set_xy(_robot_outline(scene, f["robot_x_mm"], f["robot_y_mm"], f["robot_theta_rad"]))
            ball.set_center((f["ball_x_mm"], f["ball_y_mm"]))
            ball.set_visible(bool(np.isfinite(f["ball_x_mm"])))
            robot_trail.set_data(frames["robot_x_mm"][:i + 1], frames["robot_y_mm"][:i + 1])
            ball_trail.set_data(frames["ball_x_mm"][:i + 1], frames["ball_y_mm"][:i + 1])
            ending = f": {demo.outcome.replace('_', ' ')}" if i == len(frames) - 1 else ""
            title.set_text(f"{label}   t = {f['t_s']:5.2f} s{ending}")
            writer.grab_frame()


def state_image(body: BodySpec, robot: tuple[float, float, float], ball: tuple[float, float] | None,
                 title: str) -> np.ndarray:
    """An ``(H, W, 3)`` uint8 picture of ``body``'s field with the robot at pose ``robot`` and the ball."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.patches import Circle

    scene = scene_of(body)
    aspect = (1.1 * scene.field_width_mm) / (1.2 * scene.field_length_mm)
    figure = Figure(figsize=(6.0, 6.0 * aspect + 0.7), dpi=80, layout="constrained")
    canvas = FigureCanvasAgg(figure)
    ax = figure.add_subplot()
    draw_field(ax, scene)
    ax.add_patch(_robot_patch(scene, *robot, filled=True))
    if ball is not None:
        ax.add_patch(Circle(ball, scene.ball_diameter_mm / 2, facecolor=_BALL_COLOUR, edgecolor="black",
                            linewidth=0.8, zorder=5))
    ax.set_title(title, fontsize="medium")
    # matplotlib leaves the Agg canvas's methods untyped.
    canvas.draw()  # type: ignore[no-untyped-call]
    rgba = np.asarray(canvas.buffer_rgba())  # type: ignore[no-untyped-call]
    return rgba[..., :3].copy()


def _drawn_frames(n_frames: int, stride: int) -> list[int]:
    """Every ``stride``-th frame index from 0, and the last."""
    drawn = list(range(0, n_frames, stride))
    return drawn if drawn[-1] == n_frames - 1 else [*drawn, n_frames - 1]


def _scene(demo: Demonstration) -> Scene:
    if not isinstance(demo, Demonstration):
        raise TypeError(f"expected a Demonstration, got {type(demo).__name__}")
    if len(demo.frames) == 0:
        raise ValueError("the demonstration has no frames to draw")
    return scene_of(demo.body)


def _robot_outline(scene: Scene, x_mm: float, y_mm: float, theta_rad: float) -> np.ndarray:
    """The robot's box with a notch at its front (a pentagon), in field coordinates."""
    hl, hw = scene.robot_length_mm / 2, scene.robot_width_mm / 2
    robot_frame = np.array([[-hl, -hw], [hl * 0.6, -hw], [hl, 0.0], [hl * 0.6, hw], [-hl, hw]])
    c, s = math.cos(theta_rad), math.sin(theta_rad)
    outline: np.ndarray = robot_frame @ np.array([[c, s], [-s, c]]) + np.array([x_mm, y_mm])
    return outline


def _robot_patch(scene: Scene, x_mm: float, y_mm: float, theta_rad: float, *, filled: bool) -> Any:
    from matplotlib.patches import Polygon

    outline = _robot_outline(scene, x_mm, y_mm, theta_rad) if np.isfinite([x_mm, y_mm, theta_rad]).all() else \
        np.zeros((5, 2))
    return Polygon(outline, closed=True, facecolor="0.3" if filled else "none", edgecolor="0.1", alpha=0.85,
                   linewidth=1.2, zorder=5)


def _ball_markers(ax: Axes, scene: Scene, bx: np.ndarray, by: np.ndarray) -> None:
    from matplotlib.patches import Circle

    seen = np.flatnonzero(np.isfinite(bx) & np.isfinite(by))
    if len(seen) == 0:
        return
    first, last = seen[0], seen[-1]
    r = scene.ball_diameter_mm / 2
    ax.add_patch(Circle((bx[first], by[first]), r, fill=False, edgecolor=_BALL_COLOUR, linewidth=1.5, zorder=4))
    ax.add_patch(Circle((bx[last], by[last]), r, facecolor=_BALL_COLOUR, edgecolor="black", linewidth=0.8,
                        alpha=0.9, zorder=4))


def plot_log_likelihoods(table: Mapping[str, Mapping[str, float | None]], *, ax: Axes | None = None,
                         path: str | os.PathLike[str] | None = None) -> Figure:
    """Fig 4.5: grouped bars of each HMM's mean log-likelihood on each primitive's test set.

    Parameters
    ----------
    table : dict
        ``table[model][primitive]``, as :func:`polymimic.recognition.log_likelihood_table`
        returns it.
    ax, path
        As for :func:`plot_demonstration`.

    Examples
    --------
    >>> table = {"forward": {"forward": -60.0, "backward": -400.0},
    ...          "backward": {"forward": -380.0, "backward": -70.0}}
    >>> figure = plot_log_likelihoods(table)
    >>> len(figure.axes[0].patches)
    4
    """
    figure, ax = _figure_and_axes(ax, (7.0, 4.2), chart=True)
    models = list(table)
    primitives = list(next(iter(table.values()), {}))
    width = 0.8 / max(len(models), 1)
    positions = np.arange(len(primitives))
    for i, model in enumerate(models):
        values = np.array([table[model][p] for p in primitives], dtype=float)  # an unknown mean is NaN
        ax.bar(positions + (i - (len(models) - 1) / 2) * width, values, width, label=f"{model} HMM")
    ax.set_xticks(positions, [f"{p} test set" for p in primitives])
    ax.set_ylabel("mean log-likelihood")
    ax.axhline(0.0, color="0.3", linewidth=0.8)
    ax.legend(fontsize="small")
    ax.set_title("Each HMM on each primitive's held-out sequences (thesis Fig 4.5)", fontsize="medium")
    save_figure(figure, path, dpi=120)
    return figure


def plot_metric_bars(table: Mapping[str, Mapping[str, MeanSd]], *, ylabel: str, title: str,
                     ax: Axes | None = None, path: str | os.PathLike[str] | None = None) -> Figure:
    """Bars of a per-model metric, mean ± sd over trials, with the sd written on top of each bar
    as in the thesis's Figs 4.7–4.12 and 4.19–4.25.

    Parameters
    ----------
    table : dict
        ``table[group][model] = {"mean": …, "sd": …}``: one bar per group (an experiment or an
        ordering) beside each other for every model; models are taken in their first group's
        order. A ``None`` mean draws no bar.
    ylabel, title : str
        Axis label and title.
    ax, path
        As for :func:`plot_demonstration`.

    Examples
    --------
    >>> table = {"RCB": {"expert": {"mean": 40.0, "sd": 3.0}, "humanoid": {"mean": 55.0, "sd": 6.0}},
    ...          "BCR": {"expert": {"mean": 41.0, "sd": 2.0}, "humanoid": {"mean": 54.0, "sd": 5.0}}}
    >>> figure = plot_metric_bars(table, ylabel="behaviours created", title="Fig 4.7")
    >>> len(figure.axes[0].patches)
    4
    """
    figure, ax = _figure_and_axes(ax, (7.0, 4.2), chart=True)
    groups = list(table)
    models: list[str] = []
    for group in groups:
        models += [m for m in table[group] if m not in models]
    width = 0.8 / max(len(groups), 1)
    positions = np.arange(len(models))
    for i, group in enumerate(groups):
        cells = [table[group].get(m) for m in models]
        means = np.array([np.nan if c is None or c["mean"] is None else c["mean"] for c in cells], dtype=float)
        sds = np.array([np.nan if c is None or c["sd"] is None else c["sd"] for c in cells], dtype=float)
        shown = np.isfinite(means)
        x = positions[shown] + (i - (len(groups) - 1) / 2) * width
        bars = ax.bar(x, means[shown], width, yerr=np.nan_to_num(sds[shown]), capsize=3, label=group)
        ax.bar_label(bars, labels=[f"{s:.2g}" for s in np.nan_to_num(sds[shown])], fontsize="x-small",
                     padding=2)
    ax.set_xticks(positions, models)
    ax.set_ylabel(ylabel)
    ax.margins(y=0.12)
    if len(groups) > 1:
        ax.legend(fontsize="small")
    ax.set_title(title, fontsize="medium")
    save_figure(figure, path)
    return figure


def plot_lp_over_time(histories: list[list[float]], *, stride: int, title: str, ax: Axes | None = None,
                      path: str | os.PathLike[str] | None = None) -> Figure:
    """A demonstrator model's learning preference over training, every trial overlaid (thesis
    Figs 4.13–4.18, 4.26–4.28).

    Parameters
    ----------
    histories : list of list of float
        One list per trial: its LP at every ``stride``-th change.
    stride : int
        LP changes between points, to label the x axis.
    title : str
        The figure's title.
    ax, path
        As for :func:`plot_demonstration`.

    Examples
    --------
    >>> figure = plot_lp_over_time([[0.5, 0.8, 1.0], [0.5, 0.6, 0.9, 1.0]], stride=200, title="expert")
    >>> len(figure.axes[0].lines)   # two trials, and the starting LP
    3
    """
    figure, ax = _figure_and_axes(ax, (7.0, 3.6), chart=True)
    alpha = max(0.08, min(0.8, 8.0 / max(len(histories), 1)))
    for history in histories:
        ax.plot(np.arange(len(history)) * stride, history, color="tab:blue", linewidth=0.8, alpha=alpha)
    ax.axhline(0.5, color="0.4", linewidth=0.8, linestyle=":")
    ax.set_ylim(0.0, 1.05)
    ax.set_xlabel(f"LP changes (a point every {stride})")
    ax.set_ylabel("learning preference")
    ax.set_title(f"{title} ({len(histories)} trials)", fontsize="medium")
    save_figure(figure, path)
    return figure


# A chart's margins, inches: room for a one-line title, tick labels of up to six characters and
# the axis labels. Fixed margins cost nothing to lay out, where the constrained layout measures
# every text twice and takes a third of a report's drawing time.
_CHART_MARGINS_IN = {"left": 0.9, "right": 0.15, "bottom": 0.55, "top": 0.35}


def _figure_and_axes(ax: Axes | None, size_in: tuple[float, float], *, chart: bool = False) -> tuple[Figure, Axes]:
    """The figure of ``ax``, or a new figure of ``size_in`` (inches) with one axes: laid out by
    matplotlib's constrained layout, or with fixed margins for a ``chart``."""
    from matplotlib.figure import Figure

    if ax is None:
        if chart:
            width, height = size_in
            m = _CHART_MARGINS_IN
            figure = Figure(figsize=size_in)
            figure.subplots_adjust(left=m["left"] / width, right=1 - m["right"] / width,
                                   bottom=m["bottom"] / height, top=1 - m["top"] / height)
            ax = figure.add_subplot()
        else:
            ax = Figure(figsize=size_in, layout="constrained").add_subplot()
    return cast("Figure", ax.figure), ax


def save_figure(figure: Figure, path: str | os.PathLike[str] | None, *, dpi: int = 100) -> None:
    """Write the figure to ``path`` atomically, if a path is given."""
    if path is not None:
        with atomic_path(path) as temporary:
            figure.savefig(temporary, dpi=dpi)
