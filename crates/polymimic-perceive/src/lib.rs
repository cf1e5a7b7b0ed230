//! Seeing and reading (thesis §3.1, §3.2.2): the imitator recognises its own primitives with
//! discrete HMMs over LBG-quantised tracker frames, and cuts demonstrations into segments it
//! can name.

mod error;
mod kick;
mod label;
mod motion;
mod recognizer;
mod representation;
mod segmenter;

pub use error::PerceiveError;
pub use kick::KICK_FRAMES;
pub use label::Label;
pub use motion::{MotionLimits, motion_of, motion_stats, motion_stats_with_sideways, sideways_of};
/// The domain types the recogniser shares with every crate, re-exported for its users.
pub use polymimic_types::{MotionStats, Pose, Primitive, PrimitiveSet, TrackedFrame};
pub use recognizer::{
    Emissions, LabelledSequence, NO_SCORES, PrimitiveHmm, PrimitiveModel, Recognizer, RecognizerConfig, Scores,
    best_two,
};
pub use representation::{Representation, THETA_SCALE};
pub use segmenter::{Segment, SegmenterConfig, segment, segment_many};

#[cfg(test)]
mod tests;
