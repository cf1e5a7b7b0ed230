//! What the imitator learns about the field itself from watching: how the ball responds to
//! each primitive, how good each state is, and where pushes toward the goal begin. All depend
//! only on the demonstrations watched (and their weights), not on a trial's random order, so
//! one serves every trial of an experiment.

use crate::approach::{ApproachPlan, MIN_REGION_HALF_WIDTH};
use crate::ball_response::BallResponse;
use crate::config::LearningConfig;
use crate::prediction::MotionTable;
use crate::push_region::{PushRegion, RegionShape};
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
        let (min_mm, min_rad) = MIN_REGION_HALF_WIDTH;
        // Whole turns bring any heading within half a turn of the median, so a window narrower
        // than that could be turned past, back and forth, and never entered.
        let shape = RegionShape {
            heading_tail: config.push_heading_tail,
            ..RegionShape::central((min_mm, min_rad.max(0.5 * motion.mean_turn_rad())))
        };
        let push_region = PushRegion::learn_weighted(demonstrations, weights, pitch, config.ball_moved_mm, &shape);
        Self {
            ball_response: BallResponse::learn_weighted(demonstrations, weights, pitch, config.ball_moved_mm),
            state_value: StateValue::learn_weighted(demonstrations, weights, pitch),
            approach: push_region.map(|p| ApproachPlan::new(p, motion)),
        }
    }
}

#[cfg(test)]
mod tests {
    use polymimic_perceive::{Label, Segment};
    use polymimic_types::{Pose, Primitive, TrackedFrame};

    use super::*;
    use crate::round::Ending;

    /// Ten scoring pushes, every one from 150 mm behind the ball facing the goal.
    fn straight_pushes() -> Vec<SegmentedDemonstration> {
        let frame = |x: f64, ball: f64| TrackedFrame { robot: Pose::new(x, 0.0, 0.0), ball_x_mm: ball, ball_y_mm: 0.0 };
        let push = Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: 0,
            last_frame: 30,
            start: frame(-150.0, 0.0),
            end: frame(-110.0, 40.0),
            scores: [0.0; 4],
        };
        let demo = SegmentedDemonstration {
            reach_mm: None,
            demonstrator: "expert".to_owned(),
            pitch: Pitch::LARGE,
            ending: Ending::Goal,
            segments: vec![push; 10],
        };
        vec![demo]
    }

    #[test]
    fn the_push_heading_window_is_at_least_half_the_mean_turn_either_side() {
        let demos = straight_pushes();
        let window = |turn_deg: f64| {
            let motion = MotionTable::exact(40.0, turn_deg);
            let world = WorldModel::learn(&demos, &Pitch::LARGE, &motion, &LearningConfig::default());
            world.approach.expect("pushes to route to").push_region.heading_rad
        };
        // Every push faces the goal: the window is the floor, half a 30° turn…
        let half_turn = window(30.0);
        assert!((half_turn.high - 15_f64.to_radians()).abs() < 1e-12 && (half_turn.low + half_turn.high).abs() < 1e-12);
        // …but never narrower than one of the route table's 10° heading bins.
        assert!((window(8.0).high - 10_f64.to_radians()).abs() < 1e-12);
    }
}
