"""polymimic: imitation learning from many demonstrators of different bodies and skill.

The core (discrete HMMs, LBG codebooks) is written in Rust and exposed here.

>>> import numpy as np
>>> import polymimic
>>> model = polymimic.DiscreteHMM(2, 3, seed=1).fit([np.array([0, 0, 1, 2, 2]), np.array([0, 1, 2])])
>>> model.transmat_.shape
(2, 2)
"""

import importlib.util

from polymimic._native import (
    Body,
    Codebook,
    DiscreteHMM,
    Episode,
    FieldRunError,
    ImitatorPlayer,
    ImpossibleSequenceError,
    ModelFileError,
    NotFittedError,
    PolicyError,
    PolymimicError,
    PrimitiveRecognizer,
    Reading,
    __version__,
)
from polymimic.datasets import load_demonstrations, load_self_observation, save_demonstrations, save_self_observation
from polymimic.evaluation import Attempts
from polymimic.field import Demonstration, PrimitiveSequence, command_table, record, self_observation
from polymimic.learning import (
    Evaluation,
    ImitatorPolicy,
    LearningConfig,
    ModelResult,
    SegmentedDemonstrations,
    TrialResult,
    average_demonstrator,
    evaluate,
    run_trial,
)
from polymimic.plots import animate_demonstration, plot_demonstration, plot_log_likelihoods
from polymimic.tracks import ImportedTracks, TrackLogError, import_tracks, write_tracks

if importlib.util.find_spec("gymnasium") is not None:
    from polymimic import env as _env  # noqa: F401  (registers PenaltyKick-v0 with Gymnasium)

__all__ = [
    "Attempts",
    "Body",
    "Codebook",
    "Demonstration",
    "DiscreteHMM",
    "Episode",
    "Evaluation",
    "FieldRunError",
    "ImitatorPlayer",
    "ImitatorPolicy",
    "ImportedTracks",
    "LearningConfig",
    "ImpossibleSequenceError",
    "ModelFileError",
    "ModelResult",
    "NotFittedError",
    "PolicyError",
    "PolymimicError",
    "PrimitiveRecognizer",
    "PrimitiveSequence",
    "Reading",
    "SegmentedDemonstrations",
    "TrackLogError",
    "TrialResult",
    "__version__",
    "animate_demonstration",
    "average_demonstrator",
    "command_table",
    "evaluate",
    "import_tracks",
    "load_demonstrations",
    "load_self_observation",
    "plot_demonstration",
    "plot_log_likelihoods",
    "record",
    "run_trial",
    "save_demonstrations",
    "save_self_observation",
    "self_observation",
    "write_tracks",
]
