//! The imitator's final model stepped one tracker reading at a time: what the control keeps
//! between decisions (the thesis control's behaviour in progress and its generator, the last
//! ball it saw, the primitive it holds), so that anything that reads a tracker can drive it —
//! the field's own evaluation, a recording, a Gymnasium loop or a live tracker.
//!
//! A primitive is held for one second, as the thesis's imitator executes them (§3.1.1):
//! decisions fall on a one-second grid from the episode's first reading (tracker frames 0, 30,
//! 60, … on the field), and a reading between two decisions gets the command held since the
//! last. The last-seen ball is read at decisions only, as the evaluation always has.

use polymimic_field::controller::{primitive_command, primitive_command_seeing};
use polymimic_field::{
    Command, DecisionRate, EpisodeStart, FieldConfig, FieldError, Observation, Policy, PolicyRecording, Start,
    record_policy,
};
use polymimic_types::{Point, Pose, Primitive, TrackedFrame};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::control::{ControlMode, ImitatorPolicy};
use crate::prefix_tree::PrefixTree;

/// Seconds one primitive is held for.
pub const PRIMITIVE_S: f64 = 1.0;

/// Half a tracker frame, s: how early a reading may come and still be a decision's.
const HALF_FRAME_S: f64 = 0.5 / 30.0;

/// The stream of the thesis control's draws under an episode seed.
const CONTROL_STREAM: u64 = 7;

/// One episode of the imitator in progress: everything its control keeps between readings.
#[derive(Debug, Clone)]
pub struct Stepping {
    /// The behaviours' shared beginnings (the improved control chains them at each decision).
    tree: Option<PrefixTree>,
    /// The thesis control's draws (its predicted motions).
    rng: ChaCha8Rng,
    /// The ball where it was last seen at a decision, mm.
    last_ball: (f64, f64),
    /// The robot's last tracked pose (a reading that lost it keeps this one).
    last_robot: Pose,
    /// The thesis control's behaviour in progress and the index of its next primitive.
    behaviour: Option<(usize, usize)>,
    /// The command held until the next decision.
    held: Option<Command>,
    /// Time of the episode's first reading, s: the decision grid's origin.
    origin_s: Option<f64>,
    /// Decision instants reached so far.
    decisions: u64,
    /// What was executed, as letters (whole behaviours by the thesis's rule, primitives by the
    /// improved one).
    executed: Vec<String>,
}

impl Stepping {
    /// The letters of what was executed so far.
    #[must_use]
    pub fn executed(&self) -> &[String] {
        &self.executed
    }

    /// Hand over what was executed, ending the episode's record.
    #[must_use]
    pub fn into_executed(self) -> Vec<String> {
        self.executed
    }

    /// Whether a reading at `t_s` is a decision instant (and, if so, count it).
    fn decides_at(&mut self, t_s: f64) -> bool {
        let origin_s = *self.origin_s.get_or_insert(t_s);
        let due_s = origin_s + self.decisions as f64 * PRIMITIVE_S - HALF_FRAME_S;
        if t_s < due_s && self.held.is_some() {
            return false;
        }
        // Past instants missed while no reading came are skipped, so the grid stays the same.
        let passed = ((t_s - origin_s + HALF_FRAME_S) / PRIMITIVE_S).floor().max(0.0) as u64;
        self.decisions = passed.max(self.decisions) + 1;
        true
    }
}

impl ImitatorPolicy<'_> {
    /// A new episode from `start` under episode seed `seed` (whose draws the thesis control
    /// makes; the improved control makes none). The ball is taken to be where the start puts
    /// it until the tracker shows it.
    #[must_use]
    pub fn start(&self, start: &Start, seed: u64) -> Stepping {
        let tree = (self.mode == ControlMode::Improved)
            .then(|| PrefixTree::new(self.model.behaviours.iter().map(|b| b.primitives.as_slice())));
        Stepping {
            tree,
            rng: ChaCha8Rng::seed_from_u64(polymimic_field::derive_seed(seed, CONTROL_STREAM, 0)),
            last_ball: (start.ball.x_mm(), start.ball.y_mm()),
            last_robot: start.robot,
            behaviour: None,
            held: None,
            origin_s: None,
            decisions: 0,
            executed: Vec::new(),
        }
    }

    /// The command to send after `reading` (its time, the robot's tracked pose and the ball
    /// if seen), held since the last decision or decided now. A reading whose robot pose is not
    /// finite (the tracker lost it) stands on the last one that was.
    pub fn act(&self, stepping: &mut Stepping, reading: &Observation) -> Command {
        if reading.robot.is_finite() {
            stepping.last_robot = reading.robot;
        }
        if stepping.decides_at(reading.t_s) {
            let seen = Observation { robot: stepping.last_robot, ..*reading };
            let primitive = self.decide(stepping, &seen);
            // Only a kick depends on what the robot sees now: which foot.
            let command = if primitive == Primitive::Kick {
                primitive_command_seeing(primitive, &seen)
            } else {
                primitive_command(primitive, self.body)
            };
            stepping.held = Some(command);
        }
        stepping.held.unwrap_or(Command::Primitive(Primitive::Stop))
    }

    /// The primitive to run for the next second from `reading`, decided now.
    pub fn decide(&self, stepping: &mut Stepping, reading: &Observation) -> Primitive {
        if let Some(ball) = reading.ball.filter(|b| b.is_finite()) {
            stepping.last_ball = (ball.x_mm(), ball.y_mm());
        }
        let robot = if reading.robot.is_finite() { reading.robot } else { stepping.last_robot };
        let state = TrackedFrame { robot, ball_x_mm: stepping.last_ball.0, ball_y_mm: stepping.last_ball.1 };
        if let Some(tree) = &stepping.tree {
            let primitive = self.choose_primitive(tree, &state).unwrap_or(Primitive::Stop);
            stepping.executed.push(primitive.letter().to_string());
            return primitive;
        }
        // The thesis's rule: go on with the behaviour in progress unless its next primitive
        // would leave the field, else choose one (or wait a second if none can move).
        if let Some((index, k)) = stepping.behaviour.take()
            && let Some(&primitive) = self.model.behaviours[index].primitives.get(k)
        {
            let next = self.motion.step(robot, primitive, f64::INFINITY, &mut stepping.rng);
            if self.pitch().contains(next.x_mm(), next.y_mm()) {
                stepping.behaviour = Some((index, k + 1));
                return primitive;
            }
        }
        let Some(index) = self.choose(&state, &mut stepping.rng) else {
            return Primitive::Stop;
        };
        let behaviour = &self.model.behaviours[index];
        stepping.executed.push(behaviour.letters());
        // The first primitive's check draws as every other's does; it runs even if it leaves.
        let _ = self.motion.step(robot, behaviour.primitives[0], f64::INFINITY, &mut stepping.rng);
        stepping.behaviour = Some((index, 1));
        behaviour.primitives[0]
    }
}

/// An imitator recording itself as a demonstrator does: a fresh episode at every reset, from
/// the start of the episode's configuration.
pub struct PlayingImitator<'a> {
    policy: ImitatorPolicy<'a>,
    stepping: Option<Stepping>,
}

impl<'a> PlayingImitator<'a> {
    /// `policy`, ready to play.
    #[must_use]
    pub const fn new(policy: ImitatorPolicy<'a>) -> Self {
        Self { policy, stepping: None }
    }
}

impl Policy for PlayingImitator<'_> {
    type Error = std::convert::Infallible;

    fn reset(&mut self, start: &EpisodeStart) -> Result<(), Self::Error> {
        self.stepping = Some(self.policy.start(&Start::of(start.configuration, start.body), start.seed));
        Ok(())
    }

    fn act(&mut self, reading: &Observation) -> Result<Command, Self::Error> {
        let stepping = self.stepping.get_or_insert_with(|| {
            let ball = reading.ball.unwrap_or(Point::new(0.0, 0.0));
            self.policy.start(&Start { robot: reading.robot, ball }, 0)
        });
        Ok(self.policy.act(stepping, reading))
    }
}

impl ImitatorPolicy<'_> {
    /// `n_valid` valid attempts of the imitator from `configuration`, recorded as a
    /// demonstrator's are (their episode seeds from `seed`; attempts with lost tracking
    /// skipped), so that an imitator can be watched and learned from.
    ///
    /// # Errors
    /// The field's: a config that does not validate, or too many attempts losing tracking.
    pub fn record(
        &self,
        configuration: polymimic_field::Configuration,
        n_valid: usize,
        seed: u64,
        field: &FieldConfig,
    ) -> Result<Vec<PolicyRecording>, FieldError> {
        let mut player = PlayingImitator::new(ImitatorPolicy { ..*self });
        record_policy(&mut player, self.body, configuration, n_valid, seed, DecisionRate::EVERY_FRAME, field).map_err(
            |failure| match failure.cause {
                polymimic_field::PolicyFault::Field(e) => e,
                polymimic_field::PolicyFault::Policy(never) => match never {},
            },
        )
    }
}
