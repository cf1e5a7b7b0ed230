//! Saving and loading a Gaussian model as versioned JSON, re-validated on load.

use crate::error::HmmError;

use super::GaussianHmm;

const FORMAT: &str = "polymimic.GaussianHMM";
const VERSION: u32 = 1;

impl GaussianHmm {
    /// The model as versioned JSON.
    ///
    /// # Errors
    /// Never in practice.
    pub fn to_json(&self) -> Result<String, HmmError> {
        polymimic_persist::to_envelope(FORMAT, VERSION, self).map_err(HmmError::Corrupt)
    }

    /// A model from [`Self::to_json`] text, re-validated.
    ///
    /// # Errors
    /// Another format or version, or parts that do not validate.
    pub fn from_json(text: &str) -> Result<Self, HmmError> {
        let saved: Self = polymimic_persist::from_envelope(text, FORMAT, VERSION).map_err(HmmError::Corrupt)?;
        if !saved.fitted {
            return Self::new(saved.params).map_err(|e| HmmError::Corrupt(e.to_string()));
        }
        let mut model = Self::from_parts(saved.params, saved.startprob, saved.transmat, saved.means, saved.variances)
            .map_err(|e| HmmError::Corrupt(e.to_string()))?;
        model.history = saved.history;
        model.converged = saved.converged;
        Ok(model)
    }
}

#[cfg(test)]
mod tests {
    use super::super::GaussianHmmParams;
    use super::*;
    use crate::topology::Topology;

    #[test]
    fn a_model_round_trips_through_json() {
        let mut params = GaussianHmmParams::new(2, 1);
        params.topology = Topology::Ergodic;
        let m =
            GaussianHmm::from_parts(params, vec![0.5, 0.5], vec![0.9, 0.1, 0.2, 0.8], vec![-1.0, 1.0], vec![0.5, 2.0])
                .expect("valid parts");
        let text = m.to_json().expect("saves");
        assert_eq!(GaussianHmm::from_json(&text).expect("loads"), m);
        let unfitted = GaussianHmm::new(GaussianHmmParams::new(2, 1)).expect("valid");
        assert_eq!(GaussianHmm::from_json(&unfitted.to_json().expect("saves")).expect("loads"), unfitted);
        assert!(GaussianHmm::from_json(&text.replace("\"version\":1", "\"version\":2")).is_err());
    }
}
