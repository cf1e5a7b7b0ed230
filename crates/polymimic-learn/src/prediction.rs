//! What a behaviour predicts: its primitives chained from a start pose, each drawing its
//! distance and rotation from Table 3.1 (thesis §3.3.3), and, when its ball statistics are
//! usable, where the ball will end relative to the robot.
//!
//! The thesis's forward model moves a primitive along the robot's heading and then turns it:
//! every wheeled primitive does. A humanoid's side-step moves across its heading, which those
//! two numbers read as standing still, so a body that side-steps brings a third, its step to
//! the left of its heading ([`polymimic_types::Sideways`]), and its primitives move by all
//! three. A table without it moves and draws exactly as the thesis's did.

use polymimic_types::{MotionStats, Pose, Primitive, wrap_angle_euclid_rad};
use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::behaviour::Behaviour;
use crate::config::LearningConfig;
use crate::error::LearnParamsError;

/// Mean and sd of each primitive's distance (mm), rotation (rad) and step to the left (mm, 0
/// for a body that does not side-step), indexed by primitive.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MotionTable {
    rows: Vec<(Primitive, [f64; 6])>,
}

impl MotionTable {
    /// From the recogniser's Table 3.1: a row for every primitive it measured, which must
    /// include the wheeled five.
    ///
    /// # Errors
    /// A wheeled primitive missing, or a statistic not finite.
    pub fn new(stats: &[MotionStats]) -> Result<Self, LearnParamsError> {
        if let Some(missing) = Primitive::WHEELED.into_iter().find(|p| stats.iter().all(|s| s.primitive != *p)) {
            return Err(LearnParamsError::MotionStats(missing.name()));
        }
        let mut rows = Vec::with_capacity(stats.len());
        for primitive in Primitive::ALL {
            let Some(s) = stats.iter().find(|s| s.primitive == primitive) else { continue };
            let sideways = s.sideways.map_or([0.0; 2], |s| [s.mean_mm, s.sd_mm]);
            let row = [
                s.distance_mean_mm,
                s.distance_sd_mm,
                s.rotation_mean_deg.to_radians(),
                s.rotation_sd_deg.to_radians(),
                sideways[0],
                sideways[1],
            ];
            if row.iter().any(|v| !v.is_finite()) {
                return Err(LearnParamsError::MotionStats(primitive.name()));
            }
            rows.push((primitive, row));
        }
        Ok(Self { rows })
    }

    /// The primitives it has rows for, in id order: the body's own set.
    pub fn primitives(&self) -> impl Iterator<Item = Primitive> + '_ {
        self.rows.iter().map(|(p, _)| *p)
    }

    fn row(&self, primitive: Primitive) -> [f64; 6] {
        self.rows.iter().find(|(p, _)| *p == primitive).map_or([0.0; 6], |(_, row)| *row)
    }

    /// The smaller of the left and right primitives' mean rotations (rad, unsigned).
    #[must_use]
    pub fn mean_turn_rad(&self) -> f64 {
        self.row(Primitive::Left)[2].abs().min(self.row(Primitive::Right)[2].abs())
    }

    /// The pose after one primitive from `pose` with its mean distance and rotation.
    #[must_use]
    pub fn mean_step(&self, pose: Pose, primitive: Primitive) -> Pose {
        let [distance, _, rotation, _, left, _] = self.row(primitive);
        advance(pose, distance, left, rotation)
    }

    /// The poses after one primitive from `pose` with its mean distance and rotation, then with
    /// the distance one sd longer and shorter, then with the rotation one sd more and less.
    #[must_use]
    pub fn spread_steps(&self, pose: Pose, primitive: Primitive) -> [Pose; 5] {
        let [d, d_sd, r, r_sd, left, _] = self.row(primitive);
        [(d, r), (d + d_sd, r), (d - d_sd, r), (d, r + r_sd), (d, r - r_sd)]
            .map(|(distance, rotation)| advance(pose, distance, left, rotation))
    }

    /// The pose after one primitive from `pose`: move the drawn distance along the heading
    /// (and the drawn step to its left), then turn by the drawn rotation. The step to the left
    /// is drawn only where it varies, so a table without one draws as the thesis's did.
    pub fn step(&self, pose: Pose, primitive: Primitive, noise_divisor: f64, rng: &mut ChaCha8Rng) -> Pose {
        let [d_mean, d_sd, r_mean, r_sd, left_mean, left_sd] = self.row(primitive);
        let distance = d_mean + d_sd / noise_divisor * normal(rng);
        let rotation = r_mean + r_sd / noise_divisor * normal(rng);
        let left = if left_sd > 0.0 { left_mean + left_sd / noise_divisor * normal(rng) } else { left_mean };
        advance(pose, distance, left, rotation)
    }

    /// A table without spread: forward and backward move `step_mm`, left and right turn
    /// `turn_deg` on the spot, so predictions are exact.
    #[cfg(test)]
    pub(crate) fn exact(step_mm: f64, turn_deg: f64) -> Self {
        let stats = |primitive, distance_mean_mm, rotation_mean_deg| MotionStats {
            primitive,
            count: 1,
            distance_mean_mm,
            distance_sd_mm: 0.0,
            rotation_mean_deg,
            rotation_sd_deg: 0.0,
            sideways: None,
        };
        Self::new(&[
            stats(Primitive::Forward, step_mm, 0.0),
            stats(Primitive::Backward, -step_mm, 0.0),
            stats(Primitive::Left, 0.0, turn_deg),
            stats(Primitive::Right, 0.0, -turn_deg),
            stats(Primitive::Stop, 0.0, 0.0),
        ])
        .expect("finite statistics for every primitive")
    }
}

/// Moves `distance_mm` along the heading and `left_mm` across it, then turns by
/// `rotation_rad`. Without a step across, the sums are the thesis's, term for term.
fn advance(pose: Pose, distance_mm: f64, left_mm: f64, rotation_rad: f64) -> Pose {
    let (sin, cos) = (pose.theta_rad().sin(), pose.theta_rad().cos());
    let (x_mm, y_mm) = if left_mm == 0.0 {
        (pose.x_mm() + distance_mm * cos, pose.y_mm() + distance_mm * sin)
    } else {
        (pose.x_mm() + distance_mm * cos - left_mm * sin, pose.y_mm() + distance_mm * sin + left_mm * cos)
    };
    Pose::new(x_mm, y_mm, wrap_angle_euclid_rad(pose.theta_rad() + rotation_rad))
}

/// A standard normal draw (Box-Muller), reproducible from the seeded generator.
pub(crate) fn normal(rng: &mut ChaCha8Rng) -> f64 {
    let u1: f64 = 1.0 - rng.random::<f64>();
    let u2: f64 = rng.random();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// One behaviour's prediction.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// The robot's pose after each primitive.
    pub poses: Vec<Pose>,
    /// The ball relative to the robot at the end: bearing (deg) and distance (mm), when the
    /// behaviour predicts the ball.
    pub ball: Option<(f64, f64)>,
}

impl Prediction {
    #[must_use]
    pub fn end(&self) -> Pose {
        self.poses.last().copied().unwrap_or_default()
    }

    /// Where the ball is predicted to end, in field coordinates.
    #[must_use]
    pub fn ball_position(&self) -> Option<(f64, f64)> {
        let end = self.end();
        self.ball.map(|(bearing_deg, distance_mm)| {
            let angle = end.theta_rad() + bearing_deg.to_radians();
            (end.x_mm() + distance_mm * angle.cos(), end.y_mm() + distance_mm * angle.sin())
        })
    }
}

/// Chains `behaviour`'s primitives from `start`.
pub fn predict(
    behaviour: &Behaviour,
    start: Pose,
    motion: &MotionTable,
    config: &LearningConfig,
    rng: &mut ChaCha8Rng,
) -> Prediction {
    let mut pose = start;
    let poses = behaviour
        .primitives
        .iter()
        .map(|&p| {
            pose = motion.step(pose, p, config.prediction_noise_divisor, rng);
            pose
        })
        .collect();
    let ball = behaviour.predicts_ball(config).then(|| {
        let distance = behaviour.ball_distance_mm.mean + behaviour.ball_distance_mm.sd() * normal(rng);
        (behaviour.ball_angle_deg.mean, distance.max(0.0))
    });
    Prediction { poses, ball }
}

/// Whether a predicted pose is within the match tolerances of the actual one.
#[must_use]
pub fn matches(predicted: &Pose, actual: &Pose, config: &LearningConfig) -> bool {
    predicted.distance_from_mm(actual) <= config.match_distance_mm
        && predicted.rotation_from_rad(actual).to_degrees().abs() <= config.match_rotation_deg
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    fn table() -> MotionTable {
        MotionTable::exact(40.0, 90.0)
    }

    #[test]
    fn a_side_step_moves_across_the_heading_where_the_thesiss_table_would_stand_still() {
        use polymimic_types::Sideways;
        let stats = |primitive, distance_mean_mm, left_mm: Option<f64>| MotionStats {
            primitive,
            count: 1,
            distance_mean_mm,
            distance_sd_mm: 0.0,
            rotation_mean_deg: 0.0,
            rotation_sd_deg: 0.0,
            sideways: left_mm.map(|mean_mm| Sideways { mean_mm, sd_mm: 2.0 }),
        };
        let humanoid: Vec<MotionStats> = Primitive::ALL
            .into_iter()
            .map(|p| match p {
                Primitive::SidestepLeft => stats(p, 0.0, Some(28.0)),
                Primitive::SidestepRight => stats(p, 0.0, Some(-28.0)),
                Primitive::Kick => stats(p, -10.0, Some(0.0)),
                _ => stats(p, 0.0, Some(0.0)),
            })
            .collect();
        let humanoid_table = MotionTable::new(&humanoid).expect("finite");
        assert_eq!(humanoid_table.primitives().collect::<Vec<_>>(), Primitive::ALL);
        let facing_up = Pose::new(100.0, 50.0, std::f64::consts::FRAC_PI_2);
        let left = humanoid_table.mean_step(facing_up, Primitive::SidestepLeft);
        assert!((left.x_mm() - 72.0).abs() < 1e-9 && (left.y_mm() - 50.0).abs() < 1e-9, "{left:?}");
        let kicked = humanoid_table.mean_step(facing_up, Primitive::Kick);
        assert!((kicked.x_mm() - 100.0).abs() < 1e-9 && (kicked.y_mm() - 40.0).abs() < 1e-9, "{kicked:?}");
        // A drawn side-step spreads across the heading by its sd.
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let drawn: Vec<f64> =
            (0..400).map(|_| humanoid_table.step(facing_up, Primitive::SidestepRight, 1.0, &mut rng).x_mm()).collect();
        let mean = drawn.iter().sum::<f64>() / 400.0;
        assert!((mean - 128.0).abs() < 0.5, "{mean}");
        // Without the humanoid's rows the table is the wheeled five, and a missing one is refused.
        assert_eq!(table().primitives().collect::<Vec<_>>(), Primitive::WHEELED);
        assert!(MotionTable::new(&humanoid[1..]).is_err());
    }

    #[test]
    fn chains_move_then_turn() {
        let config = LearningConfig::default();
        let b = Behaviour::new(vec![Primitive::Forward, Primitive::Left, Primitive::Forward], 0, &config);
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let p = predict(&b, Pose::new(0.0, 0.0, 0.0), &table(), &config, &mut rng);
        let end = p.end();
        assert!((end.x_mm() - 40.0).abs() < 1e-9 && (end.y_mm() - 40.0).abs() < 1e-9, "{end:?}");
        assert!((end.theta_rad() - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
        assert_eq!(p.poses.len(), 3);
        assert!(p.ball.is_none());
    }

    #[test]
    fn match_tolerances_are_40_mm_and_45_degrees() {
        let config = LearningConfig::default();
        let a = Pose::new(0.0, 0.0, 0.0);
        assert!(matches(&a, &Pose::new(39.0, 0.0, 0.7), &config));
        assert!(!matches(&a, &Pose::new(41.0, 0.0, 0.0), &config));
        assert!(!matches(&a, &Pose::new(0.0, 0.0, 0.8), &config));
    }
}
