//! Errors of learning.

use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum LearnError {
    #[error("config: {name} = {value} {why}")]
    Config { name: &'static str, value: f64, why: &'static str },
    #[error("ordering names {0:?}, which has no demonstrations")]
    UnknownDemonstrator(String),
    #[error("ordering names {0:?} twice")]
    DuplicateDemonstrator(String),
    #[error("no demonstrations: a trial needs at least one")]
    NoDemonstrations,
    #[error("the ordering is empty: name at least one demonstrator")]
    EmptyOrdering,
    #[error("learning config: {0}")]
    Parse(String),
    #[error("primitive motion statistics are missing or not finite for {0}")]
    MotionStats(&'static str),
}
