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

/// Which parts of the [`WorldModel`] the imitator's own attempts refine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Refines {
    /// How the ball responds to each primitive: its own pushes are its own body's.
    pub ball_response: bool,
    /// How good each state is: how its own attempts through it ended.
    pub state_value: bool,
    /// Where pushes toward the goal begin: where its own scoring pushes began.
    pub push_region: bool,
}

/// The imitator's own attempts, segmented by its own recogniser, as the world model learns them.
#[derive(Debug, Clone, Copy)]
pub struct Practice<'a> {
    pub attempts: &'a [SegmentedDemonstration],
    /// What every sample of an attempt weighs, beside the demonstrations' weights.
    pub weight: f64,
    pub refines: Refines,
}

impl Practice<'_> {
    /// No practice.
    pub const NONE: Practice<'static> = Practice {
        attempts: &[],
        weight: 1.0,
        refines: Refines { ball_response: false, state_value: false, push_region: false },
    };
}

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
    /// demonstration beyond the end of `weights`; one of weight 0 is left out) in the parts
    /// `config.world_weighting` names (the others weigh every demonstration 1): the ball's
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
        Self::learn_practised(demonstrations, weights, &Practice::NONE, pitch, motion, config)
    }

    /// [`Self::learn_weighted`] with the imitator's own attempts (`practice`) beside the
    /// demonstrations, in the parts of the model `practice.refines` names; the others learn from
    /// the demonstrations alone. No attempts give exactly [`Self::learn_weighted`].
    #[must_use]
    pub fn learn_practised(
        demonstrations: &[SegmentedDemonstration],
        weights: &[f64],
        practice: &Practice<'_>,
        pitch: &Pitch,
        motion: &MotionTable,
        config: &LearningConfig,
    ) -> Self {
        // Physics is the same whoever shows it; only intent is weighed where the config says so.
        let physics: &[f64] = if config.world_weighting.weighs_physics() { weights } else { &[] };
        let intent: &[f64] = if config.world_weighting.weighs_intent() { weights } else { &[] };
        let (with_own, ball_weights, value_weights, region_weights);
        let (mut ball, mut value, mut region) =
            ((demonstrations, physics), (demonstrations, intent), (demonstrations, intent));
        if !practice.attempts.is_empty() {
            with_own = [demonstrations, practice.attempts].concat();
            let with_own_weights = |weights: &[f64]| {
                (0..demonstrations.len())
                    .map(|i| weights.get(i).copied().unwrap_or(1.0))
                    .chain(std::iter::repeat_n(practice.weight, practice.attempts.len()))
                    .collect::<Vec<f64>>()
            };
            (ball_weights, value_weights, region_weights) =
                (with_own_weights(physics), with_own_weights(intent), with_own_weights(intent));
            let refines = practice.refines;
            if refines.ball_response {
                ball = (with_own.as_slice(), ball_weights.as_slice());
            }
            if refines.state_value {
                value = (with_own.as_slice(), value_weights.as_slice());
            }
            if refines.push_region {
                region = (with_own.as_slice(), region_weights.as_slice());
            }
        }
        let (min_mm, min_rad) = MIN_REGION_HALF_WIDTH;
        // Whole turns bring any heading within half a turn of the median, so a window narrower
        // than that could be turned past, back and forth, and never entered.
        let shape = RegionShape {
            heading_tail: config.push_heading_tail,
            ..RegionShape::central((min_mm, min_rad.max(0.5 * motion.mean_turn_rad())))
        };
        let push_region = PushRegion::learn_weighted(region.0, region.1, pitch, config.ball_moved_mm, &shape);
        Self {
            ball_response: BallResponse::learn_weighted(ball.0, ball.1, pitch, config.ball_moved_mm),
            state_value: StateValue::learn_weighted(value.0, value.1, pitch),
            approach: push_region.map(|p| ApproachPlan::new(p, motion)),
        }
    }
}

impl WorldModel {
    /// This model with the parts `parts` names learned from no demonstration: what the
    /// imitator's self-observation alone (its primitives, with no ball and no goal) tells of
    /// them: the ball stays where it lies, every state is worth 0, and there is no push region
    /// to route to. The ablation of what each part brings.
    #[must_use]
    pub fn without(self, parts: Refines) -> Self {
        Self {
            ball_response: if parts.ball_response { BallResponse::default() } else { self.ball_response },
            state_value: if parts.state_value { StateValue::default() } else { self.state_value },
            approach: if parts.push_region { None } else { self.approach },
        }
    }
}

#[cfg(test)]
mod tests {
    use polymimic_perceive::{Label, Segment};
    use polymimic_types::{Pose, Primitive, TrackedFrame};

    use super::*;
    use crate::config::WorldWeighting;
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
            scores: [0.0; 7],
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
    fn own_attempts_refine_only_the_parts_named() {
        let demos = straight_pushes();
        let motion = MotionTable::exact(40.0, 30.0);
        let config = LearningConfig::default();
        let alone = WorldModel::learn(&demos, &Pitch::LARGE, &motion, &config);
        let own = straight_pushes();
        let none = Refines { ball_response: false, state_value: false, push_region: false };
        let practised = |refines| {
            let practice = Practice { attempts: &own, weight: 2.0, refines };
            WorldModel::learn_practised(&demos, &[], &practice, &Pitch::LARGE, &motion, &config)
        };
        // Refining nothing, or practising nothing, is the model of the demonstrations alone.
        assert_eq!(practised(none), alone);
        assert_eq!(WorldModel::learn_practised(&demos, &[], &Practice::NONE, &Pitch::LARGE, &motion, &config), alone);
        let ball = practised(Refines { ball_response: true, ..none });
        let forward = |w: &WorldModel| w.ball_response.sample_count(Primitive::Forward);
        assert_eq!((forward(&alone), forward(&ball)), (1, 2));
        assert_eq!((ball.state_value.len(), &ball.approach), (alone.state_value.len(), &alone.approach));
        let value = practised(Refines { state_value: true, ..none });
        assert_eq!(value.state_value.len(), 2 * alone.state_value.len());
        assert_eq!(value.ball_response, alone.ball_response);
        let region = practised(Refines { push_region: true, ..none });
        assert_eq!(region.approach.expect("a region").push_region.pushes, 20);
    }

    /// A push with the ball `ball_ahead_mm` ahead of a robot facing +x, carrying it 40 mm along
    /// `direction_rad` (0: straight ahead), alone in its demonstration (so it never starts with
    /// the ball still rolling from one before).
    fn push_toward(ball_ahead_mm: f64, direction_rad: f64) -> SegmentedDemonstration {
        let (dy, dx) = direction_rad.sin_cos();
        let frame =
            |ball: (f64, f64)| TrackedFrame { robot: Pose::new(0.0, 0.0, 0.0), ball_x_mm: ball.0, ball_y_mm: ball.1 };
        let push = Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: 0,
            last_frame: 30,
            start: frame((ball_ahead_mm, 0.0)),
            end: frame((ball_ahead_mm + 40.0 * dx, 40.0 * dy)),
            scores: [0.0; 7],
        };
        SegmentedDemonstration {
            reach_mm: None,
            demonstrator: "expert".to_owned(),
            pitch: Pitch::LARGE,
            ending: Ending::Other,
            segments: vec![push],
        }
    }

    #[test]
    fn own_pushes_correct_pushes_that_all_went_wide() {
        // The demonstrators' pushes all went 90° wide, with the ball 52 mm ahead; the
        // imitator's own four went straight, with the ball 50 mm ahead.
        let wide: Vec<_> = (0..8).map(|_| push_toward(52.0, std::f64::consts::FRAC_PI_2)).collect();
        let own: Vec<_> = (0..4).map(|_| push_toward(50.0, 0.0)).collect();
        let motion = MotionTable::exact(40.0, 30.0);
        let config = LearningConfig::default();
        // Where it stands now: the ball 50 mm ahead.
        let state = TrackedFrame { robot: Pose::new(0.0, 0.0, 0.0), ball_x_mm: 50.0, ball_y_mm: 0.0 };
        let moved = |world: &WorldModel| {
            let (x, y) = world.ball_response.predict(&state, Primitive::Forward);
            (x - 50.0, y)
        };
        let practised = |weight: f64| {
            let refines = Refines { ball_response: true, state_value: true, push_region: false };
            let practice = Practice { attempts: &own, weight, refines };
            moved(&WorldModel::learn_practised(&wide, &[], &practice, &Pitch::LARGE, &motion, &config))
        };
        let close = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9;
        // Before practice the ball is predicted to go 40 mm to the side.
        let before = moved(&WorldModel::learn(&wide, &Pitch::LARGE, &motion, &config));
        assert!(close(before, (0.0, 40.0)), "{before:?}");
        // After: the eight nearest are its own four and four of theirs, so the prediction is
        // their weighted mean, 40 mm · (4w, 4) / (4w + 4): half-way at weight 1…
        assert!(close(practised(1.0), (20.0, 20.0)), "{:?}", practised(1.0));
        // …and three quarters of the way to straight ahead at weight 3.
        assert!(close(practised(3.0), (30.0, 10.0)), "{:?}", practised(3.0));
    }

    #[test]
    fn the_world_weighting_reaches_intent_alone_by_default_and_physics_only_under_every() {
        // Two scoring demonstrations of ten pushes each, the second by a member weighing 0.
        let demos = [straight_pushes(), straight_pushes()].concat();
        let motion = MotionTable::exact(40.0, 30.0);
        let learned = |world_weighting| {
            let config = LearningConfig { world_weighting, ..LearningConfig::default() };
            WorldModel::learn_weighted(&demos, &[1.0, 0.0], &Pitch::LARGE, &motion, &config)
        };
        let parts = |w: &WorldModel| {
            let region = w.approach.as_ref().map_or(0, |a| a.push_region.pushes);
            (w.ball_response.sample_count(Primitive::Forward), w.state_value.len(), region)
        };
        // One demonstration's samples: 1 ball sample (the later pushes start with the ball
        // rolling), 11 states, 10 pushes; both give twice as many.
        assert_eq!(parts(&learned(WorldWeighting::Every)), (1, 11, 10));
        assert_eq!(parts(&learned(WorldWeighting::Intent)), (2, 11, 10));
        assert_eq!(parts(&learned(WorldWeighting::Outcome)), (2, 22, 20));
        // Weights of 1 are no weights under any choice.
        for choice in [WorldWeighting::Every, WorldWeighting::Intent, WorldWeighting::Outcome] {
            let config = LearningConfig { world_weighting: choice, ..LearningConfig::default() };
            let ones = WorldModel::learn_weighted(&demos, &[1.0, 1.0], &Pitch::LARGE, &motion, &config);
            assert_eq!(ones, WorldModel::learn(&demos, &Pitch::LARGE, &motion, &config));
        }
    }

    #[test]
    fn a_part_learned_from_no_demonstration_is_what_self_observation_gives() {
        let demos = straight_pushes();
        let motion = MotionTable::exact(40.0, 30.0);
        let world = WorldModel::learn(&demos, &Pitch::LARGE, &motion, &LearningConfig::default());
        let none = Refines { ball_response: false, state_value: false, push_region: false };
        assert_eq!(world.clone().without(none), world);
        let state = TrackedFrame { robot: Pose::new(-150.0, 0.0, 0.0), ball_x_mm: 0.0, ball_y_mm: 0.0 };
        let ball = world.clone().without(Refines { ball_response: true, ..none });
        assert_eq!(ball.ball_response.predict(&state, Primitive::Forward), (0.0, 0.0), "the ball stays");
        assert_eq!((&ball.state_value, &ball.approach), (&world.state_value, &world.approach));
        let value = world.clone().without(Refines { state_value: true, ..none });
        assert!(value.state_value.is_empty() && value.approach.is_some());
        let region = world.clone().without(Refines { push_region: true, ..none });
        assert!(region.approach.is_none() && region.ball_response == world.ball_response);
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
