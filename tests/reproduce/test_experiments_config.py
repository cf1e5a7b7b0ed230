"""The run configuration: every parameter, a TOML round trip, and clear refusals."""

import dataclasses

import pytest
import tomllib

import polymimic
from polymimic.runs.config import ConfigError, RunConfig


def test_defaults_are_the_thesis_sizes():
    config = RunConfig()
    assert (config.recognizer.n_states, config.recognizer.codebook_size) == (1, 512)
    assert (config.recognizer.train_per_primitive, config.recognizer.test_per_primitive) == (1000, 340)
    assert (config.experiments.sizes.trials, config.experiments.sizes.demonstrations_per_configuration,
            config.experiments.sizes.attempts_per_configuration) == (100, 25, 25)
    assert config.learning == polymimic.LearningConfig()


@pytest.mark.parametrize("config", [
    RunConfig(),
    RunConfig.quick(),
    dataclasses.replace(RunConfig(), learning=polymimic.LearningConfig(permanency_step=0.03),
                        field={**RunConfig().field, "time_limit_s": 45.5}),
], ids=["thesis", "quick", "changed"])
def test_toml_round_trip_is_exact(config):
    text = config.to_toml()
    assert RunConfig.from_toml(text) == config
    # Every parameter is written, section by section.
    sections = tomllib.loads(text)
    assert set(sections) == {"seeds", "field", "imitator", "recognizer", "segmenter", "learning", "experiments",
                             "bodies"}
    assert sections["learning"] == config.learning.to_dict()
    assert sections["field"] == config.field


def test_a_partial_file_changes_only_what_it_names(tmp_path):
    path = tmp_path / "run.toml"
    path.write_text("[experiments]\ntrials = 7\n[field.ball]\nfriction = 0.5\n[learning]\ndecay_step = 0.01\n")
    config = RunConfig.load(path)
    assert config.experiments.sizes.trials == 7 and config.experiments.sizes.demonstrations_per_configuration == 25
    assert config.field["ball"]["friction"] == 0.5 and config.field["ball"]["restitution"] == 0.6
    assert config.learning.decay_step == 0.01
    assert RunConfig.load(path, base=RunConfig.quick()).recognizer.codebook_size == 128


def test_integers_are_accepted_where_numbers_are_expected():
    assert RunConfig.from_toml("[segmenter]\ngap_margin = 3\n").segmenter.gap_margin == 3.0


@pytest.mark.parametrize("text, message", [
    ("[recognizer]\ncodebok_size = 3\n", "unknown key in [recognizer]: codebok_size"),
    ("[learning]\nspeed = 3\nhaste = 1\n", "unknown keys in [learning]: haste, speed"),
    ("[field.tracker]\nblur = 1.0\n", "unknown key in [field.tracker]: blur"),
    ("[plots]\ndpi = 3\n", "unknown section: plots"),
    ("[experiments]\ntrials = 2.5\n", "[experiments] trials = 2.5 must be an integer"),
    ("[recognizer]\nrepresentation = 3\n", "[recognizer] representation = 3 must be a string"),
    ("[experiments]\ntrials = 0\n", "[experiments] trials = 0 must be at least 1"),
    ("[recognizer]\nemissions = \"poisson\"\n", "emissions = 'poisson' must be"),
    ("[learning]\ncreation_threshold = 1.5\n", "[learning] creation_threshold = 1.5 must be in"),
    ("[seeds]\nfirst_trial = true\n", "[seeds] first_trial = True must be an integer"),
    ("experiments = 3\n", "[experiments] must be a table"),
    ("[experiments\n", "not valid TOML"),
])
def test_bad_configs_are_refused_with_what_is_wrong(text, message):
    with pytest.raises(ConfigError) as error:
        RunConfig.from_toml(text)
    assert message in str(error.value)


def test_an_unreadable_file_is_named(tmp_path):
    with pytest.raises(ConfigError, match="cannot read config .*missing.toml"):
        RunConfig.load(tmp_path / "missing.toml")
    (tmp_path / "bad.toml").write_text("[experiments]\ntrials = -1\n")
    with pytest.raises(ConfigError, match=r"bad.toml: \[experiments\] trials = -1"):
        RunConfig.load(tmp_path / "bad.toml")
