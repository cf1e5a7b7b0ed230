"""Pictures: a still and an animated GIF are written, to scale, atomically."""

import numpy as np
import pytest
from PIL import Image

import polymimic
from polymimic.plots import animate_demonstration, plot_demonstration


@pytest.fixture(scope="module")
def demo():
    return polymimic.record("poor", configuration=2, n=1, seed=1)[0]


def test_still_is_written_and_shows_the_field(tmp_path, demo):
    figure = plot_demonstration(demo, path=tmp_path / "poor.png")
    assert [p.name for p in tmp_path.iterdir()] == ["poor.png"]
    with Image.open(tmp_path / "poor.png") as image:
        assert image.format == "PNG" and image.width > 400
    ax = figure.axes[0]
    assert ax.get_title().startswith(f"poor, configuration 2: {demo.outcome.replace('_', ' ')}")
    left, right = ax.get_xlim()
    assert left < -510 and right > 510  # both goal lines in view
    assert ax.get_aspect() == 1.0  # to scale


def test_still_draws_into_given_axes(demo):
    from matplotlib.figure import Figure

    figure = Figure()
    ax = figure.add_subplot()
    assert plot_demonstration(demo, ax=ax) is figure
    assert len(ax.patches) > 4  # field, goals, robot at start and end, ball


def test_tiny_demonstrations_are_drawn_on_the_small_field():
    tiny = polymimic.record("tiny", configuration=1, n=1, seed=2)[0]
    ax = plot_demonstration(tiny).axes[0]
    assert -400 < ax.get_xlim()[0] < -280


@pytest.mark.parametrize("stride", [40, 97])
def test_gif_has_one_frame_per_stride_and_the_last(tmp_path, demo, stride):
    path = tmp_path / "poor.gif"
    animate_demonstration(demo, path, fps=10, stride=stride)
    expected = len(range(0, len(demo.frames) - 1, stride)) + 1
    with Image.open(path) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == expected
        assert gif.info["duration"] == 100
        gif.seek(gif.n_frames - 1)
        last = np.asarray(gif.convert("RGB"))
        gif.seek(0)
        first = np.asarray(gif.convert("RGB"))
    assert not np.array_equal(first, last)  # things moved
    assert [p.name for p in tmp_path.iterdir()] == ["poor.gif"]


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(path="poor.mp4"), "writes GIF files"),
        (dict(stride=0), "stride must be an integer ≥ 1"),
        (dict(stride=1.5), "stride must be an integer ≥ 1"),
        (dict(fps=0), r"fps must be an integer in 1\.\.100"),
        (dict(fps=12.5), r"fps must be an integer in 1\.\.100"),
    ],
)
def test_bad_animation_arguments_write_nothing(tmp_path, demo, kwargs, match):
    path = tmp_path / kwargs.pop("path", "poor.gif")
    with pytest.raises(ValueError, match=match):
        animate_demonstration(demo, path, **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_not_a_demonstration_is_named(tmp_path):
    with pytest.raises(TypeError, match="expected a Demonstration, got list"):
        plot_demonstration([])
    with pytest.raises(TypeError, match="expected a Demonstration"):
        animate_demonstration("demo", tmp_path / "x.gif")
    assert list(tmp_path.iterdir()) == []
