//! A continuous-emission HMM: each state emits a Gaussian with a diagonal covariance. The
//! thesis left continuous HMMs as future work (§2.6); they skip quantisation altogether.
//!
//! The recursions are the discrete model's: per frame, the densities b_j(o_t) are computed in
//! log space, shifted by their largest value m_t so that none underflows, and handed to the
//! same scaled forward-backward; log P(O|λ) is then Σ_t log c_t + Σ_t m_t.

mod algorithm;
mod params;
mod persist;

use serde::{Deserialize, Serialize};

use crate::error::{HmmError, HmmParamsError};
use crate::forward_backward::with_lattice;

use algorithm::Score;
pub use params::GaussianHmmParams;

/// π, A, means and variances of a fitted model, row-major.
pub type Parts<'a> = (&'a [f64], &'a [f64], &'a [f64], &'a [f64]);

/// A left-right or ergodic HMM with diagonal-Gaussian emissions.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GaussianHmm {
    params: GaussianHmmParams,
    startprob: Vec<f64>,
    transmat: Vec<f64>,
    /// Row-major `n_states × dim`.
    means: Vec<f64>,
    /// Row-major `n_states × dim`.
    variances: Vec<f64>,
    history: Vec<f64>,
    converged: bool,
    fitted: bool,
}

impl GaussianHmm {
    /// An untrained model.
    ///
    /// # Errors
    /// Parameters out of range.
    pub fn new(params: GaussianHmmParams) -> Result<Self, HmmParamsError> {
        params.check()?;
        Ok(Self {
            params,
            startprob: Vec::new(),
            transmat: Vec::new(),
            means: Vec::new(),
            variances: Vec::new(),
            history: Vec::new(),
            converged: false,
            fitted: false,
        })
    }

    /// A model with the given parameters (row-major tables).
    ///
    /// # Errors
    /// Shapes, probabilities or variances that are not valid.
    pub fn from_parts(
        params: GaussianHmmParams,
        startprob: Vec<f64>,
        transmat: Vec<f64>,
        means: Vec<f64>,
        variances: Vec<f64>,
    ) -> Result<Self, HmmParamsError> {
        params.check()?;
        let (n, d) = (params.n_states, params.dim);
        // Reuse the discrete checks for π and A with a one-symbol emission table.
        crate::Probabilities::new(n, 1, startprob.clone(), transmat.clone(), vec![1.0; n], params.topology)?;
        // Saturating: a product that overflows (a damaged file's dimension) matches no table.
        if means.len() != n.saturating_mul(d) || variances.len() != n.saturating_mul(d) {
            return Err(HmmParamsError::Shape {
                name: "means/variances",
                actual: format!("{} and {} entries", means.len(), variances.len()),
                expected: format!("({n}, {d}) each"),
            });
        }
        if means.iter().any(|m| !m.is_finite()) || variances.iter().any(|v| !(v.is_finite() && *v > 0.0)) {
            return Err(HmmParamsError::MinVariance(variances.iter().copied().fold(f64::INFINITY, f64::min)));
        }
        Ok(Self { params, startprob, transmat, means, variances, history: Vec::new(), converged: false, fitted: true })
    }

    #[must_use]
    pub fn params(&self) -> &GaussianHmmParams {
        &self.params
    }

    fn fitted(&self) -> Result<(), HmmError> {
        if self.fitted { Ok(()) } else { Err(HmmError::NotFitted) }
    }

    /// π, A, means and variances (row-major), once fitted.
    ///
    /// # Errors
    /// [`HmmError::NotFitted`].
    pub fn parts(&self) -> Result<Parts<'_>, HmmError> {
        self.fitted()?;
        Ok((&self.startprob, &self.transmat, &self.means, &self.variances))
    }

    #[must_use]
    pub fn history(&self) -> &[f64] {
        &self.history
    }

    #[must_use]
    pub fn converged(&self) -> bool {
        self.converged
    }

    fn check_sequences(&self, sequences: &[&[f64]]) -> Result<(), HmmParamsError> {
        if sequences.is_empty() {
            return Err(HmmParamsError::NoSequences);
        }
        let d = self.params.dim;
        for (index, seq) in sequences.iter().enumerate() {
            if seq.is_empty() {
                return Err(HmmParamsError::EmptySequence { index });
            }
            if seq.len() % d != 0 {
                return Err(HmmParamsError::Shape {
                    name: "sequence",
                    actual: format!("{} numbers", seq.len()),
                    expected: format!("rows of {d}"),
                });
            }
            if let Some(flat) = seq.iter().position(|x| !x.is_finite()) {
                return Err(HmmParamsError::NotFinite { index, position: flat / d });
            }
        }
        Ok(())
    }

    /// log p(O|λ) of one sequence (row-major frames).
    ///
    /// # Errors
    /// An unfitted model or a bad sequence.
    pub fn score(&self, seq: &[f64]) -> Result<f64, HmmError> {
        self.fitted()?;
        self.check_sequences(&[seq])?;
        Ok(with_lattice(&self.startprob, &self.transmat, Score { model: self, sequences: &[seq] })[0])
    }

    /// log p(O|λ) of many sequences, in parallel.
    ///
    /// # Errors
    /// An unfitted model or a bad sequence.
    pub fn score_many(&self, sequences: &[&[f64]]) -> Result<Vec<f64>, HmmError> {
        self.fitted()?;
        self.check_sequences(sequences)?;
        Ok(with_lattice(&self.startprob, &self.transmat, Score { model: self, sequences }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_sequences_are_named() {
        let mut m = GaussianHmm::new(GaussianHmmParams::new(2, 2)).unwrap();
        assert_eq!(m.score(&[0.0, 0.0]).unwrap_err(), HmmError::NotFitted);
        assert!(matches!(m.fit(&[&[0.0, 1.0, 2.0]]), Err(HmmError::Params(HmmParamsError::Shape { .. }))));
        assert!(matches!(
            m.fit(&[&[0.0, 1.0], &[0.0, f64::NAN]]),
            Err(HmmError::Params(HmmParamsError::NotFinite { index: 1, position: 0 }))
        ));
    }
}
