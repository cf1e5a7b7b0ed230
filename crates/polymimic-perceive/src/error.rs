//! Errors of recognition and segmentation.

use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
pub enum PerceiveError {
    #[error("no training sequences of {0}: the recogniser needs some of every moving primitive")]
    MissingPrimitive(&'static str),
    #[error("training sequence {index} is of {primitive}, which is not a primitive of the {set} set")]
    NotInSet { index: usize, primitive: &'static str, set: &'static str },
    #[error("{what}: frame {frame} is not finite (NaN or infinite coordinate)")]
    NotFinite { what: String, frame: usize },
    #[error("{what} has {frames} frames; at least {needed} are needed")]
    TooFewFrames { what: String, frames: usize, needed: usize },
    #[error("parameter {name} = {value} is out of range: {why}")]
    Parameter { name: &'static str, value: f64, why: &'static str },
    #[error("codebook: {0}")]
    Codebook(#[from] polymimic_vq::VqParamsError),
    #[error("HMM: {0}")]
    Hmm(#[from] polymimic_hmm::HmmError),
    #[error("saved recogniser: {0}")]
    Corrupt(String),
}
