//! Errors of the vector quantiser: bad parameters or data apart from failures at run time.

use thiserror::Error;

/// Parameters or data that can never be valid.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum VqParamsError {
    #[error("size must be at least 1, got {0}")]
    NoCodewords(usize),
    #[error("points must have at least one dimension")]
    NoDimensions,
    #[error("no points: a codebook needs at least one point")]
    NoPoints,
    #[error("the data hold {len} numbers, which is not a whole number of {dim}-dimensional points")]
    RaggedPoints { len: usize, dim: usize },
    #[error("point {index} has a non-finite coordinate ({value}) in dimension {dimension}")]
    NotFinite { index: usize, dimension: usize, value: f64 },
    #[error("tol must be a finite number ≥ 0, got {0}")]
    BadTolerance(f64),
    #[error("split_epsilon must be in (0, 1), got {0}")]
    BadEpsilon(f64),
    #[error("points have {actual} dimensions but the codebook has {expected}")]
    DimensionMismatch { actual: usize, expected: usize },
    #[error("cannot grow {size} codewords from {n_points} points: at least as many points as codewords are needed")]
    TooFewPoints { size: usize, n_points: usize },
}

/// Failures that depend on stored state.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum VqError {
    #[error(transparent)]
    Params(#[from] VqParamsError),
    #[error("saved codebook: {0}")]
    Corrupt(String),
}
