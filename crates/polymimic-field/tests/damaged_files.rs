//! A damaged field config is refused with an `Err` or read as a config an episode runs with;
//! reading never panics. Each property starts from the JSON of the default config with every
//! number moved off its default.

use polymimic_damage::{arbitrary, config, flipped, reshaped, truncated};
use polymimic_field::{BodyKind, Command, Configuration, Episode, EpisodeSetup, FieldConfig, Primitive};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

fn config_file() -> String {
    let mut field = FieldConfig { substeps_per_frame: 4, time_limit_s: 30.0, ..FieldConfig::default() };
    field.tracker.position_sigma_mm *= 1.5;
    field.tracker.spike_probability = 0.1;
    field.tracker.loss_probability = 0.05;
    field.ball.restitution = 0.4;
    field.to_json()
}

/// A config read from `text` must pass its own check, round-trip, and run an episode.
fn config_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(field) = FieldConfig::from_json(text) else { return Ok(()) };
    prop_assert!(field.check().is_ok());
    prop_assert_eq!(FieldConfig::from_json(&field.to_json()), Ok(field));
    let setup = EpisodeSetup::configuration(BodyKind::Lego, Configuration::One, &field);
    let mut episode = Episode::new(&setup, &field, 3).map_err(|e| TestCaseError::fail(e.to_string()))?;
    for primitive in [Primitive::Forward, Primitive::Left, Primitive::Stop] {
        if episode.is_finished() {
            break;
        }
        episode.step(Command::Primitive(primitive)).map_err(|e| TestCaseError::fail(e.to_string()))?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn truncated_field_config_is_refused_or_valid(text in truncated(&config_file())) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_field_config_is_refused_or_valid(text in flipped(&config_file())) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_field_config_is_refused_or_valid(text in reshaped(&config_file())) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_field_config_is_refused_or_valid(text in arbitrary("polymimic.FieldConfig")) {
        config_is_refused_or_valid(&text)?;
    }
}

#[test]
fn valid_file_is_read_back() {
    config_is_refused_or_valid(&config_file()).unwrap();
    assert!(FieldConfig::from_json(&config_file()).is_ok());
}
