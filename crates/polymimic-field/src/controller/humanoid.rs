//! The humanoid's competition-style controller (local vision). It remembers where it last saw
//! the ball; when it expected to see the ball and did not, it stops and scans (Lost, Scan
//! Forward, Scan Down, Scan Left, Scan Right), then turns to search. With the ball known it
//! walks round to the ball–goal line, lines a foot up with side-steps and kicks.

use std::collections::VecDeque;

use polymimic_types::{Point, Pose};

use crate::body::HumanoidParams;
use crate::command::{Command, HumanoidCommand as H};
use crate::episode::Observation;
use crate::math::{deg, wrap_angle_rad};

use super::Controller;
use super::planner::{Plan, Sizes, aim_point, plan};

/// Scan routine after losing the ball: (command, seconds).
const SEARCH: [(H, f64); 6] = [
    (H::Lost, 0.5),
    (H::ScanForward, 0.5),
    (H::ScanDown, 0.6),
    (H::ScanLeft, 1.0),
    (H::ScanRight, 1.6),
    (H::TurnLeft, 2.5),
];

/// How long an unseen ball's remembered position is trusted, s.
const MEMORY_S: f64 = 3.0;

/// Ball centre ahead of the body centre at which the swinging foot meets it, mm.
const KICK_RANGE_MM: (f64, f64) = (85.0, 130.0);

#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    Play,
    /// Searching since this time (s), turning this way (+1 left, −1 right) at the end.
    Search(f64, f64),
}

/// The Humanoid demonstrator's controller.
#[derive(Debug, Clone)]
pub struct HumanoidController {
    memory: Option<(Point, f64)>,
    mode: Mode,
    /// A command under way and when it ends (s), then commands queued after it (s each).
    holding: Option<(H, f64)>,
    queue: VecDeque<(H, f64)>,
    sizes: Sizes,
    turning: bool,
    /// Side the ball was last seen on (+1 left): the search turns that way.
    last_side: f64,
    /// Whether the last command made it step (its camera may see nothing then).
    stepping: bool,
    params: HumanoidParams,
}

impl Default for HumanoidController {
    fn default() -> Self {
        Self::new(HumanoidParams::default())
    }
}

impl HumanoidController {
    /// A fresh controller of a humanoid built and playing as `params` say.
    #[must_use]
    pub fn new(params: HumanoidParams) -> Self {
        Self {
            memory: None,
            mode: Mode::Play,
            holding: None,
            queue: VecDeque::new(),
            sizes: Sizes {
                ball_r: 50.0,
                front: params.length_mm / 2.0,
                reach: 0.5 * params.length_mm.hypot(params.width_mm),
                gap: params.spot_gap_mm,
                spot_tol: params.spot_tolerance_mm,
                face_tol_rad: deg(15.0),
            },
            turning: false,
            last_side: 1.0,
            stepping: false,
            params,
        }
    }

    /// Did the camera look where the remembered ball should be, without seeing it?
    fn expected_but_missing(&self, robot: Pose, remembered: Point) -> bool {
        let rel = robot.relative_bearing_rad(remembered).abs();
        let dist = robot.point().dist_mm(remembered);
        rel < 0.7 * self.params.camera_half_fov_rad && dist < 0.8 * self.params.camera_range_mm && dist > 150.0
    }

    fn walk_to(&mut self, robot: Pose, target: Point) -> H {
        let e = robot.relative_bearing_rad(target);
        let limit = if self.turning { deg(10.0) } else { deg(30.0) };
        self.turning = e.abs() > limit;
        if self.turning {
            if e > 0.0 { H::TurnLeft } else { H::TurnRight }
        } else if e > deg(8.0) {
            H::WalkForwardLeft
        } else if e < deg(-8.0) {
            H::WalkForwardRight
        } else {
            H::WalkForward
        }
    }

    fn play(&mut self, obs: &Observation, ball: Point) -> H {
        let robot = obs.robot;
        let aim = aim_point(&obs.field);
        let goal_heading = ball.bearing_rad(aim);
        let heading_err = wrap_angle_rad(goal_heading - robot.theta_rad());
        let b = robot.robot_from_field(ball);
        let behind = robot.point().dist_mm(aim) > ball.dist_mm(aim);
        // Close behind the ball and roughly facing the goal: line up a foot and kick.
        if behind
            && b.x_mm() > 40.0
            && b.x_mm() < self.params.lineup_ahead_mm
            && b.y_mm().abs() < self.params.lineup_side_mm
            && heading_err.abs() < deg(30.0)
        {
            if heading_err.abs() > deg(10.0) {
                return if heading_err > 0.0 { H::TurnLeft } else { H::TurnRight };
            }
            let side = if b.y_mm() >= 0.0 { 1.0 } else { -1.0 };
            let lateral_err = b.y_mm() - side * self.params.foot_side_mm;
            if lateral_err.abs() > self.params.lineup_tolerance_mm {
                return if lateral_err > 0.0 { H::ShuffleLeft } else { H::ShuffleRight };
            }
            if b.x_mm() > KICK_RANGE_MM.1 {
                return H::WalkForward;
            }
            if b.x_mm() < KICK_RANGE_MM.0 {
                return H::WalkBackward;
            }
            return if side > 0.0 { H::KickLeft } else { H::KickRight };
        }
        match plan(robot, ball, &obs.field, &self.sizes, false) {
            Plan::GoTo(t) => self.walk_to(robot, t),
            Plan::Push(_) => self.walk_to(robot, ball),
            Plan::Face(h) => {
                if wrap_angle_rad(h - robot.theta_rad()) > 0.0 {
                    H::TurnLeft
                } else {
                    H::TurnRight
                }
            }
        }
    }
}

impl Controller for HumanoidController {
    fn command(&mut self, obs: &Observation) -> Command {
        let h = self.decide(obs);
        self.stepping = h.steps();
        Command::Humanoid(h)
    }
}

impl HumanoidController {
    fn decide(&mut self, obs: &Observation) -> H {
        let t = obs.t_s;
        if let Some(ball) = obs.ball {
            self.memory = Some((ball, t));
            self.last_side = if obs.robot.relative_bearing_rad(ball) >= 0.0 { 1.0 } else { -1.0 };
        } else if let Some((remembered, seen_s)) = self.memory {
            // Its self-localisation drifts, so memory is trusted only briefly; a camera that
            // bobs with the gait missing the ball is no news.
            let blind = self.stepping && self.params.walks_blind();
            let looked = !blind && self.expected_but_missing(obs.robot, remembered);
            if looked || t - seen_s > MEMORY_S {
                self.memory = None;
            } else if blind && self.params.look_after_s > 0.0 && t - seen_s > self.params.look_after_s {
                // Walked blind long enough: stand still and look.
                self.holding = Some((H::Wait, t + self.params.look_s));
                return H::Wait;
            }
        }
        if let Some((h, until)) = self.holding {
            if t < until - 1e-9 {
                return h;
            }
            self.holding = None;
        }
        if let Some((h, d)) = self.queue.pop_front() {
            self.holding = Some((h, t + d));
            return h;
        }
        let Some((ball, _)) = self.memory else {
            let (since, turn) = if let Mode::Search(since, turn) = self.mode {
                (since, turn)
            } else {
                self.mode = Mode::Search(t, self.last_side);
                (t, self.last_side)
            };
            let total: f64 = SEARCH.iter().map(|s| s.1).sum();
            let mut phase = (t - since) % total;
            for (h, d) in SEARCH {
                if phase < d {
                    let h = if h == H::TurnLeft && turn < 0.0 { H::TurnRight } else { h };
                    return h;
                }
                phase -= d;
            }
            return H::Lost;
        };
        if let Mode::Search(..) = self.mode {
            // Found it: settle, then get ready to walk.
            self.mode = Mode::Play;
            self.holding = Some((H::Wait, t + 0.3));
            self.queue.push_back((H::Go, 0.3));
            return H::Wait;
        }
        let h = self.play(obs, ball);
        if matches!(h, H::KickLeft | H::KickRight) {
            // A kick runs its whole course; then the robot steadies itself and gets ready.
            self.holding = Some((h, t + self.params.kick_s));
            self.queue.extend([(H::Wait, 0.4), (H::Go, 0.3)]);
        }
        h
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::BodyKind;
    use crate::geometry::{FieldGeometry, FieldSize};

    fn obs(t_s: f64, robot: Pose, ball: Option<Point>) -> Observation {
        Observation {
            t_s,
            frame_index: 0,
            robot,
            ball,
            field: FieldGeometry::of(FieldSize::Large),
            body: BodyKind::Humanoid,
        }
    }

    #[test]
    fn kicks_a_ball_lined_up_with_a_foot() {
        let mut c = HumanoidController::new(HumanoidParams::default());
        let robot = Pose::new(0.0, 0.0, 0.0);
        let ball = Point::new(110.0, 28.0);
        assert_eq!(c.command(&obs(0.0, robot, Some(ball))), Command::Humanoid(H::KickLeft));
        // The kick is held for its whole duration.
        assert_eq!(c.command(&obs(0.5, robot, None)), Command::Humanoid(H::KickLeft));
    }

    #[test]
    fn scans_when_the_ball_is_missing() {
        let mut c = HumanoidController::new(HumanoidParams::default());
        let robot = Pose::new(0.0, 0.0, 0.0);
        assert_eq!(c.command(&obs(0.0, robot, None)), Command::Humanoid(H::Lost));
        assert_eq!(c.command(&obs(0.7, robot, None)), Command::Humanoid(H::ScanForward));
        assert_eq!(c.command(&obs(1.8, robot, None)), Command::Humanoid(H::ScanLeft));
    }

    #[test]
    fn a_camera_blind_while_walking_makes_it_stop_to_look() {
        let blind = HumanoidParams { blind_gait: 0.5, look_after_s: 1.0, look_s: 0.4, ..HumanoidParams::default() };
        let robot = Pose::new(-300.0, 0.0, 0.0);
        let ball = Point::new(200.0, 0.0);
        for (params, stops) in [(blind, true), (HumanoidParams::default(), false)] {
            let mut c = HumanoidController::new(params);
            assert_eq!(c.command(&obs(0.0, robot, Some(ball))), Command::Humanoid(H::WalkForward));
            // Walking, it has not seen the ball for 1.2 s: a blind walker stands and looks,
            // for look_s; one that sees while walking has lost the ball where it expected it.
            let later = c.command(&obs(1.2, robot, None));
            assert_eq!(later == Command::Humanoid(H::Wait), stops, "{later:?}");
            if stops {
                assert_eq!(c.command(&obs(1.5, robot, None)), Command::Humanoid(H::Wait));
                assert_eq!(c.command(&obs(1.7, robot, Some(ball))), Command::Humanoid(H::WalkForward));
            }
        }
    }

    #[test]
    fn lines_up_by_side_steps_as_far_to_the_side_as_it_is_told() {
        // Facing the goal, the ball 150 mm ahead and 120 mm to the left.
        let robot = Pose::new(0.0, -120.0, 0.0);
        let ball = Point::new(150.0, 0.0);
        let narrow = HumanoidParams { lineup_side_mm: 90.0, ..HumanoidParams::default() };
        let mut narrow = HumanoidController::new(narrow);
        assert_ne!(narrow.command(&obs(0.0, robot, Some(ball))), Command::Humanoid(H::ShuffleLeft));
        let wide = HumanoidParams { lineup_side_mm: 250.0, ..HumanoidParams::default() };
        let mut wide = HumanoidController::new(wide);
        assert_eq!(wide.command(&obs(0.0, robot, Some(ball))), Command::Humanoid(H::ShuffleLeft));
    }
}
