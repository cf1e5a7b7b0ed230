//! What the imitator learns about the field itself from watching: how the ball responds to
//! each primitive and how good each state is. Both depend only on the demonstrations watched,
//! not on a trial's random order, so one serves every trial of an experiment.

use serde::{Deserialize, Serialize};

use crate::ball_response::BallResponse;
use crate::config::LearningConfig;
use crate::round::SegmentedDemonstration;
use crate::state::Pitch;
use crate::state_value::StateValue;

/// The improved control mode's knowledge of the field.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct WorldModel {
    pub ball_response: BallResponse,
    pub state_value: StateValue,
}

impl WorldModel {
    /// Learns from the demonstrations played on `pitch` (the imitator's own field).
    #[must_use]
    pub fn learn(demonstrations: &[SegmentedDemonstration], pitch: &Pitch, config: &LearningConfig) -> Self {
        Self {
            ball_response: BallResponse::learn(demonstrations, pitch, config.ball_moved_mm),
            state_value: StateValue::learn(demonstrations, pitch),
        }
    }
}
