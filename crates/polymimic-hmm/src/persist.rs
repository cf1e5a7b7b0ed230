//! Saved models: JSON with a format name and version, checked on load.

use serde::{Deserialize, Serialize};

use crate::error::HmmError;
use crate::model::DiscreteHmm;
use crate::params::HmmParams;
use crate::probabilities::Probabilities;

const FORMAT: &str = "polymimic.DiscreteHMM";
const VERSION: u32 = 1;

#[derive(Serialize, Deserialize)]
struct Saved {
    params: HmmParams,
    /// Required (null for an unfitted model): a file that lost the key is damaged, not unfitted.
    #[serde(deserialize_with = "Option::deserialize")]
    probabilities: Option<Probabilities>,
    history: Vec<f64>,
    converged: bool,
}

impl DiscreteHmm {
    /// The model as JSON text (floats round-trip exactly).
    ///
    /// # Errors
    /// Never in practice; serialisation of plain numbers cannot fail.
    pub fn to_json(&self) -> Result<String, HmmError> {
        let saved = Saved {
            params: (*self.params).clone(),
            probabilities: self.probs.clone(),
            history: self.history.clone(),
            converged: self.converged,
        };
        polymimic_persist::to_envelope(FORMAT, VERSION, &saved).map_err(HmmError::Corrupt)
    }

    /// A model from [`Self::to_json`] text, re-validated as if built by hand.
    ///
    /// # Errors
    /// Text that is not JSON, another format or version, or tables that do not validate.
    pub fn from_json(text: &str) -> Result<Self, HmmError> {
        let saved: Saved = polymimic_persist::from_envelope(text, FORMAT, VERSION).map_err(HmmError::Corrupt)?;
        let params = saved.params.check().map_err(|e| HmmError::Corrupt(e.to_string()))?;
        let mut model = match saved.probabilities {
            None => DiscreteHmm::new(params),
            Some(p) => DiscreteHmm::from_probabilities(params, p.startprob, p.transmat, p.emissionprob)
                .map_err(|e| HmmError::Corrupt(e.to_string()))?,
        };
        if saved.history.iter().any(|x| x.is_nan()) {
            return Err(HmmError::Corrupt("history holds NaN".to_owned()));
        }
        model.history = saved.history;
        model.converged = saved.converged;
        Ok(model)
    }
}

#[cfg(test)]
mod tests {
    use crate::{DiscreteHmm, HmmParams};

    #[test]
    fn a_file_that_lost_its_probabilities_is_damaged_not_unfitted() {
        let model = DiscreteHmm::new(HmmParams::new(2, 3).check().unwrap());
        let text = model.to_json().unwrap();
        assert!(text.contains("\"probabilities\":null"), "{text}");
        assert!(DiscreteHmm::from_json(&text).is_ok(), "an unfitted model's own file loads");
        let lost = text.replace(",\"probabilities\":null", "");
        assert_ne!(lost, text);
        let error = DiscreteHmm::from_json(&lost).err().expect("refused").to_string();
        assert!(error.contains("probabilities"), "{error}");
    }
}
