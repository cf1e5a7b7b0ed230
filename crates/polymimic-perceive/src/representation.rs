//! How a sequence of poses becomes points to quantise (thesis §3.1.2). Every frame is taken
//! relative to the sequence's first frame; the heading is scaled by 16 so that radians weigh
//! about as much as millimetres when clustering (§3.1.4).

use polymimic_types::{Pose, wrap_angle_euclid_rad};
use serde::{Deserialize, Serialize};

/// Radians to the scale of millimetres.
pub const THETA_SCALE: f64 = 16.0;

/// A way of turning frames into 3-D points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Representation {
    /// (dx, dy, 16·θ_t): field-axis displacement and absolute heading; separates forward
    /// from backward.
    Positional,
    /// (dx, dy, 16·wrap(θ_t − θ_0)): field-axis displacement and heading change; separates
    /// left from right.
    Rotational,
    /// Displacement in the robot's own frame at the first frame, and heading change: the same
    /// motion gives the same points wherever the robot faces (beyond the thesis).
    Egocentric,
}

impl Representation {
    /// Row-major `(n, 3)` points of `poses`, relative to the first pose.
    #[must_use]
    pub fn points(self, poses: &[Pose]) -> Vec<f64> {
        let Some(origin) = poses.first() else { return Vec::new() };
        let (sin0, cos0) = origin.theta_rad().sin_cos();
        let mut points = Vec::with_capacity(poses.len() * 3);
        for pose in poses {
            let (dx, dy) = (pose.x_mm() - origin.x_mm(), pose.y_mm() - origin.y_mm());
            let turn = wrap_angle_euclid_rad(pose.theta_rad() - origin.theta_rad());
            match self {
                Self::Positional => points.extend([dx, dy, THETA_SCALE * pose.theta_rad()]),
                Self::Rotational => points.extend([dx, dy, THETA_SCALE * turn]),
                Self::Egocentric => {
                    points.extend([dx * cos0 + dy * sin0, -dx * sin0 + dy * cos0, THETA_SCALE * turn]);
                }
            }
        }
        points
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(x_mm: f64, y_mm: f64, theta_rad: f64) -> Pose {
        Pose::new(x_mm, y_mm, theta_rad)
    }

    #[test]
    fn positional_keeps_the_absolute_heading_and_rotational_the_change() {
        let poses = [pose(10.0, 20.0, 1.0), pose(13.0, 24.0, 1.5)];
        assert_eq!(Representation::Positional.points(&poses), vec![0.0, 0.0, 16.0, 3.0, 4.0, 24.0]);
        assert_eq!(Representation::Rotational.points(&poses), vec![0.0, 0.0, 0.0, 3.0, 4.0, 8.0]);
    }

    #[test]
    fn rotational_wraps_across_pi() {
        let poses = [pose(0.0, 0.0, 3.1), pose(0.0, 0.0, -3.1)];
        let points = Representation::Rotational.points(&poses);
        assert!((points[5] - 16.0 * (std::f64::consts::TAU - 6.2)).abs() < 1e-9);
    }

    #[test]
    fn egocentric_is_the_same_whatever_the_starting_heading() {
        let ahead =
            |theta: f64| [pose(5.0, 5.0, theta), pose(5.0 + 10.0 * theta.cos(), 5.0 + 10.0 * theta.sin(), theta)];
        for theta in [0.0, 1.0, -2.5, 3.0] {
            let points = Representation::Egocentric.points(&ahead(theta));
            assert!((points[3] - 10.0).abs() < 1e-9 && points[4].abs() < 1e-9, "{points:?}");
        }
    }
}
