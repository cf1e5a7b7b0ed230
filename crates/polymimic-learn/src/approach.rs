//! Getting to where the demonstrators pushed from with the imitator's own primitives: a
//! shortest-path table over the ball–goal frame, computed once from the learned push region and
//! the primitives' mean motion (Table 3.1). At each decision the robot takes the primitive
//! whose outcomes, over its spread, have the fewest primitives still to go, so noise is
//! corrected as it arises.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::f64::consts::TAU;

use polymimic_types::{Pose, Primitive, TrackedFrame, wrap_angle_euclid_rad};

use crate::prediction::MotionTable;
use crate::push_region::{BallGoalPose, PushRegion};
use crate::state::Pitch;

/// The table's cells: square, centred on the ball (so the ball–goal line runs along a row of
/// centres), out to this many cells either side of it…
const HALF_CELLS: i64 = 30;
const CELL_MM: f64 = 20.0;
/// …and heading bins centred on facing the goal.
const HEADING_BINS: i64 = 36;
/// What a primitive ending nearer the ball than pushes are made from costs, in primitives: enough that
/// a route goes round the ball, while a robot already too near still finds the way out.
const CONTACT_COST: u32 = 50;
/// The primitives a route is made of: the body's own that move it (stopping never gets
/// anywhere, and a kick is for the ball, not a way to walk): F B L R on a wheeled body, and
/// the side-steps too on the humanoid.
fn route_moves(motion: &MotionTable) -> Vec<Primitive> {
    motion.primitives().filter(|p| !matches!(p, Primitive::Stop | Primitive::Kick)).collect()
}

const CELLS: usize = (2 * HALF_CELLS + 1) as usize;
/// The push region must hold at least one cell and one heading bin either side of its middle
/// (mm, rad), or the table could find no cell inside it.
pub(crate) const MIN_REGION_HALF_WIDTH: (f64, f64) = (CELL_MM, TAU / HEADING_BINS as f64);
const UNREACHABLE: u32 = u32::MAX;
/// What a pose with no route counts as, in primitives still to go.
const LOST_STEPS: f64 = 4.0 * CONTACT_COST as f64;

/// Primitives to go from each pose of the ball–goal frame to the push region.
#[derive(Debug, Clone, PartialEq)]
pub struct ApproachPlan {
    pub push_region: PushRegion,
    steps: Vec<u32>,
}

fn index(pose: &BallGoalPose) -> Option<usize> {
    let cell = |mm: f64| {
        let i = (mm / CELL_MM).round() + HALF_CELLS as f64;
        (0.0..CELLS as f64).contains(&i).then_some(i as usize)
    };
    let bin = ((pose.heading_rad / TAU * HEADING_BINS as f64).round() as i64).rem_euclid(HEADING_BINS) as usize;
    Some((cell(pose.along_mm)? * CELLS + cell(pose.across_mm)?) * HEADING_BINS as usize + bin)
}

fn centre(index: usize) -> BallGoalPose {
    let bins = HEADING_BINS as usize;
    let mm = |i: usize| (i as f64 - HALF_CELLS as f64) * CELL_MM;
    let bin = (index % bins) as f64;
    BallGoalPose {
        along_mm: mm(index / bins / CELLS),
        across_mm: mm((index / bins) % CELLS),
        heading_rad: wrap_angle_euclid_rad(bin / HEADING_BINS as f64 * TAU),
    }
}

/// The ball–goal frame as a field of its own (the ball does not move), so the primitives'
/// motion applies to it unchanged.
fn as_pose(pose: &BallGoalPose) -> Pose {
    Pose::new(pose.along_mm, pose.across_mm, pose.heading_rad)
}

fn from_pose(pose: Pose) -> BallGoalPose {
    BallGoalPose { along_mm: pose.x_mm(), across_mm: pose.y_mm(), heading_rad: pose.theta_rad() }
}

/// What a move from `from` to `to` costs: one primitive, and [`CONTACT_COST`] more if on the
/// way or at the end the robot comes nearer the ball than pushes are made from, outside the
/// push region.
fn move_cost(from: &BallGoalPose, to: &BallGoalPose, region: &PushRegion) -> u32 {
    let near = |p: &BallGoalPose| p.distance_mm() < region.contact_mm && !region.contains(p);
    let halfway = BallGoalPose {
        along_mm: f64::midpoint(from.along_mm, to.along_mm),
        across_mm: f64::midpoint(from.across_mm, to.across_mm),
        ..*to
    };
    if near(to) || near(&halfway) { 1 + CONTACT_COST } else { 1 }
}

impl ApproachPlan {
    /// Shortest routes (in primitives) into the push region by Dijkstra's algorithm,
    /// backward from the region over the mean motion of each primitive.
    #[must_use]
    pub fn new(push_region: PushRegion, motion: &MotionTable) -> Self {
        let states = CELLS * CELLS * HEADING_BINS as usize;
        // Every move between two states, then grouped by the state it leads into (a counting
        // sort, so each state's predecessors are one run of `from` and `cost`).
        let route = route_moves(motion);
        let mut moves: Vec<(u32, u32, u32)> = Vec::with_capacity(states * route.len());
        for from in 0..states {
            let pose = centre(from);
            for &primitive in &route {
                let after = from_pose(motion.mean_step(as_pose(&pose), primitive));
                match index(&after) {
                    Some(to) if to != from => {
                        moves.push((to as u32, from as u32, move_cost(&pose, &after, &push_region)));
                    }
                    _ => {}
                }
            }
        }
        let mut first_into = vec![0_usize; states + 1];
        for &(to, ..) in &moves {
            first_into[to as usize + 1] += 1;
        }
        for i in 0..states {
            first_into[i + 1] += first_into[i];
        }
        let mut into = vec![(0_u32, 0_u32); moves.len()];
        let mut filled = first_into.clone();
        for &(to, from, cost) in &moves {
            into[filled[to as usize]] = (from, cost);
            filled[to as usize] += 1;
        }
        let mut steps = vec![UNREACHABLE; states];
        let mut queue = BinaryHeap::new();
        for (i, s) in steps.iter_mut().enumerate() {
            if push_region.contains(&centre(i)) {
                *s = 0;
                queue.push(Reverse((0, i)));
            }
        }
        while let Some(Reverse((cost, state))) = queue.pop() {
            if cost > steps[state] {
                continue;
            }
            for &(from, step) in &into[first_into[state]..first_into[state + 1]] {
                let via = cost + step;
                if via < steps[from as usize] {
                    steps[from as usize] = via;
                    queue.push(Reverse((via, from as usize)));
                }
            }
        }
        Self { push_region, steps }
    }

    /// Primitives still to go from `pose` (`None` off the table or with no route).
    #[must_use]
    pub fn steps_from(&self, pose: &BallGoalPose) -> Option<u32> {
        index(pose).map(|i| self.steps[i]).filter(|&s| s != UNREACHABLE)
    }

    /// The primitive to take from `state` toward the push region, keeping the robot on
    /// `pitch`: the one whose outcomes (mean, and one sd either side in distance and in
    /// rotation) cost the fewest primitives, on the way and still to go. Judged from the centre
    /// of the table's cell the robot is in, as the table was made, so that the route the table
    /// promises is the one taken. `None` if the robot's cell is in the region, off the table or
    /// has no route.
    #[must_use]
    pub fn next(&self, state: &TrackedFrame, motion: &MotionTable, pitch: &Pitch) -> Option<Primitive> {
        let ball = (state.ball_x_mm, state.ball_y_mm);
        let cell = centre(index(&BallGoalPose::of(&state.robot, ball, pitch))?);
        if self.steps_from(&cell)? == 0 {
            return None;
        }
        route_moves(motion)
            .into_iter()
            .filter(|&primitive| {
                let robot = motion.mean_step(state.robot, primitive);
                pitch.contains(robot.x_mm(), robot.y_mm())
            })
            .map(|primitive| {
                let cost: f64 = motion
                    .spread_steps(as_pose(&cell), primitive)
                    .map(from_pose)
                    .iter()
                    .map(|after| match self.steps_from(after) {
                        Some(steps) => f64::from(steps + move_cost(&cell, after, &self.push_region)),
                        None => LOST_STEPS,
                    })
                    .sum();
                (cost, primitive)
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, primitive)| primitive)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::push_region::Interval;

    /// Exact primitives: 40 mm forward or back, 30° turns on the spot.
    fn exact_motion() -> MotionTable {
        MotionTable::exact(40.0, 30.0)
    }

    /// Pushes from 130 to 170 mm behind the ball, within 20 mm of the line, facing the goal.
    fn region() -> PushRegion {
        PushRegion {
            along_mm: Interval { low: -170.0, high: -130.0 },
            across_mm: Interval { low: -20.0, high: 20.0 },
            heading_rad: Interval { low: -0.1, high: 0.1 },
            contact_mm: 170.0,
            pushes: 1,
        }
    }

    #[test]
    fn routes_count_the_fewest_primitives_to_the_region() {
        let plan = ApproachPlan::new(region(), &exact_motion());
        let at = |along_mm, heading_rad| BallGoalPose { along_mm, across_mm: 0.0, heading_rad };
        assert_eq!(plan.steps_from(&at(-150.0, 0.0)), Some(0));
        // 400 mm behind facing the goal: six pushes forward reach −160 mm; five only −200 mm.
        assert_eq!(plan.steps_from(&at(-400.0, 0.0)), Some(6));
        // Facing away: at least six 30° turns and six 40 mm moves, in any order.
        assert_eq!(plan.steps_from(&at(-400.0, std::f64::consts::PI)), Some(12));
        // Beyond the table: no route known.
        assert_eq!(plan.steps_from(&at(-700.0, 0.0)), None);
    }

    #[test]
    fn a_robot_between_the_ball_and_the_goal_goes_round_the_ball() {
        let motion = exact_motion();
        let plan = ApproachPlan::new(region(), &motion);
        let pitch = Pitch::LARGE;
        // Configuration 2: the ball before the robot's own goal, the robot facing it from the goal side.
        let ball = (-170.0, 0.0);
        let mut state =
            TrackedFrame { robot: Pose::new(170.0, 0.0, std::f64::consts::PI), ball_x_mm: ball.0, ball_y_mm: ball.1 };
        let planned = plan.steps_from(&BallGoalPose::of(&state.robot, ball, &pitch)).expect("a route");
        let mut taken = 0;
        while let Some(primitive) = plan.next(&state, &motion, &pitch) {
            state.robot = motion.mean_step(state.robot, primitive);
            taken += 1;
            let pose = BallGoalPose::of(&state.robot, ball, &pitch);
            assert!(pitch.contains(state.robot.x_mm(), state.robot.y_mm()));
            // Cells are judged by their centres, up to half a cell's diagonal away.
            assert!(
                plan.steps_from(&pose) == Some(0) || pose.distance_mm() >= 170.0 - CELL_MM / 2.0_f64.sqrt(),
                "primitive {taken} ({primitive:?}) comes {:.0} mm from the ball",
                pose.distance_mm()
            );
            assert!(taken <= planned + 8, "{taken} primitives where {planned} were planned");
        }
        assert_eq!(plan.steps_from(&BallGoalPose::of(&state.robot, ball, &pitch)), Some(0));
        assert!(taken >= 12, "no route round the ball is shorter than 12 primitives, took {taken}");
    }
}
