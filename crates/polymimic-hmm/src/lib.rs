//! Discrete hidden Markov models for recognising motion primitives.
//!
//! Scaled forward-backward, multi-sequence Baum-Welch with shared denominators, Viterbi
//! decoding and sampling, over left-right or ergodic topologies. Training is parallel over
//! sequences with a fixed reduction order, so results are bit-identical for any number of
//! threads.
//!
//! ```
//! use polymimic_hmm::{DiscreteHmm, HmmParams, Init};
//!
//! let params = HmmParams::new(2, 3).check()?;
//! let sequences: Vec<&[u32]> = vec![&[0, 0, 1, 2, 2], &[0, 1, 1, 2]];
//! let mut model = DiscreteHmm::new(params);
//! model.fit(&sequences, Init::Segments)?;
//! assert!(model.score(&[0, 1, 2])? < 0.0);
//! # Ok::<(), polymimic_hmm::HmmError>(())
//! ```

mod baum_welch;
mod error;
mod forward_backward;
mod gaussian;
mod init;
mod model;
mod params;
mod persist;
mod posterior;
mod probabilities;
mod sample;
mod topology;
mod transitions;
mod viterbi;

pub use error::{HmmError, HmmParamsError};
pub use forward_backward::MAX_STATES;
pub use gaussian::{GaussianHmm, GaussianHmmParams, Parts};
pub use init::segment_emissions;
pub use model::{DiscreteHmm, Init, check_sequences};
pub use params::{HmmParams, ValidHmmParams};
pub use probabilities::Probabilities;
pub use sample::Sampled;
pub use topology::Topology;

#[cfg(test)]
mod tests;
