//! State posteriors γ_t(i) = P(q_t = i | O, λ) of one sequence, from the same scaled
//! forward-backward pass that training runs (what hmmlearn calls `predict_proba`).

use crate::error::HmmError;
use crate::forward_backward::{Counts, Lattice, Scratch, WithLattice, symbol_table, with_lattice};
use crate::model::{DiscreteHmm, check_sequences};
use crate::probabilities::Probabilities;
use crate::transitions::Transitions;

impl DiscreteHmm {
    /// γ_t(i) for every step t of `seq` (one row per step, one column per state; each row
    /// sums to 1).
    ///
    /// # Errors
    /// As [`DiscreteHmm::score`]: a bad sequence, an unfitted model, or a sequence of
    /// probability zero.
    pub fn posteriors(&self, seq: &[u32]) -> Result<Vec<Vec<f64>>, HmmError> {
        let probs = self.probabilities()?;
        check_sequences(&[seq], self.params().n_symbols)?;
        with_lattice(&probs.startprob, &probs.transmat, Posteriors { probs, seq })
            .map_err(|position| HmmError::ImpossibleSequence { index: 0, position })
    }
}

struct Posteriors<'a> {
    probs: &'a Probabilities,
    seq: &'a [u32],
}

impl WithLattice for Posteriors<'_> {
    type Output = Result<Vec<Vec<f64>>, usize>;

    fn run<const W: usize, T: Transitions<W>>(self, lattice: &Lattice<W, T>) -> Self::Output {
        let table = symbol_table::<W>(self.probs);
        let n_states = self.probs.n_states;
        let mut gammas = vec![Vec::new(); self.seq.len()];
        // The expected counts are computed on the way and dropped: γ is what is kept.
        let mut counts = Counts::zeros(lattice);
        lattice.add_counts(
            self.seq.len(),
            |t| &table[self.seq[t] as usize],
            &mut Scratch::default(),
            &mut counts,
            |t, gamma| gammas[t] = gamma[..n_states].to_vec(),
        )?;
        Ok(gammas)
    }
}

#[cfg(test)]
mod tests {
    use crate::{DiscreteHmm, HmmParams, Topology};

    fn model() -> DiscreteHmm {
        let mut params = HmmParams::new(2, 2);
        params.topology = Topology::Ergodic;
        let valid = params.check().unwrap();
        DiscreteHmm::from_probabilities(valid, vec![0.6, 0.4], vec![0.7, 0.3, 0.4, 0.6], vec![0.9, 0.1, 0.2, 0.8])
            .unwrap()
    }

    /// Brute force: P(q_t = i | O) = Σ over paths through i at t of P(O, path) / P(O).
    fn enumerated(seq: &[u32]) -> Vec<Vec<f64>> {
        let (start, trans, emit) = ([0.6, 0.4], [[0.7, 0.3], [0.4, 0.6]], [[0.9, 0.1], [0.2, 0.8]]);
        let len = seq.len();
        let mut joint = vec![vec![0.0; 2]; len];
        let mut total = 0.0;
        for code in 0..(1usize << len) {
            let path: Vec<usize> = (0..len).map(|t| (code >> t) & 1).collect();
            let mut p = start[path[0]] * emit[path[0]][seq[0] as usize];
            for t in 1..len {
                p *= trans[path[t - 1]][path[t]] * emit[path[t]][seq[t] as usize];
            }
            total += p;
            for t in 0..len {
                joint[t][path[t]] += p;
            }
        }
        joint.iter().map(|row| row.iter().map(|p| p / total).collect()).collect()
    }

    #[test]
    fn posteriors_match_enumeration_of_all_paths() {
        let seq = [0, 1, 1, 0, 1, 0];
        let gammas = model().posteriors(&seq).unwrap();
        for (ours, truth) in gammas.iter().zip(enumerated(&seq)) {
            for (a, b) in ours.iter().zip(truth) {
                assert!((a - b).abs() < 1e-12, "{a} vs {b}");
            }
        }
    }

    #[test]
    fn impossible_sequences_name_their_position() {
        let mut params = HmmParams::new(1, 2);
        params.topology = Topology::Ergodic;
        let model =
            DiscreteHmm::from_probabilities(params.check().unwrap(), vec![1.0], vec![1.0], vec![1.0, 0.0]).unwrap();
        assert!(matches!(model.posteriors(&[0, 1]), Err(crate::HmmError::ImpossibleSequence { position: 1, .. })));
    }
}
