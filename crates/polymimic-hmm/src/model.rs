//! The discrete HMM: parameters, probabilities and what training left behind.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::baum_welch::{expected_counts, reestimate};
use crate::error::{HmmError, HmmParamsError};
use crate::forward_backward::{Lattice, WithLattice, symbol_table, with_lattice};
use crate::init::segment_emissions;
use crate::params::ValidHmmParams;
use crate::probabilities::Probabilities;
use crate::sample::{Sampled, sample};
use crate::transitions::Transitions;

/// Where training starts from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Init {
    /// Emissions from the temporal split of the training sequences, random transitions that
    /// respect the topology (seeded), and the topology's start distribution.
    Segments,
    /// The probabilities the model already holds.
    Given,
}

/// A discrete hidden Markov model (Rabiner's λ = (A, B, π)).
#[derive(Debug, Clone, PartialEq)]
pub struct DiscreteHmm {
    pub(crate) params: ValidHmmParams,
    pub(crate) probs: Option<Probabilities>,
    pub(crate) history: Vec<f64>,
    pub(crate) converged: bool,
}

impl DiscreteHmm {
    /// An untrained model: [`Self::fit`] gives it probabilities.
    #[must_use]
    pub fn new(params: ValidHmmParams) -> Self {
        Self { params, probs: None, history: Vec::new(), converged: false }
    }

    /// A model with the given probabilities (row-major tables).
    ///
    /// # Errors
    /// When a table has the wrong size, holds a non-probability, has a row that does not
    /// sum to 1, or breaks the topology.
    pub fn from_probabilities(
        params: ValidHmmParams,
        startprob: Vec<f64>,
        transmat: Vec<f64>,
        emissionprob: Vec<f64>,
    ) -> Result<Self, HmmParamsError> {
        let probs =
            Probabilities::new(params.n_states, params.n_symbols, startprob, transmat, emissionprob, params.topology)?;
        Ok(Self { params, probs: Some(probs), history: Vec::new(), converged: false })
    }

    #[must_use]
    pub fn params(&self) -> &ValidHmmParams {
        &self.params
    }

    /// The probability tables.
    ///
    /// # Errors
    /// [`HmmError::NotFitted`] before the model has any.
    pub fn probabilities(&self) -> Result<&Probabilities, HmmError> {
        self.probs.as_ref().ok_or(HmmError::NotFitted)
    }

    /// Log-likelihood of the training data before each re-estimation of the last fit.
    #[must_use]
    pub fn history(&self) -> &[f64] {
        &self.history
    }

    /// Whether the last fit stopped because the gain fell below the tolerance.
    #[must_use]
    pub fn converged(&self) -> bool {
        self.converged
    }

    /// Baum-Welch over all sequences at once. On failure the model is left as it was.
    ///
    /// # Errors
    /// Bad sequences (none, an empty one, a symbol out of range), `Init::Given` on a model
    /// without probabilities, or a sequence impossible under the current model.
    pub fn fit(&mut self, sequences: &[&[u32]], init: Init) -> Result<(), HmmError> {
        check_sequences(sequences, self.params.n_symbols)?;
        let mut probs = match init {
            Init::Given => self.probabilities()?.clone(),
            Init::Segments => self.segment_start(sequences),
        };
        // Bounded: max_iter is a limit, not a promise, and a huge one must not abort on allocation.
        let mut history = Vec::with_capacity(self.params.max_iter.min(1024));
        let mut converged = false;
        for _ in 0..self.params.max_iter {
            let counts = expected_counts(&probs, sequences)?;
            let gain = counts.log_likelihood - history.last().copied().unwrap_or(f64::NEG_INFINITY);
            history.push(counts.log_likelihood);
            reestimate(&mut probs, &counts);
            if history.len() > 1 && gain < self.params.tol {
                converged = true;
                break;
            }
        }
        self.probs = Some(probs);
        self.history = history;
        self.converged = converged;
        Ok(())
    }

    fn segment_start(&self, sequences: &[&[u32]]) -> Probabilities {
        let p = &self.params;
        let mut rng = ChaCha8Rng::seed_from_u64(p.seed);
        Probabilities {
            n_states: p.n_states,
            n_symbols: p.n_symbols,
            startprob: p.topology.initial_startprob(p.n_states),
            transmat: p.topology.random_transitions(p.n_states, &mut rng),
            emissionprob: segment_emissions(sequences, p.n_states, p.n_symbols, p.emission_floor),
        }
    }

    /// A copy whose emission probabilities are floored at `floor` and renormalised, so that
    /// symbols never seen in training lower a score instead of making it impossible.
    ///
    /// # Errors
    /// An unfitted model, or a floor outside [0, 1/n_symbols].
    pub fn with_emission_floor(&self, floor: f64) -> Result<Self, HmmError> {
        let mut probs = self.probabilities()?.clone();
        let max = 1.0 / probs.n_symbols as f64;
        if !(0.0..=max).contains(&floor) {
            return Err(HmmParamsError::EmissionFloorOutOfRange { value: floor, max }.into());
        }
        for row in probs.emissionprob.chunks_exact_mut(probs.n_symbols) {
            for p in row.iter_mut() {
                *p = p.max(floor);
            }
            let total: f64 = row.iter().sum();
            for p in row.iter_mut() {
                *p /= total;
            }
        }
        Ok(Self { probs: Some(probs), ..self.clone() })
    }

    /// log P(O|λ) of one sequence.
    ///
    /// # Errors
    /// An empty sequence, a symbol out of range, an unfitted model, or a sequence of
    /// probability zero.
    pub fn score(&self, seq: &[u32]) -> Result<f64, HmmError> {
        let probs = self.probabilities()?;
        check_sequences(&[seq], self.params.n_symbols)?;
        with_lattice(&probs.startprob, &probs.transmat, Score { probs, sequences: &[seq] })
            .remove(0)
            .map_err(|position| HmmError::ImpossibleSequence { index: 0, position })
    }

    /// log P(O|λ) of every sequence, in parallel; an impossible sequence gives `Err(t)` with
    /// the first position at which its probability is zero.
    ///
    /// # Errors
    /// Bad sequences or an unfitted model.
    pub fn score_many(&self, sequences: &[&[u32]]) -> Result<Vec<Result<f64, usize>>, HmmError> {
        let probs = self.probabilities()?;
        check_sequences(sequences, self.params.n_symbols)?;
        Ok(with_lattice(&probs.startprob, &probs.transmat, Score { probs, sequences }))
    }

    /// The Viterbi state path and its log-probability.
    ///
    /// # Errors
    /// As [`Self::score`].
    pub fn decode(&self, seq: &[u32]) -> Result<(Vec<usize>, f64), HmmError> {
        let probs = self.probabilities()?;
        check_sequences(&[seq], self.params.n_symbols)?;
        crate::viterbi::viterbi(probs, seq).map_err(|position| HmmError::ImpossibleSequence { index: 0, position })
    }

    /// `count` sequences of `length` symbols, and their hidden states.
    ///
    /// # Errors
    /// An unfitted model or a zero length.
    pub fn sample(&self, count: usize, length: usize, seed: u64) -> Result<Sampled, HmmError> {
        let probs = self.probabilities()?;
        if length == 0 {
            return Err(HmmParamsError::ZeroLength(length).into());
        }
        Ok(sample(probs, count, length, seed))
    }
}

/// The log-likelihood of each sequence, in parallel.
struct Score<'a> {
    probs: &'a Probabilities,
    sequences: &'a [&'a [u32]],
}

impl WithLattice for Score<'_> {
    type Output = Vec<Result<f64, usize>>;

    fn run<const W: usize, T: Transitions<W>>(self, lattice: &Lattice<W, T>) -> Self::Output {
        let table = symbol_table::<W>(self.probs);
        self.sequences.par_iter().map(|seq| lattice.log_likelihood(seq.len(), |t| &table[seq[t] as usize])).collect()
    }
}

/// Every input sequence must be non-empty with symbols in `0..n_symbols`.
///
/// # Errors
/// Names the sequence and position at fault.
pub fn check_sequences(sequences: &[&[u32]], n_symbols: usize) -> Result<(), HmmParamsError> {
    if sequences.is_empty() {
        return Err(HmmParamsError::NoSequences);
    }
    for (index, seq) in sequences.iter().enumerate() {
        if seq.is_empty() {
            return Err(HmmParamsError::EmptySequence { index });
        }
        if let Some(position) = seq.iter().position(|&s| s as usize >= n_symbols) {
            return Err(HmmParamsError::SymbolOutOfRange {
                index,
                position,
                symbol: u64::from(seq[position]),
                n_symbols,
            });
        }
    }
    Ok(())
}
