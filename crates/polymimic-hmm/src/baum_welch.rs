//! Multi-sequence Baum-Welch (thesis eq 3.9, 3.10 with Rahimi's errata): expected counts are
//! summed over all sequences first, then every row is divided by its own sum once.

use rayon::prelude::*;

use crate::error::HmmError;
use crate::forward_backward::{Lattice, Scratch};
use crate::probabilities::Probabilities;

/// Sequences per parallel work item. Fixed, so sums are added in the same order whatever
/// the number of threads, and results are bit-identical.
pub(crate) const SEQUENCES_PER_CHUNK: usize = 64;

/// Expected counts of one E-step.
pub(crate) struct Counts {
    pub log_likelihood: f64,
    /// Σ over sequences of γ_0(i).
    start: Vec<f64>,
    /// Σ over sequences and t < T−1 of ξ_t(i, j), row-major.
    transitions: Vec<f64>,
    /// Σ over sequences and t with O_t = k of γ_t(i), symbol-major (`[k * n + i]`).
    emissions: Vec<f64>,
}

impl Counts {
    fn zeros(n: usize, m: usize) -> Self {
        Self { log_likelihood: 0.0, start: vec![0.0; n], transitions: vec![0.0; n * n], emissions: vec![0.0; n * m] }
    }

    fn add(&mut self, other: &Self) {
        self.log_likelihood += other.log_likelihood;
        add_into(&mut self.start, &other.start);
        add_into(&mut self.transitions, &other.transitions);
        add_into(&mut self.emissions, &other.emissions);
    }

    /// Adds one sequence's γ and ξ, read from a scratch filled by forward and backward.
    fn accumulate(&mut self, lattice: &Lattice, seq: &[u32], scratch: &Scratch) {
        let n = lattice.probs.n_states;
        for (t, &symbol) in seq.iter().enumerate() {
            let alpha_t = &scratch.alpha[t * n..(t + 1) * n];
            let beta_t = &scratch.beta[t * n..(t + 1) * n];
            let k = symbol as usize;
            let emitted = &mut self.emissions[k * n..(k + 1) * n];
            for i in 0..n {
                let gamma = alpha_t[i] * beta_t[i];
                emitted[i] += gamma;
                if t == 0 {
                    self.start[i] += gamma;
                }
            }
            if t + 1 < seq.len() {
                let w_next = &scratch.weight[(t + 1) * n..(t + 2) * n];
                for (i, &alpha_i) in alpha_t.iter().enumerate() {
                    if alpha_i == 0.0 {
                        continue;
                    }
                    let band = lattice.bands[i].clone();
                    let row = &lattice.probs.transmat[i * n..(i + 1) * n];
                    let xi_row = &mut self.transitions[i * n..(i + 1) * n];
                    for ((xi, &a), &w) in xi_row[band.clone()].iter_mut().zip(&row[band.clone()]).zip(&w_next[band]) {
                        *xi += alpha_i * a * w;
                    }
                }
            }
        }
    }
}

fn add_into(into: &mut [f64], from: &[f64]) {
    into.iter_mut().zip(from).for_each(|(a, b)| *a += b);
}

/// The E-step over all sequences. Fails on the first sequence (in order) that is
/// impossible under the model.
pub(crate) fn expected_counts(probs: &Probabilities, sequences: &[&[u32]]) -> Result<Counts, HmmError> {
    let lattice = Lattice::new(probs);
    let (n, m) = (probs.n_states, probs.n_symbols);
    let chunks: Vec<Result<Counts, HmmError>> = sequences
        .par_chunks(SEQUENCES_PER_CHUNK)
        .enumerate()
        .map(|(chunk_index, chunk)| {
            let mut counts = Counts::zeros(n, m);
            let mut scratch = Scratch::default();
            for (offset, seq) in chunk.iter().enumerate() {
                let log_p = lattice.forward(seq, &mut scratch).map_err(|position| HmmError::ImpossibleSequence {
                    index: chunk_index * SEQUENCES_PER_CHUNK + offset,
                    position,
                })?;
                lattice.backward(seq, &mut scratch);
                counts.accumulate(&lattice, seq, &scratch);
                counts.log_likelihood += log_p;
            }
            Ok(counts)
        })
        .collect();
    let mut total = Counts::zeros(n, m);
    for chunk in chunks {
        total.add(&chunk?);
    }
    Ok(total)
}

/// The M-step: each row of counts divided by its sum. A state that was never visited keeps
/// its old row rather than becoming 0/0.
pub(crate) fn reestimate(probs: &mut Probabilities, counts: &Counts) {
    let (n, m) = (probs.n_states, probs.n_symbols);
    let start_total: f64 = counts.start.iter().sum();
    if start_total > 0.0 {
        for (p, &c) in probs.startprob.iter_mut().zip(&counts.start) {
            *p = c / start_total;
        }
    }
    for i in 0..n {
        let row_counts = &counts.transitions[i * n..(i + 1) * n];
        let denominator: f64 = row_counts.iter().sum();
        if denominator > 0.0 {
            for (p, &c) in probs.transmat[i * n..(i + 1) * n].iter_mut().zip(row_counts) {
                *p = c / denominator;
            }
        }
        let denominator: f64 = (0..m).map(|k| counts.emissions[k * n + i]).sum();
        if denominator > 0.0 {
            for k in 0..m {
                probs.emissionprob[i * m + k] = counts.emissions[k * n + i] / denominator;
            }
        }
    }
}
