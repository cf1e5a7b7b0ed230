//! What a behaviour predicts: its primitives chained from a start pose, each drawing its
//! distance and rotation from Table 3.1 (thesis §3.3.3), and, when its ball statistics are
//! usable, where the ball will end relative to the robot.

use polymimic_types::{MotionStats, Pose, Primitive, wrap_angle_euclid_rad};
use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::behaviour::Behaviour;
use crate::config::LearningConfig;
use crate::error::LearnParamsError;

/// Mean and sd of each primitive's distance (mm) and rotation (rad), indexed by primitive.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MotionTable {
    rows: Vec<(Primitive, [f64; 4])>,
}

impl MotionTable {
    /// From the recogniser's Table 3.1.
    ///
    /// # Errors
    /// A primitive missing, or a statistic not finite.
    pub fn new(stats: &[MotionStats]) -> Result<Self, LearnParamsError> {
        let mut rows = Vec::with_capacity(5);
        for primitive in Primitive::WHEELED {
            let s = stats
                .iter()
                .find(|s| s.primitive == primitive)
                .ok_or(LearnParamsError::MotionStats(primitive.name()))?;
            let row = [
                s.distance_mean_mm,
                s.distance_sd_mm,
                s.rotation_mean_deg.to_radians(),
                s.rotation_sd_deg.to_radians(),
            ];
            if row.iter().any(|v| !v.is_finite()) {
                return Err(LearnParamsError::MotionStats(primitive.name()));
            }
            rows.push((primitive, row));
        }
        Ok(Self { rows })
    }

    fn row(&self, primitive: Primitive) -> [f64; 4] {
        self.rows.iter().find(|(p, _)| *p == primitive).map_or([0.0; 4], |(_, row)| *row)
    }

    /// The smaller of the left and right primitives' mean rotations (rad, unsigned).
    #[must_use]
    pub fn mean_turn_rad(&self) -> f64 {
        self.row(Primitive::Left)[2].abs().min(self.row(Primitive::Right)[2].abs())
    }

    /// The pose after one primitive from `pose` with its mean distance and rotation.
    #[must_use]
    pub fn mean_step(&self, pose: Pose, primitive: Primitive) -> Pose {
        let [distance, _, rotation, _] = self.row(primitive);
        advance(pose, distance, rotation)
    }

    /// The poses after one primitive from `pose` with its mean distance and rotation, then with
    /// the distance one sd longer and shorter, then with the rotation one sd more and less.
    #[must_use]
    pub fn spread_steps(&self, pose: Pose, primitive: Primitive) -> [Pose; 5] {
        let [d, d_sd, r, r_sd] = self.row(primitive);
        [(d, r), (d + d_sd, r), (d - d_sd, r), (d, r + r_sd), (d, r - r_sd)]
            .map(|(distance, rotation)| advance(pose, distance, rotation))
    }

    /// The pose after one primitive from `pose`: move the drawn distance along the heading,
    /// then turn by the drawn rotation.
    pub fn step(&self, pose: Pose, primitive: Primitive, noise_divisor: f64, rng: &mut ChaCha8Rng) -> Pose {
        let [d_mean, d_sd, r_mean, r_sd] = self.row(primitive);
        let distance = d_mean + d_sd / noise_divisor * normal(rng);
        let rotation = r_mean + r_sd / noise_divisor * normal(rng);
        advance(pose, distance, rotation)
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

/// Moves `distance_mm` along the heading, then turns by `rotation_rad`.
fn advance(pose: Pose, distance_mm: f64, rotation_rad: f64) -> Pose {
    Pose::new(
        pose.x_mm() + distance_mm * pose.theta_rad().cos(),
        pose.y_mm() + distance_mm * pose.theta_rad().sin(),
        wrap_angle_euclid_rad(pose.theta_rad() + rotation_rad),
    )
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
