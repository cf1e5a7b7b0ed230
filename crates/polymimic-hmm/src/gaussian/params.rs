//! What a Gaussian model is and how it is trained, checked before anything runs.

use serde::{Deserialize, Serialize};

use crate::error::HmmParamsError;
use crate::topology::Topology;

/// What a Gaussian model is and how it is trained.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GaussianHmmParams {
    pub n_states: usize,
    /// Dimensions of an observation.
    pub dim: usize,
    pub topology: Topology,
    pub max_iter: usize,
    #[serde(with = "crate::params::tolerance_text")]
    pub tol: f64,
    /// Lower bound on every variance, so a state never collapses onto a single point.
    pub min_variance: f64,
    pub seed: u64,
}

impl GaussianHmmParams {
    #[must_use]
    pub fn new(n_states: usize, dim: usize) -> Self {
        Self { n_states, dim, topology: Topology::default(), max_iter: 100, tol: 1e-4, min_variance: 1e-3, seed: 0 }
    }

    /// # Errors
    /// Names the field out of range.
    pub fn check(&self) -> Result<(), HmmParamsError> {
        if self.n_states == 0 {
            return Err(HmmParamsError::NoStates(0));
        }
        if self.n_states > crate::MAX_STATES {
            return Err(HmmParamsError::TooManyStates { n_states: self.n_states, max: crate::MAX_STATES });
        }
        if self.dim == 0 {
            return Err(HmmParamsError::NoDimensions);
        }
        if self.tol.is_nan() {
            return Err(HmmParamsError::TolIsNan);
        }
        if !(self.min_variance.is_finite() && self.min_variance > 0.0) {
            return Err(HmmParamsError::MinVariance(self.min_variance));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_names_the_parameter_out_of_range() {
        assert!(GaussianHmmParams::new(2, 3).check().is_ok());
        assert_eq!(GaussianHmmParams::new(0, 3).check(), Err(HmmParamsError::NoStates(0)));
        assert_eq!(GaussianHmmParams::new(2, 0).check(), Err(HmmParamsError::NoDimensions));
        let params = GaussianHmmParams { min_variance: 0.0, ..GaussianHmmParams::new(2, 3) };
        assert_eq!(params.check(), Err(HmmParamsError::MinVariance(0.0)));
    }
}
