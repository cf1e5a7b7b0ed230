//! Demonstrators whose decisions come from outside the field (docs/guides/own-data.md): a policy that may
//! fail (a Python callable, a network peer) decides at a rate it declares, each command held
//! until its next decision; a failure ends the recording with the attempt and time it struck.

use crate::body::{BodyKind, HumanoidParams};
use crate::command::Command;
use crate::controller::Controller;
use crate::demonstrate::{Demonstrator, attempts_for};
use crate::episode::{Episode, Observation, Outcome};
use crate::error::{FieldError, FieldParamError};
use crate::math::derive_seed;
use crate::setup::{Configuration, EpisodeSetup, FieldConfig};
use crate::tracker::{FRAME_RATE_HZ, Frame};

/// A demonstrator outside the field, asked for a command at every decision.
pub trait Policy {
    /// Whatever the policy can fail with.
    type Error;

    /// A new episode starts (before its first decision).
    ///
    /// # Errors
    /// Whatever the policy reports; the recording stops.
    fn reset(&mut self, start: &EpisodeStart) -> Result<(), Self::Error>;

    /// The command to send until the next decision.
    ///
    /// # Errors
    /// Whatever the policy reports; the recording stops.
    fn act(&mut self, reading: &Observation) -> Result<Command, Self::Error>;
}

/// A built-in demonstrator's controller deciding at a policy's rate (a fresh one every
/// episode): the same controller in Rust, to compare a policy written elsewhere against.
pub struct ControllerPolicy {
    demonstrator: Demonstrator,
    humanoid: HumanoidParams,
    controller: Box<dyn Controller>,
}

impl ControllerPolicy {
    /// `demonstrator`'s controller as a policy.
    #[must_use]
    pub fn new(demonstrator: Demonstrator, humanoid: HumanoidParams) -> Self {
        Self { demonstrator, humanoid, controller: demonstrator.controller(&humanoid) }
    }
}

impl Policy for ControllerPolicy {
    type Error = std::convert::Infallible;

    fn reset(&mut self, _start: &EpisodeStart) -> Result<(), Self::Error> {
        self.controller = self.demonstrator.controller(&self.humanoid);
        Ok(())
    }

    fn act(&mut self, reading: &Observation) -> Result<Command, Self::Error> {
        Ok(self.controller.command(reading))
    }
}

/// What a policy is told when an episode starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpisodeStart {
    /// The attempt's index within its configuration (0, 1, …; invalid attempts included).
    pub attempt: usize,
    /// The field configuration.
    pub configuration: Configuration,
    /// The episode seed.
    pub seed: u64,
    /// The body the policy drives.
    pub body: BodyKind,
}

/// How often a policy decides: every `frames` tracker frames (a divisor of the 30 frames a
/// second, so decisions fall on frames and every second holds the same number of them).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DecisionRate {
    frames: u32,
}

impl DecisionRate {
    /// A decision on every tracker frame, as the built-in controllers decide.
    pub const EVERY_FRAME: Self = Self { frames: 1 };

    /// The rate of `hz` decisions a second.
    ///
    /// # Errors
    /// `OutOfRange` unless `hz` divides 30 (30, 15, 10, 6, 5, 3, 2 or 1).
    pub fn from_hz(hz: f64) -> Result<Self, FieldParamError> {
        let rate = f64::from(FRAME_RATE_HZ);
        let frames = rate / hz;
        if hz.is_finite() && hz > 0.0 && frames.fract() == 0.0 && frames <= rate {
            Ok(Self { frames: frames as u32 })
        } else {
            Err(FieldParamError::OutOfRange {
                name: "decision_hz",
                value: hz,
                expected: "a divisor of the tracker's 30 frames/s: 30, 15, 10, 6, 5, 3, 2 or 1",
            })
        }
    }

    /// Tracker frames between decisions.
    #[must_use]
    pub const fn frames(self) -> u32 {
        self.frames
    }
}

/// One recorded attempt of a policy.
#[derive(Debug, Clone, PartialEq)]
pub struct PolicyRecording {
    /// The field configuration.
    pub configuration: Configuration,
    /// The episode seed.
    pub seed: u64,
    /// How it ended.
    pub outcome: Outcome,
    /// Whether tracking held throughout.
    pub valid: bool,
    /// The tracker frames, one per 1/30 s, ending with the final state.
    pub frames: Vec<Frame>,
}

/// A recording that stopped: where, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct PolicyFailure<E> {
    /// The attempt (within its configuration) it stopped in.
    pub attempt: usize,
    /// That attempt's episode seed.
    pub seed: u64,
    /// Episode time of the decision that failed, s.
    pub t_s: f64,
    /// Why.
    pub cause: PolicyFault<E>,
}

/// The cause of a [`PolicyFailure`].
#[derive(Debug, Clone, PartialEq)]
pub enum PolicyFault<E> {
    /// The policy failed.
    Policy(E),
    /// The field refused (a command this body cannot execute, too many lost recordings, …).
    Field(FieldError),
}

/// Attempt `attempt` of `configuration` runs with episode seed
/// `derive_seed(seed, POLICY_STREAM + configuration, attempt)`, apart from the built-in
/// demonstrators' streams.
const POLICY_STREAM: u64 = 400;

/// The episode seed of a policy's attempt.
#[must_use]
pub fn policy_episode_seed(seed: u64, configuration: Configuration, attempt: usize) -> u64 {
    derive_seed(seed, POLICY_STREAM + u64::from(configuration.number()), attempt as u64)
}

/// Run one attempt of `policy` (valid or not).
///
/// # Errors
/// The policy's failure, or the field's, with the time it happened.
pub fn demonstrate_policy<P: Policy>(
    policy: &mut P,
    body: BodyKind,
    start: EpisodeStart,
    rate: DecisionRate,
    config: &FieldConfig,
) -> Result<PolicyRecording, PolicyFailure<P::Error>> {
    let fail = |t_s: f64, cause| PolicyFailure { attempt: start.attempt, seed: start.seed, t_s, cause };
    let setup = EpisodeSetup::configuration(body, start.configuration, config);
    let mut episode = Episode::new(&setup, config, start.seed).map_err(|e| fail(0.0, PolicyFault::Field(e)))?;
    policy.reset(&start).map_err(|e| fail(0.0, PolicyFault::Policy(e)))?;
    let mut command = None;
    let every = rate.frames() as usize;
    while !episode.is_finished() {
        let reading = episode.observation();
        if reading.frame_index % every == 0 || command.is_none() {
            command = Some(policy.act(&reading).map_err(|e| fail(reading.t_s, PolicyFault::Policy(e)))?);
        }
        if let Some(c) = command {
            episode.step(c).map_err(|e| fail(reading.t_s, PolicyFault::Field(e)))?;
        }
    }
    let (outcome, valid) = (episode.outcome().unwrap_or(Outcome::TimeUp), episode.is_valid());
    Ok(PolicyRecording {
        configuration: start.configuration,
        seed: start.seed,
        outcome,
        valid,
        frames: episode.into_frames(),
    })
}

/// Record `n_valid` valid attempts of `policy` on `body` from `configuration`, one after the
/// other (a policy is one stateful object). Attempts with lost tracking are skipped, as the
/// built-in demonstrators' are, so the result is the first `n_valid` valid attempts in order.
///
/// # Errors
/// The policy's failure or the field's, with the attempt and time; `RetriesExhausted` (as a
/// field fault) if too many attempts lose tracking.
pub fn record_policy<P: Policy>(
    policy: &mut P,
    body: BodyKind,
    configuration: Configuration,
    n_valid: usize,
    seed: u64,
    rate: DecisionRate,
    config: &FieldConfig,
) -> Result<Vec<PolicyRecording>, PolicyFailure<P::Error>> {
    let max_attempts = attempts_for(n_valid);
    let mut out = Vec::with_capacity(n_valid);
    for attempt in 0..max_attempts {
        if out.len() == n_valid {
            return Ok(out);
        }
        let start =
            EpisodeStart { attempt, configuration, seed: policy_episode_seed(seed, configuration, attempt), body };
        let recording = demonstrate_policy(policy, body, start, rate, config)?;
        if recording.valid {
            out.push(recording);
        }
    }
    if out.len() == n_valid {
        return Ok(out);
    }
    let exhausted = FieldError::RetriesExhausted { valid: out.len(), requested: n_valid, attempts: max_attempts };
    let last = max_attempts - 1;
    let last_seed = policy_episode_seed(seed, configuration, last);
    Err(PolicyFailure { attempt: last, seed: last_seed, t_s: 0.0, cause: PolicyFault::Field(exhausted) })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controller::LapseRate;
    use crate::demonstrate::demonstrate;
    use polymimic_types::Primitive;

    #[test]
    fn a_policy_deciding_every_frame_is_the_controller_bit_for_bit() {
        let config = FieldConfig::default();
        let mut policy = ControllerPolicy::new(Demonstrator::Poor, crate::body::HUMANOID);
        let start = EpisodeStart { attempt: 0, configuration: Configuration::Two, seed: 42, body: BodyKind::Lego };
        let ours =
            demonstrate_policy(&mut policy, BodyKind::Lego, start, DecisionRate::EVERY_FRAME, &config).expect("runs");
        let theirs = demonstrate(Demonstrator::Poor, Configuration::Two, 42, LapseRate::NONE, &config).expect("runs");
        assert_eq!(ours.outcome, theirs.outcome);
        let bits = |f: &[Frame]| {
            f.iter().map(|x| (x.robot_x_mm.to_bits(), x.ball_y_mm.to_bits(), x.command)).collect::<Vec<_>>()
        };
        assert_eq!(bits(&ours.frames), bits(&theirs.frames));
    }

    struct Scripted {
        decisions: Vec<f64>,
        fail_at_s: Option<f64>,
    }

    impl Policy for Scripted {
        type Error = &'static str;
        fn reset(&mut self, _start: &EpisodeStart) -> Result<(), &'static str> {
            Ok(())
        }
        fn act(&mut self, reading: &Observation) -> Result<Command, &'static str> {
            if self.fail_at_s.is_some_and(|t| reading.t_s >= t) {
                return Err("boom");
            }
            self.decisions.push(reading.t_s);
            // Alternate so that holding a command shows in the frames.
            let p = if self.decisions.len().is_multiple_of(2) { Primitive::Left } else { Primitive::Forward };
            Ok(Command::Primitive(p))
        }
    }

    #[test]
    fn decisions_fall_on_the_declared_rate_and_commands_are_held_between_them() {
        let config = FieldConfig { time_limit_s: 2.0, ..FieldConfig::default() };
        let mut policy = Scripted { decisions: Vec::new(), fail_at_s: None };
        let start = EpisodeStart { attempt: 0, configuration: Configuration::One, seed: 1, body: BodyKind::Lego };
        let rate = DecisionRate::from_hz(10.0).expect("divides 30");
        let r = demonstrate_policy(&mut policy, BodyKind::Lego, start, rate, &config).expect("runs");
        let stepped = r.frames.len() - 1;
        assert_eq!(policy.decisions.len(), stepped.div_ceil(3));
        for (i, chunk) in r.frames[..stepped].chunks(3).enumerate() {
            assert!(chunk.iter().all(|f| f.command == chunk[0].command), "held for three frames");
            assert!((policy.decisions[i] - chunk[0].t_s).abs() < 1e-12);
        }
    }

    #[test]
    fn a_failing_policy_is_reported_with_its_attempt_and_time() {
        let config = FieldConfig::default();
        let mut policy = Scripted { decisions: Vec::new(), fail_at_s: Some(1.0) };
        let rate = DecisionRate::from_hz(5.0).expect("divides 30");
        let e = record_policy(&mut policy, BodyKind::Lego, Configuration::One, 2, 9, rate, &config).expect_err("fails");
        assert_eq!(e.cause, PolicyFault::Policy("boom"));
        assert_eq!(e.attempt, 0);
        assert!((e.t_s - 1.0).abs() < 1e-9, "fails at the first decision at or past 1 s: {}", e.t_s);
        assert_eq!(e.seed, policy_episode_seed(9, Configuration::One, 0));
    }

    #[test]
    fn a_command_the_body_cannot_execute_is_a_field_fault() {
        let config = FieldConfig::default();
        let mut policy = Scripted { decisions: Vec::new(), fail_at_s: None };
        let start = EpisodeStart { attempt: 3, configuration: Configuration::One, seed: 1, body: BodyKind::Humanoid };
        let e = demonstrate_policy(&mut policy, BodyKind::Humanoid, start, DecisionRate::EVERY_FRAME, &config)
            .expect_err("a humanoid takes no primitives");
        assert!(matches!(e.cause, PolicyFault::Field(FieldError::Param(FieldParamError::CommandNotSupported { .. }))));
        assert_eq!(e.attempt, 3);
    }

    #[test]
    fn rates_that_do_not_divide_thirty_are_refused() {
        for hz in [30.0, 15.0, 10.0, 6.0, 5.0, 3.0, 2.0, 1.0] {
            assert_eq!(DecisionRate::from_hz(hz).map(DecisionRate::frames), Ok((30.0 / hz) as u32));
        }
        for hz in [0.0, -10.0, 7.0, 60.0, 0.5, f64::NAN, f64::INFINITY] {
            assert!(DecisionRate::from_hz(hz).is_err(), "{hz}");
        }
    }

    #[test]
    fn recording_keeps_valid_attempts_in_order_and_is_deterministic() {
        let mut config = FieldConfig { time_limit_s: 3.0, ..FieldConfig::default() };
        config.tracker.loss_probability = 0.003;
        let rate = DecisionRate::from_hz(10.0).expect("divides 30");
        let run = || {
            let mut policy = Scripted { decisions: Vec::new(), fail_at_s: None };
            record_policy(&mut policy, BodyKind::Lego, Configuration::Two, 4, 5, rate, &config).expect("records")
        };
        let (a, b) = (run(), run());
        let bits = |r: &[PolicyRecording]| -> Vec<(u64, u64)> {
            r.iter().flat_map(|x| x.frames.iter().map(|f| (x.seed, f.robot_theta_rad.to_bits()))).collect()
        };
        assert_eq!(bits(&a), bits(&b));
        assert_eq!(a.len(), 4);
        assert!(a.iter().all(|r| r.valid));
        let seeds: Vec<u64> = a.iter().map(|r| r.seed).collect();
        let all: Vec<u64> = (0..20).map(|i| policy_episode_seed(5, Configuration::Two, i)).collect();
        let positions: Vec<usize> =
            seeds.iter().map(|s| all.iter().position(|x| x == s).expect("a policy seed")).collect();
        assert!(positions.windows(2).all(|w| w[0] < w[1]));
    }
}
