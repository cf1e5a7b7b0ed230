//! A point on the field, on nalgebra's `Point2`.

use std::fmt;
use std::ops::Add;

use nalgebra::{Point2, Vector2};
use serde::{Deserialize, Serialize};

/// A point on the field, mm (x toward the target goal, y to its left). Serialises as
/// `{"x_mm": …, "y_mm": …}`.
#[derive(Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(from = "PointMm", into = "PointMm")]
pub struct Point(Point2<f64>);

/// How a point is written: its coordinates, with their units.
#[derive(Serialize, Deserialize)]
struct PointMm {
    x_mm: f64,
    y_mm: f64,
}

impl From<PointMm> for Point {
    fn from(p: PointMm) -> Self {
        Self::new(p.x_mm, p.y_mm)
    }
}

impl From<Point> for PointMm {
    fn from(p: Point) -> Self {
        Self { x_mm: p.x_mm(), y_mm: p.y_mm() }
    }
}

impl Point {
    /// A point from its coordinates, mm.
    #[must_use]
    pub const fn new(x_mm: f64, y_mm: f64) -> Self {
        Self(Point2::new(x_mm, y_mm))
    }

    /// x, mm (toward the target goal).
    #[must_use]
    pub fn x_mm(self) -> f64 {
        self.0.x
    }

    /// y, mm.
    #[must_use]
    pub fn y_mm(self) -> f64 {
        self.0.y
    }

    /// The nalgebra point, mm.
    #[must_use]
    pub const fn as_point2(self) -> Point2<f64> {
        self.0
    }

    /// The displacement from `self` to `other`, mm.
    #[must_use]
    pub fn to(self, other: Point) -> Vector2<f64> {
        other.0 - self.0
    }

    /// Euclidean distance, mm (`libm::hypot`, the field's maths).
    #[must_use]
    pub fn dist_mm(self, other: Point) -> f64 {
        let d = self.to(other);
        libm::hypot(d.x, d.y)
    }

    /// Direction from `self` to `other`, rad (`libm::atan2`, the field's maths).
    #[must_use]
    pub fn bearing_rad(self, other: Point) -> f64 {
        let d = self.to(other);
        libm::atan2(d.y, d.x)
    }

    /// Whether both coordinates are finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.0.x.is_finite() && self.0.y.is_finite()
    }
}

impl Default for Point {
    /// The centre of the field.
    fn default() -> Self {
        Self::new(0.0, 0.0)
    }
}

impl From<Point2<f64>> for Point {
    fn from(p: Point2<f64>) -> Self {
        Self(p)
    }
}

impl From<Point> for Point2<f64> {
    fn from(p: Point) -> Self {
        p.0
    }
}

/// A point moved by a displacement, mm.
impl Add<Vector2<f64>> for Point {
    type Output = Point;

    fn add(self, v: Vector2<f64>) -> Point {
        Self(self.0 + v)
    }
}

impl fmt::Debug for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Point").field("x_mm", &self.x_mm()).field("y_mm", &self.y_mm()).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_and_bearing_of_a_3_4_5_triangle() {
        let (a, b) = (Point::new(1.0, 1.0), Point::new(4.0, 5.0));
        assert_eq!(a.dist_mm(b), 5.0);
        assert_eq!(a.bearing_rad(b), libm::atan2(4.0, 3.0));
        assert_eq!(a.to(b), Vector2::new(3.0, 4.0));
        assert_eq!(a + a.to(b), b);
    }

    #[test]
    fn serialises_with_units_in_the_field_names() {
        let p = Point::new(1.5, -2.0);
        let text = serde_json::to_string(&p).expect("numbers");
        assert_eq!(text, r#"{"x_mm":1.5,"y_mm":-2.0}"#);
        assert_eq!(serde_json::from_str::<Point>(&text).expect("valid"), p);
    }

    #[test]
    fn debug_reads_in_units() {
        assert_eq!(format!("{:?}", Point::new(1.0, 2.5)), "Point { x_mm: 1.0, y_mm: 2.5 }");
    }

    #[test]
    fn is_finite_checks_both_coordinates() {
        assert!(Point::new(0.0, 0.0).is_finite());
        assert!(!Point::new(f64::NAN, 0.0).is_finite());
        assert!(!Point::new(0.0, f64::INFINITY).is_finite());
    }
}
