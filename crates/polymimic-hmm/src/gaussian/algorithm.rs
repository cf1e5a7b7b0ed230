//! Training and scoring: Baum-Welch over diagonal Gaussians, on the discrete model's scaled
//! forward-backward with per-frame log densities shifted by their maximum.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::baum_welch::SEQUENCES_PER_CHUNK;
use crate::error::HmmError;
use crate::forward_backward::{Counts, Lattice, Scratch, WithLattice, with_lattice};
use crate::transitions::{Transitions, add_rows};

use super::GaussianHmm;

const LN_2PI: f64 = 1.837_877_066_409_345_5;

/// Expected counts of one E-step: log-likelihood, Σ γ_0, Σ ξ (row-major), and moment sums.
type ExpectedCounts = ((f64, Vec<f64>, Vec<f64>), MomentSums);

/// Sums of γ-weighted observations per state.
struct MomentSums {
    weight: Vec<f64>,
    first: Vec<f64>,
    second: Vec<f64>,
}

impl MomentSums {
    fn zeros(n: usize, dim: usize) -> Self {
        Self { weight: vec![0.0; n], first: vec![0.0; n * dim], second: vec![0.0; n * dim] }
    }

    fn add(&mut self, other: &Self) {
        for (a, b) in
            [(&mut self.weight, &other.weight), (&mut self.first, &other.first), (&mut self.second, &other.second)]
        {
            a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
        }
    }
}

impl GaussianHmm {
    /// Baum-Welch from the temporal split of every sequence into `n_states` pieces (each
    /// state starts with the mean and variance of its pieces) and random transitions that
    /// respect the topology. On failure the model is left as it was.
    ///
    /// # Errors
    /// Bad sequences (none, empty, ragged, not finite).
    pub fn fit(&mut self, sequences: &[&[f64]]) -> Result<(), HmmError> {
        self.check_sequences(sequences)?;
        let mut model = self.clone();
        model.initialise(sequences);
        model.history.clear();
        model.converged = false;
        for _ in 0..model.params.max_iter {
            let (counts, moments) = model.expected_counts(sequences)?;
            let gain = counts.0 - model.history.last().copied().unwrap_or(f64::NEG_INFINITY);
            model.history.push(counts.0);
            model.reestimate(&counts, &moments);
            if model.history.len() > 1 && gain < model.params.tol {
                model.converged = true;
                break;
            }
        }
        *self = model;
        Ok(())
    }

    fn initialise(&mut self, sequences: &[&[f64]]) {
        let (n, d) = (self.params.n_states, self.params.dim);
        let mut moments = MomentSums::zeros(n, d);
        let mut all = MomentSums::zeros(1, d);
        for seq in sequences {
            let len = seq.len() / d;
            let piece = len.div_ceil(n);
            for (t, frame) in seq.chunks_exact(d).enumerate() {
                for (sums, state) in [(&mut moments, t / piece), (&mut all, 0)] {
                    sums.weight[state] += 1.0;
                    for (k, &x) in frame.iter().enumerate() {
                        sums.first[state * d + k] += x;
                        sums.second[state * d + k] += x * x;
                    }
                }
            }
        }
        for state in 0..n {
            let source = if moments.weight[state] > 0.0 { (&moments, state) } else { (&all, 0) };
            self.set_moments(state, source.0, source.1);
        }
        let mut rng = ChaCha8Rng::seed_from_u64(self.params.seed);
        self.startprob = self.params.topology.initial_startprob(n);
        self.transmat = self.params.topology.random_transitions(n, &mut rng);
        self.fitted = true;
    }

    /// Mean and (floored) variance of `state` from `sums` row `row`.
    fn set_moments(&mut self, state: usize, sums: &MomentSums, row: usize) {
        let d = self.params.dim;
        if self.means.len() != self.params.n_states * d {
            self.means = vec![0.0; self.params.n_states * d];
            self.variances = vec![1.0; self.params.n_states * d];
        }
        let w = sums.weight[row];
        for k in 0..d {
            let mean = sums.first[row * d + k] / w;
            let variance = (sums.second[row * d + k] / w - mean * mean).max(self.params.min_variance);
            self.means[state * d + k] = mean;
            self.variances[state * d + k] = variance;
        }
    }

    fn expected_counts(&self, sequences: &[&[f64]]) -> Result<ExpectedCounts, HmmError> {
        with_lattice(&self.startprob, &self.transmat, EStep { model: self, sequences })
    }

    fn reestimate(&mut self, counts: &(f64, Vec<f64>, Vec<f64>), moments: &MomentSums) {
        let n = self.params.n_states;
        let (_, start, transitions) = counts;
        normalise_into(&mut self.startprob, start);
        for i in 0..n {
            normalise_into(&mut self.transmat[i * n..(i + 1) * n], &transitions[i * n..(i + 1) * n]);
        }
        for state in 0..n {
            if moments.weight[state] > 0.0 {
                self.set_moments(state, moments, state);
            }
        }
    }

    /// Log densities of every state for one frame, and their maximum.
    fn log_densities(&self, frame: &[f64], out: &mut [f64]) -> f64 {
        let d = self.params.dim;
        let mut best = f64::NEG_INFINITY;
        for (state, value) in out.iter_mut().enumerate().take(self.params.n_states) {
            let (means, variances) =
                (&self.means[state * d..(state + 1) * d], &self.variances[state * d..(state + 1) * d]);
            let mut log_b = 0.0;
            for ((&x, &mean), &variance) in frame.iter().zip(means).zip(variances) {
                let z = x - mean;
                log_b -= 0.5 * (LN_2PI + variance.ln() + z * z / variance);
            }
            *value = log_b;
            best = best.max(log_b);
        }
        best
    }

    /// Emission table of one sequence (densities over their per-frame maximum) and Σ_t m_t.
    fn emission_table<const W: usize>(&self, seq: &[f64], table: &mut Vec<[f64; W]>) -> f64 {
        let d = self.params.dim;
        table.clear();
        let mut shift = 0.0;
        let mut log_b = [0.0; W];
        for frame in seq.chunks_exact(d) {
            let best = self.log_densities(frame, &mut log_b);
            shift += best;
            let mut row = [0.0; W];
            for (b, &l) in row.iter_mut().zip(&log_b).take(self.params.n_states) {
                *b = (l - best).exp();
            }
            table.push(row);
        }
        shift
    }
}

fn normalise_into(into: &mut [f64], counts: &[f64]) {
    let total: f64 = counts.iter().sum();
    if total > 0.0 {
        for (p, &c) in into.iter_mut().zip(counts) {
            *p = c / total;
        }
    }
}

pub(super) struct Score<'a> {
    pub(super) model: &'a GaussianHmm,
    pub(super) sequences: &'a [&'a [f64]],
}

impl WithLattice for Score<'_> {
    type Output = Vec<f64>;

    fn run<const W: usize, T: Transitions<W>>(self, lattice: &Lattice<W, T>) -> Vec<f64> {
        self.sequences
            .par_iter()
            .map_init(Vec::new, |table, seq| {
                let shift = self.model.emission_table::<W>(seq, table);
                // Densities are positive everywhere, so no frame can be impossible.
                lattice.log_likelihood(table.len(), |t| &table[t]).map_or(f64::NEG_INFINITY, |log_p| log_p + shift)
            })
            .collect()
    }
}

struct EStep<'a> {
    model: &'a GaussianHmm,
    sequences: &'a [&'a [f64]],
}

impl WithLattice for EStep<'_> {
    type Output = Result<ExpectedCounts, HmmError>;

    fn run<const W: usize, T: Transitions<W>>(self, lattice: &Lattice<W, T>) -> Self::Output {
        let (n, d) = (self.model.params.n_states, self.model.params.dim);
        let chunks: Vec<Result<(Counts<W, T>, MomentSums), HmmError>> = self
            .sequences
            .par_chunks(SEQUENCES_PER_CHUNK)
            .enumerate()
            .map(|(chunk_index, chunk)| {
                let mut counts = Counts::zeros(lattice);
                let mut moments = MomentSums::zeros(n, d);
                let (mut scratch, mut table) = (Scratch::default(), Vec::new());
                for (offset, seq) in chunk.iter().enumerate() {
                    let shift = self.model.emission_table::<W>(seq, &mut table);
                    let on_gamma = |t: usize, gamma: &[f64; W]| {
                        let frame = &seq[t * d..(t + 1) * d];
                        for (state, &g) in gamma.iter().enumerate().take(n) {
                            moments.weight[state] += g;
                            for (k, &x) in frame.iter().enumerate() {
                                moments.first[state * d + k] += g * x;
                                moments.second[state * d + k] += g * x * x;
                            }
                        }
                    };
                    // Only if every reachable state's density underflowed next to an unreachable
                    // one's can a frame be impossible.
                    lattice.add_counts(table.len(), |t| &table[t], &mut scratch, &mut counts, on_gamma).map_err(
                        |position| HmmError::ImpossibleSequence {
                            index: chunk_index * SEQUENCES_PER_CHUNK + offset,
                            position,
                        },
                    )?;
                    counts.log_likelihood += shift;
                }
                Ok((counts, moments))
            })
            .collect();
        let mut total = Counts::zeros(lattice);
        let mut moments = MomentSums::zeros(n, d);
        for chunk in chunks {
            let (counts, chunk_moments) = chunk?;
            total.add(&counts);
            moments.add(&chunk_moments);
        }
        let mut start = [0.0; W];
        add_rows(std::slice::from_mut(&mut start), std::slice::from_ref(&total.start));
        let transitions = lattice.transitions.expected_transitions(&total.transitions, n);
        Ok(((total.log_likelihood, start[..n].to_vec(), transitions), moments))
    }
}

#[cfg(test)]
mod tests {
    use super::super::GaussianHmmParams;
    use super::*;
    use crate::topology::Topology;
    use rand::RngExt;

    fn density(x: &[f64], mean: &[f64], variance: &[f64]) -> f64 {
        x.iter()
            .zip(mean)
            .zip(variance)
            .map(|((x, m), v)| (-(x - m) * (x - m) / (2.0 * v)).exp() / (2.0 * std::f64::consts::PI * v).sqrt())
            .product()
    }

    fn model() -> GaussianHmm {
        let mut params = GaussianHmmParams::new(3, 2);
        params.topology = Topology::Ergodic;
        params.tol = f64::NEG_INFINITY;
        GaussianHmm::from_parts(
            params,
            vec![0.5, 0.3, 0.2],
            vec![0.6, 0.3, 0.1, 0.2, 0.5, 0.3, 0.25, 0.25, 0.5],
            vec![0.0, 0.0, 2.0, 1.0, -1.0, 3.0],
            vec![1.0, 0.5, 0.8, 1.2, 2.0, 0.7],
        )
        .unwrap()
    }

    /// Joint probability densities of every state path.
    fn all_paths(m: &GaussianHmm, seq: &[f64]) -> Vec<(Vec<usize>, f64)> {
        let (start, trans, means, vars) = m.parts().unwrap();
        let (n, d, len) = (3_usize, 2, seq.len() / 2);
        (0..n.pow(len as u32))
            .map(|code| {
                let path: Vec<usize> = (0..len).map(|t| (code / n.pow(t as u32)) % n).collect();
                let b = |t: usize, s: usize| {
                    density(&seq[t * d..(t + 1) * d], &means[s * d..(s + 1) * d], &vars[s * d..(s + 1) * d])
                };
                let mut p = start[path[0]] * b(0, path[0]);
                for t in 1..len {
                    p *= trans[path[t - 1] * n + path[t]] * b(t, path[t]);
                }
                (path, p)
            })
            .collect()
    }

    const SEQ: [f64; 10] = [0.1, -0.2, 1.8, 1.1, 2.2, 0.7, -0.9, 2.5, 0.3, 0.4];

    #[test]
    fn likelihood_matches_brute_force_enumeration() {
        let m = model();
        let total: f64 = all_paths(&m, &SEQ).iter().map(|(_, p)| p).sum();
        assert!((m.score(&SEQ).unwrap() - total.ln()).abs() < 1e-12);
    }

    #[test]
    fn far_away_frames_do_not_underflow() {
        let m = model();
        let far = [1e3, -1e3, 2e3, 5e2];
        assert!(m.score(&far).unwrap().is_finite());
    }

    #[test]
    fn one_reestimation_matches_brute_force_posteriors() {
        let mut m = model();
        let seqs: Vec<&[f64]> = vec![&SEQ, &SEQ[..6]];
        let (n, d) = (3, 2);
        let (mut weight, mut first, mut second) = (vec![0.0; n], vec![0.0; n * d], vec![0.0; n * d]);
        let mut trans = vec![0.0; n * n];
        for seq in &seqs {
            let paths = all_paths(&m, seq);
            let total: f64 = paths.iter().map(|(_, p)| p).sum();
            for (path, p) in &paths {
                let w = p / total;
                for (t, &s) in path.iter().enumerate() {
                    weight[s] += w;
                    for k in 0..d {
                        first[s * d + k] += w * seq[t * d + k];
                        second[s * d + k] += w * seq[t * d + k] * seq[t * d + k];
                    }
                    if t + 1 < path.len() {
                        trans[s * n + path[t + 1]] += w;
                    }
                }
            }
        }
        let counts = m.expected_counts(&seqs).unwrap();
        m.reestimate(&counts.0, &counts.1);
        let (_, a, means, vars) = m.parts().unwrap();
        for s in 0..n {
            let row: f64 = trans[s * n..(s + 1) * n].iter().sum();
            for j in 0..n {
                assert!((a[s * n + j] - trans[s * n + j] / row).abs() < 1e-12);
            }
            for k in 0..d {
                let mean = first[s * d + k] / weight[s];
                let var = second[s * d + k] / weight[s] - mean * mean;
                assert!((means[s * d + k] - mean).abs() < 1e-12);
                assert!((vars[s * d + k] - var.max(1e-3)).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn training_recovers_well_separated_states_and_never_loses_likelihood() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let data: Vec<Vec<f64>> = (0..200)
            .map(|_| {
                (0..20)
                    .flat_map(|t| {
                        let centre = if t < 10 { -5.0 } else { 5.0 };
                        [centre + rng.random::<f64>() - 0.5]
                    })
                    .collect()
            })
            .collect();
        let refs: Vec<&[f64]> = data.iter().map(Vec::as_slice).collect();
        let mut params = GaussianHmmParams::new(2, 1);
        params.max_iter = 30;
        params.tol = f64::NEG_INFINITY;
        let mut m = GaussianHmm::new(params).unwrap();
        m.fit(&refs).unwrap();
        let (_, _, means, vars) = m.parts().unwrap();
        assert!((means[0] + 5.0).abs() < 0.05 && (means[1] - 5.0).abs() < 0.05, "{means:?}");
        assert!((vars[0] - 1.0 / 12.0).abs() < 0.01, "{vars:?}");
        for pair in m.history().windows(2) {
            assert!(pair[1] >= pair[0] - 1e-9 * (pair[0].abs() + 1.0));
        }
    }
}
