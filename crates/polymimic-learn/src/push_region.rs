//! Where the demonstrators were when they pushed the ball toward the goal, learned from the
//! demonstrations that ended in goals. A pose is taken relative to the ball and the line from
//! the ball to the target goal's centre, so one region serves wherever the ball lies.

use polymimic_types::{Pose, wrap_angle_euclid_rad};
use serde::{Deserialize, Serialize};

use crate::round::{Ending, SegmentedDemonstration};
use crate::state::{Pitch, ball_to_goal_mm};

/// The share of pushing poses left out at each end of a range (the 10th to 90th percentile).
const RANGE_TAIL: f64 = 0.1;

/// The robot's pose in the ball–goal frame: behind (−) or ahead (+) of the ball along the line
/// from the ball to the goal, to its left (+) or right (−), and heading relative to the line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallGoalPose {
    pub along_mm: f64,
    pub across_mm: f64,
    pub heading_rad: f64,
}

impl BallGoalPose {
    #[must_use]
    pub fn of(robot: &Pose, ball: (f64, f64), pitch: &Pitch) -> Self {
        let (gx, gy) = pitch.target_goal();
        let line_rad = (gy - ball.1).atan2(gx - ball.0);
        let (sin, cos) = line_rad.sin_cos();
        let (dx, dy) = (robot.x_mm() - ball.0, robot.y_mm() - ball.1);
        Self {
            along_mm: cos * dx + sin * dy,
            across_mm: -sin * dx + cos * dy,
            heading_rad: wrap_angle_euclid_rad(robot.theta_rad() - line_rad),
        }
    }

    #[must_use]
    pub fn distance_mm(&self) -> f64 {
        self.along_mm.hypot(self.across_mm)
    }
}

/// A closed interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Interval {
    pub low: f64,
    pub high: f64,
}

impl Interval {
    /// The central part of `values` (at least `min_half_width` either side of the median).
    fn central(values: &mut [f64], min_half_width: f64) -> Self {
        values.sort_by(f64::total_cmp);
        let at = |share: f64| values[((values.len() - 1) as f64 * share).round() as usize];
        let median = at(0.5);
        Self {
            low: at(RANGE_TAIL).min(median - min_half_width),
            high: at(1.0 - RANGE_TAIL).max(median + min_half_width),
        }
    }

    #[must_use]
    pub fn contains(&self, value: f64) -> bool {
        (self.low..=self.high).contains(&value)
    }
}

/// The region of the ball–goal frame from which the demonstrators pushed the ball toward the
/// goal, and how near the ball the robot may come elsewhere without touching it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PushRegion {
    pub along_mm: Interval,
    pub across_mm: Interval,
    pub heading_rad: Interval,
    /// The median distance from the ball from which pushes were made: nearer than that,
    /// outside the region, the robot would touch the ball.
    pub contact_mm: f64,
    /// Pushing segments the region was learned from.
    pub pushes: usize,
}

impl PushRegion {
    /// From every segment of the demonstrations on `pitch` that ended in a goal which carried
    /// the ball more than `ball_moved_mm` nearer the goal, whether it set the ball moving or
    /// kept a push going (so the region holds where a push continues as well as where it
    /// begins); `None` if there is no such segment. Ranges are at least `min_half_width` (mm, rad) either side
    /// of their medians.
    #[must_use]
    pub fn learn(
        demonstrations: &[SegmentedDemonstration],
        pitch: &Pitch,
        ball_moved_mm: f64,
        min_half_width: (f64, f64),
    ) -> Option<Self> {
        let mut starts = Vec::new();
        for demo in demonstrations.iter().filter(|d| d.pitch == *pitch && d.ending == Ending::Goal) {
            for segment in &demo.segments {
                let (start, end) = (&segment.start, &segment.end);
                if ball_to_goal_mm(start, pitch) - ball_to_goal_mm(end, pitch) <= ball_moved_mm {
                    continue;
                }
                let pose = BallGoalPose::of(&start.robot, (start.ball_x_mm, start.ball_y_mm), pitch);
                if [pose.along_mm, pose.across_mm, pose.heading_rad].iter().all(|v| v.is_finite()) {
                    starts.push(pose);
                }
            }
        }
        if starts.is_empty() {
            return None;
        }
        let column = |f: fn(&BallGoalPose) -> f64| starts.iter().map(f).collect::<Vec<f64>>();
        let (mm, rad) = min_half_width;
        let mut distances = column(BallGoalPose::distance_mm);
        distances.sort_by(f64::total_cmp);
        Some(Self {
            along_mm: Interval::central(&mut column(|p| p.along_mm), mm),
            across_mm: Interval::central(&mut column(|p| p.across_mm), mm),
            heading_rad: Interval::central(&mut column(|p| p.heading_rad), rad),
            contact_mm: distances[distances.len() / 2],
            pushes: starts.len(),
        })
    }

    /// Whether the demonstrators pushed from poses like `pose`.
    #[must_use]
    pub fn contains(&self, pose: &BallGoalPose) -> bool {
        self.along_mm.contains(pose.along_mm)
            && self.across_mm.contains(pose.across_mm)
            && self.heading_rad.contains(pose.heading_rad)
    }
}

#[cfg(test)]
mod tests {
    use polymimic_perceive::{Label, Segment};
    use polymimic_types::{Primitive, TrackedFrame};

    use super::*;

    fn frame(robot: (f64, f64, f64), ball: (f64, f64)) -> TrackedFrame {
        TrackedFrame { robot: Pose::new(robot.0, robot.1, robot.2), ball_x_mm: ball.0, ball_y_mm: ball.1 }
    }

    fn segment(start: TrackedFrame, end: TrackedFrame) -> Segment {
        Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: 0,
            last_frame: 30,
            start,
            end,
            scores: [0.0; 4],
        }
    }

    fn demo(ending: Ending, segments: Vec<Segment>) -> SegmentedDemonstration {
        SegmentedDemonstration { demonstrator: "expert".to_owned(), pitch: Pitch::LARGE, ending, segments }
    }

    #[test]
    fn the_ball_goal_frame_measures_from_the_ball_along_the_line_to_the_goal() {
        // Ball at (110, 400): the goal's centre (510, 0) lies 45° to its right.
        let ball = (110.0, 400.0);
        let line = (-1.0_f64).atan2(1.0);
        let behind = Pose::new(110.0 - 100.0 * line.cos(), 400.0 - 100.0 * line.sin(), line);
        let pose = BallGoalPose::of(&behind, ball, &Pitch::LARGE);
        assert!((pose.along_mm + 100.0).abs() < 1e-9 && pose.across_mm.abs() < 1e-9 && pose.heading_rad.abs() < 1e-12);
        // 50 mm to the line's left (counter-clockwise from it), facing back along it.
        let left = Pose::new(110.0 - 50.0 * line.sin(), 400.0 + 50.0 * line.cos(), line + std::f64::consts::PI);
        let pose = BallGoalPose::of(&left, ball, &Pitch::LARGE);
        assert!(pose.along_mm.abs() < 1e-9 && (pose.across_mm - 50.0).abs() < 1e-9);
        assert!((pose.heading_rad.abs() - std::f64::consts::PI).abs() < 1e-9);
    }

    #[test]
    fn the_region_spans_the_central_pushing_poses_of_scoring_demonstrations() {
        // Ten pushes straight at the goal from 120, 130, … 210 mm behind the ball.
        let pushes = (0..10)
            .map(|k| {
                let back = 120.0 + 10.0 * f64::from(k);
                segment(frame((-back, 0.0, 0.0), (0.0, 0.0)), frame((40.0 - back, 0.0, 0.0), (40.0, 0.0)))
            })
            .collect();
        // Not learned from: a demonstration ending in an own goal, and a segment that moved the
        // ball no nearer the goal.
        let own_goal = demo(
            Ending::OwnGoal,
            vec![segment(frame((-400.0, 300.0, 1.0), (0.0, 0.0)), frame((-400.0, 300.0, 1.0), (60.0, 0.0)))],
        );
        let sideways = segment(frame((0.0, -300.0, 0.0), (0.0, 0.0)), frame((0.0, -300.0, 0.0), (0.0, 60.0)));
        let demos = [demo(Ending::Goal, pushes), own_goal, demo(Ending::Goal, vec![sideways])];
        let region = PushRegion::learn(&demos, &Pitch::LARGE, 10.0, (20.0, 0.1)).expect("ten pushes");
        assert_eq!(region.pushes, 10);
        // Percentiles by rank: the 10th of 10 values is the second smallest, the 90th the ninth.
        assert_eq!((region.along_mm.low, region.along_mm.high), (-200.0, -130.0));
        // Every push on the line, facing the goal: the minimum widths apply.
        assert_eq!((region.across_mm.low, region.across_mm.high), (-20.0, 20.0));
        assert_eq!((region.heading_rad.low, region.heading_rad.high), (-0.1, 0.1));
        assert_eq!(region.contact_mm, 170.0);
        let inside = BallGoalPose { along_mm: -150.0, across_mm: 10.0, heading_rad: 0.05 };
        assert!(region.contains(&inside));
        assert!(!region.contains(&BallGoalPose { heading_rad: 0.2, ..inside }));
        assert!(!region.contains(&BallGoalPose { along_mm: -250.0, ..inside }));
        assert!(PushRegion::learn(&demos[1..2], &Pitch::LARGE, 10.0, (20.0, 0.1)).is_none());
        assert!(PushRegion::learn(&demos, &Pitch::SMALL, 10.0, (20.0, 0.1)).is_none());
    }
}
