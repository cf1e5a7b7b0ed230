//! Field geometry: field sizes and goal mouths, in field coordinates (mm, origin at the
//! centre, +x toward the target goal). Points and poses are `polymimic_types`'.

use polymimic_types::Point;
use serde::{Deserialize, Serialize};

use crate::error::{FieldParamError, check_range};

/// The two field sizes of the thesis (§4.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FieldSize {
    /// 1020 × 810 mm, 100 mm foam ball: the Lego and humanoid robots.
    Large,
    /// 560 × 345 mm, 25 mm styrofoam ball: the tiny robot.
    Small,
}

/// Field dimensions and the goal mouths (centred on the goal lines at x = ±length/2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FieldGeometry {
    /// Length along x (goal to goal), mm.
    pub length_mm: f64,
    /// Width along y, mm.
    pub width_mm: f64,
    /// Ball diameter, mm.
    pub ball_diameter_mm: f64,
    /// Width of each goal mouth, mm (the thesis's fields: half the field's width).
    pub goal_mouth_mm: f64,
}

impl FieldGeometry {
    /// The geometry of a field size.
    #[must_use]
    pub const fn of(size: FieldSize) -> Self {
        match size {
            FieldSize::Large => {
                Self { length_mm: 1020.0, width_mm: 810.0, ball_diameter_mm: 100.0, goal_mouth_mm: 405.0 }
            }
            FieldSize::Small => {
                Self { length_mm: 560.0, width_mm: 345.0, ball_diameter_mm: 25.0, goal_mouth_mm: 172.5 }
            }
        }
    }

    /// Check a field of the user's: every size positive, the ball narrower than the mouth, the
    /// mouth no wider than the field.
    ///
    /// # Errors
    /// `OutOfRange` naming the first size that is not.
    pub fn check(&self) -> Result<(), FieldParamError> {
        check_range("field.length_mm", self.length_mm, f64::MIN_POSITIVE, 1e6, "positive")?;
        check_range("field.width_mm", self.width_mm, f64::MIN_POSITIVE, 1e6, "positive")?;
        check_range(
            "field.goal_mouth_mm",
            self.goal_mouth_mm,
            f64::MIN_POSITIVE,
            self.width_mm,
            "positive, at most the width",
        )?;
        check_range(
            "field.ball_diameter_mm",
            self.ball_diameter_mm,
            f64::MIN_POSITIVE,
            self.goal_mouth_mm,
            "positive, below the goal mouth",
        )
    }

    /// A field from JSON (its four sizes by name), checked.
    ///
    /// # Errors
    /// `Json` for malformed JSON or an unknown or missing size; `OutOfRange` as
    /// [`FieldGeometry::check`].
    pub fn from_json(json: &str) -> Result<Self, FieldParamError> {
        let field: Self = serde_json::from_str(json).map_err(|e| FieldParamError::Json(e.to_string()))?;
        field.check()?;
        Ok(field)
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

    /// Half the goal mouth, mm.
    #[must_use]
    pub fn goal_half_mouth_mm(&self) -> f64 {
        self.goal_mouth_mm / 2.0
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
        p.x_mm().abs() <= self.half_length_mm() && p.y_mm().abs() <= self.half_width_mm()
    }

    /// Distance from the point to the nearest boundary line, mm (negative outside).
    #[must_use]
    pub fn margin_mm(&self, p: Point) -> f64 {
        (self.half_length_mm() - p.x_mm().abs()).min(self.half_width_mm() - p.y_mm().abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
