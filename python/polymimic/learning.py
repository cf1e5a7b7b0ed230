"""Learning from many demonstrators: one trial of the thesis's two-phase training (§3.4).

Demonstrations are segmented by a trained :class:`~polymimic.PrimitiveRecognizer`, then every
demonstrator's forward model and the imitator's learn from them in Rust. Scoring the imitator
(:func:`evaluate`, :class:`Evaluation`) is :mod:`polymimic.evaluation`'s, re-exported here.

>>> import polymimic
>>> from polymimic import recognition
>>> recognizer = recognition.train_recognizer(polymimic.self_observation(60, seed=1), codebook_size=64)
>>> demos = [d for who in ("expert", "poor") for d in polymimic.record(who, configuration=1, n=3, seed=1)]
>>> result = run_trial(demos, recognizer=recognizer, ordering=["expert", "poor"], seed=0)
>>> sorted(result.models), result.imitator.lp
(['expert', 'poor'], 0.9)
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from typing import Any, Union

import numpy as np
import numpy.typing as npt

from polymimic import _native
from polymimic._atomic import atomic_write_text
from polymimic._native import ModelFileError, ModelResult, SegmentedDemonstrations, TrialResult
from polymimic._toml import dumps, loads
from polymimic.bodies import BodySpec, as_body
from polymimic.evaluation import Evaluation, Plays, attempts_as_demonstrations, evaluate, net_goals, spare_attempts
from polymimic.field import Demonstration, record
from polymimic.field_config import native_field_config
from polymimic.imitator_file import PolicyInputs, read_policy_file, write_policy_file
from polymimic.stepping import predict as predict_with

__all__ = ["Demonstrations", "Evaluation", "ImitatorPolicy", "LearningConfig", "ModelResult", "Plays",
           "SegmentedDemonstrations", "TrialResult", "as_segmented", "average_demonstrator", "evaluate",
           "net_goals", "run_trial", "segmented", "spare_attempts"]



class LearningConfig(_native.LearningConfig):
    """Every constant of learning (thesis Table 3.2, §3.3, §3.4); defaults are the thesis's.

    Keyword arguments set constants; the config is checked once, when made (a value out of
    range is a ``ValueError`` naming the constant, the value and what it may be; an unknown
    constant a ``TypeError`` listing them all). It is immutable: :meth:`replace` makes a changed
    copy, :meth:`to_dict` gives every constant, and it compares, hashes and pickles by value.

    Values the thesis leaves open are choices: ``permanency_step``, the ball-prediction
    thresholds (``ball_min_samples``, ``ball_max_angle_sd_deg``, ``ball_moved_mm``), the dead
    bands of the approach criteria (``ball_dead_band_mm``, ``robot_dead_band_mm``),
    ``prefer_sooner_goals`` (``False``; ``True`` makes the improved control rate, of two
    behaviours predicted to score, the one scoring in fewer primitives the better, instead of
    the one carrying the ball further: the robot then stops turning one way for a goal three
    pushes later and back for another), ``push_heading_tail`` (``0.1``: the improved control
    pushes from headings between the 10th and 90th percentiles of the demonstrators' pushing
    headings; a larger share, below 0.5, keeps it to headings nearer the line to the goal; at
    any share the window reaches at least max(10°, half the smaller of the imitator's mean left
    and right turns) either side of the median heading), and how the LP is shaped:

    - ``lp_bounds``: ``"soft"`` (a rise moves the LP by ``amount · 2(1 − LP)``, a fall by
      ``amount · 2 LP``: the thesis's step at the midpoint, none at a bound, so each
      demonstrator settles where its gains balance its losses) or ``"clamp"`` (the thesis's
      letter: add, then clamp to [0, 1], which drifts every model to a bound);
    - ``lp_scope``: ``"own_demonstrator"`` (goals, ball and robot criteria shape a model's LP
      only on its own demonstrator's demonstrations, since the LP rates that demonstrator) or
      ``"every"`` (also on the others' in phase 2);
    - ``lp_criteria``: ``"foremost"`` (the ball criterion when the ball's distance to the goal
      changed beyond its dead band, else the robot criterion: the thesis ranks them) or
      ``"both"`` (added);
    - ``lp_approach_weight``: ``"per_demonstration"`` (a span's approach criteria weigh by the
      share of its demonstration's segments it covers, so every demonstration weighs the same
      and a demonstrator that wanders for a minute is not judged by its wandering many times
      over its outcome) or ``"per_span"`` (a whole step each span, the thesis's letter);
    - ``lp_own_goal_weight``: ``3.0`` (an own goal lowers the LP by three times ``lp_goal``)
      or ``1.0``, the thesis's letter (an own goal mirrors a goal). Under soft bounds a
      demonstrator scoring g and conceding o times settles, by its outcomes alone, near
      ``g / (g + lp_own_goal_weight · o)``: at 1, one that concedes as often as it scores sits
      at 0.5 and the skill-blind rises (accurate ball predictions) lift it above
      ``initial_lp``; at 3 it ends near 0.3 (with the other steps), where the thesis's Poor
      hovered. It shapes the LP only: control already rates a predicted own goal worst.

    Two switches decide how much the LP shapes the imitator:

    - ``hold_lp``: ``False``, or ``True`` to hold every demonstrator's LP at ``initial_lp``
      throughout a trial (the uniform-LP ablation: nothing moves it);
    - ``imitator_weighting``: ``"even"`` (every demonstration counts the same for the imitator,
      the thesis) or ``"lp"``: a demonstration by member m counts with weight
      ``w_m = LP_m / max_k LP_k`` (the best member weighs 1; if every LP is 0 all weigh 1). In
      phase 2 of a trial the weights come from the demonstrator models' LPs at that moment and
      scale the imitator's gains from the demonstration (the frequency step of eq 3.11 and the
      permanency step; not the decay), so behaviours shown only by members of low LP gain
      little and decay away; :class:`ImitatorPolicy` with ``control="improved"`` weighs each
      demonstration's samples by the trial's final LP weight of its demonstrator in the parts
      of its world model ``world_weighting`` names (a state's value as a weighted mean, the push
      region as weighted percentiles; ``"every"`` weighs the ball's response too, ``"outcome"``
      no part); or ``"lp_gain"``: the same, each member weighed by how far its LP rose
      above ``initial_lp``, ``w_m = (LP_m − LP₀)⁺ / max_k (LP_k − LP₀)⁺`` (all 1 if none rose),
      so a member the LP likes no better than a stranger teaches nothing. With ``"even"``, or
      with ``hold_lp`` (all LPs equal), every weight is 1 and the results are exactly those of
      the thesis's scheme.
    - ``world_weighting``, improved control only: the parts of its world model those weights
      reach. ``"outcome"`` (the default): none, each sample counting by the outcome it led to
      alone (the push region keeps the pushes of scoring demonstrations, a state's value is its
      demonstration's outcome); ``"intent"``: where pushes begin and which states lead to
      goals, while what a primitive does to the ball (physics, the same whoever pushes) learns
      from every demonstration at full weight; ``"every"``: the ball's response too.

    ``save``/``load`` use TOML.

    Examples
    --------
    >>> config = LearningConfig(permanency_step=0.03)
    >>> config.permanency_step, config.lp_bounds, config.replace(ball_min_samples=8).ball_min_samples
    (0.03, 'soft', 8)
    >>> LearningConfig.from_toml(config.to_toml()) == config
    True
    >>> LearningConfig(lp_bounds="hard")
    Traceback (most recent call last):
    ...
    ValueError: lp_bounds must be "soft" or "clamp", got "hard"
    """

    __slots__ = ()

    def to_toml(self) -> str:
        """One ``name = value`` line per constant."""
        return dumps(self.to_dict())

    @classmethod
    def from_toml(cls, text: str) -> LearningConfig:
        """A config from TOML; missing keys take their defaults, unknown ones are refused."""
        values = loads(text)
        unknown = sorted(set(values) - set(_native.LearningConfig().to_dict()))
        if unknown:
            raise ValueError(f"unknown learning constants: {', '.join(unknown)}")
        return cls(**values)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Writes every constant to ``path`` as TOML (atomically); :meth:`load` reads it back."""
        atomic_write_text(path, self.to_toml())

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> LearningConfig:
        """Reads a config written by :meth:`save` (or any TOML of its keys).

        Raises
        ------
        ValueError
            For an unknown key or a value out of range (the message names it).
        """
        with open(path, encoding="utf-8") as file:
            return cls.from_toml(file.read())


def segmented(demonstrations: Sequence[Demonstration], recognizer: _native.PrimitiveRecognizer,
              **segmenter: Any) -> SegmentedDemonstrations:
    """The demonstrations as the learner takes them: segments, field size and outcome, checked
    once; ``segmenter`` passes the segmenter's settings (``min_frames``, ``gap_margin``, …).

    >>> import polymimic
    >>> from polymimic import recognition
    >>> recognizer = recognition.train_recognizer(polymimic.self_observation(30, seed=1), codebook_size=16)
    >>> batch = segmented(polymimic.record("tiny", configuration=1, n=2, seed=0), recognizer)
    >>> len(batch), batch.pitches
    (2, ['small', 'small'])
    """
    segments = recognizer.segment_many([d.frames for d in demonstrations], **segmenter)
    return SegmentedDemonstrations(
        [{"demonstrator": d.demonstrator, "outcome": d.outcome, "segments": s,
          "body": d.body}
         for d, s in zip(demonstrations, segments)],
        frame_counts=[len(d.frames) for d in demonstrations])


Demonstrations = Union[SegmentedDemonstrations, Sequence[Demonstration], Sequence[Mapping[str, Any]]]
"""What a trial or a policy learns from: a segmented batch (shared as it is), recordings
(segmented with the recogniser's default settings) or segmented dictionaries (checked)."""


def as_segmented(demonstrations: Demonstrations, recognizer: _native.PrimitiveRecognizer) -> SegmentedDemonstrations:
    """``demonstrations`` as one segmented batch: a batch as it is, recordings segmented,
    dictionaries (as :func:`segmented` once gave them) checked."""
    if isinstance(demonstrations, SegmentedDemonstrations):
        return demonstrations
    items: list[Any] = list(demonstrations)
    if items and isinstance(items[0], Demonstration):
        return segmented(items, recognizer)
    return SegmentedDemonstrations(items)


def run_trial(demonstrations: Demonstrations, *, recognizer: _native.PrimitiveRecognizer, ordering: Sequence[str],
              config: LearningConfig | None = None, phase_one: str = "by-model", seed: int = 0,
              body: BodySpec = "lego") -> TrialResult:
    """One learning trial: phase 1 (each demonstrator's model learns its own demonstrations;
    ``phase_one="interleaved"`` mixes them at random), phase 2 (every demonstration, in random
    order, to every demonstrator's model and then to the imitator's), and the final pruning.

    ``demonstrations`` may be already segmented (a :class:`SegmentedDemonstrations`, as
    :func:`segmented` returns), so that many trials share one segmentation. The trial learns on
    the field of ``body``, the imitator's (the Lego robot's by default): a demonstration played
    on another field is brought onto it first (:func:`polymimic.bodies.onto_field`). The thesis's
    two-phase training is its §3.4.

    Parameters
    ----------
    demonstrations : sequence of Demonstration, or SegmentedDemonstrations
        What the imitator watches, from any demonstrators; each is segmented by ``recognizer``
        unless already segmented.
    recognizer : PrimitiveRecognizer
        The imitator's recogniser of its own primitives (trained on ``body``'s self-observation).
    ordering : sequence of str
        The demonstrators whose forward models learn, in phase one's order; every
        demonstration's demonstrator must be named.
    config : LearningConfig, optional
        Every learning constant; the thesis's by default.
    phase_one : {"by-model", "interleaved"}
        Whether phase one shows each model its demonstrations in turn, or all of them mixed.
    seed : int
        The trial's seed, in ``[0, 2**64)``: the trial depends on it alone.
    body : polymimic.Body, str or polymimic.bodies.WheeledBody
        The imitator's body, whose setting the trial learns in.

    Returns
    -------
    TrialResult
        Every demonstrator's model (``models``) and the imitator's (``imitator``), with their
        LPs, match rates and behaviour counts.

    Raises
    ------
    ValueError
        For no demonstrations, a demonstrator missing from ``ordering``, or an argument out of
        range.
    """
    if len(demonstrations) == 0:
        raise ValueError("no demonstrations: a trial needs at least one")
    return _native.learning_trial(as_segmented(demonstrations, recognizer), list(ordering), recognizer,
                                  config=config, phase_one=phase_one, seed=seed, body=as_body(body))


class ImitatorPolicy(_native.ImitatorPolicy):
    """The imitator's final model driving ``body`` (by default the thesis's Lego robot; a
    :class:`polymimic.Body`, any built-in body's name or a :class:`polymimic.bodies.WheeledBody`)
    on that body's field; the policy's ``body`` is that :class:`polymimic.Body`.

    ``control="thesis"`` is the thesis's rule (§3.4): behaviours whose preconditions hold
    (else all) predict their outcome with their own ball statistics, and the best by the
    learning-preference criteria runs primitive by primitive, stopping before leaving the
    field. ``control="improved"`` goes where the thesis's future work points, learning from
    ``demonstrations`` (those the imitator watched; a segmented batch, recordings or segmented
    dictionaries): every behaviour predicts the ball with the response to each primitive
    learned from every segment of them (§5.4: far more samples); a predicted state is rated by
    a goal, then by whether the demonstrations passing near it ended, on balance, in own goals,
    then by how many millimetres the ball comes nearer the goal, then the robot nearer the
    ball; and only the first primitive runs before choosing again (§4.4.1). Behaviours push
    only from where the scoring demonstrations pushed the ball toward the goal (a region
    relative to the ball and the goal, learned from them) or when one predicts a goal; anywhere
    else the robot takes the shortest route there in its own primitives, round the ball rather
    than through it. With ``config.imitator_weighting == "lp"`` what the improved control learns
    from a demonstration weighs its demonstrator's final LP relative to the best in ``trial``
    (see :class:`LearningConfig`); a demonstration whose demonstrator has no model in ``trial``
    is a ``ValueError`` naming it. What the improved control learns, it learns on the imitator's
    own field: a demonstration played on another is brought onto it first
    (:func:`polymimic.bodies.onto_field`).
    The motion of each primitive is the recogniser's (learned from the imitator's own
    self-observation: give it the recogniser of the body it drives).

    The policy itself is the compiled one; this class segments recordings it is given, and
    keeps what the policy is made from so that :meth:`save` can write it to one file and
    :meth:`load` make it again, playing the same episodes bit for bit (the format:
    :mod:`polymimic.imitator_file`). A policy :meth:`for_trial` makes is the compiled one alone,
    sharing what this one learned, and has no file: to save one, make it with the constructor.

    >>> import pathlib, tempfile
    >>> import polymimic
    >>> from polymimic import recognition
    >>> recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)
    >>> demos = polymimic.record("expert", configuration=1, n=2, seed=0)
    >>> trial = run_trial(demos, recognizer=recognizer, ordering=["expert"])
    >>> policy = ImitatorPolicy(trial, recognizer=recognizer, control="improved", demonstrations=demos)
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "imitator.zip"
    >>> policy.save(path)
    >>> again = ImitatorPolicy.load(path)
    >>> again.control, again.body.name
    ('improved', 'lego')
    >>> played = [evaluate(p, attempts_per_configuration=1, seed=3).attempts for p in (policy, again)]
    >>> all(a.frames.tobytes() == b.frames.tobytes() for a, b in zip(*played))
    True
    """

    __slots__ = ("_made_from", "_players")
    _made_from: PolicyInputs
    _players: list[_native.ImitatorPlayer]

    def __new__(cls, trial: TrialResult, *, recognizer: _native.PrimitiveRecognizer,
                config: LearningConfig | None = None, control: str = "thesis",
                demonstrations: Demonstrations | None = None,
                body: BodySpec = "lego", practice: SegmentedDemonstrations | None = None,
                practice_weight: float = 1.0, refines: Sequence[str] | None = None) -> ImitatorPolicy:
        batch = None
        if demonstrations is not None and control == "improved":
            batch = as_segmented(demonstrations, recognizer)
        if practice is not None and control != "improved":
            raise ValueError(f"practice refines the improved control's world model; control={control!r} has none")
        driven = as_body(body)
        policy = super().__new__(cls, trial, recognizer=recognizer, config=config, control=control,
                                 demonstrations=batch, body=driven, practice=practice,
                                 practice_weight=practice_weight, refines=None if refines is None else list(refines))
        policy._made_from = PolicyInputs(trial=trial, recognizer=recognizer, config=config or LearningConfig(),
                                         control=control, body=driven, demonstrations=batch, practice=practice,
                                         practice_weight=float(practice_weight),
                                         practice_refines=None if refines is None else tuple(refines))
        policy._players = []
        return policy

    def predict(self, observation: npt.ArrayLike, state: Sequence[_native.ImitatorPlayer] | None = None,
                episode_start: npt.ArrayLike | None = None,
                deterministic: bool = True) -> tuple[np.ndarray, tuple[_native.ImitatorPlayer, ...]]:
        """stable-baselines3's ``predict`` on ``PenaltyKick-v0``'s observations, one ``(5,)`` or a
        batch ``(n, 5)``: the primitive (an index into the body's set, the env's action) the
        imitator runs next in each, and the players that decided (``state``: pass it back, or
        None to use the policy's own). ``episode_start`` marks the observations that begin an
        episode (each player then starts afresh from what it shows). The control is
        deterministic: ``deterministic`` is accepted and has no effect. See
        :mod:`polymimic.stepping`.

        >>> import gymnasium, polymimic
        >>> from polymimic import recognition
        >>> recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=32)
        >>> demos = polymimic.record("expert", configuration=1, n=2, seed=0)
        >>> policy = ImitatorPolicy(run_trial(demos, recognizer=recognizer, ordering=["expert"]),
        ...                         recognizer=recognizer, control="improved", demonstrations=demos)
        >>> env = gymnasium.make("PenaltyKick-v0")
        >>> observation, info = env.reset(seed=0, options={"configuration": 1})
        >>> state, done = None, False
        >>> while not done:
        ...     action, state = policy.predict(observation, state=state, episode_start=state is None)
        ...     observation, reward, terminated, truncated, info = env.step(action)
        ...     done = terminated or truncated
        >>> info["outcome"]
        'goal'
        """
        return predict_with(self, self._players, observation, state, episode_start)

    @property
    def made_from(self) -> PolicyInputs:
        """What the policy is made from: its constructor's arguments, demonstrations segmented."""
        return self._made_from

    def practised(self, attempts: SegmentedDemonstrations, *, weight: float = 1.0,
                  refines: Sequence[str] | None = None) -> ImitatorPolicy:
        """This policy, its world model learned again with ``attempts`` (its own, segmented by
        its own recogniser) beside the demonstrations: what :func:`polymimic.practice` makes
        after each round. ``weight`` is what every sample of its own attempts weighs;
        ``refines`` the parts they refine (``"ball_response"``, ``"state_value"``,
        ``"push_region"``; None: the first two; ``practice`` passes ``("ball_response",)`` by
        default)."""
        made = self._made_from
        return type(self)(made.trial, recognizer=made.recognizer, config=LearningConfig(**made.config.to_dict()),
                          control=made.control, demonstrations=made.demonstrations, body=made.body,
                          practice=attempts, practice_weight=weight, refines=refines)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write the policy to ``path``, atomically: one zip archive of its trial, recogniser,
        learning constants, body (one of your own) and, for the improved control, the segmented
        demonstrations it learns from (:mod:`polymimic.imitator_file`)."""
        write_policy_file(path, self._made_from)

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> ImitatorPolicy:
        """The policy :meth:`save` wrote to ``path``, made again from its parts.

        Raises
        ------
        polymimic.ModelFileError
            If ``path`` is not a policy file, is damaged or cut short, lacks a part, or was
            written in a later format version; the message names the file and the problem.
        """
        made_from = read_policy_file(path)
        try:
            return cls(made_from.trial, recognizer=made_from.recognizer,
                       config=LearningConfig(**made_from.config.to_dict()),
                       control=made_from.control, demonstrations=made_from.demonstrations, body=made_from.body,
                       practice=made_from.practice, practice_weight=made_from.practice_weight,
                       refines=made_from.practice_refines)
        except ValueError as error:
            raise ModelFileError(f"{os.fspath(path)}: its parts make no policy ({error})") from None


def average_demonstrator(recognizer: _native.PrimitiveRecognizer, *, n: int = 25, seed: int = 0,
                         max_trials: int = 10, config: LearningConfig | None = None,
                         recorded: Mapping[str, Sequence[Demonstration]] | None = None,
                         field_config: dict[str, Any] | str | None = None,
                         segmenter: dict[str, Any] | None = None,
                         body: BodySpec = "lego") -> tuple[list[Demonstration], TrialResult]:
    """The thesis's Average demonstrator (§4.4.2): an imitator trained in the heterogeneous
    experiment (Expert, Tiny, Humanoid; ordering RCB) and driven by the thesis's control rule.

    The imitators of trials with seeds ``seed`` … ``seed + max_trials - 1`` each attempt the kick
    from both configurations until ``n`` attempts per configuration held tracking throughout
    (as every demonstrator's recordings do; a few spare attempts stand in for lost ones). The
    Average is the imitator whose net goals (goals less own goals) over those attempts lie
    nearest the middle of the Poor's and the Expert's, strictly between them (the earliest on a
    tie). Net goals, not goals, because that is what put the thesis's own Average between its
    Poor and its Expert: it scored fewer goals than the Poor but far fewer own goals. Its
    attempts, renamed ``"average"``, are returned with the trial that made it. The choice is
    the one the Rust ``Laboratory`` makes, in the same compiled function. The imitators drive
    ``body`` (the Lego robot, the thesis's, by default) and learn on its field; the Average's
    attempts are that body's.

    ``recorded`` gives the Expert's, Tiny's, Humanoid's and Poor's demonstrations (``n`` per
    configuration each) when they exist already; otherwise they are recorded with ``seed`` on
    the field ``field_config`` describes, where the imitators are also evaluated. ``segmenter``
    passes the segmenter's settings.

    Raises
    ------
    polymimic.PolymimicError
        If no imitator of ``max_trials`` trials falls between the two.
    """
    if recorded is None:
        recorded = {who: [d for c in (1, 2) for d in record(who, configuration=c, n=n, seed=seed,
                                                             config=field_config)]
                    for who in ("expert", "tiny", "humanoid", "poor")}
    ordering = ["expert", "tiny", "humanoid"]
    batch = segmented([d for who in ordering for d in recorded[who]], recognizer, **(segmenter or {}))
    trial, raw = _native.average_demonstrator(
        batch, recognizer, ordering=ordering, poor_net_goals=net_goals(recorded["poor"]),
        expert_net_goals=net_goals(recorded["expert"]), per_configuration=n, first_seed=seed, max_trials=max_trials,
        config=config, field_config=native_field_config(field_config), body=as_body(body))
    return attempts_as_demonstrations(raw, "average", body=body), trial
