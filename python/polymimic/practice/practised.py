"""A practised imitator: the trained imitator as the guide for an episode's first decisions,
then the RL actor that practice trained (:mod:`polymimic.practice.teacher`).

It plays wherever an imitator plays: :meth:`PractisedPolicy.player` steps it one tracker
reading at a time (the demonstrator protocol, so :func:`polymimic.record` and the live loop
take it), :meth:`PractisedPolicy.predict` answers ``PenaltyKick-v0``'s observations as
stable-baselines3 does, :func:`polymimic.evaluate` scores it on the evaluation's attempts, and
:meth:`PractisedPolicy.save` and :meth:`PractisedPolicy.load` keep it in one file.
"""

from __future__ import annotations

import io
import json
import math
import os
import tempfile
import zipfile
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from polymimic import _native
from polymimic._atomic import atomic_path
from polymimic._native import ModelFileError
from polymimic.bodies import Body
from polymimic.field import PRIMITIVE_SETS, primitive_command
from polymimic.learning import ImitatorPolicy
from polymimic.practice.playing import play_episode
from polymimic.stepping import predict as predict_with

__all__ = ["PractisedPlayer", "PractisedPolicy"]

FORMAT = "polymimic-practised-policy"
VERSION = 1
_HALF_FRAME_S = 0.5 / 30
_SIDE_STEPS = {"sidestep_left": "Shuffle Left", "sidestep_right": "Shuffle Right"}


class PractisedPolicy:
    """The ``guide`` (a trained :class:`polymimic.ImitatorPolicy`) decides an episode's first
    ``handover`` decisions (one a second), then ``actor`` (a
    :class:`polymimic.baselines.ppo.PPOPolicy`, the practised RL policy reading only the
    tracker's view) decides the rest. ``handover=0`` is the actor alone."""

    def __init__(self, guide: ImitatorPolicy, actor: Any, *, handover: int, method: str = "jsrl",
                 steps: int = 0) -> None:
        if isinstance(handover, bool) or not isinstance(handover, (int, np.integer)) or handover < 0:
            raise ValueError(f"handover must be a whole number of decisions ≥ 0, got {handover!r}")
        self.guide, self.actor, self.handover = guide, actor, int(handover)
        self.method, self.steps = method, int(steps)
        self._players: list[PractisedPlayer] = []

    @property
    def body(self) -> Body:
        """The body it drives (the guide's)."""
        return self.guide.body

    @property
    def control(self) -> str:
        """``"practised (<method>)"``, as an imitator's ``control`` names its rule."""
        return f"practised ({self.method})"

    def player(self) -> PractisedPlayer:
        """A player of this policy, stepped one tracker reading at a time; ``reset`` it first."""
        return PractisedPlayer(self)

    def evaluate(self, attempts_per_configuration: int, *, seed: int = 0, field_config: str | None = None,
                 starts: Sequence[int | Mapping[str, Any]] | None = None) -> list[dict[str, Any]]:
        """Attempts as :meth:`polymimic.ImitatorPolicy.evaluate` plays them (the same starts,
        episode seeds and dicts), stepped by :meth:`player` in Python."""
        if starts is not None:
            raise ValueError("a practised policy plays the thesis's two configurations; starts= is for an imitator")
        driven = self.body
        out = []
        for configuration, episode_seed in _native.attempt_seeds(attempts_per_configuration, seed=seed):
            player = self.player()
            episode = play_episode(player, driven, configuration=configuration, seed=episode_seed,
                                   field_config=field_config)
            out.append({"frames": episode.frames, "outcome": episode.outcome, "configuration": configuration,
                        "seed": episode_seed, "behaviours": player.executed,
                        "start": {"configuration": configuration}})
        return out

    def predict(self, observation: npt.ArrayLike, state: Sequence[PractisedPlayer] | None = None,
                episode_start: npt.ArrayLike | None = None,
                deterministic: bool = True) -> tuple[np.ndarray, tuple[PractisedPlayer, ...]]:
        """stable-baselines3's ``predict`` on ``PenaltyKick-v0``'s observations, as
        :meth:`polymimic.ImitatorPolicy.predict` (:func:`polymimic.stepping.predict`)."""
        return predict_with(self, self._players, observation, state, episode_start)

    def save(self, path: str | os.PathLike[str]) -> None:
        """One zip file: the guide's policy file, the actor's network, and what joins them."""
        with tempfile.TemporaryDirectory() as scratch:
            guide_path = os.path.join(scratch, "guide.policy.zip")
            self.guide.save(guide_path)
            actor = io.BytesIO()
            self.actor.model.save(actor)
            about = {"format": FORMAT, "version": VERSION, "method": self.method, "handover": self.handover,
                     "steps": self.steps, "feature_set": self.actor.feature_set,
                     "frames_per_action": self.actor.frames_per_action}
            with atomic_path(path) as temporary, zipfile.ZipFile(temporary, "w", zipfile.ZIP_DEFLATED) as bundle:
                bundle.writestr("practised.json", json.dumps(about, indent=2))
                bundle.write(guide_path, "guide.policy.zip")
                bundle.writestr("actor.zip", actor.getvalue())

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> PractisedPolicy:
        """A policy :meth:`save` wrote; a ``ModelFileError`` naming the file for anything else."""
        from stable_baselines3 import PPO  # type: ignore[import-not-found, unused-ignore]

        from polymimic.baselines.ppo import PPOPolicy

        try:
            with zipfile.ZipFile(path) as bundle, tempfile.TemporaryDirectory() as scratch:
                about = json.loads(bundle.read("practised.json"))
                if about.get("format") != FORMAT or about.get("version") != VERSION:
                    raise ModelFileError(f"{os.fspath(path)}: not a practised policy of version {VERSION}")
                guide_path = os.path.join(scratch, "guide.policy.zip")
                with open(guide_path, "wb") as out:
                    out.write(bundle.read("guide.policy.zip"))
                guide = ImitatorPolicy.load(guide_path)
                model = PPO.load(io.BytesIO(bundle.read("actor.zip")), device="cpu")
        except (OSError, KeyError, ValueError, zipfile.BadZipFile) as error:
            raise ModelFileError(f"{os.fspath(path)}: not a practised policy ({error})") from None
        actor = PPOPolicy(model, feature_set=about["feature_set"], frames_per_action=about["frames_per_action"],
                          total_timesteps=about["steps"], method=about["method"], body=guide.body)
        return cls(guide, actor, handover=about["handover"], method=about["method"], steps=about["steps"])

    def __repr__(self) -> str:
        return f"PractisedPolicy(method={self.method!r}, body={self.body.name!r}, handover={self.handover})"


class PractisedPlayer:
    """A :class:`PractisedPolicy` stepped one tracker reading at a time, as
    :class:`polymimic.ImitatorPlayer` is: decisions on a one-second grid from the episode's first
    reading, the guide's for the first ``handover``, the actor's after. ``executed`` lists the
    command each decision sent."""

    def __init__(self, policy: PractisedPolicy) -> None:
        self._policy = policy
        self._guide = policy.guide.player()
        body = policy.body
        self._primitives = PRIMITIVE_SETS[body.primitive_set]
        self._commands = [primitive_command(p, body) for p in self._primitives[:5]]
        self._length_mm = body.field.length_mm
        self._reset_state()

    def _reset_state(self) -> None:
        self._decisions, self._origin_s, self._held = 0, math.nan, "stop"
        self._last: np.ndarray | None = None
        self.executed: list[str] = []

    def reset(self, episode: Mapping[str, Any] | None = None, *, start: int | Mapping[str, Any] | None = None,
              seed: int | None = None) -> None:
        """Start an episode, as :meth:`polymimic.ImitatorPlayer.reset`."""
        self._guide.reset(episode, start=start, seed=seed)
        self._reset_state()

    def act(self, reading: Sequence[float] | _native.Reading) -> str:
        """The command to send after ``reading`` until the next (see
        :meth:`polymimic.ImitatorPlayer.act`)."""
        values: tuple[float, ...]
        if isinstance(reading, _native.Reading):
            values = (reading.t_s, reading.robot_x_mm, reading.robot_y_mm, reading.robot_theta_rad,
                      reading.ball_x_mm, reading.ball_y_mm)
        else:
            values = tuple(float(v) for v in reading)
        t_s = values[0]
        if math.isnan(self._origin_s):
            self._origin_s = t_s
        due_s = self._origin_s + self._decisions - _HALF_FRAME_S
        if self._decisions and t_s < due_s:
            if self._decisions <= self._policy.handover:
                self._guide.act(values)  # the guide keeps its own clock and holds its command
            return self._held
        self._decisions = max(self._decisions, int((t_s - self._origin_s + _HALF_FRAME_S) // 1.0)) + 1
        if self._decisions <= self._policy.handover:
            self._held = self._guide.act(values)
            self.executed.append(self._held)
            return self._held
        index = self.decide(*values[1:], count=False)
        self._held = self._command(index, values)
        self.executed[-1] = self._held
        return self._held

    def decide(self, robot_x_mm: float, robot_y_mm: float, robot_theta_rad: float, ball_x_mm: float,
               ball_y_mm: float, *, count: bool = True) -> int:
        """One decision now (an index into the body's primitive set), as
        :meth:`polymimic.ImitatorPlayer.decide`."""
        if count:
            self._decisions += 1
            if self._decisions <= self._policy.handover:
                index = self._guide.decide(robot_x_mm, robot_y_mm, robot_theta_rad, ball_x_mm, ball_y_mm)
                self.executed.append(self._primitives[index])
                return index
        from polymimic.baselines.evaluation import ball_as_read  # the actor's own reading of a lost ball

        ball = ball_as_read((ball_x_mm, ball_y_mm), self._last, robot_x_mm=robot_x_mm,
                            field_length_mm=self._length_mm)
        seen = np.array([robot_x_mm, robot_y_mm, robot_theta_rad, *ball])
        self._last = seen
        index = int(self._policy.actor.predict(seen[None, :])[0])
        self.executed.append(self._primitives[index])
        return index

    def _command(self, index: int, values: Sequence[float]) -> str:
        if index < len(self._commands):
            return self._commands[index]
        # The humanoid's own: its side-steps, and its kick with the foot on the ball's side.
        if self._primitives[index] != "kick":
            return _SIDE_STEPS[self._primitives[index]]
        _, x, y, theta, bx, by = values
        if not (math.isfinite(bx) and math.isfinite(by)):
            return "Kick Right"
        left_of_robot = -math.sin(theta) * (bx - x) + math.cos(theta) * (by - y) > 0.0
        return "Kick Left" if left_of_robot else "Kick Right"

    @property
    def episode(self) -> dict[str, Any]:
        """The episode's start and seed, as :attr:`polymimic.ImitatorPlayer.episode`."""
        return self._guide.episode
