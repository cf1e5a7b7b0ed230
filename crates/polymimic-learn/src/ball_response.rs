//! How the ball responds to each primitive, learned from every demonstration the imitator
//! watched: the thesis's future work asks for far more samples behind ball predictions
//! (§5.4) than one behaviour's own spans give. Every segment named by a primitive is one
//! sample: where the ball lay relative to the robot when the segment began, and how far it
//! moved, in the robot's frame. A prediction averages the samples whose ball lay nearest,
//! each weighing what its demonstration weighs.

use polymimic_perceive::Label;
use polymimic_types::{Pose, Primitive, TrackedFrame};

use crate::nearest::NearestIndex;
use crate::round::SegmentedDemonstration;
use crate::state::Pitch;
use crate::weighting::weighted;

/// Samples averaged by one prediction…
const NEIGHBOURS: usize = 8;
/// …taken only from within this distance of where the ball lies now; missing ones count as
/// the ball staying put, so a lone sample cannot speak for a whole region.
const NEIGHBOURHOOD_MM: f64 = 50.0;

/// A point in the robot's frame: ahead (+x) and to the left (+y) of it, mm.
fn to_robot_frame(robot: &Pose, dx_mm: f64, dy_mm: f64) -> [f64; 2] {
    let (sin, cos) = robot.theta_rad().sin_cos();
    [cos * dx_mm + sin * dy_mm, -sin * dx_mm + cos * dy_mm]
}

fn to_field_frame(robot: &Pose, local: [f64; 2]) -> (f64, f64) {
    let (sin, cos) = robot.theta_rad().sin_cos();
    (cos * local[0] - sin * local[1], sin * local[0] + cos * local[1])
}

/// The ball's response to each primitive, as samples.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BallResponse {
    /// Per primitive (in [`Primitive::ALL`] order): the ball's start and its displacement, both
    /// in the robot's frame at the start, mm, and the sample's weight.
    samples: Vec<Vec<[f64; 5]>>,
    /// Per primitive, the samples' ball starts, to find the nearest.
    starts: Vec<NearestIndex<2>>,
}

impl BallResponse {
    /// Samples from every primitive segment of the demonstrations played on `pitch` that
    /// began with the ball at rest (it moved no more than `ball_moved_mm` over the segment before).
    #[must_use]
    pub fn learn(demonstrations: &[SegmentedDemonstration], pitch: &Pitch, ball_moved_mm: f64) -> Self {
        Self::learn_weighted(demonstrations, &[], pitch, ball_moved_mm)
    }

    /// [`Self::learn`], every sample of demonstration i weighing `weights[i]` (see
    /// [`crate::WorldModel::learn_weighted`]).
    #[must_use]
    pub fn learn_weighted(
        demonstrations: &[SegmentedDemonstration],
        weights: &[f64],
        pitch: &Pitch,
        ball_moved_mm: f64,
    ) -> Self {
        let mut samples = vec![Vec::new(); Primitive::ALL.len()];
        for (demo, weight) in weighted(demonstrations, weights).filter(|(d, _)| d.pitch == *pitch) {
            for (k, segment) in demo.segments.iter().enumerate() {
                // A ball still rolling from before would credit the primitive with its roll.
                let rolling = k > 0 && {
                    let before = &demo.segments[k - 1];
                    (before.end.ball_x_mm - before.start.ball_x_mm).hypot(before.end.ball_y_mm - before.start.ball_y_mm)
                        > ball_moved_mm
                };
                let Label::Primitive(primitive) = segment.label else { continue };
                if rolling {
                    continue;
                }
                let (start, end) = (&segment.start, &segment.end);
                let ball = to_robot_frame(
                    &start.robot,
                    start.ball_x_mm - start.robot.x_mm(),
                    start.ball_y_mm - start.robot.y_mm(),
                );
                let moved =
                    to_robot_frame(&start.robot, end.ball_x_mm - start.ball_x_mm, end.ball_y_mm - start.ball_y_mm);
                if ball.iter().chain(&moved).all(|v| v.is_finite()) {
                    samples[primitive as usize].push([ball[0], ball[1], moved[0], moved[1], weight]);
                }
            }
        }
        let starts = samples.iter().map(|s| NearestIndex::new(s.iter().map(|s| [s[0], s[1]]))).collect();
        Self { samples, starts }
    }

    /// Samples behind the predictions for `primitive`.
    #[must_use]
    pub fn sample_count(&self, primitive: Primitive) -> usize {
        self.samples.get(primitive as usize).map_or(0, Vec::len)
    }

    /// Where the ball will be after `primitive` starts from `state`, in field coordinates: the
    /// mean displacement of the samples whose ball lay nearest to where it lies now, counting
    /// the ball as staying put for every one of the [`NEIGHBOURS`] missing nearby. Samples
    /// weigh their weights and each missing one 1: Σ wᵢ·dᵢ / (Σ wᵢ + missing), summed nearest
    /// first.
    #[must_use]
    pub fn predict(&self, state: &TrackedFrame, primitive: Primitive) -> (f64, f64) {
        let robot = &state.robot;
        let here = to_robot_frame(robot, state.ball_x_mm - robot.x_mm(), state.ball_y_mm - robot.y_mm());
        let Some(samples) = self.samples.get(primitive as usize).filter(|s| !s.is_empty()) else {
            return (state.ball_x_mm, state.ball_y_mm);
        };
        let nearest = self.starts[primitive as usize].nearest(&here, NEIGHBOURS);
        let near: Vec<&[f64; 5]> = nearest
            .iter()
            .filter(|(d2, _)| *d2 <= NEIGHBOURHOOD_MM * NEIGHBOURHOOD_MM)
            .map(|&(_, i)| &samples[i])
            .collect();
        // With every weight 1 the denominator is NEIGHBOURS and each share exactly 1/NEIGHBOURS.
        let denominator = near.iter().map(|s| s[4]).sum::<f64>() + (NEIGHBOURS - near.len()) as f64;
        let mut mean = [0.0; 2];
        for sample in near {
            let share = sample[4] / denominator;
            mean[0] += sample[2] * share;
            mean[1] += sample[3] * share;
        }
        let (dx, dy) = to_field_frame(robot, mean);
        (state.ball_x_mm + dx, state.ball_y_mm + dy)
    }
}

#[cfg(test)]
mod tests {
    use polymimic_perceive::Segment;

    use super::*;
    use crate::nearest::brute_force_nearest;
    use crate::round::Ending;

    fn frame(robot: Pose, ball: (f64, f64)) -> TrackedFrame {
        TrackedFrame { robot, ball_x_mm: ball.0, ball_y_mm: ball.1 }
    }

    /// A robot facing +y pushes a ball lying 50 mm ahead of it 30 mm further along +y.
    fn pushes() -> SegmentedDemonstration {
        let robot = Pose::new(0.0, 0.0, std::f64::consts::FRAC_PI_2);
        let segment = Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: 0,
            last_frame: 30,
            start: frame(robot, (0.0, 50.0)),
            end: frame(Pose::new(robot.x_mm(), 40.0, robot.theta_rad()), (0.0, 80.0)),
            scores: [0.0; 7],
        };
        SegmentedDemonstration {
            demonstrator: "expert".to_owned(),
            pitch: Pitch::LARGE,
            reach_mm: None,
            ending: Ending::Other,
            segments: vec![segment],
        }
    }

    #[test]
    fn a_push_learned_facing_one_way_predicts_the_same_push_facing_another() {
        let response = BallResponse::learn(&[pushes()], &Pitch::LARGE, 10.0);
        assert_eq!(response.sample_count(Primitive::Forward), 1);
        // Facing +x with the ball 50 mm ahead: one sample of eight says the ball moves 30 mm
        // along +x, the seven missing say it stays: 30/8 mm.
        let state = frame(Pose::new(100.0, 0.0, 0.0), (150.0, 0.0));
        let (x, y) = response.predict(&state, Primitive::Forward);
        assert!((x - (150.0 + 30.0 / 8.0)).abs() < 1e-9 && y.abs() < 1e-9, "({x}, {y})");
        // With the ball far from anything seen, nothing is known: it stays.
        let far = frame(Pose::new(100.0, 0.0, 0.0), (400.0, 0.0));
        assert_eq!(response.predict(&far, Primitive::Forward), (400.0, 0.0));
        // No samples for a turn: the ball stays.
        assert_eq!(response.predict(&state, Primitive::Left), (150.0, 0.0));
    }

    /// [`pushes`] carrying the ball `moved_mm` instead of 30 mm.
    fn pushes_by(moved_mm: f64) -> SegmentedDemonstration {
        let mut demo = pushes();
        demo.segments[0].end.ball_y_mm = 50.0 + moved_mm;
        demo
    }

    #[test]
    fn a_sample_weighs_its_demonstrations_weight_and_a_missing_one_counts_as_staying_put() {
        let state = frame(Pose::new(100.0, 0.0, 0.0), (150.0, 0.0));
        let demos = [pushes(), pushes_by(60.0)];
        // Weight 0 leaves the 60 mm push out: the 30 mm push alone, as if never shown the other.
        let alone = BallResponse::learn(&demos[..1], &Pitch::LARGE, 10.0).predict(&state, Primitive::Forward);
        let weighted = BallResponse::learn_weighted(&demos, &[1.0, 0.0], &Pitch::LARGE, 10.0);
        assert_eq!(weighted.sample_count(Primitive::Forward), 1);
        assert_eq!(weighted.predict(&state, Primitive::Forward), alone);
        // Weights 1 and ½ with six missing: (30 · 1 + 60 · ½) / (1 + ½ + 6) = 8 mm.
        let half = BallResponse::learn_weighted(&demos, &[1.0, 0.5], &Pitch::LARGE, 10.0);
        let (x, y) = half.predict(&state, Primitive::Forward);
        assert!((x - 158.0).abs() < 1e-12 && y.abs() < 1e-12, "({x}, {y})");
        // Evenly: (30 + 60) / 8.
        let even = BallResponse::learn(&demos, &Pitch::LARGE, 10.0).predict(&state, Primitive::Forward);
        assert!((even.0 - (150.0 + 90.0 / 8.0)).abs() < 1e-12, "{even:?}");
    }

    #[test]
    fn weights_of_one_predict_bit_for_bit_what_the_unweighted_mean_did() {
        // Pushes of many lengths from around the ball, more than eight of them near it.
        let demos: Vec<SegmentedDemonstration> = (0..20)
            .map(|k| {
                let mut demo = pushes_by(7.0 + 3.3 * f64::from(k));
                demo.segments[0].start.ball_x_mm = 1.7 * f64::from(k) - 15.0;
                demo
            })
            .collect();
        let response = BallResponse::learn_weighted(&demos, &vec![1.0; demos.len()], &Pitch::LARGE, 10.0);
        assert_eq!(response, BallResponse::learn(&demos, &Pitch::LARGE, 10.0));
        // The mean as it was written before weights: each nearby displacement / NEIGHBOURS.
        let unweighted = |state: &TrackedFrame| {
            let robot = &state.robot;
            let here = to_robot_frame(robot, state.ball_x_mm - robot.x_mm(), state.ball_y_mm - robot.y_mm());
            let samples = &response.samples[Primitive::Forward as usize];
            let mut mean = [0.0; 2];
            for &(d2, i) in &brute_force_nearest(samples.iter().map(|s| [s[0], s[1]]), &here, NEIGHBOURS) {
                if d2 <= NEIGHBOURHOOD_MM * NEIGHBOURHOOD_MM {
                    mean[0] += samples[i][2] / NEIGHBOURS as f64;
                    mean[1] += samples[i][3] / NEIGHBOURS as f64;
                }
            }
            let (dx, dy) = to_field_frame(robot, mean);
            (state.ball_x_mm + dx, state.ball_y_mm + dy)
        };
        for k in 0..40 {
            let k = f64::from(k);
            let state = frame(Pose::new(3.0 * k, -2.0 * k, 0.1 * k), (3.0 * k + 45.0 + k, -2.0 * k + 0.7 * k));
            let (x, y) = response.predict(&state, Primitive::Forward);
            let (ux, uy) = unweighted(&state);
            assert_eq!((x.to_bits(), y.to_bits()), (ux.to_bits(), uy.to_bits()), "state {k}");
        }
    }

    #[test]
    fn demonstrations_on_another_pitch_are_left_out() {
        let response = BallResponse::learn(&[pushes()], &Pitch::SMALL, 10.0);
        assert_eq!(response.sample_count(Primitive::Forward), 0);
    }
}
