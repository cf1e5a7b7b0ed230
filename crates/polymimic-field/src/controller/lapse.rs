//! Lapses (docs/guides/crowd.md): a demonstrator of known, graded skill. At the start of every second,
//! with probability ε, the demonstrator spends that second on one uniformly random imitator
//! primitive instead of its controller's commands; the controller is still asked every frame,
//! so that its clocks and its view of the ball stay current when it takes over again.

use polymimic_types::Primitive;
use rand::RngExt;
use serde::{Deserialize, Serialize};

use crate::body::BodyKind;
use crate::command::{Command, HumanoidCommand};
use crate::episode::Observation;
use crate::error::{FieldParamError, check_range};
use crate::math::{Rng, rng, stream, uniform};
use crate::tracker::FRAME_RATE_HZ;

use super::Controller;

/// Frames in a second: a lapse is drawn on frames 0, 30, 60, … and lasts until the next draw.
const SECOND_FRAMES: usize = FRAME_RATE_HZ as usize;

/// The probability ε ∈ [0, 1] that a second of a demonstration is a lapse.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Default, Serialize, Deserialize)]
#[serde(try_from = "f64", into = "f64")]
pub struct LapseRate(f64);

impl LapseRate {
    /// No lapses: the controller itself, bit for bit.
    pub const NONE: LapseRate = LapseRate(0.0);

    /// ε, checked.
    ///
    /// # Errors
    /// `OutOfRange` naming `lapse` for a value outside [0, 1] or not finite.
    pub fn new(epsilon: f64) -> Result<Self, FieldParamError> {
        check_range("lapse", epsilon, 0.0, 1.0, "a probability in [0, 1]")?;
        // + 0.0 turns −0.0 into 0.0, so that equal rates have equal bits.
        Ok(Self(epsilon + 0.0))
    }

    /// ε.
    #[must_use]
    pub const fn get(self) -> f64 {
        self.0
    }
}

impl TryFrom<f64> for LapseRate {
    type Error = FieldParamError;

    fn try_from(epsilon: f64) -> Result<Self, Self::Error> {
        Self::new(epsilon)
    }
}

impl From<LapseRate> for f64 {
    fn from(rate: LapseRate) -> f64 {
        rate.0
    }
}

/// The command that executes primitive `p` on `body`: the primitive itself on a wheeled body,
/// the humanoid's walking, turning, side-stepping or kicking command on the humanoid (which
/// takes no primitives; its kick is the right foot's). A wheeled body refuses the humanoid's
/// own primitives when it is sent them.
#[must_use]
pub fn primitive_command(p: Primitive, body: BodyKind) -> Command {
    match body {
        BodyKind::Lego | BodyKind::Tiny | BodyKind::Wheeled(..) => Command::Primitive(p),
        BodyKind::Humanoid => Command::Humanoid(match p {
            Primitive::Forward => HumanoidCommand::WalkForward,
            Primitive::Backward => HumanoidCommand::WalkBackward,
            Primitive::Left => HumanoidCommand::TurnLeft,
            Primitive::Right => HumanoidCommand::TurnRight,
            Primitive::Stop => HumanoidCommand::Wait,
            Primitive::SidestepLeft => HumanoidCommand::ShuffleLeft,
            Primitive::SidestepRight => HumanoidCommand::ShuffleRight,
            Primitive::Kick => HumanoidCommand::KickRight,
        }),
    }
}

/// [`primitive_command`] for a controller that sees: the humanoid kicks with the foot on the
/// side of the ball it sees (with the right one when it sees none, or the ball dead ahead).
#[must_use]
pub fn primitive_command_seeing(p: Primitive, observation: &Observation) -> Command {
    let left_of_robot = |ball| observation.robot.robot_from_field(ball).y_mm() > 0.0;
    match (p, observation.body, observation.ball) {
        (Primitive::Kick, BodyKind::Humanoid, Some(ball)) if left_of_robot(ball) => {
            Command::Humanoid(HumanoidCommand::KickLeft)
        }
        _ => primitive_command(p, observation.body),
    }
}

/// A controller that lapses at rate ε (see the module's documentation).
pub struct Lapsing {
    inner: Box<dyn Controller>,
    rate: LapseRate,
    /// The lapses' own stream; none at ε = 0, so that no draw can touch the demonstration.
    rng: Option<Rng>,
    /// The primitive of the second under way, if it is a lapse.
    lapse: Option<Primitive>,
}

impl Lapsing {
    /// `inner`, lapsing at `rate`, with draws seeded by the episode's seed (a stream of their
    /// own: the episode's noise is the same at every ε).
    #[must_use]
    pub fn new(inner: Box<dyn Controller>, rate: LapseRate, episode_seed: u64) -> Self {
        let rng = (rate.get() > 0.0).then(|| rng(episode_seed, stream::LAPSE));
        Self { inner, rate, rng, lapse: None }
    }

    /// The primitive of the current second if it is a lapse.
    #[must_use]
    pub const fn lapse(&self) -> Option<Primitive> {
        self.lapse
    }
}

impl Controller for Lapsing {
    fn command(&mut self, observation: &Observation) -> Command {
        let own = self.inner.command(observation);
        if let Some(rng) = self.rng.as_mut()
            && observation.frame_index.is_multiple_of(SECOND_FRAMES)
        {
            // Both draws every second, lapse or not: under one seed the seconds lapsed at a
            // smaller ε are among those lapsed at a larger one, with the same primitives.
            let u = uniform(rng);
            let p = Primitive::WHEELED[rng.random_range(0..Primitive::WHEELED.len())];
            self.lapse = (u < self.rate.get()).then_some(p);
        }
        self.lapse.map_or(own, |p| primitive_command(p, observation.body))
    }

    fn reposition(&mut self, observation: &Observation) -> Option<polymimic_types::Pose> {
        self.inner.reposition(observation)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{FieldGeometry, FieldSize};
    use polymimic_types::Pose;

    /// Always the same command, one no lapse sends.
    struct Steady;

    impl Controller for Steady {
        fn command(&mut self, _: &Observation) -> Command {
            OWN
        }
    }

    const OWN: Command = Command::Humanoid(HumanoidCommand::KickLeft);

    fn seen(frame_index: usize, body: BodyKind) -> Observation {
        Observation {
            t_s: frame_index as f64 / 30.0,
            frame_index,
            robot: Pose::default(),
            ball: None,
            field: FieldGeometry::of(FieldSize::Large),
            body,
        }
    }

    /// The command of every frame of `seconds` seconds at rate `epsilon` under `seed`.
    fn run(epsilon: f64, seed: u64, seconds: usize, body: BodyKind) -> Vec<Command> {
        let inner = Box::new(Steady);
        let mut c = Lapsing::new(inner, LapseRate::new(epsilon).expect("valid"), seed);
        (0..seconds * SECOND_FRAMES).map(|k| c.command(&seen(k, body))).collect()
    }

    #[test]
    fn the_humanoid_kicks_with_the_foot_on_the_balls_side() {
        let mut o = seen(0, BodyKind::Humanoid);
        o.robot = Pose::new(0.0, 0.0, std::f64::consts::FRAC_PI_2);
        let kick = |o: &Observation| primitive_command_seeing(Primitive::Kick, o);
        o.ball = Some(polymimic_types::Point::new(-30.0, 100.0));
        assert_eq!(kick(&o), Command::Humanoid(HumanoidCommand::KickLeft));
        o.ball = Some(polymimic_types::Point::new(30.0, 100.0));
        assert_eq!(kick(&o), Command::Humanoid(HumanoidCommand::KickRight));
        o.ball = None;
        assert_eq!(kick(&o), Command::Humanoid(HumanoidCommand::KickRight));
        assert_eq!(primitive_command_seeing(Primitive::Left, &o), primitive_command(Primitive::Left, o.body));
    }

    #[test]
    fn zero_lapse_is_the_controller_and_draws_nothing() {
        let c = Lapsing::new(Box::new(Steady), LapseRate::NONE, 3);
        assert!(c.rng.is_none());
        assert!(run(0.0, 3, 50, BodyKind::Lego).iter().all(|&x| x == OWN));
    }

    #[test]
    fn the_controller_is_asked_every_frame_even_in_a_lapse() {
        struct Shared(std::sync::Arc<std::sync::atomic::AtomicUsize>);
        impl Controller for Shared {
            fn command(&mut self, _: &Observation) -> Command {
                self.0.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                OWN
            }
        }
        let calls = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
        let mut c = Lapsing::new(Box::new(Shared(calls.clone())), LapseRate::new(1.0).expect("valid"), 1);
        for k in 0..95 {
            assert_ne!(c.command(&seen(k, BodyKind::Lego)), OWN);
        }
        assert_eq!(calls.load(std::sync::atomic::Ordering::Relaxed), 95);
    }

    /// The primitive each second executed (None: the controller's own), checking that a
    /// second's command is constant and in the body's language.
    fn seconds(commands: &[Command], body: BodyKind) -> Vec<Option<Primitive>> {
        commands
            .chunks(SECOND_FRAMES)
            .map(|second| {
                assert!(second.iter().all(|&x| x == second[0]), "a second changes command: {second:?}");
                (second[0] != OWN).then(|| {
                    let p = second[0].primitive();
                    assert_eq!(second[0], primitive_command(p, body));
                    p
                })
            })
            .collect()
    }

    #[test]
    fn full_lapse_sends_uniform_primitives_a_second_at_a_time() {
        for body in [BodyKind::Lego, BodyKind::Tiny, BodyKind::Humanoid] {
            let n = 2000;
            let lapses = seconds(&run(1.0, 17, n, body), body);
            let mut counts = [0usize; 5];
            for p in lapses {
                counts[p.expect("every second lapses at ε = 1").index()] += 1;
            }
            // χ² with 4 degrees of freedom: 18.5 is its 0.1 % tail.
            let expected = n as f64 / 5.0;
            let chi2: f64 = counts.iter().map(|&c| (c as f64 - expected).powi(2) / expected).sum();
            assert!(chi2 < 18.5, "{body:?} {counts:?} χ² = {chi2}");
        }
    }

    #[test]
    fn a_lapse_rate_is_the_share_of_lapsed_seconds() {
        for epsilon in [0.05, 0.5, 0.9] {
            let (mut lapsed, mut total) = (0usize, 0usize);
            for seed in 0..100 {
                let s = seconds(&run(epsilon, seed, 20, BodyKind::Lego), BodyKind::Lego);
                lapsed += s.iter().filter(|p| p.is_some()).count();
                total += s.len();
            }
            let share = lapsed as f64 / total as f64;
            assert!((share - epsilon).abs() < 0.05, "ε = {epsilon}: {lapsed} of {total} seconds lapsed");
        }
    }

    #[test]
    fn lapses_repeat_under_a_seed_and_nest_across_rates() {
        assert_eq!(run(0.5, 8, 200, BodyKind::Tiny), run(0.5, 8, 200, BodyKind::Tiny));
        assert_ne!(run(0.5, 8, 200, BodyKind::Tiny), run(0.5, 9, 200, BodyKind::Tiny));
        let low = seconds(&run(0.3, 8, 200, BodyKind::Lego), BodyKind::Lego);
        let high = seconds(&run(0.7, 8, 200, BodyKind::Lego), BodyKind::Lego);
        assert!(low.iter().zip(&high).all(|(l, h)| l.is_none() || l == h));
        assert!(low.iter().filter(|p| p.is_some()).count() < high.iter().filter(|p| p.is_some()).count());
    }

    #[test]
    fn the_humanoid_lapses_into_the_commands_that_look_like_primitives() {
        for p in Primitive::WHEELED {
            assert_eq!(primitive_command(p, BodyKind::Humanoid).primitive(), p);
            assert_eq!(primitive_command(p, BodyKind::Lego), Command::Primitive(p));
        }
    }

    #[test]
    fn a_lapse_rate_outside_the_unit_interval_is_refused_by_name() {
        for bad in [1.5, -0.1, f64::NAN, f64::INFINITY] {
            let e = LapseRate::new(bad).expect_err("out of range");
            assert!(matches!(e, FieldParamError::OutOfRange { name: "lapse", .. }), "{e:?}");
            assert!(e.to_string().contains("[0, 1]"), "{e}");
        }
        assert!(LapseRate::new(1.5).expect_err("out").to_string().contains("1.5"));
        assert_eq!(LapseRate::new(-0.0).expect("zero").get().to_bits(), 0.0f64.to_bits());
        assert!(serde_json::from_str::<LapseRate>("2.0").is_err());
        assert_eq!(serde_json::from_str::<LapseRate>("0.25").expect("valid").get(), 0.25);
    }
}
