//! How good a state is, learned from how the demonstrations that passed near it ended: a goal
//! counts +1, an own goal −1, anything else 0, discounted by the time still to go. The
//! thesis's LP criteria judge one step (goal, then ball nearer the goal, then robot nearer the
//! ball); a value learned from whole demonstrations can also see that going round the ball
//! leads to a goal later, as the skilled demonstrators showed.

use polymimic_field::FRAME_DT_S;
use polymimic_types::TrackedFrame;

use crate::nearest::NearestIndex;
use crate::round::{Ending, SegmentedDemonstration};
use crate::state::Pitch;
use crate::weighting::weighted;

/// What an outcome one second further ahead is worth, relative to one now.
const DISCOUNT_PER_S: f64 = 0.95;
/// States averaged by one estimate.
const NEIGHBOURS: usize = 8;
/// A heading difference of one radian weighs as much as this distance, mm.
const MM_PER_RADIAN: f64 = 100.0;

/// A state as a point: robot position, heading (as a scaled unit vector) and ball position.
fn features(state: &TrackedFrame) -> [f64; 6] {
    let robot = &state.robot;
    [
        robot.x_mm(),
        robot.y_mm(),
        MM_PER_RADIAN * robot.theta_rad().cos(),
        MM_PER_RADIAN * robot.theta_rad().sin(),
        state.ball_x_mm,
        state.ball_y_mm,
    ]
}

/// States seen in demonstrations, each with its discounted outcome and its weight.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StateValue {
    samples: Vec<([f64; 6], f64, f64)>,
    /// The samples' points, to find the nearest.
    points: NearestIndex<6>,
}

impl StateValue {
    /// Every segment boundary of the demonstrations played on `pitch`.
    #[must_use]
    pub fn learn(demonstrations: &[SegmentedDemonstration], pitch: &Pitch) -> Self {
        Self::learn_weighted(demonstrations, &[], pitch)
    }

    /// [`Self::learn`], every state of demonstration i weighing `weights[i]` (see
    /// [`crate::WorldModel::learn_weighted`]).
    #[must_use]
    pub fn learn_weighted(demonstrations: &[SegmentedDemonstration], weights: &[f64], pitch: &Pitch) -> Self {
        let mut samples = Vec::new();
        for (demo, weight) in weighted(demonstrations, weights).filter(|(d, _)| d.pitch == *pitch) {
            let outcome = match demo.ending {
                Ending::Goal => 1.0,
                Ending::OwnGoal => -1.0,
                Ending::Other => 0.0,
            };
            let Some(last) = demo.segments.last() else { continue };
            let end_frame = last.last_frame as f64;
            let states = demo.segments.iter().map(|s| (&s.start, s.first_frame)).chain([(&last.end, last.last_frame)]);
            for (state, frame) in states {
                let point = features(state);
                if point.iter().all(|v| v.is_finite()) {
                    let to_go_s = (end_frame - frame as f64) * FRAME_DT_S;
                    samples.push((point, outcome * DISCOUNT_PER_S.powf(to_go_s), weight));
                }
            }
        }
        let points = NearestIndex::new(samples.iter().map(|(point, ..)| *point));
        Self { samples, points }
    }

    #[must_use]
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// The mean value of the demonstrated states nearest `state`, weighted by their weights:
    /// Σ w·v / Σ w (0 with none), summed nearest first.
    #[must_use]
    pub fn estimate(&self, state: &TrackedFrame) -> f64 {
        let nearest = self.points.nearest(&features(state), NEIGHBOURS);
        let total: f64 = nearest.iter().map(|&(_, i)| self.samples[i].2).sum();
        if total <= 0.0 {
            return 0.0;
        }
        // With every weight 1 this is the plain sum over the count, bit for bit.
        nearest.iter().map(|&(_, i)| self.samples[i].1 * self.samples[i].2).sum::<f64>() / total
    }
}

#[cfg(test)]
mod tests {
    use polymimic_perceive::{Label, Segment};
    use polymimic_types::{Pose, Primitive};

    use super::*;
    use crate::nearest::brute_force_nearest;

    /// One forward segment of 30 frames (1 s) from x to x + 50 with the ball at 0, ending as told.
    fn demo(x_mm: f64, ending: Ending, pitch: Pitch) -> SegmentedDemonstration {
        let frame = |x: f64| TrackedFrame { robot: Pose::new(x, 0.0, 0.0), ball_x_mm: 0.0, ball_y_mm: 0.0 };
        let segment = Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: 0,
            last_frame: 30,
            start: frame(x_mm),
            end: frame(x_mm + 50.0),
            scores: [0.0; 7],
        };
        SegmentedDemonstration { demonstrator: "d".to_owned(), pitch, reach_mm: None, ending, segments: vec![segment] }
    }

    #[test]
    fn a_state_is_worth_the_discounted_outcome_of_the_demonstrations_near_it() {
        let demos = [demo(-300.0, Ending::Goal, Pitch::LARGE), demo(300.0, Ending::OwnGoal, Pitch::LARGE)];
        let value = StateValue::learn(&demos, &Pitch::LARGE);
        assert_eq!(value.len(), 4, "each segment's start and the last end");
        let at =
            |x: f64| value.estimate(&TrackedFrame { robot: Pose::new(x, 0.0, 0.0), ball_x_mm: 0.0, ball_y_mm: 0.0 });
        // Fewer than eight states: all four are averaged, a goal 1 s ahead and at the end,
        // an own goal likewise.
        let expected = (0.95 + 1.0 - 0.95 - 1.0) / 4.0;
        assert!((at(-300.0) - expected).abs() < 1e-12);
        assert!(StateValue::learn(&demos, &Pitch::SMALL).is_empty());
        // With eight or more states, the nearest eight: a cluster of goal states wins.
        let many: Vec<SegmentedDemonstration> = (0..4)
            .map(|i| demo(-300.0 + f64::from(i), Ending::Goal, Pitch::LARGE))
            .chain((0..4).map(|i| demo(300.0 + f64::from(i), Ending::OwnGoal, Pitch::LARGE)))
            .collect();
        let value = StateValue::learn(&many, &Pitch::LARGE);
        let near_goals =
            value.estimate(&TrackedFrame { robot: Pose::new(-280.0, 0.0, 0.0), ball_x_mm: 0.0, ball_y_mm: 0.0 });
        assert!((near_goals - (4.0 * 0.95 + 4.0 * 1.0) / 8.0).abs() < 1e-12, "{near_goals}");
        assert_eq!(StateValue::default().estimate(&demos[0].segments[0].start), 0.0);
    }

    fn at(x: f64) -> TrackedFrame {
        TrackedFrame { robot: Pose::new(x, 0.0, 0.0), ball_x_mm: 0.0, ball_y_mm: 0.0 }
    }

    #[test]
    fn a_state_is_worth_the_weighted_mean_of_its_neighbours() {
        let demos = [demo(-300.0, Ending::Goal, Pitch::LARGE), demo(-290.0, Ending::OwnGoal, Pitch::LARGE)];
        // Weight 0: the own goal is left out, the goal alone counts.
        let goal_only = StateValue::learn(&demos[..1], &Pitch::LARGE).estimate(&at(-300.0));
        let weighted = StateValue::learn_weighted(&demos, &[1.0, 0.0], &Pitch::LARGE);
        assert_eq!(weighted.len(), 2);
        assert_eq!(weighted.estimate(&at(-300.0)), goal_only);
        assert!((goal_only - 1.95 / 2.0).abs() < 1e-12);
        // Weights 1 and ¼: (0.95 + 1 − ¼ (0.95 + 1)) / (2 + 2 · ¼) = 0.3 · 1.95.
        let quarter = StateValue::learn_weighted(&demos, &[1.0, 0.25], &Pitch::LARGE).estimate(&at(-300.0));
        assert!((quarter - 0.3 * 1.95).abs() < 1e-12, "{quarter}");
    }

    #[test]
    fn weights_of_one_estimate_bit_for_bit_what_the_plain_mean_did() {
        let demos: Vec<SegmentedDemonstration> = (0..12)
            .map(|i| {
                let ending = [Ending::Goal, Ending::OwnGoal, Ending::Other][i % 3];
                demo(-300.0 + 37.0 * i as f64, ending, Pitch::LARGE)
            })
            .collect();
        let value = StateValue::learn_weighted(&demos, &vec![1.0; demos.len()], &Pitch::LARGE);
        assert_eq!(value, StateValue::learn(&demos, &Pitch::LARGE));
        for k in 0..50 {
            let state = at(-350.0 + 17.3 * f64::from(k));
            let near =
                brute_force_nearest(value.samples.iter().map(|(point, ..)| *point), &features(&state), NEIGHBOURS);
            let plain = near.iter().map(|&(_, i)| value.samples[i].1).sum::<f64>() / near.len() as f64;
            assert_eq!(value.estimate(&state).to_bits(), plain.to_bits(), "state {k}");
        }
    }
}
