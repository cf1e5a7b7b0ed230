//! What the imitator learns about the field itself from watching: how the ball responds to
//! each primitive, how good each state is, and where pushes toward the goal begin. All depend
//! only on the demonstrations watched (and their weights), not on a trial's random order, so
//! one serves every trial of an experiment.

use crate::approach::{ApproachPlan, MIN_REGION_HALF_WIDTH};
use crate::ball_response::BallResponse;
use crate::config::LearningConfig;
use crate::prediction::MotionTable;
use crate::push_region::PushRegion;
use crate::round::SegmentedDemonstration;
use crate::state::Pitch;
use crate::state_value::StateValue;

/// The improved control mode's knowledge of the field.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WorldModel {
    pub ball_response: BallResponse,
    pub state_value: StateValue,
    /// Routes to where the demonstrators' goalward pushes began (`None` if no demonstration
    /// on the pitch pushed the ball toward the goal and scored).
    pub approach: Option<ApproachPlan>,
}

impl WorldModel {
    /// Learns from the demonstrations played on `pitch` (the imitator's own field), moving
    /// with `motion` (the imitator's primitives), every demonstration counting the same.
    #[must_use]
    pub fn learn(
        demonstrations: &[SegmentedDemonstration],
        pitch: &Pitch,
        motion: &MotionTable,
        config: &LearningConfig,
    ) -> Self {
        Self::learn_weighted(demonstrations, &[], pitch, motion, config)
    }

    /// [`Self::learn`] with every sample of demonstration i weighing `weights[i]` (1 for a
    /// demonstration beyond the end of `weights`; one of weight 0 is left out): the ball's
    /// response and a state's value are weighted means, the push region's ranges weighted
    /// percentiles. Weights of 1 give exactly [`Self::learn`].
    #[must_use]
    pub fn learn_weighted(
        demonstrations: &[SegmentedDemonstration],
        weights: &[f64],
        pitch: &Pitch,
        motion: &MotionTable,
        config: &LearningConfig,
    ) -> Self {
        let push_region =
            PushRegion::learn_weighted(demonstrations, weights, pitch, config.ball_moved_mm, MIN_REGION_HALF_WIDTH);
        Self {
            ball_response: BallResponse::learn_weighted(demonstrations, weights, pitch, config.ball_moved_mm),
            state_value: StateValue::learn_weighted(demonstrations, weights, pitch),
            approach: push_region.map(|p| ApproachPlan::new(p, motion)),
        }
    }
}
