//! Hyper-parameters of a discrete HMM: a builder checked once into a valid set.

use serde::{Deserialize, Serialize};

use crate::error::HmmParamsError;
use crate::topology::Topology;

/// What a model is and how it is trained. Build with [`HmmParams::new`], adjust the
/// fields, then call [`HmmParams::check`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HmmParams {
    pub n_states: usize,
    pub n_symbols: usize,
    pub topology: Topology,
    /// Baum-Welch re-estimations at the most.
    pub max_iter: usize,
    /// Training stops once the log-likelihood gains less than this; `-inf` never stops early.
    #[serde(with = "tolerance_text")]
    pub tol: f64,
    /// Lower bound on the initial emission probabilities (then each row is renormalised),
    /// so that a symbol unseen in a state's piece is not ruled out before training starts.
    pub emission_floor: f64,
    /// Seed of the random initial transitions.
    pub seed: u64,
}

impl HmmParams {
    /// The thesis's defaults: left-right with two forward links, 100 iterations, tolerance
    /// 1e-4 (log units), floor 1e-8.
    #[must_use]
    pub fn new(n_states: usize, n_symbols: usize) -> Self {
        Self {
            n_states,
            n_symbols,
            topology: Topology::default(),
            max_iter: 100,
            tol: 1e-4,
            emission_floor: 1e-8,
            seed: 0,
        }
    }

    /// Validates every field once.
    ///
    /// # Errors
    /// Names the first field that is out of range.
    pub fn check(self) -> Result<ValidHmmParams, HmmParamsError> {
        if self.n_states == 0 {
            return Err(HmmParamsError::NoStates(self.n_states));
        }
        if self.n_states > crate::MAX_STATES {
            return Err(HmmParamsError::TooManyStates { n_states: self.n_states, max: crate::MAX_STATES });
        }
        if self.n_symbols == 0 {
            return Err(HmmParamsError::NoSymbols(self.n_symbols));
        }
        if self.tol.is_nan() {
            return Err(HmmParamsError::TolIsNan);
        }
        let max_floor = 1.0 / self.n_symbols as f64;
        if !(0.0..=max_floor).contains(&self.emission_floor) {
            return Err(HmmParamsError::EmissionFloorOutOfRange { value: self.emission_floor, max: max_floor });
        }
        Ok(ValidHmmParams(self))
    }
}

/// Parameters that passed [`HmmParams::check`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ValidHmmParams(HmmParams);

impl std::ops::Deref for ValidHmmParams {
    type Target = HmmParams;
    fn deref(&self) -> &HmmParams {
        &self.0
    }
}

/// JSON has no infinities, and `-inf` is a meaningful tolerance: infinities go as text.
pub(crate) mod tolerance_text {
    use serde::{Deserialize, Deserializer, Serializer};

    #[derive(Deserialize)]
    #[serde(untagged)]
    enum NumberOrText {
        Number(f64),
        Text(String),
    }

    #[allow(clippy::trivially_copy_pass_by_ref)] // serde's `with` passes fields by reference
    pub fn serialize<S: Serializer>(value: &f64, serializer: S) -> Result<S::Ok, S::Error> {
        match *value {
            f64::NEG_INFINITY => serializer.serialize_str("-inf"),
            f64::INFINITY => serializer.serialize_str("inf"),
            finite => serializer.serialize_f64(finite),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<f64, D::Error> {
        match NumberOrText::deserialize(deserializer)? {
            NumberOrText::Number(x) => Ok(x),
            NumberOrText::Text(t) if t == "-inf" => Ok(f64::NEG_INFINITY),
            NumberOrText::Text(t) if t == "inf" => Ok(f64::INFINITY),
            NumberOrText::Text(t) => Err(serde::de::Error::custom(format!("tol: {t:?} is not a number"))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_zero_states_and_symbols() {
        assert_eq!(HmmParams::new(0, 4).check(), Err(HmmParamsError::NoStates(0)));
        assert_eq!(HmmParams::new(2, 0).check(), Err(HmmParamsError::NoSymbols(0)));
    }

    #[test]
    fn rejects_nan_tol_but_accepts_minus_infinity() {
        let mut p = HmmParams::new(2, 4);
        p.tol = f64::NAN;
        assert_eq!(p.clone().check(), Err(HmmParamsError::TolIsNan));
        p.tol = f64::NEG_INFINITY;
        assert!(p.check().is_ok());
    }

    #[test]
    fn rejects_a_floor_that_cannot_be_renormalised() {
        let mut p = HmmParams::new(2, 4);
        p.emission_floor = 0.3;
        assert!(matches!(p.check(), Err(HmmParamsError::EmissionFloorOutOfRange { .. })));
    }
}
