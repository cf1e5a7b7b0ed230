//! One episode: a body (and maybe a ball) on the field, stepped one tracker frame at a time by
//! whoever chooses the commands: a built-in controller or an external policy.

use polymimic_types::{Point, Pose};
use serde::{Deserialize, Serialize};

use crate::body::{Body, BodyKind};
use crate::command::Command;
use crate::error::{FieldError, FieldParamError};
use crate::geometry::FieldGeometry;
use crate::math::{Rng, rng, stream};
use crate::physics::{Physics, Scene};
use crate::setup::{EpisodeSetup, FieldConfig};
use crate::tracker::{FRAME_DT_S, Frame, Measurement, Tracker};

/// How an episode ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Outcome {
    /// The ball's centre crossed the target goal line (+x) inside the mouth.
    Goal,
    /// The ball's centre crossed the own goal line (−x) inside the mouth.
    OwnGoal,
    /// The ball's centre left the field elsewhere.
    BallOut,
    /// The robot's centre left the field.
    RobotOut,
    /// The time limit passed.
    TimeUp,
}

impl Outcome {
    /// Name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Outcome::Goal => "goal",
            Outcome::OwnGoal => "own_goal",
            Outcome::BallOut => "ball_out",
            Outcome::RobotOut => "robot_out",
            Outcome::TimeUp => "time_up",
        }
    }
}

/// What a controller gets each frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Observation {
    /// Time, s.
    pub t_s: f64,
    /// Index of the frame about to be recorded.
    pub frame_index: usize,
    /// The robot's tracked pose (the last good one while tracking is lost).
    pub robot: Pose,
    /// The tracked ball, if the robot can see it (a humanoid sees it only through its camera).
    pub ball: Option<Point>,
    /// The field.
    pub field: FieldGeometry,
    /// The robot.
    pub body: BodyKind,
}

/// The result of one [`Episode::step`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepResult {
    /// The frame recorded for this step (state at its start, and the command sent).
    pub frame: Frame,
    /// Set once the episode has ended.
    pub outcome: Option<Outcome>,
    /// Whether tracking was lost on this frame (the episode is then invalid).
    pub tracking_lost: bool,
}

/// A running episode.
pub struct Episode {
    config: FieldConfig,
    setup: EpisodeSetup,
    field: FieldGeometry,
    body: Body,
    body_rng: Rng,
    physics: Option<Physics>,
    ball: Option<Point>,
    tracker: Tracker,
    pending: Measurement,
    last_good: Measurement,
    frames: Vec<Frame>,
    t_s: f64,
    steps: usize,
    outcome: Option<Outcome>,
    tracking_lost: bool,
    last_command: Option<Command>,
}

impl Episode {
    /// Start an episode.
    ///
    /// # Errors
    /// A parameter error for an invalid config, or a robot or ball placed off the field.
    pub fn new(setup: &EpisodeSetup, config: &FieldConfig, seed: u64) -> Result<Self, FieldError> {
        config.check()?;
        let field = setup.body.field();
        field.check()?;
        check_on_field(&field, "robot", setup.robot.point(), setup.robot.is_finite())?;
        if let Some(b) = setup.ball {
            check_on_field(&field, "ball", b, b.is_finite())?;
        }
        if setup.time_limit_s.is_nan() || setup.time_limit_s <= 0.0 {
            return Err(FieldParamError::OutOfRange {
                name: "time_limit_s",
                value: setup.time_limit_s,
                expected: "positive (infinite allowed)",
            }
            .into());
        }
        let body = Body::new(setup.body, setup.robot, &config.humanoid);
        let dt_s = FRAME_DT_S / f64::from(config.substeps_per_frame);
        let physics = setup.ball.map(|ball| {
            let scene = Scene {
                ball,
                ball_diameter_mm: field.ball_diameter_mm,
                ball_params: config.ball,
                robot: setup.robot,
                footprint_mm: body.footprint_mm(),
                foot_size_mm: body.foot_size_mm(),
            };
            Physics::new(&scene, dt_s, rng(seed, stream::BALL))
        });
        let mut tracker = Tracker::new(config.tracker, rng(seed, stream::TRACKER));
        let pending = tracker.measure(setup.robot, setup.ball);
        let mut episode = Self {
            config: *config,
            setup: *setup,
            field,
            body,
            body_rng: rng(seed, stream::BODY),
            physics,
            ball: setup.ball,
            tracker,
            pending,
            last_good: pending,
            frames: Vec::new(),
            t_s: 0.0,
            steps: 0,
            outcome: None,
            tracking_lost: pending.lost,
            last_command: None,
        };
        if pending.lost {
            // Nothing good seen yet: the controller gets the truth until tracking returns.
            episode.last_good = Measurement { robot: setup.robot, ball: setup.ball, lost: false };
        }
        Ok(episode)
    }

    /// What a controller sees now.
    #[must_use]
    pub fn observation(&self) -> Observation {
        let m = if self.pending.lost { self.last_good } else { self.pending };
        let seen = self.ball.is_some_and(|b| self.body.sees(b));
        Observation {
            t_s: self.t_s,
            frame_index: self.frames.len(),
            robot: m.robot,
            ball: m.ball.filter(|_| seen),
            field: self.field,
            body: self.setup.body,
        }
    }

    /// Record the current frame with `command` and simulate one frame period.
    ///
    /// # Errors
    /// `EpisodeFinished` after the end; a parameter error for a command this body cannot
    /// execute; `Diverged` if the physics produced a non-finite state.
    pub fn step(&mut self, command: Command) -> Result<StepResult, FieldError> {
        if let Some(o) = self.outcome {
            return Err(FieldError::EpisodeFinished(o.name()));
        }
        self.body.command(command, &mut self.body_rng)?;
        self.last_command = Some(command);
        let lost_now = self.pending.lost;
        let frame = self.frame_of(self.pending, command);
        self.frames.push(frame);
        let substeps = self.config.substeps_per_frame;
        let dt_s = FRAME_DT_S / f64::from(substeps);
        for _ in 0..substeps {
            self.body.substep(dt_s, &mut self.body_rng);
            let pose = self.body.pose();
            if let Some(physics) = self.physics.as_mut() {
                let foot = self.body.foot().map(|f| (f.pose, f.active));
                physics.advance(pose, foot);
                let before = self.ball.unwrap_or(physics.ball());
                let now = physics.ball();
                self.ball = Some(now);
                if !now.is_finite() {
                    return Err(FieldError::Diverged("ball position"));
                }
                if let Some(o) = ball_outcome(&self.field, before, now) {
                    self.outcome = Some(o);
                    break;
                }
            }
            if !pose.is_finite() {
                return Err(FieldError::Diverged("robot pose"));
            }
            if !self.field.contains(pose.point()) {
                self.outcome = Some(Outcome::RobotOut);
                break;
            }
        }
        self.steps += 1;
        self.t_s = self.steps as f64 * FRAME_DT_S;
        if self.outcome.is_none() && self.t_s >= self.setup.time_limit_s - 1e-9 {
            self.outcome = Some(Outcome::TimeUp);
        }
        self.pending = self.tracker.measure(self.body.pose(), self.ball);
        if self.pending.lost {
            self.tracking_lost = true;
        } else {
            self.last_good = self.pending;
        }
        if self.outcome.is_some() {
            // The final state, so the frames show how it ended.
            let last = self.frame_of(self.pending, command);
            self.frames.push(last);
        }
        Ok(StepResult { frame, outcome: self.outcome, tracking_lost: lost_now })
    }

    /// Lift the robot and put it down at rest at `pose` (the experimenter's hand, §3.1.1).
    ///
    /// # Errors
    /// `OutsideField` for a pose off the field; `EpisodeFinished` after the end.
    pub fn place_robot(&mut self, pose: Pose) -> Result<(), FieldError> {
        if let Some(o) = self.outcome {
            return Err(FieldError::EpisodeFinished(o.name()));
        }
        check_on_field(&self.field, "robot", pose.point(), pose.is_finite())?;
        self.body.place(pose);
        if let Some(p) = self.physics.as_mut() {
            p.teleport_robot(pose);
        }
        self.pending = self.tracker.measure(self.body.pose(), self.ball);
        if self.pending.lost {
            self.tracking_lost = true;
        } else {
            self.last_good = self.pending;
        }
        Ok(())
    }

    fn frame_of(&self, m: Measurement, command: Command) -> Frame {
        let ball = m.ball.unwrap_or(Point::new(f64::NAN, f64::NAN));
        Frame {
            t_s: self.t_s,
            robot_x_mm: m.robot.x_mm(),
            robot_y_mm: m.robot.y_mm(),
            robot_theta_rad: m.robot.theta_rad(),
            ball_x_mm: ball.x_mm(),
            ball_y_mm: ball.y_mm(),
            command: command.id(),
        }
    }

    /// The field's configuration it runs under.
    #[must_use]
    pub fn config(&self) -> &FieldConfig {
        &self.config
    }

    /// Frames recorded so far.
    #[must_use]
    pub fn frames(&self) -> &[Frame] {
        &self.frames
    }

    /// Take the recorded frames.
    #[must_use]
    pub fn into_frames(self) -> Vec<Frame> {
        self.frames
    }

    /// How it ended, once it has.
    #[must_use]
    pub fn outcome(&self) -> Option<Outcome> {
        self.outcome
    }

    /// Has it ended?
    #[must_use]
    pub fn is_finished(&self) -> bool {
        self.outcome.is_some()
    }

    /// False once tracking has dropped out (the demonstration must be discarded).
    #[must_use]
    pub fn is_valid(&self) -> bool {
        !self.tracking_lost
    }

    /// Time, s.
    #[must_use]
    pub fn t_s(&self) -> f64 {
        self.t_s
    }

    /// The robot's true pose (not what the tracker saw).
    #[must_use]
    pub fn robot_pose(&self) -> Pose {
        self.body.pose()
    }

    /// The ball's true position.
    #[must_use]
    pub fn ball_position(&self) -> Option<Point> {
        self.ball
    }

    /// The field.
    #[must_use]
    pub fn field(&self) -> FieldGeometry {
        self.field
    }

    /// The set-up it started from.
    #[must_use]
    pub fn setup(&self) -> &EpisodeSetup {
        &self.setup
    }

    /// Is the humanoid in the middle of a kick (commands are ignored until it ends)?
    #[must_use]
    pub fn is_kicking(&self) -> bool {
        self.body.is_kicking()
    }

    /// The last command sent.
    #[must_use]
    pub fn last_command(&self) -> Option<Command> {
        self.last_command
    }
}

fn check_on_field(field: &FieldGeometry, what: &'static str, p: Point, finite: bool) -> Result<(), FieldParamError> {
    if finite && field.contains(p) {
        Ok(())
    } else {
        Err(FieldParamError::OutsideField { what, x_mm: p.x_mm(), y_mm: p.y_mm() })
    }
}

/// Did the ball leave the field between two positions, and how?
fn ball_outcome(field: &FieldGeometry, before: Point, now: Point) -> Option<Outcome> {
    let (hl, hw) = (field.half_length_mm(), field.half_width_mm());
    if now.x_mm().abs() > hl {
        let line = hl.copysign(now.x_mm());
        let dx = now.x_mm() - before.x_mm();
        let f = if dx.abs() > 0.0 { ((line - before.x_mm()) / dx).clamp(0.0, 1.0) } else { 1.0 };
        let y_cross = before.y_mm() + f * (now.y_mm() - before.y_mm());
        return Some(if y_cross.abs() <= field.goal_half_mouth_mm() {
            if now.x_mm() > 0.0 { Outcome::Goal } else { Outcome::OwnGoal }
        } else {
            Outcome::BallOut
        });
    }
    (now.y_mm().abs() > hw).then_some(Outcome::BallOut)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::FieldSize;
    use crate::setup::Configuration;
    use polymimic_types::Primitive;

    #[test]
    fn ball_crossing_inside_the_mouth_is_a_goal() {
        let f = FieldGeometry::of(FieldSize::Large);
        let goal = ball_outcome(&f, Point::new(505.0, 10.0), Point::new(515.0, 12.0));
        assert_eq!(goal, Some(Outcome::Goal));
        let own = ball_outcome(&f, Point::new(-505.0, -10.0), Point::new(-515.0, -12.0));
        assert_eq!(own, Some(Outcome::OwnGoal));
        let wide = ball_outcome(&f, Point::new(505.0, 300.0), Point::new(515.0, 300.0));
        assert_eq!(wide, Some(Outcome::BallOut));
        let side = ball_outcome(&f, Point::new(0.0, 400.0), Point::new(0.0, 406.0));
        assert_eq!(side, Some(Outcome::BallOut));
        assert_eq!(ball_outcome(&f, Point::new(0.0, 0.0), Point::new(1.0, 0.0)), None);
    }

    #[test]
    fn driving_forward_in_configuration_one_scores() {
        let config = FieldConfig { tracker: crate::TrackerConfig::noiseless(), ..FieldConfig::default() };
        let setup = EpisodeSetup::configuration(BodyKind::Lego, Configuration::One, &config);
        let mut e = Episode::new(&setup, &config, 5).expect("valid");
        let fwd = Command::Primitive(Primitive::Forward);
        while !e.is_finished() {
            e.step(fwd).expect("step");
        }
        assert!(matches!(e.outcome(), Some(Outcome::Goal | Outcome::BallOut | Outcome::RobotOut)));
        assert!(e.frames().len() > 100);
        assert!(e.step(fwd).is_err());
    }

    #[test]
    fn same_seed_gives_identical_frames() {
        let config = FieldConfig::default();
        let setup = EpisodeSetup::configuration(BodyKind::Lego, Configuration::Two, &config);
        let run = |seed| {
            let mut e = Episode::new(&setup, &config, seed).expect("valid");
            for i in 0..300 {
                let p = Primitive::WHEELED[(i / 30) % 5];
                e.step(Command::Primitive(p)).expect("step");
            }
            e.into_frames()
        };
        let (a, b, c) = (run(1), run(1), run(2));
        let bits = |f: &[Frame]| -> Vec<u64> {
            f.iter()
                .flat_map(|x| [x.robot_x_mm.to_bits(), x.robot_theta_rad.to_bits(), x.ball_x_mm.to_bits()])
                .collect()
        };
        assert_eq!(bits(&a), bits(&b));
        assert_ne!(bits(&a), bits(&c));
    }

    #[test]
    fn bad_setups_are_parameter_errors() {
        let config = FieldConfig::default();
        let mut setup = EpisodeSetup::alone(BodyKind::Lego);
        setup.robot = Pose::new(2000.0, setup.robot.y_mm(), setup.robot.theta_rad());
        assert!(matches!(
            Episode::new(&setup, &config, 0),
            Err(FieldError::Param(FieldParamError::OutsideField { .. }))
        ));
        setup.robot = Pose::new(f64::NAN, setup.robot.y_mm(), setup.robot.theta_rad());
        assert!(Episode::new(&setup, &config, 0).is_err());
        let setup = EpisodeSetup::alone(BodyKind::Humanoid);
        let mut e = Episode::new(&setup, &config, 0).expect("valid");
        assert!(matches!(
            e.step(Command::Primitive(Primitive::Forward)),
            Err(FieldError::Param(FieldParamError::CommandNotSupported { .. }))
        ));
    }
}

#[cfg(test)]
mod thread_safety {
    use super::*;

    #[test]
    fn episodes_and_results_can_cross_threads() {
        fn send_sync<T: Send + Sync>() {}
        send_sync::<Episode>();
        send_sync::<crate::Demonstration>();
        send_sync::<crate::PrimitiveSequence>();
    }
}
