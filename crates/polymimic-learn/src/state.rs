//! The field as learning sees it: the robot's pose and the ball, on a pitch of known size.

use polymimic_field::BodyKind;
use polymimic_types::{Pose, TrackedFrame, wrap_angle_euclid_rad};
use serde::{Deserialize, Serialize};

/// The size of the field a demonstration was played on; the target goal's centre is at
/// (+length/2, 0) and the own goal's at (−length/2, 0), each mouth `goal_mouth_mm` wide.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pitch {
    pub length_mm: f64,
    pub width_mm: f64,
    pub goal_mouth_mm: f64,
}

impl Pitch {
    /// The thesis's fields: their mouths are half their width.
    pub const LARGE: Self = Self { length_mm: 1020.0, width_mm: 810.0, goal_mouth_mm: 405.0 };
    pub const SMALL: Self = Self { length_mm: 560.0, width_mm: 345.0, goal_mouth_mm: 172.5 };

    /// The field `body` plays on.
    #[must_use]
    pub const fn of_body(body: BodyKind) -> Self {
        let field = body.field();
        Self { length_mm: field.length_mm, width_mm: field.width_mm, goal_mouth_mm: field.goal_mouth_mm }
    }

    /// A pitch from its sizes as JSON (`{"length_mm", "width_mm", "goal_mouth_mm"}`), if they
    /// are all there, nothing else is, and they are valid.
    #[must_use]
    pub fn from_json(text: &str) -> Option<Self> {
        serde_json::from_str::<Self>(text).ok().filter(Self::is_valid)
    }

    /// Whether every size is a positive number and the mouth no wider than the field.
    #[must_use]
    pub fn is_valid(&self) -> bool {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        positive(self.length_mm)
            && positive(self.width_mm)
            && positive(self.goal_mouth_mm)
            && self.goal_mouth_mm <= self.width_mm
    }

    #[must_use]
    pub fn target_goal(&self) -> (f64, f64) {
        (self.length_mm / 2.0, 0.0)
    }

    #[must_use]
    pub fn own_goal(&self) -> (f64, f64) {
        (-self.length_mm / 2.0, 0.0)
    }

    #[must_use]
    pub fn contains(&self, x_mm: f64, y_mm: f64) -> bool {
        x_mm.abs() <= self.length_mm / 2.0 && y_mm.abs() <= self.width_mm / 2.0
    }

    /// Whether a ball at (x, y) is past the target goal line inside the mouth.
    #[must_use]
    pub fn in_target_goal(&self, x_mm: f64, y_mm: f64) -> bool {
        x_mm >= self.length_mm / 2.0 && y_mm.abs() <= self.goal_mouth_mm / 2.0
    }

    /// Whether a ball at (x, y) is past the own goal line inside the mouth.
    #[must_use]
    pub fn in_own_goal(&self, x_mm: f64, y_mm: f64) -> bool {
        x_mm <= -self.length_mm / 2.0 && y_mm.abs() <= self.goal_mouth_mm / 2.0
    }
}

/// Distance (mm) and bearing relative to the robot's heading (deg, in (−180, 180]) from the
/// robot to a point.
#[must_use]
pub fn range_bearing(robot: &Pose, x_mm: f64, y_mm: f64) -> (f64, f64) {
    let (dx, dy) = (x_mm - robot.x_mm(), y_mm - robot.y_mm());
    (dx.hypot(dy), wrap_angle_euclid_rad(dy.atan2(dx) - robot.theta_rad()).to_degrees())
}

/// The six precondition measures of a state: distance and bearing from the robot to the
/// target goal, the own goal and the ball (thesis §3.3.3).
#[must_use]
pub fn precondition_measures(frame: &TrackedFrame, pitch: &Pitch) -> [f64; 6] {
    let robot = &frame.robot;
    let (tx, ty) = pitch.target_goal();
    let (ox, oy) = pitch.own_goal();
    let target = range_bearing(robot, tx, ty);
    let own = range_bearing(robot, ox, oy);
    let ball = range_bearing(robot, frame.ball_x_mm, frame.ball_y_mm);
    [target.0, target.1, own.0, own.1, ball.0, ball.1]
}

/// Distance from the ball to the target goal's centre.
#[must_use]
pub fn ball_to_goal_mm(frame: &TrackedFrame, pitch: &Pitch) -> f64 {
    let (tx, ty) = pitch.target_goal();
    (frame.ball_x_mm - tx).hypot(frame.ball_y_mm - ty)
}

/// Distance from the robot to the ball.
#[must_use]
pub fn robot_to_ball_mm(frame: &TrackedFrame) -> f64 {
    (frame.ball_x_mm - frame.robot.x_mm()).hypot(frame.ball_y_mm - frame.robot.y_mm())
}
