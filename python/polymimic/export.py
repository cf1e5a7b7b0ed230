"""Demonstrations out to the tools offline-RL and imitation users already have: Minari datasets
of ``PenaltyKick-v0`` episodes, and back.

An episode is a demonstration cut into the environment's steps: every ``step_frames`` tracker
frames (30 a second) the observation the environment would give (robot x, y, θ and ball x, y,
the last good reading repeated through a tracking dropout, and the first good one before it
is first seen), so that a dataset holds one more observation than it has actions, as Minari
expects. Its reward is the environment's (+1 on the step of a goal, −1 on an own goal, 0
otherwise); it terminates on a goal, an own goal or the ball or robot leaving the field, and is
truncated by the time limit.

Actions, one of the five primitives a step, come from one of two places:

- ``actions="recognizer"`` (the default): the imitator's own reading of the demonstration —
  learning from observation, as the imitator itself learns (the dataset says so in its
  metadata). Each step takes the primitive the recogniser names for the second of motion from
  the step's first frame (:func:`polymimic.window_names.name_windows`), as BCO's inverse model
  names a transition; a recogniser of the humanoid's own primitives names its side-steps and
  kick by their wheeled equivalents (``polymimic.field.WHEELED_EQUIVALENT``), in windows and
  segments alike. A second too close to call (a gap: no primitive fits, as for a humanoid
  side-step read by a wheeled recogniser) names nothing; its step takes the nearest named step's
  primitive (the earlier on a tie), flagged ``infos["gap"]``. ``labels="segments"`` gives each
  step the primitive most of its frames' segments are named instead (thesis §3.2.2). A segment grows
  until its motion exceeds any one primitive's, so the Expert's are 98 % forward while it turns
  in 31 % of its frames: over ten Expert demonstrations read by the full reproduction's
  recogniser, the window names agree with the commands sent in 87.1 % of frames, the segments' in
  79.3 %, and the commands' own most frequent primitive in 90.7 % (the Expert changes command
  within a second).
- ``actions="commands"``: the primitive equivalent of the commands the demonstrator sent
  (privileged: a real tracker does not see them), the most frequent over the step.

Each episode's demonstrator, body, lapse, configuration, episode seed and outcome go in its
Minari episode metadata, and :func:`from_minari` reads back all but the lapse (a demonstration
has none). Needs ``pip install "polymimic[minari]"``.
"""

from __future__ import annotations

import dataclasses
import numbers
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from polymimic._native import PrimitiveRecognizer
from polymimic.env import ENV_ID
from polymimic.field import (
    FRAME_DTYPE,
    OUTCOME_REWARDS,
    OUTCOMES,
    PRIMITIVES,
    WHEELED_EQUIVALENT,
    Demonstration,
    primitives_sent,
)
from polymimic.window_names import LABELS, NO_NAME, name_windows, repeat_last_good, segmenter_settings, window_settings

__all__ = ["ACTIONS", "LABELS", "OBSERVED", "SIMULATED_BODIES", "from_minari", "steps_of", "to_minari"]

ACTIONS = ("recognizer", "commands")
"""Where a dataset's actions come from (see the module's documentation)."""

OBSERVED = ("robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm")
"""The frame columns an observation holds, in order."""

_TRUNCATING = frozenset({"time_up"})
SIMULATED_BODIES = ("lego",)
"""The bodies ``PenaltyKick-v0`` simulates, whose demonstrations a dataset may hold."""


@dataclasses.dataclass(frozen=True)
class Steps:
    """One demonstration as environment steps: ``observations`` ``(T + 1, 5)`` float32,
    ``actions`` ``(T,)`` primitive indices, ``rewards``, ``terminations``, ``truncations`` and
    ``gap`` (a step whose action no named frame gave) ``(T,)``."""

    observations: np.ndarray
    actions: np.ndarray
    rewards: np.ndarray
    terminations: np.ndarray
    truncations: np.ndarray
    gap: np.ndarray


def steps_of(demonstration: Demonstration, *, step_frames: int = 30, actions: str = "recognizer",
             recognizer: PrimitiveRecognizer | None = None, segmenter: Mapping[str, Any] | None = None,
             labels: str = "steps") -> Steps:
    """``demonstration`` cut into environment steps of ``step_frames`` frames (the last may be
    shorter: it ends where the demonstration ends), with ``actions`` named as the module's
    documentation says (``labels`` choosing how the recogniser names them).

    Examples
    --------
    >>> import polymimic
    >>> demo = polymimic.record("expert", configuration=1, n=1, seed=4)[0]
    >>> steps = steps_of(demo, actions="commands")
    >>> len(steps.observations) == len(steps.actions) + 1, steps.observations.dtype
    (True, dtype('float32'))
    """
    _check_step_frames(step_frames)
    if actions not in ACTIONS:
        raise ValueError(f"actions must be one of {', '.join(map(repr, ACTIONS))}, got {actions!r}")
    if labels not in LABELS:
        raise ValueError(f"labels must be one of {', '.join(map(repr, LABELS))}, got {labels!r}")
    frames = demonstration.frames
    if len(frames) < 2:
        raise ValueError(f"a demonstration of {len(frames)} frame(s) has no step: it needs at least 2")
    observed = repeat_last_good(np.column_stack([frames[c] for c in OBSERVED]).astype(np.float32))
    n_steps = -(-(len(frames) - 1) // step_frames)
    ends = np.minimum(np.arange(1, n_steps + 1) * step_frames, len(frames) - 1)
    starts = np.concatenate([[0], ends[:-1]])
    if actions == "commands":
        sent = np.array([PRIMITIVES.index(str(p)) for p in primitives_sent(demonstration)])
        chosen, gap = _majorities(sent, starts, ends)
    elif recognizer is None:
        raise ValueError('actions="recognizer" needs the recognizer= that reads the demonstrations')
    elif labels == "segments":
        named = _recognised(recognizer.segment(frames, **segmenter_settings(segmenter)), len(frames))
        chosen, gap = _majorities(named, starts, ends)
    else:
        chosen, gap = _nearest_named(name_windows(frames, recognizer, starts, **window_settings(segmenter)))
    rewards = np.zeros(n_steps)
    rewards[-1] = OUTCOME_REWARDS.get(demonstration.outcome, 0.0)
    terminations, truncations = np.zeros(n_steps, dtype=bool), np.zeros(n_steps, dtype=bool)
    if demonstration.outcome in _TRUNCATING:
        truncations[-1] = True
    else:
        terminations[-1] = True
    return Steps(observations=observed[np.concatenate([[0], ends])], actions=np.array(chosen, dtype=np.int64),
                 rewards=rewards, terminations=terminations, truncations=truncations, gap=np.array(gap, dtype=bool))


def to_minari(demonstrations: Sequence[Demonstration], dataset_id: str, *, actions: str = "recognizer",
              recognizer: PrimitiveRecognizer | None = None, segmenter: Mapping[str, Any] | None = None,
              labels: str = "steps", lapses: Mapping[str, float] | None = None, step_frames: int = 30,
              overwrite: bool = False, author: str | None = None, author_email: str | None = None,
              code_permalink: str | None = None, description: str | None = None) -> Any:
    """Write ``demonstrations`` as a Minari dataset of ``PenaltyKick-v0`` episodes; return it.

    Parameters
    ----------
    demonstrations : list of Demonstration
        Of bodies the environment simulates (the Lego robot: the Expert, the Poor, the
        Average, an imitator's attempts).
    dataset_id : str
        Minari's id, ``[namespace/](env_name-)(dataset_name)(-v(version))``, e.g.
        ``"polymimic/expert-v0"``. An existing one is refused unless ``overwrite=True``.
    actions : {"recognizer", "commands"}
        The imitator's own reading (learning from observation), or the commands sent.
    recognizer, segmenter
        The recogniser (and segmenter settings) that reads them, for ``actions="recognizer"``.
    labels : {"steps", "segments"}
        How the recogniser names a step: by the second of motion from its first frame, or by
        the segments its frames lie in (see the module's documentation).
    lapses : mapping of str to float, optional
        Each demonstrator's lapse ε (docs/guides/crowd.md: a crowd member's, :meth:`polymimic.crowds.Crowd.lapses`),
        written in its episodes' metadata; a demonstrator not named is its controller itself, ε = 0.
    step_frames : int
        Tracker frames a step (the environment's ``frames_per_action``).
    author, author_email, code_permalink, description
        Passed to Minari, which asks for them.

    Raises
    ------
    ValueError
        An existing ``dataset_id`` (without ``overwrite``), a demonstration of a body the
        environment does not simulate (naming it), or bad arguments.
    ModuleNotFoundError
        Without Minari installed.
    """
    minari, episode_buffer = _minari()
    if not demonstrations:
        raise ValueError("no demonstrations: a dataset needs at least one")
    for i, demo in enumerate(demonstrations):
        if not isinstance(demo, Demonstration):
            raise TypeError(f"demonstration {i} is a {type(demo).__name__}, not a polymimic.Demonstration")
        if demo.body.kind not in SIMULATED_BODIES:
            raise ValueError(f"demonstration {i} ({demo.demonstrator}) is of the {demo.body.name} body; "
                             f"{ENV_ID} simulates the Lego robot only")
    lapse_of = _checked_lapses(lapses, {d.demonstrator for d in demonstrations})
    exists = dataset_id in minari.list_local_datasets()
    if exists and not overwrite:
        raise ValueError(f"a Minari dataset {dataset_id!r} exists already: pass overwrite=True to replace it")
    # Every step first: a bad argument or an unreadable demonstration leaves the old dataset be.
    all_steps = [steps_of(d, step_frames=step_frames, actions=actions, recognizer=recognizer, segmenter=segmenter,
                          labels=labels) for d in demonstrations]
    if exists:
        minari.delete_dataset(dataset_id)
    buffers = [episode_buffer(observations=s.observations, actions=s.actions, rewards=s.rewards.tolist(),
                              terminations=s.terminations.tolist(), truncations=s.truncations.tolist(),
                              infos={"gap": [*s.gap.tolist(), False]}) for s in all_steps]
    spec = _env_spec(step_frames)
    learned_from = "observation" if actions == "recognizer" else "the commands sent"
    dataset = minari.create_dataset_from_buffers(
        dataset_id, buffers, env=spec, eval_env=spec, algorithm_name=f"polymimic ({actions})",
        author=author, author_email=author_email, code_permalink=code_permalink, data_format="arrow",
        description=description or f"polymimic demonstrations; actions learned from {learned_from}")
    dataset.storage.update_metadata({"polymimic_actions": actions, "learned_from_observation": actions == "recognizer",
                                     "polymimic_labels": labels if actions == "recognizer" else "commands",
                                     "step_frames": step_frames})
    dataset.storage.update_episode_metadata(
        [{"demonstrator": d.demonstrator, "body": d.body.name, "lapse": lapse_of.get(d.demonstrator, 0.0),
          "configuration": d.configuration, "episode_seed": str(d.seed), "outcome": d.outcome}
         for d in demonstrations],
        range(len(demonstrations)))
    return minari.load_dataset(dataset_id)


def from_minari(dataset: Any) -> list[Demonstration]:
    """The episodes of a dataset :func:`to_minari` wrote (a ``MinariDataset`` or its id), as
    demonstrations at the dataset's step rate: one frame per observation, ``t_s`` the step's
    time, ``command`` the step's action (the primitive's command id; the last frame repeats the
    last action), with the demonstrator, configuration, seed and outcome restored.

    Raises
    ------
    ValueError
        A dataset polymimic did not write (no ``polymimic_actions`` in its metadata).
    """
    minari, _ = _minari()
    if isinstance(dataset, str):
        dataset = minari.load_dataset(dataset)
    metadata = dataset.storage.metadata
    if "polymimic_actions" not in metadata:
        raise ValueError(f"{metadata.get('dataset_id')!r} was not written by polymimic.export.to_minari")
    step_s = int(metadata["step_frames"]) / 30.0
    episodes = list(dataset.iterate_episodes())
    info = list(dataset.storage.get_episode_metadata([e.id for e in episodes]))
    demonstrations = []
    for episode, meta in zip(episodes, info):
        observations = np.asarray(episode.observations, dtype=float)
        frames = np.zeros(len(observations), dtype=FRAME_DTYPE)
        frames["t_s"] = np.arange(len(observations)) * step_s
        for i, column in enumerate(OBSERVED):
            frames[column] = observations[:, i]
        actions = np.asarray(episode.actions, dtype=int)
        frames["command"] = np.append(actions, actions[-1:])  # a primitive's command id is its index
        if meta["outcome"] not in OUTCOMES:
            raise ValueError(f"episode {episode.id} has outcome {meta['outcome']!r}; expected one of "
                             f"{', '.join(OUTCOMES)}")
        demonstrations.append(Demonstration(frames=frames, outcome=meta["outcome"], demonstrator=meta["demonstrator"],
                                            configuration=int(meta["configuration"]), seed=int(meta["episode_seed"]),
                                            body=str(meta.get("body", ""))))
    return demonstrations


def _minari() -> tuple[Any, Any]:
    try:
        import minari
        from minari.data_collector import EpisodeBuffer
    except ImportError as error:
        raise ModuleNotFoundError('Minari export needs minari: pip install "polymimic[minari]"',
                                  name="minari") from error
    return minari, EpisodeBuffer


def _env_spec(step_frames: int) -> Any:
    """``PenaltyKick-v0``'s spec with the dataset's step length, so the env is remade as recorded."""
    import gymnasium

    return dataclasses.replace(gymnasium.spec(ENV_ID), kwargs={"frames_per_action": step_frames})


def _checked_lapses(lapses: Mapping[str, float] | None, demonstrators: set[str]) -> dict[str, float]:
    """``lapses`` as floats in [0, 1], or a ValueError naming a bad one or one no demonstration has."""
    checked: dict[str, float] = {}
    for name, value in dict(lapses or {}).items():
        if name not in demonstrators:
            raise ValueError(f"lapses names {name!r}, who demonstrates none of these; they are by "
                             f"{', '.join(sorted(demonstrators))}")
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0.0 <= value <= 1.0:
            raise ValueError(f"lapses[{name!r}] must be a number in [0, 1], got {value!r}")
        checked[name] = float(value)
    return checked


def _check_step_frames(step_frames: Any) -> None:
    if not isinstance(step_frames, int) or isinstance(step_frames, bool) or step_frames < 1:
        raise ValueError(f"step_frames must be an integer ≥ 1, got {step_frames!r}")


def _recognised(segments: Mapping[str, Any], n_frames: int) -> np.ndarray:
    """The primitive index each frame's segment is named, the humanoid's own by their wheeled
    equivalents (−1: a gap, or in no segment)."""
    named = np.full(n_frames, -1)
    for label, first, last in zip(segments["label"], segments["first_frame"], segments["last_frame"]):
        primitive = WHEELED_EQUIVALENT.get(label, label)
        if primitive in PRIMITIVES:
            named[int(first):int(last)] = PRIMITIVES.index(primitive)
    return named


def _nearest_named(named: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each step's name, a nameless step taking its nearest named step's (the earlier on a
    tie), and which steps were nameless."""
    gap = named == NO_NAME
    known = np.flatnonzero(~gap)
    if not len(known):
        raise ValueError("the recogniser names no step of this demonstration: every second is a gap")
    nearest = known[np.abs(known[None, :] - np.arange(len(named))[:, None]).argmin(axis=1)]
    return named[nearest], gap


def _majorities(named: np.ndarray, starts: np.ndarray, ends: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_majority` of every step ``[start, end)``: the primitives, and which were nameless."""
    chosen, gap = zip(*(_majority(named, a, b) for a, b in zip(starts, ends)))
    return np.array(chosen), np.array(gap)


def _majority(named: np.ndarray, start: int, end: int) -> tuple[int, bool]:
    """The primitive most frames of ``[start, end)`` are named (the first such on a tie), and
    whether none is: then the nearest named frame's, outward from the step."""
    window = named[start:end]
    known = window[window >= 0]
    if len(known):
        return int(np.bincount(known, minlength=len(PRIMITIVES)).argmax()), False
    labelled = np.flatnonzero(named >= 0)
    if not len(labelled):
        raise ValueError("the recogniser names no frame of this demonstration: it is all gaps")
    nearest = labelled[np.argmin(np.abs(labelled - start))]
    return int(named[nearest]), True


