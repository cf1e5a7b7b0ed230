//! Where the demonstrators were when they pushed the ball toward the goal, learned from the
//! demonstrations that ended in goals. A pose is taken relative to the ball and the line from
//! the ball to the target goal's centre, so one region serves wherever the ball lies.

use polymimic_types::{Pose, wrap_angle_euclid_rad};
use serde::{Deserialize, Serialize};

use crate::round::{Ending, SegmentedDemonstration};
use crate::state::{Pitch, ball_to_goal_mm};
use crate::weighting::weighted;

/// The share of pushing poses left out at each end of the along and across ranges (the 10th to
/// 90th percentile); the heading range's share is [`RegionShape::heading_tail`].
const RANGE_TAIL: f64 = 0.1;

/// How the region's ranges are cut from the pushing poses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegionShape {
    /// The least half-width of the along and across ranges either side of their medians (mm)…
    pub min_half_width_mm: f64,
    /// …and of the heading range (rad).
    pub min_half_width_rad: f64,
    /// The share of pushing headings left out at each end of the heading range, in [0, 0.5)
    /// (as [`crate::LearningConfig::check`] holds `push_heading_tail` to).
    pub heading_tail: f64,
}

impl RegionShape {
    /// Ranges from the 10th to the 90th percentile, at least `min_half_width` (mm, rad) either
    /// side of their medians.
    #[must_use]
    pub const fn central(min_half_width: (f64, f64)) -> Self {
        Self { min_half_width_mm: min_half_width.0, min_half_width_rad: min_half_width.1, heading_tail: RANGE_TAIL }
    }
}

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

/// The weighted percentile `share` of `values` (each a value and its weight), sorted by value:
/// the value k whose cumulative weight before it, `c_k`, lies nearest `share · c_{n−1}` (the
/// later on a tie). With every weight 1 that is the value of rank `round((n − 1) · share)`.
fn percentile(sorted: &[(f64, f64)], share: f64) -> f64 {
    let Some(((last, _), before)) = sorted.split_last() else { return f64::NAN };
    let target = before.iter().map(|&(_, w)| w).sum::<f64>() * share;
    let (mut best, mut best_gap, mut cumulative) = (*last, f64::INFINITY, 0.0);
    for &(value, weight) in sorted {
        let gap = (cumulative - target).abs();
        if gap <= best_gap {
            (best, best_gap) = (value, gap);
        }
        cumulative += weight;
    }
    best
}

/// `values` sorted by value (a stable sort: equal values keep their order).
fn sorted(mut values: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    values.sort_by(|a, b| a.0.total_cmp(&b.0));
    values
}

impl Interval {
    /// The central part of `values` (each a value and its weight): from the weighted
    /// percentile `tail` to `1 − tail`, and at least `min_half_width` either side of the
    /// weighted median.
    fn central(values: Vec<(f64, f64)>, min_half_width: f64, tail: f64) -> Self {
        let values = sorted(values);
        let at = |share: f64| percentile(&values, share);
        let median = at(0.5);
        Self { low: at(tail).min(median - min_half_width), high: at(1.0 - tail).max(median + min_half_width) }
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
    /// begins); `None` if there is no such segment. `shape` says how the ranges are cut.
    #[must_use]
    pub fn learn(
        demonstrations: &[SegmentedDemonstration],
        pitch: &Pitch,
        ball_moved_mm: f64,
        shape: &RegionShape,
    ) -> Option<Self> {
        Self::learn_weighted(demonstrations, &[], pitch, ball_moved_mm, shape)
    }

    /// [`Self::learn`], every push of demonstration i weighing `weights[i]` (see
    /// [`crate::WorldModel::learn_weighted`]): ranges and the contact distance are weighted
    /// percentiles, `pushes` counts the pushes of weight above 0.
    #[must_use]
    pub fn learn_weighted(
        demonstrations: &[SegmentedDemonstration],
        weights: &[f64],
        pitch: &Pitch,
        ball_moved_mm: f64,
        shape: &RegionShape,
    ) -> Option<Self> {
        let mut starts = Vec::new();
        let scoring = weighted(demonstrations, weights).filter(|(d, _)| d.pitch == *pitch && d.ending == Ending::Goal);
        for (demo, weight) in scoring {
            for segment in &demo.segments {
                let (start, end) = (&segment.start, &segment.end);
                if ball_to_goal_mm(start, pitch) - ball_to_goal_mm(end, pitch) <= ball_moved_mm {
                    continue;
                }
                let pose = BallGoalPose::of(&start.robot, (start.ball_x_mm, start.ball_y_mm), pitch);
                if [pose.along_mm, pose.across_mm, pose.heading_rad].iter().all(|v| v.is_finite()) {
                    starts.push((pose, weight));
                }
            }
        }
        if starts.is_empty() {
            return None;
        }
        let column = |f: fn(&BallGoalPose) -> f64| starts.iter().map(|(p, w)| (f(p), *w)).collect::<Vec<_>>();
        let mm = shape.min_half_width_mm;
        Some(Self {
            along_mm: Interval::central(column(|p| p.along_mm), mm, RANGE_TAIL),
            across_mm: Interval::central(column(|p| p.across_mm), mm, RANGE_TAIL),
            heading_rad: Interval::central(column(|p| p.heading_rad), shape.min_half_width_rad, shape.heading_tail),
            // The weighted median: with every weight 1, the value of rank n / 2.
            contact_mm: percentile(&sorted(column(BallGoalPose::distance_mm)), 0.5),
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

    const SHAPE: RegionShape = RegionShape::central((20.0, 0.1));

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
            scores: [0.0; 7],
        }
    }

    fn demo(ending: Ending, segments: Vec<Segment>) -> SegmentedDemonstration {
        SegmentedDemonstration {
            demonstrator: "expert".to_owned(),
            pitch: Pitch::LARGE,
            reach_mm: None,
            ending,
            segments,
        }
    }

    #[test]
    fn a_weighted_percentile_is_the_value_whose_weight_before_it_is_nearest_the_share() {
        // Weights 1, 3, 1, 1 on 10, 20, 30, 40: c = 0, 1, 4, 5 and c₃ = 5.
        let values = sorted(vec![(30.0, 1.0), (10.0, 1.0), (40.0, 1.0), (20.0, 3.0)]);
        assert_eq!(percentile(&values, 0.3), 20.0, "1.5: c₁ = 1 is nearest");
        assert_eq!(percentile(&values, 0.05), 10.0, "0.25: c₀ = 0 is nearest");
        assert_eq!(percentile(&values, 0.7), 30.0, "3.5: c₂ = 4 is nearest");
        assert_eq!(percentile(&values, 0.5), 30.0, "2.5: c₁ = 1 and c₂ = 4 tie, the later wins");
        assert_eq!(percentile(&values, 0.9), 40.0, "4.5: c₂ = 4 and c₃ = 5 tie, the later wins");
        // Evenly, the median of four is the third (rank round(1.5) = 2).
        let even = sorted(vec![(30.0, 1.0), (10.0, 1.0), (40.0, 1.0), (20.0, 1.0)]);
        assert_eq!((percentile(&even, 0.5), percentile(&even, 0.3)), (30.0, 20.0));
        assert_eq!(percentile(&[(7.0, 0.5)], 0.9), 7.0);
    }

    #[test]
    fn weights_of_one_pick_the_rank_the_unweighted_percentile_picked() {
        for n in 1..80_u32 {
            // Values out of order, some repeated.
            let values: Vec<f64> = (0..n).map(|k| f64::from((k * 37) % 23) - 0.5 * f64::from(k % 4)).collect();
            let mut plain = values.clone();
            plain.sort_by(f64::total_cmp);
            let ones = sorted(values.iter().map(|&v| (v, 1.0)).collect());
            for share in [RANGE_TAIL, 0.5, 1.0 - RANGE_TAIL, 0.0, 1.0, 0.25] {
                let rank = ((plain.len() - 1) as f64 * share).round() as usize;
                assert_eq!(percentile(&ones, share).to_bits(), plain[rank].to_bits(), "n = {n}, share = {share}");
            }
            assert_eq!(percentile(&ones, 0.5).to_bits(), plain[plain.len() / 2].to_bits(), "the median, n = {n}");
        }
    }

    #[test]
    fn pushes_weigh_what_their_demonstrations_weigh() {
        let push =
            |back: f64| segment(frame((-back, 0.0, 0.0), (0.0, 0.0)), frame((40.0 - back, 0.0, 0.0), (40.0, 0.0)));
        let near = demo(Ending::Goal, (0..5).map(|k| push(120.0 + 10.0 * f64::from(k))).collect());
        let far = demo(Ending::Goal, (0..5).map(|k| push(300.0 + 10.0 * f64::from(k))).collect());
        let demos = [near, far];
        let learn = |weights: &[f64]| PushRegion::learn_weighted(&demos, weights, &Pitch::LARGE, 10.0, &SHAPE);
        assert_eq!(learn(&[1.0, 0.0]), PushRegion::learn(&demos[..1], &Pitch::LARGE, 10.0, &SHAPE));
        assert_eq!(learn(&[1.0, 1.0]), PushRegion::learn(&demos, &Pitch::LARGE, 10.0, &SHAPE));
        // Evenly, the median distance is the sixth of ten (300) and the 10th percentile of
        // along_mm the second (−330).
        let even = learn(&[]).expect("ten pushes");
        assert_eq!((even.contact_mm, even.along_mm.low, even.along_mm.high), (300.0, -330.0, -130.0));
        // The near pushes weigh 4, the far 1. Distances 120 … 160 then 300 … 340: c = 0, 4, 8,
        // 12, 16, 20, … with c₉ = 24, so the median (12) is the fourth, 150 mm. along_mm
        // −340 … −300 then −160 … −120: c = 0 … 5, 9, 13, 17, 21 (c₉ = 21); the 10th percentile
        // (2.1) is the third, −320, the 90th (18.9) the ninth, −130.
        let region = learn(&[4.0, 1.0]).expect("ten pushes");
        assert_eq!(region.pushes, 10);
        assert_eq!(region.contact_mm, 150.0);
        assert_eq!((region.along_mm.low, region.along_mm.high), (-320.0, -130.0));
        assert_eq!(learn(&[0.0, 0.0]), None);
    }

    #[test]
    fn a_heading_tail_cuts_the_heading_range_alone_at_its_percentiles() {
        // Ten pushes from 150 mm behind the ball, headings −0.45, −0.35, … 0.45 rad.
        let pushes = (0..10)
            .map(|k| {
                let heading = -0.45 + 0.1 * f64::from(k);
                segment(frame((-150.0, 0.0, heading), (0.0, 0.0)), frame((-110.0, 0.0, heading), (40.0, 0.0)))
            })
            .collect();
        let demos = [demo(Ending::Goal, pushes)];
        let cut = |heading_tail| {
            PushRegion::learn(&demos, &Pitch::LARGE, 10.0, &RegionShape { heading_tail, ..SHAPE }).expect("pushes")
        };
        let close = |interval: Interval, low: f64, high: f64| {
            (interval.low - low).abs() < 1e-12 && (interval.high - high).abs() < 1e-12
        };
        // Ranks round(9 · share): 10th and 90th percentiles the second and ninth values, 30th and
        // 70th the fourth and seventh, none left out the first and last.
        assert!(close(cut(0.1).heading_rad, -0.35, 0.35));
        assert!(close(cut(0.3).heading_rad, -0.15, 0.15));
        assert!(close(cut(0.0).heading_rad, -0.45, 0.45));
        assert_eq!(cut(0.3).along_mm, cut(0.1).along_mm, "the other ranges keep their tails");
        // The median is the sixth value, 0.05: a wide minimum half-width overrules any cut.
        let floored = PushRegion::learn(
            &demos,
            &Pitch::LARGE,
            10.0,
            &RegionShape { heading_tail: 0.3, min_half_width_rad: 0.3, ..SHAPE },
        );
        assert!(close(floored.expect("pushes").heading_rad, -0.25, 0.35));
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
        let region = PushRegion::learn(&demos, &Pitch::LARGE, 10.0, &SHAPE).expect("ten pushes");
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
        assert!(PushRegion::learn(&demos[1..2], &Pitch::LARGE, 10.0, &SHAPE).is_none());
        assert!(PushRegion::learn(&demos, &Pitch::SMALL, 10.0, &SHAPE).is_none());
    }
}
