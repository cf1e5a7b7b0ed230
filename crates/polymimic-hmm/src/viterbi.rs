//! The most likely state path, in log space so that long sequences do not underflow.

use crate::probabilities::Probabilities;

/// The Viterbi path and its log-probability, or `Err(t)` with the first position at which
/// every path has probability zero. Ties go to the lowest state index.
pub(crate) fn viterbi(probs: &Probabilities, seq: &[u32]) -> Result<(Vec<usize>, f64), usize> {
    let n = probs.n_states;
    let log_a: Vec<f64> = probs.transmat.iter().map(|p| p.ln()).collect();
    let bands = probs.transition_bands();
    let mut delta: Vec<f64> = (0..n).map(|i| probs.startprob[i].ln() + probs.b(i, seq[0] as usize).ln()).collect();
    if delta.iter().all(|d| *d == f64::NEG_INFINITY) {
        return Err(0);
    }
    let mut next = vec![f64::NEG_INFINITY; n];
    let mut back_pointers = vec![0usize; seq.len() * n];
    for (t, &symbol) in seq.iter().enumerate().skip(1) {
        next.fill(f64::NEG_INFINITY);
        let pointers = &mut back_pointers[t * n..(t + 1) * n];
        for (i, &delta_i) in delta.iter().enumerate() {
            if delta_i == f64::NEG_INFINITY {
                continue;
            }
            for j in bands[i].clone() {
                let candidate = delta_i + log_a[i * n + j];
                if candidate > next[j] {
                    next[j] = candidate;
                    pointers[j] = i;
                }
            }
        }
        for (j, value) in next.iter_mut().enumerate() {
            *value += probs.b(j, symbol as usize).ln();
        }
        if next.iter().all(|d| *d == f64::NEG_INFINITY) {
            return Err(t);
        }
        std::mem::swap(&mut delta, &mut next);
    }
    let (mut state, &log_p) =
        delta.iter().enumerate().fold((0, &f64::NEG_INFINITY), |best, (i, d)| if *d > *best.1 { (i, d) } else { best });
    let mut path = vec![0; seq.len()];
    for t in (0..seq.len()).rev() {
        path[t] = state;
        state = back_pointers[t * n + state];
    }
    Ok((path, log_p))
}
