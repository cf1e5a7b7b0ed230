//! Drawing sequences from a model.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::probabilities::Probabilities;

/// Sampled sequences of symbols and the hidden states that emitted them.
pub type Sampled = (Vec<Vec<u32>>, Vec<Vec<usize>>);

/// `count` sequences of `length` symbols with their hidden states, reproducible from `seed`.
pub(crate) fn sample(probs: &Probabilities, count: usize, length: usize, seed: u64) -> Sampled {
    let (n, m) = (probs.n_states, probs.n_symbols);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut symbols = Vec::with_capacity(count);
    let mut states = Vec::with_capacity(count);
    for _ in 0..count {
        let mut seq = Vec::with_capacity(length);
        let mut path = Vec::with_capacity(length);
        let mut state = draw(&probs.startprob, &mut rng);
        for t in 0..length {
            if t > 0 {
                state = draw(&probs.transmat[state * n..(state + 1) * n], &mut rng);
            }
            path.push(state);
            seq.push(draw(&probs.emissionprob[state * m..(state + 1) * m], &mut rng) as u32);
        }
        symbols.push(seq);
        states.push(path);
    }
    (symbols, states)
}

/// An index drawn from a discrete distribution; rounding never selects a zero-probability
/// entry, because the last entry with positive probability takes whatever is left.
fn draw(distribution: &[f64], rng: &mut ChaCha8Rng) -> usize {
    let u: f64 = rng.random();
    let mut cumulative = 0.0;
    let mut last_possible = 0;
    for (index, &p) in distribution.iter().enumerate() {
        if p > 0.0 {
            cumulative += p;
            last_possible = index;
            if u < cumulative {
                return index;
            }
        }
    }
    last_possible
}
