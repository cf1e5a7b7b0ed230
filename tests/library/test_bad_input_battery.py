"""A property-based battery of bad input: malformed arrays, strings, mappings and randomly
damaged saved files thrown at every public entry point. Each must raise a clean exception
(ValueError, TypeError, an OSError for files, or a polymimic.PolymimicError) or return a
well-defined value — never panic, crash, hang or return NaN.

The number of examples per property is bounded (``EXAMPLES``) so that CI stays quick; raise it
with ``POLYMIMIC_BATTERY_EXAMPLES`` for a longer search.
"""

import json
import math
import os
import pathlib
import pickle
import tempfile

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import polymimic
from polymimic import datasets, learning
from polymimic.field import PRIMITIVES, check_config, default_config

EXAMPLES = int(os.environ.get("POLYMIMIC_BATTERY_EXAMPLES", "40"))
CLEAN = (ValueError, TypeError, OSError, polymimic.PolymimicError)
"""What a refusal may raise (and, for an integer too large for its argument, OverflowError)."""
battery = settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
                   suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])

# Arrays as a careless caller passes them: any shape of up to three axes, any of the usual dtypes,
# NaN and infinities included, empty ones too.
floats = st.floats(allow_nan=True, allow_infinity=True, width=64)
dtypes = st.sampled_from([np.float64, np.float32, np.int64, np.int32, np.uint8, np.bool_])
# (hypothesis draws NaN and infinities among a float dtype's elements.)
arrays = dtypes.flatmap(lambda dtype: hnp.arrays(dtype, hnp.array_shapes(min_dims=0, max_dims=3, min_side=0,
                                                                         max_side=9)))
odd_values = st.one_of(st.none(), st.integers(-2**70, 2**70), floats, st.text(max_size=8), st.booleans(),
                       st.lists(st.integers(-3, 3), max_size=4), st.dictionaries(st.text(max_size=4),
                                                                                   st.integers(), max_size=3))


def _finite_or_clean(call):
    """Run ``call``; it may raise a clean exception, and whatever it returns holds no NaN."""
    try:
        value = call()
    except CLEAN:
        return None
    except OverflowError as error:
        # An integer too large for its argument: Python's own error, with a note naming the
        # argument ("while processing 'n'"), as every extraction failure of the bindings has.
        assert any("while processing" in note for note in getattr(error, "__notes__", [])), repr(error)
        return None
    for number in np.asarray(value if not isinstance(value, tuple) else value[-1], dtype=object).ravel():
        if isinstance(number, float):
            assert not math.isnan(number), value
    return value


@pytest.fixture(scope="module")
def hmm():
    return polymimic.DiscreteHMM(2, 4, seed=1).fit([np.array([0, 1, 2, 3]), np.array([0, 0, 1, 3, 3])])


@pytest.fixture(scope="module")
def recognizer():
    sequences = polymimic.self_observation(12, seed=3)
    return polymimic.PrimitiveRecognizer.train([s.frames for s in sequences], [s.primitive for s in sequences],
                                               codebook_size=8)


@battery
@given(sequence=arrays)
def test_hmm_scores_and_decodes_any_array_cleanly(hmm, sequence):
    _finite_or_clean(lambda: hmm.score(sequence))
    _finite_or_clean(lambda: hmm.decode(sequence))
    _finite_or_clean(lambda: hmm.score_samples([sequence], impossible="-inf"))


@battery
@given(sequences=st.lists(arrays, max_size=3), n_states=st.integers(-2, 4), n_symbols=st.integers(-2, 5))
def test_hmm_fits_any_sequences_cleanly(sequences, n_states, n_symbols):
    def fit():
        model = polymimic.DiscreteHMM(n_states, n_symbols, max_iter=3)
        model.fit(sequences)
        assert np.isfinite(model.transmat_).all() and np.isfinite(model.emissionprob_).all()
        return model.history_
    _finite_or_clean(fit)


@battery
@given(start=arrays, trans=arrays, emit=arrays)
def test_hmm_from_any_parameters_cleanly(start, trans, emit):
    _finite_or_clean(lambda: polymimic.DiscreteHMM.from_params(start, trans, emit, topology="ergodic").score([0]))


@battery
@given(centroids=arrays, points=arrays)
def test_codebooks_take_any_array_cleanly(centroids, points):
    def encode():
        return polymimic.Codebook(centroids).encode(points)
    _finite_or_clean(encode)
    _finite_or_clean(lambda: polymimic.Codebook.fit(points, size=2, max_iter=3).distortion(points))


@battery
@given(frames=arrays, option=st.sampled_from(["min_frames", "gap_margin", "limit_sds"]), value=odd_values)
def test_the_recognizer_takes_any_frames_cleanly(recognizer, frames, option, value):
    _finite_or_clean(lambda: recognizer.log_likelihoods(frames))
    _finite_or_clean(lambda: recognizer.classify(frames))
    _finite_or_clean(lambda: recognizer.segment(frames))
    _finite_or_clean(lambda: recognizer.segment(np.zeros((30, 5)), **{option: value}))


@battery
@given(demonstrator=st.one_of(st.sampled_from(["expert", "Expert", "", "average"]), odd_values),
       configuration=odd_values, n=odd_values, seed=odd_values)
def test_recording_takes_any_arguments_cleanly(demonstrator, configuration, n, seed):
    # Only small n is ever valid here, so that a lucky draw does not record for minutes.
    if isinstance(n, int) and not isinstance(n, bool) and n > 2:
        n = 2
    _finite_or_clean(lambda: polymimic.record(demonstrator, configuration=configuration, n=n, seed=seed))


@pytest.fixture(scope="module")
def segmented_batch(recognizer):
    return learning.segmented(polymimic.record("expert", configuration=1, n=2, seed=5), recognizer)


ITEM_KEYS = ("demonstrator", "outcome", "pitch", "segments")
SEGMENT_COLUMNS = ("label", "first_frame", "last_frame", "start", "end", "scores")


@battery
@given(index=st.integers(0, 1), key=st.sampled_from(ITEM_KEYS + SEGMENT_COLUMNS), value=st.one_of(odd_values, arrays),
       how=st.sampled_from(["assign", "delete", "element", "resize"]))
def test_changed_segments_are_refused_and_the_batch_keeps_what_it_checked(recognizer, segmented_batch, index, key,
                                                                            value, how):
    before = pickle.dumps(segmented_batch)
    item = segmented_batch[index]
    target = item if key in ITEM_KEYS else item["segments"]
    column = target[key]

    def change():
        if how == "assign":
            target[key] = value
        elif how == "delete":
            del target[key]
        elif how == "element":
            column[0] = value
        else:
            column.resize(1)

    with pytest.raises((TypeError, ValueError, AttributeError, IndexError)):
        change()
    assert segmented_batch == pickle.loads(before)
    # The same change made to a copy is checked again wherever the copy is taken.
    copy = {**item, "segments": dict(item["segments"])}
    (copy if key in ITEM_KEYS else copy["segments"])[key] = value
    batch = _finite_or_clean(lambda: polymimic.SegmentedDemonstrations([copy]))
    if batch is not None:
        _finite_or_clean(lambda: polymimic.run_trial(batch, recognizer=recognizer, ordering=batch.demonstrators,
                                                     seed=1))


def _mangled_configs():
    default = default_config()
    keys = list(default) + ["time_limt_s", "tracker.sigma"]
    return st.dictionaries(st.sampled_from(keys), odd_values, max_size=3)


@battery
@given(config=_mangled_configs())
def test_field_configs_are_checked_cleanly(config):
    checked = _finite_or_clean(lambda: check_config(config))
    if checked is not None:
        assert set(checked) == set(default_config())


@battery
@given(commands=st.lists(st.one_of(st.sampled_from(PRIMITIVES), odd_values), max_size=4),
       pose=st.tuples(floats, floats, floats))
def test_episodes_take_any_commands_cleanly(commands, pose):
    episode = polymimic.Episode()
    _finite_or_clean(lambda: episode.run(commands))
    _finite_or_clean(lambda: episode.place_robot(*pose))
    seen = episode.observation()
    assert all(math.isfinite(v) for v in seen["robot"]) or episode.finished


def _damaged(data: bytes, draw) -> bytes:
    """``data`` truncated, with bytes flipped, or both."""
    cut = draw(st.integers(0, len(data)))
    flips = draw(st.lists(st.tuples(st.integers(0, max(len(data) - 1, 0)), st.integers(1, 255)), max_size=4))
    damaged = bytearray(data[:cut] if draw(st.booleans()) else data)
    for at, mask in flips:
        if at < len(damaged):
            damaged[at] ^= mask
    return bytes(damaged)


def _retyped(text: str, draw) -> str:
    """A saved JSON model with one key removed or its value retyped, somewhere inside."""
    data = json.loads(text)
    node, path = data, []
    while isinstance(node, dict) and node:
        key = draw(st.sampled_from(sorted(node)))
        path.append(key)
        if not isinstance(node[key], dict) or draw(st.booleans()):
            break
        node = node[key]
    if path and isinstance(node, dict):
        if draw(st.booleans()):
            del node[path[-1]]
        else:
            node[path[-1]] = draw(st.one_of(st.none(), st.text(max_size=3), st.integers(-5, 5),
                                            st.lists(st.integers(), max_size=2)))
    return json.dumps(data)


@pytest.fixture(scope="module")
def saved(hmm, recognizer, tmp_path_factory):
    """One saved file of every kind polymimic writes, and its loader."""
    root = tmp_path_factory.mktemp("saved")
    hmm.save(root / "hmm.json")
    polymimic.Codebook(np.eye(3)).save(root / "codebook.json")
    recognizer.save(root / "recognizer.json")
    datasets.save_demonstrations(polymimic.record("tiny", configuration=1, n=1, seed=2), root / "demos.parquet")
    datasets.save_self_observation(polymimic.self_observation(1, seed=2), root / "self.parquet")
    return {"hmm.json": polymimic.DiscreteHMM.load, "codebook.json": polymimic.Codebook.load,
            "recognizer.json": polymimic.PrimitiveRecognizer.load, "demos.parquet": datasets.load_demonstrations,
            "self.parquet": datasets.load_self_observation}, root


@battery
@given(data=st.data())
def test_randomly_damaged_files_are_refused_or_read_whole(saved, data):
    loaders, root = saved
    name = data.draw(st.sampled_from(sorted(loaders)))
    original = (root / name).read_bytes()
    if name.endswith(".json") and data.draw(st.booleans()):
        damaged = _retyped(original.decode(), data.draw).encode()
    else:
        damaged = _damaged(original, data.draw)
    with tempfile.TemporaryDirectory() as scratch:
        path = pathlib.Path(scratch) / name
        path.write_bytes(damaged)
        try:
            loaded = loaders[name](path)
        except (OSError, ValueError, TypeError, polymimic.PolymimicError) as error:
            # A damaged file is refused by a ModelFileError naming it (a missing one by an OSError).
            assert isinstance(error, polymimic.ModelFileError) and str(path) in str(error), repr(error)
            return
    # Read without complaint: then it must be usable, as a whole file is.
    if damaged == original:
        return
    if isinstance(loaded, list):
        assert all(len(item.frames) for item in loaded)
    elif isinstance(loaded, polymimic.DiscreteHMM):
        # A file read whole may be an unfitted model's (probabilities null): scoring then
        # refuses cleanly; a fitted one scores a number.
        _finite_or_clean(lambda: loaded.score([0]))
    elif isinstance(loaded, polymimic.Codebook):
        assert loaded.encode(np.zeros((1, loaded.dim))).shape == (1,)
    else:
        assert set(loaded.motion_stats()) >= {"forward", "backward", "left", "right"}
