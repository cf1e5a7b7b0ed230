//! A damaged envelope is refused with an `Err` or read as the payload it holds; reading never
//! panics, whatever the payload type asked for.

use std::collections::BTreeMap;

use polymimic_damage::{arbitrary, config, flipped, reshaped, truncated};
use polymimic_persist::{from_envelope, to_envelope};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use serde::{Deserialize, Serialize};

const FORMAT: &str = "polymimic.Test";

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Payload {
    name: String,
    count: usize,
    values: Vec<f64>,
    table: Vec<Vec<u32>>,
    by_name: BTreeMap<String, f64>,
    optional: Option<i64>,
}

fn envelope_file() -> String {
    let payload = Payload {
        name: "model".to_owned(),
        count: 3,
        values: vec![0.1, 1.0 / 3.0, 1e-300, f64::MAX],
        table: vec![vec![0, 1], vec![2]],
        by_name: [("a".to_owned(), 1.5), ("b".to_owned(), -2.0)].into_iter().collect(),
        optional: Some(-7),
    };
    to_envelope(FORMAT, 1, &payload).unwrap()
}

/// What the envelope accepts must write back to an envelope it reads the same.
fn envelope_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    if let Ok(payload) = from_envelope::<Payload>(text, FORMAT, 1) {
        let again = to_envelope(FORMAT, 1, &payload).map_err(TestCaseError::fail)?;
        prop_assert_eq!(from_envelope::<Payload>(&again, FORMAT, 1), Ok(payload));
    }
    if let Ok(value) = from_envelope::<serde_json::Value>(text, FORMAT, 1) {
        let again = to_envelope(FORMAT, 1, &value).map_err(TestCaseError::fail)?;
        prop_assert_eq!(from_envelope::<serde_json::Value>(&again, FORMAT, 1), Ok(value));
    }
    let _ = from_envelope::<Vec<u8>>(text, FORMAT, 1);
    let _ = from_envelope::<String>(text, "polymimic.Other", 1);
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn truncated_envelope_is_refused_or_valid(text in truncated(&envelope_file())) {
        envelope_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_envelope_is_refused_or_valid(text in flipped(&envelope_file())) {
        envelope_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_envelope_is_refused_or_valid(text in reshaped(&envelope_file())) {
        envelope_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_envelope_is_refused_or_valid(text in arbitrary(FORMAT)) {
        envelope_is_refused_or_valid(&text)?;
    }
}

#[test]
fn valid_file_is_read_back() {
    envelope_is_refused_or_valid(&envelope_file()).unwrap();
    assert!(from_envelope::<Payload>(&envelope_file(), FORMAT, 1).is_ok());
}
