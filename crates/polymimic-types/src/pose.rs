//! A robot's pose on the field, on nalgebra: the position a `Point2`, the heading kept as the
//! angle itself (so it reads back bit for bit) and turned into a `UnitComplex` rotation with
//! `libm`'s cosine and sine whenever a transform needs one.

use std::fmt;

use nalgebra::{Isometry2, Point2, Translation2, UnitComplex, Vector2};
use serde::{Deserialize, Serialize};

use crate::angle::{direction_rad, rotation_by_rad, wrap_angle_rad};
use crate::point::Point;

/// A robot pose: position (mm) and heading (rad, counter-clockwise from +x). Serialises as
/// `{"x_mm": …, "y_mm": …, "theta_rad": …}`.
#[derive(Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(from = "PoseMmRad", into = "PoseMmRad")]
pub struct Pose {
    position: Point2<f64>,
    theta_rad: f64,
}

/// How a pose is written: its coordinates and heading, with their units.
#[derive(Serialize, Deserialize)]
struct PoseMmRad {
    x_mm: f64,
    y_mm: f64,
    theta_rad: f64,
}

impl From<PoseMmRad> for Pose {
    fn from(p: PoseMmRad) -> Self {
        Self::new(p.x_mm, p.y_mm, p.theta_rad)
    }
}

impl From<Pose> for PoseMmRad {
    fn from(p: Pose) -> Self {
        Self { x_mm: p.x_mm(), y_mm: p.y_mm(), theta_rad: p.theta_rad }
    }
}

impl Pose {
    /// A pose from its parts.
    #[must_use]
    pub const fn new(x_mm: f64, y_mm: f64, theta_rad: f64) -> Self {
        Self { position: Point2::new(x_mm, y_mm), theta_rad }
    }

    /// A pose at `point` with heading `theta_rad`.
    #[must_use]
    pub fn at(point: Point, theta_rad: f64) -> Self {
        Self { position: point.as_point2(), theta_rad }
    }

    /// x, mm.
    #[must_use]
    pub fn x_mm(&self) -> f64 {
        self.position.x
    }

    /// y, mm.
    #[must_use]
    pub fn y_mm(&self) -> f64 {
        self.position.y
    }

    /// Heading, rad, counter-clockwise from +x (as given: not wrapped).
    #[must_use]
    pub const fn theta_rad(&self) -> f64 {
        self.theta_rad
    }

    /// The position part.
    #[must_use]
    pub fn point(&self) -> Point {
        Point::from(self.position)
    }

    /// The heading as a rotation, from `libm`'s cosine and sine (the field's maths).
    #[must_use]
    pub fn rotation(&self) -> UnitComplex<f64> {
        rotation_by_rad(self.theta_rad)
    }

    /// The unit vector along the heading, field axes (`libm`, the field's maths).
    #[must_use]
    pub fn heading(&self) -> Vector2<f64> {
        direction_rad(self.theta_rad)
    }

    /// The point `dist_mm` along the heading (behind the pose if negative), field coordinates:
    /// the position plus `dist_mm` times [`Self::heading`], each axis one product and one sum.
    #[must_use]
    pub fn ahead(&self, dist_mm: f64) -> Point {
        self.point() + self.heading() * dist_mm
    }

    /// The robot's frame (x forward, y to the left) in field coordinates: `field_from_robot`
    /// as an isometry, its rotation from [`Self::rotation`].
    #[must_use]
    pub fn isometry(&self) -> Isometry2<f64> {
        Isometry2::from_parts(Translation2::from(self.position.coords), self.rotation())
    }

    /// A point given in the robot's frame (x forward, y to the left), in field coordinates.
    ///
    /// The robot's two axes are added to the position one after the other, (x + c·px) − s·py,
    /// the order the field has always summed them in; `self.isometry() * p` rounds
    /// x + (c·px − s·py) instead.
    #[must_use]
    pub fn field_from_robot(&self, p: Point) -> Point {
        let forward = self.heading();
        let left = Vector2::new(-forward.y, forward.x);
        Point::from(self.position + forward * p.x_mm() + left * p.y_mm())
    }

    /// A field point in the robot's frame (x forward, y to the left).
    #[must_use]
    pub fn robot_from_field(&self, p: Point) -> Point {
        Point::from(self.isometry().inverse_transform_point(&p.as_point2()))
    }

    /// Angle of a field point relative to the heading, rad in (−π, π] (positive: to the left).
    #[must_use]
    pub fn relative_bearing_rad(&self, p: Point) -> f64 {
        wrap_angle_rad(self.point().bearing_rad(p) - self.theta_rad)
    }

    /// Whether every part is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.position.x.is_finite() && self.position.y.is_finite() && self.theta_rad.is_finite()
    }
}

impl Default for Pose {
    /// At the centre of the field, facing the target goal.
    fn default() -> Self {
        Self::new(0.0, 0.0, 0.0)
    }
}

// Reads as the pose was always printed: the position as its two coordinates, in mm.
#[expect(clippy::missing_fields_in_debug, reason = "the position is printed as x_mm and y_mm")]
impl fmt::Debug for Pose {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Pose")
            .field("x_mm", &self.x_mm())
            .field("y_mm", &self.y_mm())
            .field("theta_rad", &self.theta_rad)
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use super::*;

    #[test]
    fn robot_frame_round_trips() {
        let pose = Pose::new(10.0, -20.0, 0.8);
        let p = Point::new(33.0, 7.0);
        let q = pose.field_from_robot(pose.robot_from_field(p));
        assert!(p.dist_mm(q) < 1e-9);
        let r = pose.robot_from_field(pose.field_from_robot(p));
        assert!(p.dist_mm(r) < 1e-9);
        // A point straight ahead has bearing zero.
        let ahead = pose.field_from_robot(Point::new(50.0, 0.0));
        assert!(pose.relative_bearing_rad(ahead).abs() < 1e-12);
    }

    #[test]
    fn a_quarter_turn_maps_forward_to_plus_y_exactly() {
        let pose = Pose::new(100.0, 50.0, FRAC_PI_2);
        let (c, s) = (libm::cos(FRAC_PI_2), libm::sin(FRAC_PI_2));
        assert_eq!(s, 1.0);
        let ahead = pose.field_from_robot(Point::new(10.0, 0.0));
        assert_eq!(ahead, Point::new(100.0 + c * 10.0, 50.0 + 10.0));
        let left = pose.field_from_robot(Point::new(0.0, 10.0));
        assert_eq!(left, Point::new(100.0 - 10.0, 50.0 + c * 10.0));
        let back = pose.robot_from_field(Point::new(100.0, 60.0));
        assert_eq!(back, Point::new(c * 0.0 + s * 10.0, -s * 0.0 + c * 10.0));
        assert_eq!(pose.relative_bearing_rad(Point::new(90.0, 50.0)), FRAC_PI_2);
    }

    #[test]
    fn transforms_keep_the_fields_order_of_operations() {
        // The field computed these by hand; the nalgebra forms must give the same bits.
        for (x, y, theta) in [(10.0, -20.0, 0.8), (-333.3, 12.7, -2.9), (0.1, 0.2, 3.1)] {
            let pose = Pose::new(x, y, theta);
            let (s, c) = (libm::sin(theta), libm::cos(theta));
            for (px, py) in [(33.0, 7.0), (-0.3, 1e-3), (123.456, -98.7)] {
                let f = pose.field_from_robot(Point::new(px, py));
                assert_eq!(f, Point::new(x + c * px - s * py, y + s * px + c * py));
                let r = pose.robot_from_field(Point::new(px, py));
                let (dx, dy) = (px - x, py - y);
                assert_eq!(r, Point::new(c * dx + s * dy, -s * dx + c * dy));
            }
        }
    }

    #[test]
    fn ahead_is_the_hand_written_step_along_the_heading() {
        for (x, y, theta) in [(10.0, -20.0, 0.8), (-333.3, 12.7, -2.9), (0.1, 0.2, 3.1), (-0.0, -0.0, -0.0)] {
            let pose = Pose::new(x, y, theta);
            let (s, c) = (libm::sin(theta), libm::cos(theta));
            for d in [33.0, -7.25, 1e-3, 0.0] {
                let p = pose.ahead(d);
                assert_eq!((p.x_mm().to_bits(), p.y_mm().to_bits()), ((x + c * d).to_bits(), (y + s * d).to_bits()));
                if d != 0.0 {
                    assert_eq!(p, pose.field_from_robot(Point::new(d, 0.0)));
                }
            }
        }
    }

    #[test]
    fn serialises_with_units_in_the_field_names() {
        let pose = Pose::new(1.0, -2.5, 0.25);
        let text = serde_json::to_string(&pose).expect("numbers");
        assert_eq!(text, r#"{"x_mm":1.0,"y_mm":-2.5,"theta_rad":0.25}"#);
        assert_eq!(serde_json::from_str::<Pose>(&text).expect("valid"), pose);
    }

    #[test]
    fn debug_reads_in_units() {
        assert_eq!(format!("{:?}", Pose::new(1.0, 2.0, 0.5)), "Pose { x_mm: 1.0, y_mm: 2.0, theta_rad: 0.5 }");
    }

    #[test]
    fn heading_is_the_rotated_x_axis() {
        let pose = Pose::new(0.0, 0.0, 0.7);
        assert_eq!(pose.heading(), pose.rotation() * Vector2::x());
        assert_eq!(pose.theta_rad(), 0.7);
        assert!(!Pose::new(0.0, f64::NAN, 0.0).is_finite());
    }
}
