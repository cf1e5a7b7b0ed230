//! Scaled forward and backward recursions (thesis eq 3.8, Rabiner §V-A with its errata fixed).
//!
//! α̂_t(j) = [Σ_i α̂_{t−1}(i) a_ij] b_j(O_t) / c_t, where c_t normalises α̂_t to sum to 1, and
//! log P(O|λ) = Σ_t log c_t. The backward variable is scaled with the same c_t, so that
//! γ_t(i) = α̂_t(i) β̂_t(i) and ξ_t(i, j) = α̂_t(i) a_ij b_j(O_{t+1}) β̂_{t+1}(j) / c_{t+1}.

use std::ops::Range;

use crate::probabilities::Probabilities;

/// Read-only views of a model arranged for the recursions.
pub(crate) struct Lattice<'a> {
    pub probs: &'a Probabilities,
    /// `[k * n + j]` is b_j(k).
    pub emissions_by_symbol: Vec<f64>,
    pub bands: Vec<Range<usize>>,
}

impl<'a> Lattice<'a> {
    pub fn new(probs: &'a Probabilities) -> Self {
        Self { probs, emissions_by_symbol: probs.emissions_by_symbol(), bands: probs.transition_bands() }
    }

    fn n(&self) -> usize {
        self.probs.n_states
    }

    fn emissions(&self, symbol: u32) -> &[f64] {
        let n = self.n();
        let k = symbol as usize;
        &self.emissions_by_symbol[k * n..(k + 1) * n]
    }

    /// One forward step: `next = (prevᵀ A) ⊙ b(symbol)`, normalised. Returns c_t, which is 0
    /// when the symbol cannot be emitted by any state reachable now.
    fn step(&self, prev: &[f64], symbol: u32, next: &mut [f64]) -> f64 {
        next.fill(0.0);
        for (i, &alpha_i) in prev.iter().enumerate() {
            if alpha_i == 0.0 {
                continue;
            }
            let band = self.bands[i].clone();
            let row = &self.probs.transmat[i * self.n()..(i + 1) * self.n()];
            for (acc, &a_ij) in next[band.clone()].iter_mut().zip(&row[band]) {
                *acc += alpha_i * a_ij;
            }
        }
        normalise_emitted(next, self.emissions(symbol))
    }

    fn first(&self, symbol: u32, alpha0: &mut [f64]) -> f64 {
        alpha0.copy_from_slice(&self.probs.startprob);
        normalise_emitted(alpha0, self.emissions(symbol))
    }

    /// log P(O|λ) by the scaled forward pass, or `Err(t)` with the first position whose
    /// probability is zero.
    pub fn log_likelihood(&self, seq: &[u32], prev: &mut Vec<f64>, next: &mut Vec<f64>) -> Result<f64, usize> {
        let n = self.n();
        prev.resize(n, 0.0);
        next.resize(n, 0.0);
        let mut log_p = 0.0;
        for (t, &symbol) in seq.iter().enumerate() {
            let c = if t == 0 { self.first(symbol, prev) } else { self.step(prev, symbol, next) };
            if c <= 0.0 || !c.is_finite() {
                return Err(t);
            }
            if t > 0 {
                std::mem::swap(prev, next);
            }
            log_p += c.ln();
        }
        Ok(log_p)
    }

    /// Fills `scratch` with α̂ (T × n) and the scale factors; returns log P(O|λ) or `Err(t)`.
    pub fn forward(&self, seq: &[u32], scratch: &mut Scratch) -> Result<f64, usize> {
        let n = self.n();
        let len = seq.len();
        scratch.resize(len, n);
        let mut log_p = 0.0;
        for (t, &symbol) in seq.iter().enumerate() {
            let c = if t == 0 {
                self.first(symbol, &mut scratch.alpha[..n])
            } else {
                let (done, rest) = scratch.alpha.split_at_mut(t * n);
                self.step(&done[(t - 1) * n..], symbol, &mut rest[..n])
            };
            if c <= 0.0 || !c.is_finite() {
                return Err(t);
            }
            scratch.scale[t] = c;
            log_p += c.ln();
        }
        Ok(log_p)
    }

    /// After [`Self::forward`], fills β̂ and the weights w_t(j) = b_j(O_t) β̂_t(j) / c_t that both
    /// the backward recursion and ξ need.
    pub fn backward(&self, seq: &[u32], scratch: &mut Scratch) {
        let n = self.n();
        let len = seq.len();
        scratch.beta[(len - 1) * n..len * n].fill(1.0);
        for t in (1..len).rev() {
            let b = self.emissions(seq[t]);
            let c = scratch.scale[t];
            let (before, after) = scratch.beta.split_at_mut(t * n);
            let beta_t = &after[..n];
            let w_t = &mut scratch.weight[t * n..(t + 1) * n];
            for j in 0..n {
                w_t[j] = b[j] * beta_t[j] / c;
            }
            let beta_prev = &mut before[(t - 1) * n..];
            for (i, beta_i) in beta_prev.iter_mut().enumerate() {
                let band = self.bands[i].clone();
                let row = &self.probs.transmat[i * n..(i + 1) * n];
                *beta_i = row[band.clone()].iter().zip(&w_t[band]).map(|(a, w)| a * w).sum();
            }
        }
    }
}

/// b ⊙ values, normalised to sum to 1; returns the sum before normalising.
fn normalise_emitted(values: &mut [f64], emissions: &[f64]) -> f64 {
    let mut sum = 0.0;
    for (v, &b) in values.iter_mut().zip(emissions) {
        *v *= b;
        sum += *v;
    }
    if sum > 0.0 {
        values.iter_mut().for_each(|v| *v /= sum);
    }
    sum
}

/// Buffers reused across the sequences one worker processes.
#[derive(Default)]
pub(crate) struct Scratch {
    pub alpha: Vec<f64>,
    pub beta: Vec<f64>,
    pub weight: Vec<f64>,
    pub scale: Vec<f64>,
}

impl Scratch {
    fn resize(&mut self, len: usize, n: usize) {
        self.alpha.resize(len * n, 0.0);
        self.beta.resize(len * n, 0.0);
        self.weight.resize(len * n, 0.0);
        self.scale.resize(len, 0.0);
    }
}
