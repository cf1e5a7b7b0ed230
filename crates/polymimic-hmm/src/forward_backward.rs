//! Scaled forward and backward recursions (thesis eq 3.8, Rabiner §V-A with its errata fixed).
//!
//! α̂_t(j) = [Σ_i α̂_{t−1}(i) a_ij] b_j(O_t) / c_t, where c_t normalises α̂_t to sum to 1, and
//! log P(O|λ) = Σ_t log c_t. The backward variable is scaled with the same c_t, so that
//! γ_t(i) = α̂_t(i) β̂_t(i) and ξ_t(i, j) = α̂_t(i) a_ij w_{t+1}(j), with
//! w_t(j) = b_j(O_t) β̂_t(j) / c_t and β̂_{t−1} = A w_t.
//!
//! The recursions run on arrays of a width `W` fixed at compile time: every loop over
//! states unrolls and the vectors of a time step stay in registers. A model whose number
//! of states is not one of the compiled widths is padded to the next one with states that
//! no probability reaches, which changes no result.

use crate::probabilities::Probabilities;
use crate::transitions::{Banded, Dense, Transitions, add_rows};

/// The most states a model may have.
pub const MAX_STATES: usize = 256;

/// Run the product of scale factors into the log-likelihood before it can underflow.
const SMALLEST_PRODUCT: f64 = 1e-250;

/// A model's start and transitions padded to `W` states and arranged for the recursions.
/// Emissions come separately, as a table of b_·(O_t) per time step, so the same recursions
/// serve discrete and continuous observations.
pub(crate) struct Lattice<const W: usize, T> {
    start: [f64; W],
    pub transitions: T,
}

/// Work to do with a lattice of whatever width and transition layout suit the model.
pub(crate) trait WithLattice {
    type Output;
    fn run<const W: usize, T: Transitions<W>>(self, lattice: &Lattice<W, T>) -> Self::Output;
}

/// Runs `work` on the model laid out for speed: compiled for its width, and banded when it
/// is left-right with at most two links. `transmat` is row-major `n × n`.
pub(crate) fn with_lattice<V: WithLattice>(startprob: &[f64], transmat: &[f64], work: V) -> V::Output {
    match startprob.len() {
        0..=1 => with_layout::<1, V>(startprob, transmat, work),
        2 => with_layout::<2, V>(startprob, transmat, work),
        3 => with_layout::<3, V>(startprob, transmat, work),
        4 => with_layout::<4, V>(startprob, transmat, work),
        5 => with_layout::<5, V>(startprob, transmat, work),
        6 => with_layout::<6, V>(startprob, transmat, work),
        7..=8 => with_layout::<8, V>(startprob, transmat, work),
        9..=10 => with_layout::<10, V>(startprob, transmat, work),
        11..=12 => with_layout::<12, V>(startprob, transmat, work),
        13..=16 => with_layout::<16, V>(startprob, transmat, work),
        17..=20 => with_layout::<20, V>(startprob, transmat, work),
        21..=32 => with_layout::<32, V>(startprob, transmat, work),
        33..=64 => with_layout::<64, V>(startprob, transmat, work),
        _ => with_layout::<MAX_STATES, V>(startprob, transmat, work),
    }
}

fn with_layout<const W: usize, V: WithLattice>(startprob: &[f64], transmat: &[f64], work: V) -> V::Output {
    let n = startprob.len();
    let mut start = [0.0; W];
    start[..n].copy_from_slice(startprob);
    if let Some(banded) = Banded::<W, 1>::new(transmat, n) {
        work.run(&Lattice { start, transitions: banded })
    } else if let Some(banded) = Banded::<W, 2>::new(transmat, n) {
        work.run(&Lattice { start, transitions: banded })
    } else if let Some(banded) = Banded::<W, 3>::new(transmat, n) {
        work.run(&Lattice { start, transitions: banded })
    } else {
        work.run(&Lattice { start, transitions: Dense::<W>::new(transmat, n) })
    }
}

/// Emission probabilities b_j(k) of a discrete model, padded to `W` states: `[k][j]`.
pub(crate) fn symbol_table<const W: usize>(probs: &Probabilities) -> Vec<[f64; W]> {
    let mut table = vec![[0.0; W]; probs.n_symbols];
    for (k, column) in table.iter_mut().enumerate() {
        for (j, b) in column.iter_mut().enumerate().take(probs.n_states) {
            *b = probs.b(j, k);
        }
    }
    table
}

impl<const W: usize, T: Transitions<W>> Lattice<W, T> {
    /// log P(O|λ) by the scaled forward pass over `len` steps whose emissions are
    /// `emission(t)`, or `Err(t)` with the first position whose probability is zero. `keep`
    /// receives every α̂_t and c_t.
    #[inline(always)]
    fn forward_with<'e>(
        &self,
        len: usize,
        emission: impl Fn(usize) -> &'e [f64; W],
        mut keep: impl FnMut([f64; W], f64),
    ) -> Result<f64, usize> {
        let mut log_p = 0.0;
        let mut product = 1.0;
        let mut alpha = self.start;
        for t in 0..len {
            if t > 0 {
                alpha = self.transitions.forward(&alpha);
            }
            let c = normalise_emitted(&mut alpha, emission(t));
            if !(c > 0.0 && c.is_finite()) {
                return Err(t);
            }
            keep(alpha, c);
            product *= c;
            if product < SMALLEST_PRODUCT {
                log_p += product.ln();
                product = 1.0;
            }
        }
        Ok(log_p + product.ln())
    }

    /// log P(O|λ) of `len` steps with emissions `emission(t)`.
    pub fn log_likelihood<'e>(&self, len: usize, emission: impl Fn(usize) -> &'e [f64; W]) -> Result<f64, usize> {
        self.forward_with(len, emission, |_, _| {})
    }

    /// Adds one sequence's expected start and transition counts to `counts` and hands each
    /// γ_t to `on_gamma(t, γ_t)`; returns its log-likelihood or the first position at which its
    /// probability is zero (then nothing was added).
    pub fn add_counts<'e>(
        &self,
        len: usize,
        emission: impl Fn(usize) -> &'e [f64; W],
        scratch: &mut Scratch<W>,
        counts: &mut Counts<W, T>,
        mut on_gamma: impl FnMut(usize, &[f64; W]),
    ) -> Result<f64, usize> {
        let [result] = self.add_counts_lanes(
            [len],
            |_, t| emission(t),
            std::array::from_mut(scratch),
            std::array::from_mut(counts),
            |_, t, gamma| on_gamma(t, gamma),
        );
        result
    }

    /// [`Self::add_counts`] for `L` sequences at once, each into its own counts. The recursions
    /// of one sequence form a chain of dependent arithmetic; stepping `L` independent chains
    /// side by side lets the processor overlap them. Results are the same as one at a time.
    pub fn add_counts_lanes<'e, const L: usize>(
        &self,
        lens: [usize; L],
        emission: impl Fn(usize, usize) -> &'e [f64; W],
        scratch: &mut [Scratch<W>; L],
        counts: &mut [Counts<W, T>; L],
        mut on_gamma: impl FnMut(usize, usize, &[f64; W]),
    ) -> [Result<f64, usize>; L] {
        let longest = lens.iter().copied().max().unwrap_or(0);
        let mut results = [Ok(0.0); L];
        let mut alpha = [self.start; L];
        let mut product = [1.0; L];
        for (lane, s) in scratch.iter_mut().enumerate() {
            s.alpha.clear();
            s.scale.clear();
            s.alpha.reserve(lens[lane]);
            s.scale.reserve(lens[lane]);
        }
        for t in 0..longest {
            for lane in 0..L {
                let Ok(log_p) = &mut results[lane] else { continue };
                if t >= lens[lane] {
                    continue;
                }
                if t > 0 {
                    alpha[lane] = self.transitions.forward(&alpha[lane]);
                }
                let c = normalise_emitted(&mut alpha[lane], emission(lane, t));
                if !(c > 0.0 && c.is_finite()) {
                    results[lane] = Err(t);
                    continue;
                }
                scratch[lane].alpha.push(alpha[lane]);
                scratch[lane].scale.push(c);
                product[lane] *= c;
                if product[lane] < SMALLEST_PRODUCT {
                    *log_p += product[lane].ln();
                    product[lane] = 1.0;
                }
            }
        }
        let mut beta = [[1.0; W]; L];
        for t in (0..longest).rev() {
            for lane in 0..L {
                if results[lane].is_err() || t >= lens[lane] {
                    continue;
                }
                let alpha_t = &scratch[lane].alpha[t];
                let mut gamma = [0.0; W];
                for i in 0..W {
                    gamma[i] = alpha_t[i] * beta[lane][i];
                }
                on_gamma(lane, t, &gamma);
                if t == 0 {
                    for (start, g) in counts[lane].start.iter_mut().zip(gamma) {
                        *start += g;
                    }
                    continue;
                }
                let b = emission(lane, t);
                let inverse_scale = 1.0 / scratch[lane].scale[t];
                let mut w = [0.0; W];
                for j in 0..W {
                    w[j] = b[j] * beta[lane][j] * inverse_scale;
                }
                // ξ_{t−1}(i, j) / a_ij accumulates as an outer product; a_ij is applied once at the end.
                self.transitions.add_outer(&scratch[lane].alpha[t - 1], &w, &mut counts[lane].transitions);
                beta[lane] = self.transitions.backward(&w);
            }
        }
        for lane in 0..L {
            if let Ok(log_p) = &mut results[lane] {
                *log_p += product[lane].ln();
                counts[lane].log_likelihood += *log_p;
            }
        }
        results
    }
}

/// b ⊙ values, normalised to sum to 1; returns the sum before normalising.
#[inline(always)]
fn normalise_emitted<const W: usize>(values: &mut [f64; W], emissions: &[f64; W]) -> f64 {
    let mut sum = 0.0;
    for j in 0..W {
        values[j] *= emissions[j];
        sum += values[j];
    }
    if sum > 0.0 {
        let inverse = 1.0 / sum;
        for v in values.iter_mut() {
            *v *= inverse;
        }
    }
    sum
}

/// Buffers reused across the sequences one worker processes.
pub(crate) struct Scratch<const W: usize> {
    alpha: Vec<[f64; W]>,
    scale: Vec<f64>,
}

impl<const W: usize> Default for Scratch<W> {
    fn default() -> Self {
        Self { alpha: Vec::new(), scale: Vec::new() }
    }
}

/// Expected start and transition counts over some sequences, in the lattice's layout.
pub(crate) struct Counts<const W: usize, T: Transitions<W>> {
    pub log_likelihood: f64,
    /// Σ γ_0(i).
    pub start: [f64; W],
    /// Σ_t α̂_t(i) w_{t+1}(j) in the transitions' own layout; times a_ij this is Σ_t ξ_t(i, j).
    pub transitions: T::Sums,
}

impl<const W: usize, T: Transitions<W>> Counts<W, T> {
    pub fn zeros(lattice: &Lattice<W, T>) -> Self {
        Self { log_likelihood: 0.0, start: [0.0; W], transitions: lattice.transitions.zero_sums() }
    }

    pub fn add(&mut self, other: &Self) {
        self.log_likelihood += other.log_likelihood;
        add_rows(std::slice::from_mut(&mut self.start), std::slice::from_ref(&other.start));
        T::add_sums(&mut self.transitions, &other.transitions);
    }
}
