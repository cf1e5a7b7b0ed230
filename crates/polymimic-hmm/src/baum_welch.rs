//! Multi-sequence Baum-Welch (thesis eq 3.9, 3.10 with Rahimi's errata): expected counts are
//! summed over all sequences first, then every row is divided by its own sum once.

use rayon::prelude::*;

use crate::error::HmmError;
use crate::forward_backward::{Counts as LatticeCounts, Lattice, Scratch, WithLattice, symbol_table, with_lattice};
use crate::probabilities::Probabilities;
use crate::transitions::{Transitions, add_rows};

/// Sequences per parallel work item. Fixed, so sums are added in the same order whatever
/// the number of threads, and results are bit-identical.
pub(crate) const SEQUENCES_PER_CHUNK: usize = 256;

/// Sequences stepped side by side within a chunk.
const LANES: usize = 2;

/// Expected counts of one E-step, in the model's own layout.
pub(crate) struct Counts {
    pub log_likelihood: f64,
    /// Σ over sequences of γ_0(i).
    start: Vec<f64>,
    /// Σ over sequences and t < T−1 of ξ_t(i, j), row-major.
    transitions: Vec<f64>,
    /// Σ over sequences and t with O_t = k of γ_t(i), symbol-major (`[k * n + i]`).
    emissions: Vec<f64>,
}

/// The E-step over all sequences. Fails on the first sequence (in order) that is
/// impossible under the model.
pub(crate) fn expected_counts(probs: &Probabilities, sequences: &[&[u32]]) -> Result<Counts, HmmError> {
    with_lattice(&probs.startprob, &probs.transmat, EStep { probs, sequences })
}

/// Per chunk of sequences: start and transition counts, and `emitted[k][i]`.
type ChunkCounts<const W: usize, T> = (LatticeCounts<W, T>, Vec<[f64; W]>);

struct EStep<'a> {
    probs: &'a Probabilities,
    sequences: &'a [&'a [u32]],
}

impl WithLattice for EStep<'_> {
    type Output = Result<Counts, HmmError>;

    fn run<const W: usize, T: Transitions<W>>(self, lattice: &Lattice<W, T>) -> Self::Output {
        let (n, m) = (self.probs.n_states, self.probs.n_symbols);
        let table = symbol_table::<W>(self.probs);
        let chunks: Vec<Result<ChunkCounts<W, T>, HmmError>> = self
            .sequences
            .par_chunks(SEQUENCES_PER_CHUNK)
            .enumerate()
            .map(|(chunk_index, chunk)| {
                // A few sequences at a time, each lane with its own sums; the lanes are added
                // together at the end of the chunk, in a fixed order.
                let mut counts: [_; LANES] = std::array::from_fn(|_| LatticeCounts::zeros(lattice));
                // `emitted[lane][k][i]`: Σ γ_t(i) over the t with O_t = k.
                let mut emitted: [_; LANES] = std::array::from_fn(|_| vec![[0.0; W]; m]);
                let mut scratch: [_; LANES] = std::array::from_fn(|_| Scratch::default());
                for (pair_index, pair) in chunk.chunks(LANES).enumerate() {
                    let seqs: [&[u32]; LANES] = std::array::from_fn(|i| pair.get(i).copied().unwrap_or(&[]));
                    let emission = |lane: usize, t: usize| &table[seqs[lane][t] as usize];
                    let on_gamma = |lane: usize, t: usize, gamma: &[f64; W]| {
                        let row = &mut emitted[lane][seqs[lane][t] as usize];
                        for i in 0..W {
                            row[i] += gamma[i];
                        }
                    };
                    let lens = seqs.map(<[u32]>::len);
                    let results = lattice.add_counts_lanes(lens, emission, &mut scratch, &mut counts, on_gamma);
                    for (lane, result) in results.into_iter().enumerate() {
                        result.map_err(|position| HmmError::ImpossibleSequence {
                            index: chunk_index * SEQUENCES_PER_CHUNK + pair_index * LANES + lane,
                            position,
                        })?;
                    }
                }
                let mut lanes = counts.into_iter().zip(emitted);
                let (mut counts, mut emitted) = lanes.next().unwrap_or_else(|| unreachable!("LANES > 0"));
                for (lane_counts, lane_emitted) in lanes {
                    counts.add(&lane_counts);
                    add_rows(&mut emitted, &lane_emitted);
                }
                Ok((counts, emitted))
            })
            .collect();
        let mut total = LatticeCounts::zeros(lattice);
        let mut emitted = vec![[0.0; W]; m];
        for chunk in chunks {
            let (counts, chunk_emitted) = chunk?;
            total.add(&counts);
            add_rows(&mut emitted, &chunk_emitted);
        }
        Ok(Counts {
            log_likelihood: total.log_likelihood,
            start: total.start[..n].to_vec(),
            // a_ij is applied once, here, so a zero of the topology stays exactly zero.
            transitions: lattice.transitions.expected_transitions(&total.transitions, n),
            emissions: emitted.iter().flat_map(|column| column[..n].iter().copied()).collect(),
        })
    }
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
