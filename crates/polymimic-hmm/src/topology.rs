//! Which transitions a model may have, and random transitions that respect it.

use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// The transition structure of a model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Topology {
    /// Each state links to itself and the next `links` states; the chain starts in state 0.
    /// A left-to-right model suits signals that unfold in time, such as one motion primitive.
    LeftRight { links: usize },
    /// Every state links to every state.
    Ergodic,
}

impl Default for Topology {
    fn default() -> Self {
        Self::LeftRight { links: 2 }
    }
}

impl Topology {
    /// Whether the topology allows a transition from state `from` to state `to`.
    #[must_use]
    pub fn allows(self, from: usize, to: usize) -> bool {
        match self {
            Self::LeftRight { links } => to >= from && to - from <= links,
            Self::Ergodic => true,
        }
    }

    /// Random row-stochastic transitions (row-major `n × n`) with zeros where the topology
    /// forbids a transition.
    #[must_use]
    pub fn random_transitions(self, n_states: usize, rng: &mut ChaCha8Rng) -> Vec<f64> {
        let mut transmat = vec![0.0; n_states * n_states];
        for (from, row) in transmat.chunks_exact_mut(n_states).enumerate() {
            for (to, cell) in row.iter_mut().enumerate() {
                if self.allows(from, to) {
                    // Bounded away from zero so no allowed link starts out dead.
                    *cell = 0.05 + rng.random::<f64>();
                }
            }
            let sum: f64 = row.iter().sum();
            for cell in row.iter_mut() {
                *cell /= sum;
            }
        }
        transmat
    }

    /// The topology a model's probabilities imply: left-right, with as many links as its
    /// longest forward jump, where it starts in state 0 and never moves back; ergodic otherwise.
    /// (`transmat` is row-major `n × n`; `startprob` has `n` entries.)
    #[must_use]
    pub fn implied_by(startprob: &[f64], transmat: &[f64], n_states: usize) -> Self {
        let starts_first = startprob.iter().skip(1).all(|&p| p == 0.0);
        let mut links = 0;
        for (from, row) in transmat.chunks_exact(n_states).enumerate() {
            for (to, &p) in row.iter().enumerate() {
                if p != 0.0 {
                    if to < from {
                        return Self::Ergodic;
                    }
                    links = links.max(to - from);
                }
            }
        }
        if starts_first { Self::LeftRight { links } } else { Self::Ergodic }
    }

    /// The start distribution a fresh model begins with.
    #[must_use]
    pub fn initial_startprob(self, n_states: usize) -> Vec<f64> {
        match self {
            Self::LeftRight { .. } => {
                let mut start = vec![0.0; n_states];
                start[0] = 1.0;
                start
            }
            Self::Ergodic => vec![1.0 / n_states as f64; n_states],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn left_right_rows_keep_only_self_and_next_links() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let a = Topology::LeftRight { links: 2 }.random_transitions(5, &mut rng);
        for i in 0..5 {
            let row = &a[i * 5..(i + 1) * 5];
            assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            for (j, &p) in row.iter().enumerate() {
                assert_eq!(p > 0.0, j >= i && j <= i + 2, "a[{i}][{j}] = {p}");
            }
        }
        assert!((a[24] - 1.0).abs() < 1e-15, "the last state can only stay");
    }

    #[test]
    fn ergodic_rows_are_dense() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let a = Topology::Ergodic.random_transitions(3, &mut rng);
        assert!(a.iter().all(|&p| p > 0.0));
    }

    #[test]
    fn implied_topology_reads_the_band_and_the_start() {
        let band = [0.5, 0.3, 0.2, 0.0, 0.0, 0.6, 0.4, 0.0, 0.0, 0.0, 0.7, 0.3, 0.0, 0.0, 0.0, 1.0];
        assert_eq!(Topology::implied_by(&[1.0, 0.0, 0.0, 0.0], &band, 4), Topology::LeftRight { links: 2 });
        let chain = [0.9, 0.1, 0.0, 0.0, 0.8, 0.2, 0.0, 0.0, 1.0];
        assert_eq!(Topology::implied_by(&[1.0, 0.0, 0.0], &chain, 3), Topology::LeftRight { links: 1 });
        // Starting anywhere but state 0, or any move back, is ergodic.
        assert_eq!(Topology::implied_by(&[0.5, 0.5, 0.0], &chain, 3), Topology::Ergodic);
        let back = [0.9, 0.1, 0.0, 0.1, 0.7, 0.2, 0.0, 0.0, 1.0];
        assert_eq!(Topology::implied_by(&[1.0, 0.0, 0.0], &back, 3), Topology::Ergodic);
        assert_eq!(Topology::implied_by(&[1.0], &[1.0], 1), Topology::LeftRight { links: 0 });
    }
}
