//! Errors of learning: bad parameters apart from failures at run time, and what can stop an
//! experiment run end to end (the laboratory's, and the search for the Average demonstrator).

use polymimic_field::FieldError;
use polymimic_perceive::PerceiveError;
use thiserror::Error;

/// A config, ordering, demonstration set or motion table that can never be valid.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LearnParamsError {
    #[error("config: {name} = {value} {why}")]
    Config { name: &'static str, value: f64, why: &'static str },
    #[error("ordering names {0:?}, which has no demonstrations")]
    UnknownDemonstrator(String),
    #[error("ordering names {0:?} twice")]
    DuplicateDemonstrator(String),
    #[error(
        "demonstration {index} is {demonstrator:?}'s, whom the ordering leaves out: name every demonstrator whose demonstrations are given"
    )]
    OutsideOrdering { index: usize, demonstrator: String },
    #[error(
        "demonstration {index} is {demonstrator:?}'s, who has no model in the trial: its weight is that model's LP"
    )]
    NoModelFor { index: usize, demonstrator: String },
    #[error("no demonstrations: a trial needs at least one")]
    NoDemonstrations,
    #[error("the ordering is empty: name at least one demonstrator")]
    EmptyOrdering,
    #[error("learning config: {0}")]
    Parse(String),
    #[error("primitive motion statistics are missing or not finite for {0}")]
    MotionStats(&'static str),
}

/// A failure found while running: a parameter error, or a saved model that does not load.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LearnError {
    #[error(transparent)]
    Params(#[from] LearnParamsError),
    /// A saved forward model of another format or version, or of the wrong shape.
    #[error("{0}")]
    Corrupt(String),
}

impl LearnError {
    /// The same error, a corrupt file's message prefixed with what was being read.
    #[must_use]
    pub fn context(self, what: &str) -> Self {
        match self {
            Self::Corrupt(why) => Self::Corrupt(format!("{what}: {why}")),
            params @ Self::Params(_) => params,
        }
    }
}

/// What can stop an experiment.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LaboratoryError {
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error(transparent)]
    Perceive(#[from] PerceiveError),
    #[error(transparent)]
    Learn(#[from] LearnError),
    #[error(
        "no imitator of {tried} trials, with tracking held in enough attempts, scored net goals (goals less own goals) between the Poor's {poor} and the Expert's {expert}"
    )]
    NoAverage { tried: usize, poor: i64, expert: i64 },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameter_errors_read_the_same_through_the_run_time_error() {
        let e = LearnError::from(LearnParamsError::UnknownDemonstrator("poor".to_owned()));
        assert_eq!(e.to_string(), "ordering names \"poor\", which has no demonstrations");
        assert_eq!(e.clone().context("imitator model"), e);
    }

    #[test]
    fn context_names_what_a_corrupt_file_was() {
        let e = LearnError::Corrupt("not a saved polymimic file".to_owned()).context("imitator model");
        assert_eq!(e.to_string(), "imitator model: not a saved polymimic file");
    }
}
