//! What the tracker reports, as the recogniser and segmenter need it.

use serde::{Deserialize, Serialize};

/// A robot's position and heading on the field.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    pub x_mm: f64,
    pub y_mm: f64,
    pub theta_rad: f64,
}

/// One tracker frame: the robot's pose and the ball's position.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TrackedFrame {
    pub robot: Pose,
    pub ball_x_mm: f64,
    pub ball_y_mm: f64,
}

/// An angle wrapped into (−π, π].
#[must_use]
pub fn wrap_angle_rad(angle_rad: f64) -> f64 {
    let wrapped = angle_rad.rem_euclid(std::f64::consts::TAU);
    if wrapped > std::f64::consts::PI { wrapped - std::f64::consts::TAU } else { wrapped }
}

impl Pose {
    /// How far the robot moved from `origin`, mm.
    #[must_use]
    pub fn distance_from_mm(&self, origin: &Pose) -> f64 {
        (self.x_mm - origin.x_mm).hypot(self.y_mm - origin.y_mm)
    }

    /// How far the robot turned from `origin`, rad in (−π, π].
    #[must_use]
    pub fn rotation_from_rad(&self, origin: &Pose) -> f64 {
        wrap_angle_rad(self.theta_rad - origin.theta_rad)
    }

    /// Displacement from `origin` along `origin`'s heading, mm (negative when moving backward).
    #[must_use]
    pub fn advance_from_mm(&self, origin: &Pose) -> f64 {
        (self.x_mm - origin.x_mm) * origin.theta_rad.cos() + (self.y_mm - origin.y_mm) * origin.theta_rad.sin()
    }

    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.x_mm.is_finite() && self.y_mm.is_finite() && self.theta_rad.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn wraps_into_minus_pi_to_pi() {
        assert!((wrap_angle_rad(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-12);
        assert!((wrap_angle_rad(-3.0 * PI / 2.0) - PI / 2.0).abs() < 1e-12);
        assert!((wrap_angle_rad(PI) - PI).abs() < 1e-12);
    }

    #[test]
    fn advance_is_signed_along_the_starting_heading() {
        let origin = Pose { x_mm: 0.0, y_mm: 0.0, theta_rad: PI / 2.0 };
        let ahead = Pose { x_mm: 0.0, y_mm: 10.0, theta_rad: PI / 2.0 };
        let behind = Pose { x_mm: 0.0, y_mm: -10.0, theta_rad: PI / 2.0 };
        assert!((ahead.advance_from_mm(&origin) - 10.0).abs() < 1e-12);
        assert!((behind.advance_from_mm(&origin) + 10.0).abs() < 1e-12);
    }
}
