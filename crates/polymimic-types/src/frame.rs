//! What the tracker reports, as the recogniser, the segmenter and the learner read it.

use serde::{Deserialize, Serialize};

use crate::point::Point;
use crate::pose::Pose;

/// One tracker frame: the robot's pose and the ball's position (mm; NaN while not tracked).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TrackedFrame {
    /// The robot's pose.
    pub robot: Pose,
    /// Ball x, mm.
    pub ball_x_mm: f64,
    /// Ball y, mm.
    pub ball_y_mm: f64,
}

impl TrackedFrame {
    /// A frame from the robot's pose and the ball's position.
    #[must_use]
    pub fn new(robot: Pose, ball: Point) -> Self {
        Self { robot, ball_x_mm: ball.x_mm(), ball_y_mm: ball.y_mm() }
    }

    /// The ball's position.
    #[must_use]
    pub const fn ball(&self) -> Point {
        Point::new(self.ball_x_mm, self.ball_y_mm)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serialises_with_the_robot_nested_and_the_ball_flat() {
        let frame = TrackedFrame::new(Pose::new(1.0, 2.0, 0.5), Point::new(3.0, 4.0));
        let text = serde_json::to_string(&frame).expect("numbers");
        assert_eq!(text, r#"{"robot":{"x_mm":1.0,"y_mm":2.0,"theta_rad":0.5},"ball_x_mm":3.0,"ball_y_mm":4.0}"#);
        assert_eq!(serde_json::from_str::<TrackedFrame>(&text).expect("valid"), frame);
        assert_eq!(frame.ball(), Point::new(3.0, 4.0));
    }
}
