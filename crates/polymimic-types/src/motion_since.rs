//! How far a robot moved and turned since an earlier pose, as the recogniser and the learner
//! measure it: with std's `f64` maths (the platform's `hypot`, `cos`, `sin`) and the
//! [`wrap_angle_euclid_rad`] wrap, which their saved models and results were computed with. The
//! field measures the same things with `libm` and the exact wrap (its `primitive_motion`).

use crate::angle::wrap_angle_euclid_rad;
use crate::pose::Pose;

impl Pose {
    /// How far the robot moved from `origin`, mm (std `hypot`).
    #[must_use]
    pub fn distance_from_mm(&self, origin: &Pose) -> f64 {
        (self.x_mm() - origin.x_mm()).hypot(self.y_mm() - origin.y_mm())
    }

    /// How far the robot turned from `origin`, rad in (−π, π] ([`wrap_angle_euclid_rad`]).
    #[must_use]
    pub fn rotation_from_rad(&self, origin: &Pose) -> f64 {
        wrap_angle_euclid_rad(self.theta_rad() - origin.theta_rad())
    }

    /// Displacement from `origin` along `origin`'s heading, mm, negative when moving backward
    /// (std `cos` and `sin`).
    #[must_use]
    pub fn advance_from_mm(&self, origin: &Pose) -> f64 {
        (self.x_mm() - origin.x_mm()) * origin.theta_rad().cos()
            + (self.y_mm() - origin.y_mm()) * origin.theta_rad().sin()
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;

    #[test]
    fn advance_is_signed_along_the_starting_heading() {
        let origin = Pose::new(0.0, 0.0, PI / 2.0);
        let ahead = Pose::new(0.0, 10.0, PI / 2.0);
        let behind = Pose::new(0.0, -10.0, PI / 2.0);
        assert!((ahead.advance_from_mm(&origin) - 10.0).abs() < 1e-12);
        assert!((behind.advance_from_mm(&origin) + 10.0).abs() < 1e-12);
    }

    #[test]
    fn distance_and_rotation_since_an_origin() {
        let origin = Pose::new(1.0, 1.0, 3.0);
        let now = Pose::new(4.0, 5.0, -3.0);
        assert_eq!(now.distance_from_mm(&origin), 5.0);
        assert_eq!(now.rotation_from_rad(&origin), wrap_angle_euclid_rad(-6.0));
        assert!((now.rotation_from_rad(&origin) - (2.0 * PI - 6.0)).abs() < 1e-12);
    }
}
