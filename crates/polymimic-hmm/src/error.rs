//! Errors of the HMM crate: bad parameters apart from failures at run time.

use thiserror::Error;

/// A parameter, probability table or input sequence that can never be valid.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HmmParamsError {
    #[error("n_states must be at least 1, got {0}")]
    NoStates(usize),
    #[error("n_states must be at most {max}, got {n_states}")]
    TooManyStates { n_states: usize, max: usize },
    #[error("n_symbols must be at least 1, got {0}")]
    NoSymbols(usize),
    #[error("tol must be a number (it may be -inf to run exactly max_iter iterations), got NaN")]
    TolIsNan,
    #[error("emission_floor must be in [0, 1/n_symbols] = [0, {max}], got {value}")]
    EmissionFloorOutOfRange { value: f64, max: f64 },
    #[error("{name} has shape {actual}, expected {expected}")]
    Shape { name: &'static str, actual: String, expected: String },
    #[error("{name}{index} = {value} is not a probability (finite, in [0, 1])")]
    NotAProbability { name: &'static str, index: String, value: f64 },
    #[error("{name}{index} sums to {sum}, not 1")]
    RowSum { name: &'static str, index: String, sum: f64 },
    #[error(
        "transmat[{from}, {to}] = {value} but the left-right topology with links={links} \
         allows only transitions from a state to itself and the next {links} states"
    )]
    OutsideTopology { from: usize, to: usize, links: usize, value: f64 },
    #[error("no sequences: fit needs at least one sequence")]
    NoSequences,
    #[error("sequence {index} is empty")]
    EmptySequence { index: usize },
    #[error(
        "sequence {index} holds symbol {symbol} at position {position}, but the model has only {n_symbols} symbols (0..{n_symbols})"
    )]
    SymbolOutOfRange { index: usize, position: usize, symbol: u64, n_symbols: usize },
    #[error("dim must be at least 1")]
    NoDimensions,
    #[error("min_variance must be a finite number > 0, got {0}")]
    MinVariance(f64),
    #[error("sequence {index} has a non-finite value at frame {position}")]
    NotFinite { index: usize, position: usize },
    #[error("length must be at least 1, got {0}")]
    ZeroLength(usize),
}

/// A failure that depends on the data meeting the model, found while computing.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HmmError {
    #[error(transparent)]
    Params(#[from] HmmParamsError),
    #[error(
        "sequence {index} is impossible under the model: its probability is 0 at position {position} (a symbol no reachable state can emit)"
    )]
    ImpossibleSequence { index: usize, position: usize },
    #[error("the model is not fitted: call fit first, or build it with from_params")]
    NotFitted,
    #[error("saved model: {0}")]
    Corrupt(String),
}
