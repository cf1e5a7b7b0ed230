//! Seeing and reading (thesis §3.1, §3.2.2): the imitator recognises its own primitives with
//! discrete HMMs over LBG-quantised tracker frames, and cuts demonstrations into segments it
//! can name.

mod error;
mod motion;
mod pose;
mod primitive;
mod recognizer;
mod representation;
mod segmenter;

pub use error::PerceiveError;
pub use motion::{MotionLimits, MotionStats, motion_of, motion_stats};
pub use pose::{Pose, TrackedFrame, wrap_angle_rad};
pub use primitive::{Label, Primitive};
pub use recognizer::{
    Emissions, LabelledSequence, PrimitiveHmm, PrimitiveModel, Recognizer, RecognizerConfig, best_two,
};
pub use representation::{Representation, THETA_SCALE};
pub use segmenter::{Segment, SegmenterConfig, segment, segment_many};

#[cfg(test)]
mod tests;
