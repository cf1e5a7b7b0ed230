//! Field geometry: poses and points in field coordinates (mm, origin at the centre, +x toward
//! the target goal), field sizes and goal mouths.

use serde::{Deserialize, Serialize};

use crate::math::{atan2, cos, hypot, sin, wrap_angle_rad};

/// A point on the field, mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct Point {
    /// x, mm (toward the target goal).
    pub x_mm: f64,
    /// y, mm.
    pub y_mm: f64,
}

impl Point {
    /// A point from its coordinates, mm.
    #[must_use]
    pub const fn new(x_mm: f64, y_mm: f64) -> Self {
        Self { x_mm, y_mm }
    }

    /// Euclidean distance, mm.
    #[must_use]
    pub fn dist_mm(self, other: Point) -> f64 {
        hypot(other.x_mm - self.x_mm, other.y_mm - self.y_mm)
    }

    /// Direction from `self` to `other`, rad.
    #[must_use]
    pub fn bearing_rad(self, other: Point) -> f64 {
        atan2(other.y_mm - self.y_mm, other.x_mm - self.x_mm)
    }

    pub(crate) fn is_finite(self) -> bool {
        self.x_mm.is_finite() && self.y_mm.is_finite()
    }
}

/// A robot pose: position (mm) and heading (rad, counter-clockwise from +x).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct Pose {
    /// x, mm.
    pub x_mm: f64,
    /// y, mm.
    pub y_mm: f64,
    /// Heading, rad, counter-clockwise from +x.
    pub theta_rad: f64,
}

impl Pose {
    /// A pose from its parts.
    #[must_use]
    pub const fn new(x_mm: f64, y_mm: f64, theta_rad: f64) -> Self {
        Self { x_mm, y_mm, theta_rad }
    }

    /// The position part.
    #[must_use]
    pub const fn point(self) -> Point {
        Point::new(self.x_mm, self.y_mm)
    }

    /// A point given in the robot's frame (x forward, y to the left), in field coordinates.
    #[must_use]
    pub fn field_from_robot(self, p: Point) -> Point {
        let (s, c) = (sin(self.theta_rad), cos(self.theta_rad));
        Point::new(self.x_mm + c * p.x_mm - s * p.y_mm, self.y_mm + s * p.x_mm + c * p.y_mm)
    }

    /// A field point in the robot's frame (x forward, y to the left).
    #[must_use]
    pub fn robot_from_field(self, p: Point) -> Point {
        let (s, c) = (sin(self.theta_rad), cos(self.theta_rad));
        let (dx, dy) = (p.x_mm - self.x_mm, p.y_mm - self.y_mm);
        Point::new(c * dx + s * dy, -s * dx + c * dy)
    }

    /// Angle of a field point relative to the heading, rad in (−π, π] (positive: to the left).
    #[must_use]
    pub fn relative_bearing_rad(self, p: Point) -> f64 {
        wrap_angle_rad(self.point().bearing_rad(p) - self.theta_rad)
    }

    pub(crate) fn is_finite(self) -> bool {
        self.x_mm.is_finite() && self.y_mm.is_finite() && self.theta_rad.is_finite()
    }
}

/// The two field sizes of the thesis (§4.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FieldSize {
    /// 1020 × 810 mm, 100 mm foam ball: the Lego and humanoid robots.
    Large,
    /// 560 × 345 mm, 25 mm styrofoam ball: the tiny robot.
    Small,
}

/// Field dimensions and the derived goal geometry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FieldGeometry {
    /// Length along x (goal to goal), mm.
    pub length_mm: f64,
    /// Width along y, mm.
    pub width_mm: f64,
    /// Ball diameter, mm.
    pub ball_diameter_mm: f64,
}

impl FieldGeometry {
    /// The geometry of a field size.
    #[must_use]
    pub const fn of(size: FieldSize) -> Self {
        match size {
            FieldSize::Large => Self { length_mm: 1020.0, width_mm: 810.0, ball_diameter_mm: 100.0 },
            FieldSize::Small => Self { length_mm: 560.0, width_mm: 345.0, ball_diameter_mm: 25.0 },
        }
    }

    /// Half the length: the goal lines are at x = ±this, mm.
    #[must_use]
    pub fn half_length_mm(&self) -> f64 {
        self.length_mm / 2.0
    }

    /// Half the width: the side lines are at y = ±this, mm.
    #[must_use]
    pub fn half_width_mm(&self) -> f64 {
        self.width_mm / 2.0
    }

    /// Half the goal mouth (the mouth is half the field width, centred), mm.
    #[must_use]
    pub fn goal_half_mouth_mm(&self) -> f64 {
        self.width_mm / 4.0
    }

    /// Centre of the target goal's mouth (+x).
    #[must_use]
    pub fn target_goal(&self) -> Point {
        Point::new(self.half_length_mm(), 0.0)
    }

    /// Centre of the demonstrator's own goal's mouth (−x).
    #[must_use]
    pub fn own_goal(&self) -> Point {
        Point::new(-self.half_length_mm(), 0.0)
    }

    /// Is the point on the field (boundary included)?
    #[must_use]
    pub fn contains(&self, p: Point) -> bool {
        p.x_mm.abs() <= self.half_length_mm() && p.y_mm.abs() <= self.half_width_mm()
    }

    /// Distance from the point to the nearest boundary line, mm (negative outside).
    #[must_use]
    pub fn margin_mm(&self, p: Point) -> f64 {
        (self.half_length_mm() - p.x_mm.abs()).min(self.half_width_mm() - p.y_mm.abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn robot_frame_round_trips() {
        let pose = Pose::new(10.0, -20.0, 0.8);
        let p = Point::new(33.0, 7.0);
        let q = pose.field_from_robot(pose.robot_from_field(p));
        assert!(p.dist_mm(q) < 1e-9);
        // A point straight ahead has bearing zero.
        let ahead = pose.field_from_robot(Point::new(50.0, 0.0));
        assert!(pose.relative_bearing_rad(ahead).abs() < 1e-12);
    }

    #[test]
    fn goal_mouth_is_half_the_width() {
        let g = FieldGeometry::of(FieldSize::Large);
        assert!((g.goal_half_mouth_mm() * 2.0 - 405.0).abs() < 1e-12);
        assert_eq!(g.target_goal(), Point::new(510.0, 0.0));
        let s = FieldGeometry::of(FieldSize::Small);
        assert!((s.ball_diameter_mm - 25.0).abs() < 1e-12);
        assert!(s.contains(Point::new(280.0, 172.5)));
        assert!(!s.contains(Point::new(280.1, 0.0)));
    }
}
