//! A damaged saved codebook is refused with an `Err` or read as a codebook that encodes;
//! reading never panics. Each property starts from a file written by `to_json` of a codebook
//! grown by LBG.

use polymimic_damage::{arbitrary, config, flipped, reshaped, truncated};
use polymimic_vq::{Codebook, LbgParams};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

fn codebook_file() -> String {
    let data: Vec<f64> = (0..240).map(|i| f64::from(i).sin() * 7.3).collect();
    Codebook::fit(&data, 3, LbgParams::new(8)).unwrap().to_json().unwrap()
}

/// A codebook read from `text` must round-trip, hold finite codewords, and encode points of
/// its dimension to codewords it has.
fn codebook_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(codebook) = Codebook::from_json(text) else { return Ok(()) };
    let again = Codebook::from_json(&codebook.to_json().map_err(|e| TestCaseError::fail(e.to_string()))?);
    prop_assert_eq!(again.as_ref(), Ok(&codebook));
    let dim = codebook.dim();
    prop_assert!(dim >= 1 && !codebook.is_empty());
    prop_assert_eq!(codebook.codewords().len() % dim, 0);
    prop_assert!(codebook.codewords().iter().all(|x| x.is_finite()));
    let points: Vec<f64> = (0..5 * dim).map(|i| (i as f64).cos() * 10.0).collect();
    let symbols = codebook.encode(&points, dim).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(symbols.len(), 5);
    prop_assert!(symbols.iter().all(|&s| (s as usize) < codebook.len()));
    let distortion = codebook.distortion(&points, dim).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert!(distortion >= 0.0, "distortion {distortion}");
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn truncated_codebook_is_refused_or_valid(text in truncated(&codebook_file())) {
        codebook_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_codebook_is_refused_or_valid(text in flipped(&codebook_file())) {
        codebook_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_codebook_is_refused_or_valid(text in reshaped(&codebook_file())) {
        codebook_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_codebook_is_refused_or_valid(text in arbitrary("polymimic.Codebook")) {
        codebook_is_refused_or_valid(&text)?;
    }
}

#[test]
fn valid_file_is_read_back() {
    codebook_is_refused_or_valid(&codebook_file()).unwrap();
    assert!(Codebook::from_json(&codebook_file()).is_ok());
}
