"""Type stubs of the compiled core (kept honest by ``mypy.stubtest polymimic._native``)."""

import os
from collections.abc import Iterable, Iterator, Mapping, Sequence
from typing import Any, Literal, Protocol, Self, final

import numpy as np
import numpy.typing as npt
from typing_extensions import disjoint_base

from polymimic.bodies import Field, WheeledBody

__version__: str

class PolymimicError(Exception):
    """Base class of every polymimic error."""
class NotFittedError(PolymimicError):
    """A model was used before it was fitted or given parameters."""
class ImpossibleSequenceError(PolymimicError):
    """A sequence has probability zero under the model."""
class ModelFileError(PolymimicError):
    """A saved file is corrupt, of another kind, or of an unsupported version."""
class FieldRunError(PolymimicError):
    """A simulation could not run: a finished episode stepped, a command the body cannot execute, too
    many lost recordings.
    """
class PolicyError(PolymimicError):
    """A Python demonstrator failed: it raised (its exception is the cause), answered with something
    that is not a command of its body, or did not answer in time.
    """

FRAME_COLUMNS: list[str]

_Symbols = npt.ArrayLike
_Path = str | os.PathLike[str]

class _NativeBody(Protocol):
    def _native_body(self) -> tuple[str, str]: ...

_Body = str | _NativeBody | "Body"

@final
class Body:
    """A body: one of the built-in ones by name (``"lego"``, ``"tiny"``, ``"humanoid"``), or a
    :class:`polymimic.bodies.WheeledBody` of your own (a wheeled body equal to the Lego or the tiny robot
    is that body, bit for bit). Everything that asks which body also learns from it which field
    it plays on, which primitives it has and how far it reaches for the ball.

    >>> lego = Body("lego")
    >>> lego.kind, lego.field.length_mm, lego.reach_mm, Body("tiny").primitive_set
    ('lego', 1020.0, 120.0, 'wheeled')
    >>> Body("robot")
    Traceback (most recent call last):
    ...
    ValueError: unknown body "robot": the built-in bodies are lego, tiny, humanoid; describe a body
    of your own with polymimic.bodies.WheeledBody(name, length_mm=…, width_mm=…, wheel_base_mm=…,
    top_wheel_speed_mm_s=…) (or a [bodies.robot] table) and make it a polymimic.Body
    """
    def __new__(cls, body: str | _NativeBody | Body) -> Self: ...
    @classmethod
    def from_table(cls, name: str, table: Mapping[str, Any], *, where: str = "") -> Self:
        """A body from its TOML table (``[bodies.<name>]``; see
        :meth:`polymimic.bodies.WheeledBody.from_table`), a ``ValueError`` naming ``where`` and the key
        for anything unknown or out of range.

        >>> Body.from_table("cart", {"length_mm": 90, "width_mm": 80, "wheel_base_mm": 70,
        ...                          "top_wheel_speed_mm_s": 60}).field.length_mm
        1020.0
        """
    @property
    def name(self) -> str:
        """The body's name: a built-in body's, or the one its description gives."""
    @property
    def kind(self) -> Literal["lego", "tiny", "humanoid", "wheeled"]:
        """What kind of body: ``"lego"``, ``"tiny"``, ``"humanoid"`` (the built-in ones) or
        ``"wheeled"`` (a two-wheeled robot of your own).
        """
    @property
    def primitive_set(self) -> Literal["wheeled", "humanoid"]:
        """Which primitive set it moves with: ``"wheeled"`` (forward, backward, left, right, stop) or
        ``"humanoid"`` (those, its side-steps and its kick).
        """
    @property
    def primitives(self) -> list[str]:
        """Its own primitives' names, in the set's order."""
    @property
    def field(self) -> Field:
        """The field it plays on, as a :class:`polymimic.bodies.Field`."""
    @property
    def reach_mm(self) -> float:
        """How far from its centre it moves the ball as a demonstrator, mm: the ball's radius beyond
        a wheeled body's front (half its length), or beyond the humanoid's kicking foot at full
        reach. The learner's correspondence between bodies keeps a touch a touch.
        """
    @property
    def imitating_reach_mm(self) -> float:
        """How far from its centre it moves the ball as an imitator, mm: the ball's radius beyond its
        front (the humanoid walks into the ball, even over its own set with a kick).
        """
    @property
    def description(self) -> WheeledBody | None:
        """The :class:`polymimic.bodies.WheeledBody` describing it: a body of your own's, the Lego's and the
        tiny robot's constants (:data:`polymimic.bodies.THESIS_BODIES`); ``None`` for the humanoid.
        """
    def __eq__(self, other: object, /) -> bool: ...
    def __hash__(self) -> int: ...

@final
class DiscreteHMM:
    """A discrete hidden Markov model trained by scaled Baum-Welch over many sequences at once.

    The thesis's recogniser holds one per moving primitive (thesis §3.1.3–3.1.4): a left-right
    model whose states each link to themselves and the next `links` states (thesis Fig. 3.10), or
    an ergodic one. Training starts from the temporal split of every sequence into `n_states`
    pieces (thesis Fig. 3.11) or from parameters you give (`from_params`, `fit(init="given")`).

    Parameters
    ----------
    n_states : int
        Hidden states, at least 1.
    n_symbols : int
        Size of the symbol alphabet: every sequence holds integers in `0..n_symbols`.
    topology : {"left-right", "ergodic"}
        Which transitions may be non-zero.
    links : int
        For a left-right model, how many states ahead each state may move (2: itself, the next
        and the one after). Ignored for an ergodic model.
    max_iter : int
        Most Baum-Welch re-estimations per `fit`.
    tol : float
        A fit stops when the log-likelihood gains less than this; `-inf` runs exactly `max_iter`.
    emission_floor : float
        Every emission probability is floored here (and rows renormalised), so an unseen symbol
        does not make a sequence impossible.
    seed : int
        Seeds the random transitions a fit starts from and `sample`'s default stream.

    Attributes
    ----------
    startprob_ : ndarray of shape (n_states,)
        Initial state probabilities (after `fit` or `from_params`).
    transmat_ : ndarray of shape (n_states, n_states)
        Transition probabilities; row i is P(next state | state i).
    emissionprob_ : ndarray of shape (n_states, n_symbols)
        Emission probabilities; row i is P(symbol | state i).
    history_ : ndarray of shape (n_iterations,)
        The training data's log-likelihood before each re-estimation of the last fit.
    converged_ : bool
        Whether the last fit stopped because the gain fell below `tol`.

    Raises
    ------
    ValueError
        For a parameter out of range (the message names it).

    Examples
    --------
    >>> import numpy as np, polymimic
    >>> model = polymimic.DiscreteHMM(2, 3, seed=1).fit([np.array([0, 0, 1, 2, 2]), np.array([0, 1, 2])])
    >>> model.transmat_.shape, model.emissionprob_.shape
    ((2, 2), (2, 3))
    """
    def __new__(
        cls,
        n_states: int,
        n_symbols: int,
        *,
        topology: Literal["left-right", "ergodic"] = "left-right",
        links: int = 2,
        max_iter: int = 100,
        tol: float = 1e-4,
        emission_floor: float = 1e-8,
        seed: int = 0,
    ) -> DiscreteHMM: ...
    @classmethod
    def from_params(
        cls,
        startprob: npt.ArrayLike,
        transmat: npt.ArrayLike,
        emissionprob: npt.ArrayLike,
        *,
        topology: Literal["left-right", "ergodic"] | None = None,
        links: int | None = None,
        max_iter: int = 100,
        tol: float = 1e-4,
        emission_floor: float = 1e-8,
        seed: int = 0,
    ) -> DiscreteHMM:
        """A model with the probabilities you give, ready to score, decode, sample or train further.

        Parameters
        ----------
        startprob : array_like of shape (n_states,)
        transmat : array_like of shape (n_states, n_states)
        emissionprob : array_like of shape (n_states, n_symbols)
            Probabilities; each (row) must sum to 1.
        topology : {"left-right", "ergodic"}, optional
            Without it (and without `links`), the topology `transmat` implies: left-right with as many
            links as its longest forward jump where it starts in state 0 and never moves back, ergodic
            otherwise. Giving `links` alone names a left-right model.
        links, max_iter, tol, emission_floor, seed
            As for the constructor.

        Raises
        ------
        ValueError
            If the shapes disagree, a probability is negative or a row does not sum to 1.
        """
    def fit(self, sequences: Iterable[_Symbols], *, init: Literal["segments", "given"] = "segments") -> DiscreteHMM:
        """Trains the model by scaled Baum-Welch on many sequences of any lengths; returns the model.

        Parameters
        ----------
        sequences : iterable of array_like of int
            One-dimensional sequences of symbols in `0..n_symbols`.
        init : {"segments", "given"}
            `"segments"` starts from the temporal split of every sequence into `n_states` pieces
            (state i counts the symbols of piece i, floored at `emission_floor`) and random
            transitions that respect the topology; `"given"` starts from the model's current
            probabilities (those of `from_params`, or of an earlier fit).

        Returns
        -------
        DiscreteHMM
            The model itself, fitted (`startprob_`, `transmat_`, `emissionprob_`, `history_`,
            `converged_`).

        Raises
        ------
        ValueError
            If a sequence is empty or holds a symbol outside `0..n_symbols` (the message names the
            sequence and position); the model is left as it was.
        NotFittedError
            For `init="given"` on a model that has no probabilities yet.
        """
    def score(self, sequence: _Symbols) -> float:
        """log P(sequence | model)."""
    def score_samples(
        self, sequences: Iterable[_Symbols], *, impossible: Literal["raise", "-inf"] = "raise"
    ) -> npt.NDArray[np.float64]:
        """log P(sequence | model) of each sequence. `impossible="raise"` raises on a sequence of
        probability zero; `impossible="-inf"` scores it -inf.
        """
    def decode(self, sequence: _Symbols) -> tuple[npt.NDArray[np.int64], float]:
        """The Viterbi state path (int64 array) and its log-probability."""
    def predict_proba(self, sequence: _Symbols) -> npt.NDArray[np.float64]:
        """The posterior of every state at every step, γ_t(i) = P(q_t = i | O): a `(T, n_states)`
        array whose rows sum to 1 (hmmlearn's `predict_proba`).
        """
    @classmethod
    def from_hmmlearn(cls, model: Any, *, seed: int | None = None) -> DiscreteHMM:
        """A model from a fitted `hmmlearn.hmm.CategoricalHMM`: its probabilities exactly, its
        `n_iter` and `tol`, and the topology its `startprob_` and `transmat_` imply (see
        `from_params`). The seed is `seed`, else the model's `random_state`: an integer as it is,
        0 for None, and for a `RandomState` (what fitting leaves there) or a `Generator` the
        first draw of a copy of it, so the same state gives the same seed and the model's own
        state is left as it was.
        """
    def to_hmmlearn(self) -> Any:
        """The model as a `hmmlearn.hmm.CategoricalHMM` (scaling implementation), ready to score,
        decode or train further: the same probabilities, `n_iter`, `tol` and `random_state`,
        with `init_params=""` so that fitting starts from them.
        """
    def sample(self, n: int, length: int, *, seed: int = 0) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]:
        """`n` sequences of `length` symbols and their hidden states, as two `(n, length)` arrays."""
    @property
    def startprob_(self) -> npt.NDArray[np.float64]:
        """Initial state probabilities, shape `(n_states,)`.

        Raises `NotFittedError` before the model has probabilities.
        """
    @property
    def transmat_(self) -> npt.NDArray[np.float64]:
        """Transition probabilities, shape `(n_states, n_states)`; row i is P(next state | state i).

        Raises `NotFittedError` before the model has probabilities.
        """
    @property
    def emissionprob_(self) -> npt.NDArray[np.float64]:
        """Emission probabilities, shape `(n_states, n_symbols)`; row i is P(symbol | state i).

        Raises `NotFittedError` before the model has probabilities.
        """
    @property
    def history_(self) -> npt.NDArray[np.float64]:
        """Log-likelihood of the training data before each re-estimation of the last fit."""
    @property
    def converged_(self) -> bool:
        """Whether the last fit stopped because the log-likelihood gain fell below `tol` (False
        before any fit, and for a fit that ran out of `max_iter`).
        """
    @property
    def n_states(self) -> int:
        """Number of hidden states."""
    @property
    def n_symbols(self) -> int:
        """Size of the symbol alphabet: symbols are `0..n_symbols`."""
    @property
    def topology(self) -> str:
        """`"left-right"` or `"ergodic"`."""
    @property
    def links(self) -> int | None:
        """How many states ahead a left-right model's states may move; None for an ergodic model."""
    @property
    def max_iter(self) -> int:
        """Most Baum-Welch re-estimations per fit."""
    @property
    def tol(self) -> float:
        """The log-likelihood gain below which a fit stops (`-inf`: run `max_iter`)."""
    @property
    def emission_floor(self) -> float:
        """The floor of every emission probability."""
    @property
    def seed(self) -> int:
        """The seed of the random start and of `sample`'s default stream."""
    def save(self, path: _Path) -> None:
        """Writes the model to `path` (JSON, versioned)."""
    @classmethod
    def load(cls, path: _Path) -> DiscreteHMM:
        """Reads a model written by `save`."""
    @staticmethod
    def _from_json(text: str) -> DiscreteHMM: ...
    def __reduce__(self) -> tuple[Any, tuple[str]]: ...

@final
class Codebook:
    """A vector-quantisation codebook: codewords and nearest-codeword encoding.

    The recogniser quantises each representation of the tracker's frames with one (thesis
    §3.1.3). `Codebook.fit` grows it by LBG: from the points' mean, every codeword splits in two and
    k-means (Lloyd) refines them, until there are `size`; `encode` finds each point's nearest
    codeword with a k-d tree.

    Parameters
    ----------
    centroids : array_like of shape (k, d)
        The codewords, for a codebook you already have (`fit` grows one from points).

    Attributes
    ----------
    centroids : ndarray of shape (k, d)
        The codewords.
    distortion_ : float
        Mean squared distance of the training points to their nearest codewords at the end of the
        last `fit` or `refine`.
    n_iter_ : int
        Lloyd iterations of the last `fit` (over every size) or `refine`.

    Examples
    --------
    >>> import numpy as np, polymimic
    >>> points = np.random.default_rng(0).normal(size=(1000, 3))
    >>> codebook = polymimic.Codebook.fit(points, size=8, seed=0)
    >>> codebook.centroids.shape, codebook.encode(points[:4]).shape
    ((8, 3), (4,))
    """
    def __new__(cls, centroids: npt.ArrayLike) -> Codebook: ...
    @classmethod
    def fit(
        cls,
        points: npt.ArrayLike,
        *,
        size: int = 512,
        tol: float = 1e-4,
        max_iter: int = 100,
        seed: int = 0,
        split_epsilon: float = 1e-3,
    ) -> Codebook:
        """Grows a codebook of `size` codewords on `(n, d)` points by LBG.

        Parameters
        ----------
        points : array_like of shape (n, d)
            The training points (finite).
        size : int
            Codewords to grow, at least 1 (the thesis's 512 by default).
        tol : float
            Each Lloyd refinement stops when the distortion falls by less than this share.
        max_iter : int
            Most Lloyd iterations per refinement.
        seed : int
            Seeds the perturbation that splits codewords.
        split_epsilon : float
            How far apart, relative to the data's scale, a split puts the two new codewords.

        Returns
        -------
        Codebook

        Raises
        ------
        ValueError
            For points that are not a finite 2-D array, or a parameter out of range.
        """
    def refine(self, points: npt.ArrayLike, *, tol: float = 0.0, max_iter: int = 300) -> Codebook:
        """Lloyd iterations from these codewords on `points`; returns a new codebook."""
    def encode(self, points: npt.ArrayLike) -> npt.NDArray[np.int64]:
        """The index of the nearest codeword of every point (int64 array)."""
    def distortion(self, points: npt.ArrayLike) -> float:
        """Mean squared distance of `points` to their nearest codewords."""
    @property
    def centroids(self) -> npt.NDArray[np.float64]:
        """The `(k, d)` codewords."""
    @property
    def size(self) -> int:
        """Number of codewords, k."""
    @property
    def dim(self) -> int:
        """Dimension of every codeword, d."""
    @property
    def distortion_(self) -> float:
        """Distortion on the training points at the end of the last fit or refine."""
    @property
    def n_iter_(self) -> int:
        """Lloyd iterations of the last fit (over every size) or refine."""
    def __len__(self) -> int: ...
    def save(self, path: _Path) -> None:
        """Writes the codebook to `path` (JSON, versioned)."""
    @classmethod
    def load(cls, path: _Path) -> Codebook:
        """Reads a codebook written by `save`."""
    @staticmethod
    def _from_json(text: str) -> Codebook: ...
    def __reduce__(self) -> tuple[Any, tuple[str]]: ...

_Primitive = Literal["forward", "backward", "left", "right", "stop"]

@final
class PrimitiveRecognizer:
    """Recognises the imitator's primitives in tracker frames and segments demonstrations.

    One codebook per representation and one HMM per moving primitive of the imitator's set, each
    reading one-second sequences of frames through its own representation (thesis §3.1); a
    sequence that barely moves is `stop`. `segment` cuts a demonstration into segments it names
    (thesis §3.2.2). Train one with `PrimitiveRecognizer.train`, or with
    `polymimic.recognition.train_recognizer` from self-observation sequences.

    Examples
    --------
    >>> import polymimic
    >>> from polymimic import recognition
    >>> recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=16)
    >>> recognizer.moving
    ['forward', 'backward', 'left', 'right']
    >>> frames = polymimic.record("expert", configuration=1, n=1, seed=0)[0].frames
    >>> sorted(recognizer.segment(frames))
    ['end', 'first_frame', 'label', 'last_frame', 'scores', 'start']
    """
    @classmethod
    def train(
        cls,
        sequences: Iterable[npt.ArrayLike],
        labels: list[str],
        *,
        n_states: int = 1,
        codebook_size: int = 512,
        links: int = 2,
        max_iter: int = 100,
        tol: float = 1e-4,
        representation: Literal["thesis", "egocentric"] = "thesis",
        emissions: Literal["discrete", "gaussian"] = "discrete",
        emission_floor: float = 1e-8,
        min_variance: float = 0.01,
        seed: int = 0,
        primitives: Literal["wheeled", "humanoid"] = "wheeled",
    ) -> PrimitiveRecognizer:
        """Trains the codebooks and an HMM per moving primitive of `primitives` (`"wheeled"`, the
        four, or `"humanoid"`, the humanoid's seven) on self-observation sequences.
        """
    def log_likelihoods(self, frames: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """log-likelihoods of its moving primitives (`moving`: forward, backward, left and right,
        then the humanoid's) for one sequence of frames.
        """
    def log_likelihoods_many(self, sequences: Iterable[npt.ArrayLike]) -> npt.NDArray[np.float64]:
        """`(k, m)` log-likelihoods of many sequences under its `m` moving primitives, in parallel."""
    def classify(self, frames: npt.ArrayLike) -> str:
        """The moving primitive whose HMM scores the frames highest."""
    def segment(
        self,
        frames: npt.ArrayLike,
        *,
        min_frames: int = 10,
        stop_distance_mm: float = 1.0,
        stop_rotation_deg: float = 20.0,
        limit_sds: float = 2.0,
        gap_margin: float = 2.0,
    ) -> dict[str, Any]:
        """Segments a demonstration; returns columns: `label` (list of str), `first_frame`,
        `last_frame` (int arrays), `start` and `end` (`(k, 5)` frames) and `scores` (`(k, m)`, a
        column per moving primitive).
        Settings, keyword-only: `min_frames=10`, `stop_distance_mm=1.0`, `stop_rotation_deg=20.0`,
        `limit_sds=2.0`, `gap_margin=2.0`.
        """
    def segment_many(
        self,
        demonstrations: Iterable[npt.ArrayLike],
        *,
        min_frames: int = 10,
        stop_distance_mm: float = 1.0,
        stop_rotation_deg: float = 20.0,
        limit_sds: float = 2.0,
        gap_margin: float = 2.0,
    ) -> list[dict[str, Any]]:
        """`segment` for many demonstrations, in parallel, with the same settings; one dictionary
        of columns each.
        """
    def motion_stats(self) -> dict[str, dict[str, float]]:
        """Table 3.1 of the training set: per primitive, distance and rotation mean and sd."""
    def hmm(self, primitive: str) -> DiscreteHMM:
        """The HMM of a moving primitive."""
    def codebook(self, primitive: str) -> Codebook:
        """The codebook a primitive's HMM reads through."""
    @property
    def representations(self) -> dict[str, str]:
        """The representation each primitive's HMM reads (`positional`, `rotational`, `egocentric`)."""
    @property
    def emissions(self) -> str:
        """`"discrete"` (codebook symbols) or `"gaussian"` (continuous points)."""
    @property
    def n_states(self) -> int:
        """States of each primitive's HMM."""
    @property
    def codebook_size(self) -> int:
        """Codewords of each representation's codebook (the HMMs' alphabet size)."""
    @property
    def primitive_set(self) -> str:
        """The set of primitives it recognises: `"wheeled"` or `"humanoid"`."""
    @property
    def moving(self) -> list[str]:
        """Its moving primitives, in the order of its scores' columns."""
    def save(self, path: _Path) -> None:
        """Writes the recogniser to `path` (JSON, versioned)."""
    @classmethod
    def load(cls, path: _Path) -> PrimitiveRecognizer:
        """Reads a recogniser written by `save`."""
    @staticmethod
    def _from_json(text: str) -> PrimitiveRecognizer: ...
    def __reduce__(self) -> tuple[Any, tuple[str]]: ...

def record_demonstrations(
    demonstrator: str,
    *,
    configuration: int,
    n: int,
    seed: int = 0,
    lapse: float = 0.0,
    config: str | None = None,
    body: _Body | None = None,
) -> list[dict[str, Any]]: ...
def thesis_wheeled_bodies() -> list[tuple[str, str]]: ...
def record_self_observation(
    n_per_primitive: int,
    *,
    seed: int = 0,
    config: str | None = None,
    body: _Body | None = None,
    primitives: Literal["wheeled", "own"] = "wheeled",
) -> tuple[list[npt.NDArray[np.float64]], list[str]]: ...
def record_python_policy(
    act: Any,
    reset: Any,
    *,
    name: str,
    body: _Body,
    configuration: int,
    n: int,
    seed: int = 0,
    decision_hz: float = 30.0,
    timeout_s: float | None = None,
    config: str | None = None,
) -> list[dict[str, Any]]: ...
def record_builtin_at_rate(
    demonstrator: str, *, configuration: int, n: int, seed: int = 0, decision_hz: float = 30.0
) -> list[int]: ...

@final
class Reading:
    """The tracker's latest reading, as a Python policy gets it."""
    t_s: float
    frame: int
    robot_x_mm: float
    robot_y_mm: float
    robot_theta_rad: float
    ball_x_mm: float
    ball_y_mm: float
    field_length_mm: float
    field_width_mm: float
    goal_mouth_mm: float
    @property
    def ball_seen(self) -> bool:
        """Whether the robot sees the ball."""

def commands() -> list[dict[str, Any]]: ...
def primitive_command(primitive: str, body: _Body) -> str: ...
def thesis_table_3_1() -> dict[str, dict[str, float]]: ...
def default_field_config() -> str: ...
def check_field_config(config: str) -> str: ...

@final
class EpisodeBatch:
    def __new__(
        cls, n: int, *, frames_per_action: int = 30, config: str | None = None, body: _Body = "lego"
    ) -> EpisodeBatch: ...
    @property
    def body(self) -> Body:
        """The body every slot drives, a :class:`polymimic.Body`."""
    def __len__(self) -> int: ...
    def reset(
        self, index: int, *, configuration: int | None = None, seed: int, start: int | Mapping[str, Any] | None = None
    ) -> None:
        """Starts slot `index` afresh from `configuration` (1 or 2), or from a chosen `start`
        (``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``), with episode `seed`.
        """
    def step(
        self, actions: list[int]
    ) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.float64], npt.NDArray[np.int8], npt.NDArray[np.bool_]]:
        """Holds `actions[i]` (an index into the body's primitive set: 0 forward … 4 stop, and on
        the humanoid 5 side-step left, 6 side-step right, 7 kick) in slot `i`, every slot at once with the GIL
        released; a slot whose action is −1 is left as it is. Returns what every slot shows then.
        """
    def status(
        self,
    ) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.float64], npt.NDArray[np.int8], npt.NDArray[np.bool_]]:
        """What every slot shows now (a slot never started shows NaN and outcome −1)."""

@final
class Episode:
    """An episode on the field, stepped one tracker frame at a time by a policy.

    The simulated field (rapier2d) with a body, the ball and the overhead tracker at 30 frames a
    second, from field configuration 1 or 2 (thesis Fig. 4.4). `run` plays a list of commands,
    `step` one at a time; `frames` holds every tracker frame so far as a `(k, 7)` array (time,
    robot x, y, θ, ball x, y, command), millimetres, radians and seconds.
    """
    def __new__(
        cls,
        body: _Body = "lego",
        *,
        configuration: int | None = 1,
        seed: int = 0,
        config: str | None = None,
        start: int | Mapping[str, Any] | None = None,
    ) -> Episode: ...
    def command_for(self, primitive: str) -> str:
        """The command that runs `primitive` (a name of the body's primitive set) on this body now:
        on the humanoid a kick is the foot on the side of the ball it sees.
        """
    def step(self, command: str | int) -> tuple[npt.NDArray[np.float64], str | None]:
        """Sends one command for one tracker frame; returns the frame recorded and the outcome
        (None while the episode goes on). `command` is a primitive name, a command name or id.
        """
    def run(self, commands: list[str | int]) -> tuple[npt.NDArray[np.float64], str | None]:
        """Sends a whole list of commands (one per frame) in Rust with the GIL released, stopping
        early if the episode ends; returns the frames recorded and the outcome.
        """
    def place_robot(self, x_mm: float, y_mm: float, theta_rad: float) -> None:
        """Puts the robot at a pose (the experimenter's hand)."""
    @property
    def frames(self) -> npt.NDArray[np.float64]:
        """Every frame so far, `(k, 7)`."""
    def observation(self) -> dict[str, Any]:
        """What the robot's controller sees now: time, robot pose, ball (None if not seen), and
        the field: its (length, width), goal mouth and ball, mm.
        """
    @property
    def outcome(self) -> str | None:
        """How the episode ended (`"goal"`, `"own_goal"`, `"ball_out"`, `"robot_out"` or
        `"time_up"`), or None while it runs.
        """
    @property
    def finished(self) -> bool:
        """Whether the episode has ended (`outcome` then says how)."""
    @property
    def valid(self) -> bool:
        """False once tracking was lost."""

_Outcome = Literal["goal", "own_goal", "ball_out", "robot_out", "time_up"]

@disjoint_base
class LearningConfig:
    """Every constant of learning (thesis Table 3.2, §3.3, §3.4); defaults are the thesis's.

    Keyword arguments set constants (an unknown one is a ``TypeError`` listing them all); the
    whole config is checked once, here, and a value out of range is a ``ValueError`` naming the
    constant, the value and what it may be. Instances are immutable: ``replace`` makes a
    changed copy. They compare, hash and pickle by value.

    ``hold_lp=True`` holds every demonstrator's LP at ``initial_lp`` throughout a trial (the
    uniform-LP ablation). ``imitator_weighting`` is ``"even"`` (every demonstration counts the
    same for the imitator, the thesis) or ``"lp"``: a demonstration by member m counts with
    weight ``LP_m / max_k LP_k`` (all 1 if every LP is 0), scaling the imitator's frequency
    and permanency gains from it in phase 2 (the LPs of that moment; decay is not scaled) and
    its samples in the improved control's world model (the final LPs); or ``"lp_gain"``: the
    same, each member weighed by how far its LP rose above ``initial_lp``,
    ``(LP_m − LP₀)⁺ / max_k (LP_k − LP₀)⁺`` (all 1 if none rose). ``world_weighting`` names
    the parts of the improved control's world model those weights reach: ``"outcome"`` (the
    default) none, each sample counting by the outcome it led to alone; ``"intent"`` the push
    region and the states' values, while the ball's response (physics, the same whoever
    pushes) learns from every demonstration at full weight; ``"every"`` all three.

    Examples
    --------
    >>> config = LearningConfig(permanency_step=0.03)
    >>> config.permanency_step, config.lp_bounds
    (0.03, 'soft')
    >>> config.replace(lp_bounds="clamp") == LearningConfig(permanency_step=0.03, lp_bounds="clamp")
    True
    >>> LearningConfig(initial_lp=1.5)
    Traceback (most recent call last):
    ...
    ValueError: config: initial_lp = 1.5 must be in [0, 1]
    """
    def __new__(
        cls,
        *,
        creation_threshold: float = 0.3,
        default_permanency: float = 0.5,
        permanency_threshold: float = 0.8,
        deletion_threshold: float = 0.0,
        min_frequency: float = 0.05,
        decay_step: float = 0.007,
        permanency_step: float = 0.02,
        initial_lp: float = 0.5,
        imitator_lp: float = 0.9,
        hold_lp: bool = False,
        imitator_weighting: Literal["even", "lp", "lp_gain"] = "even",
        world_weighting: Literal["every", "intent", "outcome"] = "outcome",
        lp_goal: float = 0.01,
        lp_own_goal_weight: float = 3.0,
        lp_ball_to_goal: float = 0.005,
        lp_robot_to_ball: float = 0.002,
        lp_event: float = 0.001,
        match_distance_mm: float = 40.0,
        match_rotation_deg: float = 45.0,
        ball_angle_tolerance_deg: float = 22.5,
        ball_min_samples: int = 5,
        ball_max_angle_sd_deg: float = 30.0,
        ball_moved_mm: float = 10.0,
        prediction_noise_divisor: float = 3.0,
        ball_dead_band_mm: float = 10.0,
        robot_dead_band_mm: float = 10.0,
        prefer_sooner_goals: bool = False,
        push_heading_tail: float = 0.1,
        lp_bounds: Literal["soft", "clamp"] = "soft",
        lp_scope: Literal["own_demonstrator", "every"] = "own_demonstrator",
        lp_criteria: Literal["foremost", "both"] = "foremost",
        lp_approach_weight: Literal["per_demonstration", "per_span"] = "per_demonstration",
    ) -> Self: ...
    def replace(self, **changes: Any) -> Self:
        """A copy with the constants given changed, checked again.

        >>> LearningConfig().replace(decay_step=0.01).decay_step
        0.01
        """
    def to_dict(self) -> dict[str, Any]:
        """Every constant by name, in order: plain Python floats, an int and strings.

        >>> list(LearningConfig().to_dict())[:2]
        ['creation_threshold', 'default_permanency']
        """
    @classmethod
    def _from_dict(cls, values: dict[str, Any]) -> Self: ...
    def __reduce__(self) -> tuple[Any, tuple[dict[str, Any]]]: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __hash__(self) -> int: ...
    @property
    def creation_threshold(self) -> float: ...
    @property
    def default_permanency(self) -> float: ...
    @property
    def permanency_threshold(self) -> float: ...
    @property
    def deletion_threshold(self) -> float: ...
    @property
    def min_frequency(self) -> float: ...
    @property
    def decay_step(self) -> float: ...
    @property
    def permanency_step(self) -> float: ...
    @property
    def initial_lp(self) -> float: ...
    @property
    def imitator_lp(self) -> float: ...
    @property
    def hold_lp(self) -> bool:
        """Whether every demonstrator's LP is held at `initial_lp` throughout a trial."""
    @property
    def imitator_weighting(self) -> str:
        """`"even"`, `"lp"` or `"lp_gain"`."""
    @property
    def world_weighting(self) -> str:
        """`"outcome"`, `"intent"` or `"every"`: the parts of the improved control's world model
        the imitator weighting reaches.
        """
    @property
    def lp_goal(self) -> float: ...
    @property
    def lp_own_goal_weight(self) -> float:
        """How many times `lp_goal` an own goal lowers the LP by."""
    @property
    def lp_ball_to_goal(self) -> float: ...
    @property
    def lp_robot_to_ball(self) -> float: ...
    @property
    def lp_event(self) -> float: ...
    @property
    def match_distance_mm(self) -> float: ...
    @property
    def match_rotation_deg(self) -> float: ...
    @property
    def ball_angle_tolerance_deg(self) -> float: ...
    @property
    def ball_min_samples(self) -> int: ...
    @property
    def ball_max_angle_sd_deg(self) -> float: ...
    @property
    def ball_moved_mm(self) -> float: ...
    @property
    def prediction_noise_divisor(self) -> float: ...
    @property
    def ball_dead_band_mm(self) -> float: ...
    @property
    def robot_dead_band_mm(self) -> float: ...
    @property
    def prefer_sooner_goals(self) -> bool:
        """Whether, under the improved control, of two predicted goals the sooner rates better."""
    @property
    def push_heading_tail(self) -> float:
        """The share of pushing headings the improved control's push region leaves out at each end."""
    @property
    def lp_bounds(self) -> str: ...
    @property
    def lp_scope(self) -> str: ...
    @property
    def lp_criteria(self) -> str: ...
    @property
    def lp_approach_weight(self) -> str: ...
def attempt_seeds(attempts_per_configuration: int, *, seed: int) -> list[tuple[int, int]]: ...

@final
class SegmentedDemonstrations:
    """Segmented demonstrations: who demonstrated, how each ended, on which field, and its
    segments (as :meth:`PrimitiveRecognizer.segment` gives them).

    Built from dictionaries with ``demonstrator``, ``outcome`` (a field outcome: ``"goal"``,
    ``"own_goal"``, ``"ball_out"``, ``"robot_out"``, ``"time_up"``), ``pitch`` (``"large"`` or
    ``"small"``) and ``segments`` (columns ``label``, ``first_frame``, ``last_frame``, ``start``
    and ``end`` of shape ``(k, 5)`` and, optionally, ``scores`` of shape ``(k, 4)``), every value
    is checked once, here: a bad one is a ``ValueError`` naming the demonstration, the field,
    the value and what is allowed. ``frame_counts`` (one per demonstration) also checks that
    every segment lies inside its demonstration. The batch is immutable and shared, not copied,
    by every trial and policy it is given to; indexing gives a demonstration back read-only
    (mappings that refuse assignment, labels as a tuple, arrays that refuse writes), so what
    was checked cannot change; ``dict(item)`` and the columns' copies make a new one to edit
    and check again. Batches add and pickle.

    Examples
    --------
    >>> import numpy as np
    >>> state = np.zeros((1, 5))
    >>> segments = {"label": ["forward"], "first_frame": np.array([0]), "last_frame": np.array([9]),
    ...             "start": state, "end": state}
    >>> batch = SegmentedDemonstrations([{"demonstrator": "expert", "outcome": "goal", "pitch": "large",
    ...                                   "segments": segments}])
    >>> len(batch), batch.outcomes, batch[0]["segments"]["label"]
    (1, ['goal'], ('forward',))
    >>> batch[0]["segments"]["label"] = ["jump"]
    Traceback (most recent call last):
    ...
    TypeError: 'mappingproxy' object does not support item assignment
    >>> SegmentedDemonstrations([{"demonstrator": "expert", "outcome": "own-goal", "pitch": "large",
    ...                           "segments": segments}])
    Traceback (most recent call last):
    ...
    ValueError: demonstration 0: outcome 'own-goal' is not one of 'goal', 'own_goal', 'ball_out',
    'robot_out', 'time_up'
    """
    def __new__(
        cls, demonstrations: Iterable[Mapping[str, Any]], *, frame_counts: Sequence[int] | None = None
    ) -> SegmentedDemonstrations: ...
    @staticmethod
    def concat(batches: Sequence[SegmentedDemonstrations]) -> SegmentedDemonstrations:
        """The batches one after another.

        >>> len(SegmentedDemonstrations.concat([SegmentedDemonstrations([]), SegmentedDemonstrations([])]))
        0
        """
    def __add__(self, other: SegmentedDemonstrations, /) -> SegmentedDemonstrations: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int, /) -> Mapping[str, Any]: ...
    def __iter__(self) -> Iterator[Mapping[str, Any]]: ...
    @property
    def demonstrators(self) -> list[str]:
        """Who demonstrated each."""
    @property
    def outcomes(self) -> list[str]:
        """How each ended."""
    @property
    def pitches(self) -> list[str]:
        """The field each was played on: ``"large"``, ``"small"`` or its sizes as JSON."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[Any, tuple[list[dict[str, Any]]]]: ...

@final
class ModelResult:
    """One forward model at the end of a trial: its LP (and every change of it), the share of
    prediction rounds with a match, the counts of Tables 4.1 and 4.2, its behaviours (one
    dictionary each: ``primitives``, ``permanency``, ``permanent``, ``age``, ``selected``,
    ``ball_samples``, ``ball_angle_deg`` and ``ball_distance_mm`` as ``[mean, sd]``) and how
    often each cause of Table 3.3 changed the LP (``lp_causes``: ``goal``, ``own_goal``,
    ``ball_nearer_goal``, ``ball_farther_from_goal``, ``robot_nearer_ball``,
    ``robot_farther_from_ball``, ``ball_predicted``, ``candidate_permanent``,
    ``candidate_deleted``).

    Every value is checked when made: a ``ValueError`` names the field.

    Examples
    --------
    >>> model = ModelResult("expert", 0.6, [0.5, 0.6], 0.25, 3, 1, 2, 1, 0, 1, 8, 2, [])
    >>> model.lp, model.rounds_matched, model.lp_causes
    (0.6, 2, {})
    >>> ModelResult("expert", 1.5, [0.5], 0.25, 3, 1, 2, 1, 0, 1, 8, 2, [])
    Traceback (most recent call last):
    ...
    ValueError: lp: 1.5 is not a number in [0, 1]
    """
    def __new__(
        cls,
        name: str,
        lp: float,
        lp_history: Sequence[float],
        match_rate: float,
        created: int,
        deleted: int,
        permanent: int,
        candidates: int,
        duplicates: int,
        candidates_permanent: int,
        rounds: int,
        rounds_matched: int,
        behaviours: Sequence[Mapping[str, Any]],
        lp_causes: Mapping[str, int] | None = None,
    ) -> ModelResult: ...
    @property
    def name(self) -> str:
        """The demonstrator the model represents (`"imitator"` for the imitator's own)."""
    @property
    def lp(self) -> float:
        """The final learning preference, in [0, 1] under the default bounds (the imitator's is fixed)."""
    @property
    def lp_history(self) -> list[float]:
        """The LP after every change, from the first."""
    @property
    def match_rate(self) -> float:
        """Share of prediction rounds in which the model's prediction matched the demonstration
        (thesis Tables 4.7 and 4.10), in [0, 1].
        """
    @property
    def created(self) -> int:
        """Behaviours the model created over the trial (thesis Figs. 4.7 and 4.19)."""
    @property
    def deleted(self) -> int:
        """Behaviours the model deleted over the trial (thesis Figs. 4.8 and 4.20)."""
    @property
    def permanent(self) -> int:
        """Behaviours permanent in the model at the end of the trial (thesis Figs. 4.9 and 4.21)."""
    @property
    def candidates(self) -> int:
        """Candidate behaviours moved from this model to the imitator's (thesis Figs. 4.10 and 4.22)."""
    @property
    def duplicates(self) -> int:
        """Candidates not moved because the imitator's model already held them (thesis Figs. 4.11
        and 4.23).
        """
    @property
    def candidates_permanent(self) -> int:
        """Moved candidates that became permanent in the imitator's model (thesis Figs. 4.12 and 4.24)."""
    @property
    def rounds(self) -> int:
        """Prediction rounds the model took part in."""
    @property
    def rounds_matched(self) -> int:
        """Prediction rounds in which its prediction matched (`match_rate` = this / `rounds`)."""
    @property
    def behaviours(self) -> list[dict[str, Any]]:
        """One dictionary per behaviour (a copy)."""
    @property
    def lp_causes(self) -> dict[str, int]:
        """How often each cause changed the LP (a copy)."""
    def to_dict(self) -> dict[str, Any]:
        """Every field by name, as plain data."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[Any, tuple[Any, ...]]: ...

@final
class TrialResult:
    """Every demonstrator's model (by name, in the ordering) and the imitator's, the trial's seed
    and the imitator's final model as versioned JSON (``imitator_model``: what
    :class:`ImitatorPolicy` drives).

    ``save``/``load`` (and ``to_json``/``from_json``) keep the trial files of a run: loading
    checks every value's type and range and raises :class:`ModelFileError` naming the file and
    the key of anything damaged, truncated or foreign.

    Examples
    --------
    >>> model = ModelResult("imitator", 0.9, [0.9], 0.0, 5, 0, 0, 0, 0, 0, 0, 0, [])
    >>> trial = TrialResult({}, model, 7)
    >>> TrialResult.from_json(trial.to_json()) == trial, trial.seed
    (True, 7)
    >>> TrialResult.from_json(trial.to_json().replace('"lp": 0.9', '"lp": "high"'))
    Traceback (most recent call last):
    ...
    polymimic.ModelFileError: not a saved trial result: imitator.lp: "high" is not a number
    """
    def __new__(
        cls, models: Mapping[str, ModelResult], imitator: ModelResult, seed: int, imitator_model: str = ""
    ) -> TrialResult: ...
    @property
    def models(self) -> dict[str, ModelResult]:
        """Every demonstrator's model by name, in the ordering (a new dictionary)."""
    @property
    def imitator(self) -> ModelResult:
        """The imitator's own model's record (a `ModelResult`)."""
    @property
    def seed(self) -> int:
        """The trial's seed: the trial depends on it alone."""
    @property
    def imitator_model(self) -> str:
        """The imitator's final model, as versioned JSON."""
    def to_dict(self) -> dict[str, Any]:
        """Every field as plain data (``models`` a dictionary of dictionaries)."""
    def to_json(self) -> str:
        """The trial as JSON text (what ``save`` writes)."""
    @classmethod
    def from_json(cls, text: str) -> TrialResult:
        """A trial from ``to_json`` text, every value checked."""
    def save(self, path: _Path) -> None:
        """Writes the trial to ``path`` (JSON), atomically."""
    @classmethod
    def load(cls, path: _Path) -> TrialResult:
        """Reads a trial written by ``save``."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[Any, tuple[str]]: ...

def learning_trial(
    demonstrations: SegmentedDemonstrations | Iterable[Mapping[str, Any]],
    ordering: list[str],
    recognizer: PrimitiveRecognizer,
    *,
    config: LearningConfig | None = None,
    phase_one: str = "by-model",
    seed: int = 0,
    body: _Body = "lego",
) -> TrialResult: ...
def average_demonstrator(
    demonstrations: SegmentedDemonstrations | Iterable[Mapping[str, Any]],
    recognizer: PrimitiveRecognizer,
    *,
    ordering: list[str],
    poor_net_goals: int,
    expert_net_goals: int,
    per_configuration: int,
    first_seed: int,
    max_trials: int,
    config: LearningConfig | None = None,
    field_config: str | None = None,
    body: _Body = "lego",
) -> tuple[TrialResult, list[dict[str, Any]]]: ...
def net_goals(outcomes: Sequence[str]) -> int: ...
def observations_onto(observations: npt.ArrayLike, recorded_by: _Body, imitator: _Body) -> npt.NDArray[np.float64]: ...
def lp_order_hits(trials: Sequence[TrialResult], order: Sequence[str]) -> int: ...
def spare_attempts(per_configuration: int) -> int: ...

@final
class ImitatorPlayer:
    """A trained imitator as an owned, stateful player: :meth:`reset` starts an episode and
    :meth:`act` takes one tracker reading and answers the command to send until the next (a
    primitive is held for one second, decisions falling on a one-second grid from the
    episode's first reading). It keeps what the control keeps between decisions: the thesis
    control's behaviour in progress and its random generator (seeded by the episode seed), and
    the ball where it was last seen at a decision (the start's ball until then). Made by
    :meth:`polymimic.ImitatorPolicy.player`.
    """
    def reset(
        self,
        episode: Mapping[str, Any] | None = None,
        *,
        start: int | Mapping[str, Any] | None = None,
        seed: int | None = None,
    ) -> None:
        """Start an episode.

        ``episode`` is what :func:`polymimic.record` passes a demonstrator (a dict with the
        episode's ``configuration`` and ``seed``); otherwise ``start`` (1, 2 or ``{"robot": (x_mm,
        y_mm, theta_rad), "ball": (x_mm, y_mm)}``, default 1) and ``seed`` (the episode seed,
        whose draws the thesis control makes; default 0). Raises ``ValueError`` for a start off
        the body's field or with the ball on the robot.
        """
    def act(self, reading: Reading | Sequence[float] | npt.NDArray[np.float64]) -> str:
        """The command to send after ``reading`` until the next one: a :class:`polymimic.Reading`
        or six numbers ``(t_s, robot_x_mm, robot_y_mm, robot_theta_rad, ball_x_mm, ball_y_mm)``
        (float64; NaN where the tracker lost it). Returns the command's name (a primitive's on a
        wheeled body, ``"forward"`` …; the humanoid's own, ``"Walk Forward"``, ``"Kick Left"`` …).
        """
    def decide(
        self, robot_x_mm: float, robot_y_mm: float, robot_theta_rad: float, ball_x_mm: float, ball_y_mm: float
    ) -> int:
        """One decision now from the robot's pose and the ball (NaN where not seen): the primitive
        to run for the next second, as its index in the body's primitive set (the action
        :class:`polymimic.env.PenaltyKickEnv` takes). No time grid: every call decides.
        """
    @property
    def executed(self) -> list[str]:
        """What was executed this episode, in order, as letters: whole behaviours by the thesis's
        rule, single primitives by the improved one.
        """
    @property
    def episode(self) -> dict[str, Any]:
        """The episode's start (``configuration``: 1, 2 or None for a chosen one; ``robot``;
        ``ball``) and ``seed``.
        """

@disjoint_base
class ImitatorPolicy:
    """The imitator's final model driving ``body`` (default the Lego robot) on that body's field.

    ``control="thesis"`` is the thesis's rule (§3.4): behaviours whose preconditions hold
    (else all) predict their outcome with their own ball statistics, and the best by the
    learning-preference criteria runs primitive by primitive, stopping before leaving the
    field. ``control="improved"`` learns from ``demonstrations`` (those the imitator watched,
    segmented) how the ball responds to each primitive, how good each state is and where the
    scoring demonstrations pushed from, and chooses again after every primitive. With
    ``config.imitator_weighting == "lp"`` each demonstration's samples weigh
    ``LP / max LP`` of its demonstrator's model in ``trial`` (the final LPs); a demonstration
    whose demonstrator has no model there is a ``ValueError``. The improved control learns the
    ball's response from the demonstrations played on the imitator's field only.
    ``unlearned`` names parts the demonstrations do not teach (an ablation), each left as the
    imitator's self-observation alone would: ``"ball_response"`` (the ball stays),
    ``"state_value"`` (every state worth 0), ``"push_region"`` (no region to route to) and
    ``"behaviours"`` (the imitator's primitives, none chained).
    """
    def __new__(
        cls,
        trial: TrialResult,
        *,
        recognizer: PrimitiveRecognizer,
        config: LearningConfig | None = None,
        control: str = "thesis",
        demonstrations: SegmentedDemonstrations | Iterable[Mapping[str, Any]] | None = None,
        body: _Body = "lego",
        practice: SegmentedDemonstrations | Iterable[Mapping[str, Any]] | None = None,
        practice_weight: float = 1.0,
        refines: Sequence[str] | None = None,
        unlearned: Sequence[str] | None = None,
    ) -> Self: ...
    @property
    def control(self) -> str:
        """`"thesis"` or `"improved"`."""
    @property
    def body(self) -> Body:
        """The body the imitator drives, a :class:`polymimic.Body` (the one it was made with)."""
    def for_trial(self, trial: TrialResult) -> ImitatorPolicy:
        """The same control driving ``trial``'s imitator, with what this one learned from the
        demonstrations (the improved control's ball response, state values and routes) shared
        rather than learned again: the policy ``ImitatorPolicy(trial, ...)`` with this one's
        arguments would make, sooner. Under ``imitator_weighting="lp"`` or ``"lp_gain"`` what the
        improved control learns depends on the trial's LPs, so that is a ``ValueError``: make a
        new policy.
        """
    def evaluate(
        self,
        attempts_per_configuration: int,
        *,
        seed: int = 0,
        field_config: str | None = None,
        starts: Sequence[int | Mapping[str, Any]] | None = None,
    ) -> list[dict[str, Any]]:
        """Attempts from each start (by default the thesis's configurations 1 and 2; a chosen
        start is ``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``), played by the
        stepped player; one dict per attempt with `frames`, `outcome`, `configuration` (None for
        a chosen start), `start`, `seed` and the `behaviours` executed.
        """
    def record(
        self, *, configuration: int, n: int, seed: int = 0, field_config: str | None = None
    ) -> list[dict[str, Any]]:
        """``n`` valid attempts of the imitator from ``configuration``, recorded as a
        demonstrator's are (episode seeds from ``seed`` as a Python policy's; attempts whose
        tracking was lost replaced): dicts like :func:`polymimic.record`'s.
        """
    def player(self) -> ImitatorPlayer:
        """A player of this imitator, stepped one tracker reading at a time (see
        :class:`polymimic.ImitatorPlayer`); call its ``reset`` first.
        """
    def __len__(self) -> int: ...
