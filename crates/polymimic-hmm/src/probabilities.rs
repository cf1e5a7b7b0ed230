//! The three probability tables of a discrete HMM, validated on construction.

use serde::{Deserialize, Serialize};

use crate::error::HmmParamsError;
use crate::topology::Topology;

/// How far a row may sum from 1 and still count as a distribution.
const ROW_SUM_TOLERANCE: f64 = 1e-6;

/// π, A and B in Rabiner's notation, stored row-major: `transmat[i * n + j]` is a_ij and
/// `emissionprob[i * m + k]` is b_i(k).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Probabilities {
    pub n_states: usize,
    pub n_symbols: usize,
    pub startprob: Vec<f64>,
    pub transmat: Vec<f64>,
    pub emissionprob: Vec<f64>,
}

impl Probabilities {
    /// Checks shapes, that every entry is a probability, that every row sums to 1, and that
    /// the transitions respect the topology.
    ///
    /// # Errors
    /// Names the table and the entry or row at fault.
    pub fn new(
        n_states: usize,
        n_symbols: usize,
        startprob: Vec<f64>,
        transmat: Vec<f64>,
        emissionprob: Vec<f64>,
        topology: Topology,
    ) -> Result<Self, HmmParamsError> {
        check_len("startprob", startprob.len(), n_states, format!("({n_states},)"))?;
        check_len("transmat", transmat.len(), n_states * n_states, format!("({n_states}, {n_states})"))?;
        // Saturating: a product that overflows (a damaged file's symbol count) matches no table.
        let emissions = n_states.saturating_mul(n_symbols);
        check_len("emissionprob", emissionprob.len(), emissions, format!("({n_states}, {n_symbols})"))?;
        check_rows("startprob", &startprob, n_states, false)?;
        check_rows("transmat", &transmat, n_states, true)?;
        check_rows("emissionprob", &emissionprob, n_symbols, true)?;
        if let Topology::LeftRight { links } = topology {
            for from in 0..n_states {
                for to in 0..n_states {
                    let value = transmat[from * n_states + to];
                    if value != 0.0 && !topology.allows(from, to) {
                        return Err(HmmParamsError::OutsideTopology { from, to, links, value });
                    }
                }
            }
        }
        Ok(Self { n_states, n_symbols, startprob, transmat, emissionprob })
    }

    /// a_ij.
    #[inline]
    #[must_use]
    pub fn a(&self, i: usize, j: usize) -> f64 {
        self.transmat[i * self.n_states + j]
    }

    /// b_i(k).
    #[inline]
    #[must_use]
    pub fn b(&self, i: usize, k: usize) -> f64 {
        self.emissionprob[i * self.n_symbols + k]
    }

    /// For each state, the range of destination states with a non-zero transition. A zero
    /// stays zero under re-estimation, so Viterbi may skip everything outside it.
    #[must_use]
    pub fn transition_bands(&self) -> Vec<std::ops::Range<usize>> {
        let n = self.n_states;
        (0..n)
            .map(|i| {
                let row = &self.transmat[i * n..(i + 1) * n];
                let first = row.iter().position(|&p| p != 0.0);
                let last = row.iter().rposition(|&p| p != 0.0);
                match (first, last) {
                    (Some(first), Some(last)) => first..last + 1,
                    _ => 0..0,
                }
            })
            .collect()
    }
}

fn check_len(name: &'static str, actual: usize, expected: usize, shape: String) -> Result<(), HmmParamsError> {
    if actual == expected {
        Ok(())
    } else {
        Err(HmmParamsError::Shape { name, actual: format!("{actual} entries"), expected: shape })
    }
}

fn check_rows(name: &'static str, values: &[f64], row_len: usize, indexed_rows: bool) -> Result<(), HmmParamsError> {
    for (r, row) in values.chunks_exact(row_len).enumerate() {
        for (c, &value) in row.iter().enumerate() {
            if !(value.is_finite() && (0.0..=1.0).contains(&value)) {
                let index = if indexed_rows { format!("[{r}, {c}]") } else { format!("[{c}]") };
                return Err(HmmParamsError::NotAProbability { name, index, value });
            }
        }
        let sum: f64 = row.iter().sum();
        if (sum - 1.0).abs() > ROW_SUM_TOLERANCE {
            let index = if indexed_rows { format!(" row {r}") } else { String::new() };
            return Err(HmmParamsError::RowSum { name, index, sum });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_state(transmat: Vec<f64>, topology: Topology) -> Result<Probabilities, HmmParamsError> {
        Probabilities::new(2, 2, vec![1.0, 0.0], transmat, vec![0.5, 0.5, 0.1, 0.9], topology)
    }

    #[test]
    fn rejects_rows_that_do_not_sum_to_one() {
        let err = two_state(vec![0.5, 0.6, 0.0, 1.0], Topology::Ergodic).unwrap_err();
        assert!(matches!(err, HmmParamsError::RowSum { name: "transmat", .. }), "{err}");
    }

    #[test]
    fn rejects_negative_and_nan_entries() {
        let err = two_state(vec![1.5, -0.5, 0.0, 1.0], Topology::Ergodic).unwrap_err();
        assert!(matches!(err, HmmParamsError::NotAProbability { .. }));
        let err = two_state(vec![f64::NAN, 1.0, 0.0, 1.0], Topology::Ergodic).unwrap_err();
        assert!(matches!(err, HmmParamsError::NotAProbability { .. }));
    }

    #[test]
    fn rejects_backward_links_in_a_left_right_model() {
        let err = two_state(vec![0.5, 0.5, 0.2, 0.8], Topology::LeftRight { links: 1 }).unwrap_err();
        assert!(matches!(err, HmmParamsError::OutsideTopology { from: 1, to: 0, .. }));
    }

    #[test]
    fn bands_cover_exactly_the_non_zero_links() {
        let p = two_state(vec![0.5, 0.5, 0.0, 1.0], Topology::LeftRight { links: 1 }).unwrap();
        assert_eq!(p.transition_bands(), vec![0..2, 1..2]);
    }
}
