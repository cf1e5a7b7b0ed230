//! A damaged saved HMM is refused with an `Err` or read as a model that works; reading never
//! panics. Each property starts from a file written by `to_json` of a trained model.

use polymimic_damage::{arbitrary, config, flipped, reshaped, truncated};
use polymimic_hmm::{DiscreteHmm, GaussianHmm, GaussianHmmParams, HmmParams, Init, Topology};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

fn discrete_file(topology: Topology) -> String {
    let mut params = HmmParams::new(3, 5);
    params.topology = topology;
    let sequences: Vec<&[u32]> = vec![&[0, 0, 1, 2, 2, 3, 4], &[0, 1, 1, 2, 3, 3, 4, 4], &[0, 2, 2, 4]];
    let mut model = DiscreteHmm::new(params.check().unwrap());
    model.fit(&sequences, Init::Segments).unwrap();
    model.to_json().unwrap()
}

fn left_right_file() -> String {
    discrete_file(Topology::LeftRight { links: 1 })
}

fn ergodic_file() -> String {
    discrete_file(Topology::Ergodic)
}

fn unfitted_file() -> String {
    DiscreteHmm::new(HmmParams::new(2, 4).check().unwrap()).to_json().unwrap()
}

fn gaussian_file() -> String {
    let mut model = GaussianHmm::new(GaussianHmmParams::new(2, 3)).unwrap();
    let a: Vec<f64> = (0..30).map(|i| f64::from(i).sin()).collect();
    let b: Vec<f64> = (0..24).map(|i| f64::from(i).cos() * 2.0).collect();
    model.fit(&[&a, &b]).unwrap();
    model.to_json().unwrap()
}

/// A discrete model read from `text` must round-trip, hold probabilities, and score, decode
/// and sample without panicking.
fn discrete_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(model) = DiscreteHmm::from_json(text) else { return Ok(()) };
    let again = DiscreteHmm::from_json(&model.to_json().map_err(|e| TestCaseError::fail(e.to_string()))?);
    prop_assert_eq!(again.as_ref(), Ok(&model));
    let Ok(probs) = model.probabilities() else { return Ok(()) };
    let (n, m) = (model.params().n_states, model.params().n_symbols);
    prop_assert_eq!(probs.startprob.len(), n);
    prop_assert_eq!(probs.transmat.len(), n * n);
    prop_assert_eq!(Some(probs.emissionprob.len()), n.checked_mul(m));
    let tables = probs.startprob.iter().chain(&probs.transmat).chain(&probs.emissionprob);
    prop_assert!(tables.clone().all(|p| p.is_finite() && (0.0..=1.0).contains(p)));
    let symbols: Vec<u32> = (0..8).map(|t| (t % m) as u32).collect();
    if let Ok(score) = model.score(&symbols) {
        prop_assert!(score <= 1e-9, "log-likelihood {score} > 0");
    }
    let _ = model.decode(&symbols);
    let (sampled, states) = model.sample(2, 8, 7).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert!(states.iter().flatten().all(|&s| s < n));
    let refs: Vec<&[u32]> = sampled.iter().map(Vec::as_slice).collect();
    let _ = model.score_many(&refs);
    let _ = model.with_emission_floor(0.0);
    Ok(())
}

/// A Gaussian model read from `text` must round-trip and score without panicking.
fn gaussian_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(model) = GaussianHmm::from_json(text) else { return Ok(()) };
    let again = GaussianHmm::from_json(&model.to_json().map_err(|e| TestCaseError::fail(e.to_string()))?);
    prop_assert_eq!(again.as_ref(), Ok(&model));
    let Ok((start, transmat, means, variances)) = model.parts() else { return Ok(()) };
    let (n, d) = (model.params().n_states, model.params().dim);
    prop_assert_eq!((start.len(), transmat.len()), (n, n * n));
    prop_assert_eq!((Some(means.len()), Some(variances.len())), (n.checked_mul(d), n.checked_mul(d)));
    prop_assert!(means.iter().all(|x| x.is_finite()));
    prop_assert!(variances.iter().all(|v| v.is_finite() && *v > 0.0));
    let frames: Vec<f64> = (0..4 * d).map(|i| (i as f64).sin()).collect();
    if let Ok(score) = model.score(&frames) {
        prop_assert!(!score.is_nan(), "log-likelihood is NaN");
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn truncated_discrete_hmm_is_refused_or_valid(text in truncated(&left_right_file())) {
        discrete_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_discrete_hmm_is_refused_or_valid(text in flipped(&left_right_file())) {
        discrete_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_left_right_hmm_is_refused_or_valid(text in reshaped(&left_right_file())) {
        discrete_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_ergodic_hmm_is_refused_or_valid(text in reshaped(&ergodic_file())) {
        discrete_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_unfitted_hmm_is_refused_or_valid(text in reshaped(&unfitted_file())) {
        discrete_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_discrete_hmm_is_refused_or_valid(text in arbitrary("polymimic.DiscreteHMM")) {
        discrete_is_refused_or_valid(&text)?;
    }

    #[test]
    fn truncated_gaussian_hmm_is_refused_or_valid(text in truncated(&gaussian_file())) {
        gaussian_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_gaussian_hmm_is_refused_or_valid(text in flipped(&gaussian_file())) {
        gaussian_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_gaussian_hmm_is_refused_or_valid(text in reshaped(&gaussian_file())) {
        gaussian_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_gaussian_hmm_is_refused_or_valid(text in arbitrary("polymimic.GaussianHMM")) {
        gaussian_is_refused_or_valid(&text)?;
    }
}

#[test]
fn valid_files_are_read_back() {
    for text in [left_right_file(), ergodic_file(), unfitted_file()] {
        discrete_is_refused_or_valid(&text).unwrap();
        assert!(DiscreteHmm::from_json(&text).is_ok());
    }
    gaussian_is_refused_or_valid(&gaussian_file()).unwrap();
    assert!(GaussianHmm::from_json(&gaussian_file()).is_ok());
}

/// `n_states × n_symbols` that wraps around to 0 must not let empty emission tables through: a
/// model with 2 states and 2^63 symbols then tried to build a 2^63-entry table to score.
#[test]
fn symbol_counts_whose_table_size_overflows_are_refused() {
    let mut file: serde_json::Value = serde_json::from_str(&discrete_file(Topology::Ergodic)).unwrap();
    let payload = &mut file["payload"];
    payload["params"]["n_states"] = 2.into();
    payload["params"]["n_symbols"] = (1_u64 << 63).into();
    payload["params"]["emission_floor"] = 0.0.into();
    payload["probabilities"]["startprob"] = serde_json::json!([0.5, 0.5]);
    payload["probabilities"]["transmat"] = serde_json::json!([0.5, 0.5, 0.5, 0.5]);
    payload["probabilities"]["emissionprob"] = serde_json::json!([]);
    let text = file.to_string();
    discrete_is_refused_or_valid(&text).unwrap();
    assert!(DiscreteHmm::from_json(&text).is_err());
}

/// The same for a Gaussian model's `n_states × dim` means and variances.
#[test]
fn dimensions_whose_table_size_overflows_are_refused() {
    let mut file: serde_json::Value = serde_json::from_str(&gaussian_file()).unwrap();
    let payload = &mut file["payload"];
    payload["params"]["dim"] = (1_u64 << 63).into();
    payload["means"] = serde_json::json!([]);
    payload["variances"] = serde_json::json!([]);
    let text = file.to_string();
    gaussian_is_refused_or_valid(&text).unwrap();
    assert!(GaussianHmm::from_json(&text).is_err());
}
