//! Recording: self-observation data (§3.1.1) and demonstrations (§3.2.1).

use polymimic_types::{Point, Pose, Primitive, PrimitiveSet};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::body::BodyKind;
use crate::command::{Command, HumanoidCommand};
use crate::controller::{Babbler, Controller};
use crate::episode::Episode;
use crate::error::FieldError;
use crate::math::{derive_seed, stream};
use crate::setup::{EpisodeSetup, FieldConfig};
use crate::tracker::Frame;

/// One second of the imitator executing one primitive, as the tracker saw it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PrimitiveSequence {
    /// The primitive commanded.
    #[serde(with = "polymimic_types::capitalised")]
    pub primitive: Primitive,
    /// Its 30 frames, from the frame at which the command started.
    pub frames: Vec<Frame>,
}

/// Self-observation (§2.1 of the spec, §3.1.1) of the thesis's imitator, the Lego robot on the
/// large field: [`self_observation_of`] that body.
///
/// # Errors
/// As [`self_observation_of`].
pub fn self_observation(
    n_per_primitive: usize,
    seed: u64,
    config: &FieldConfig,
) -> Result<Vec<PrimitiveSequence>, FieldError> {
    self_observation_of(BodyKind::Lego, n_per_primitive, seed, config)
}

/// Self-observation of `body`: alone on its field it executes random one-second primitives (on
/// the humanoid, their walking, turning and waiting equivalents), put back at the centre near
/// an edge; each primitive is one sequence. Returns exactly `n_per_primitive` sequences of each
/// of F B L R S, in the order they were executed; sequences with a tracking dropout are
/// discarded.
///
/// # Errors
/// A parameter error for an invalid config; `RetriesExhausted` if dropouts are so frequent that
/// the sequences cannot be collected.
pub fn self_observation_of(
    body: BodyKind,
    n_per_primitive: usize,
    seed: u64,
    config: &FieldConfig,
) -> Result<Vec<PrimitiveSequence>, FieldError> {
    self_observation_of_set(body, PrimitiveSet::Wheeled, n_per_primitive, seed, config)
}

/// Self-observation of `body` over `set`, as [`self_observation_of`] (which is this over the
/// wheeled set, bit for bit). The humanoid's kick shows only with a ball: before each kick the
/// experimenter puts one before the kicking foot, and the kick is played on a copy of the field
/// holding that ball and the robot where it stands (the session's own field has none); a kick
/// whose ball leaves the field within the second is discarded like a dropout.
///
/// # Errors
/// As [`self_observation_of`]; a parameter error for a primitive of `set` the body cannot
/// execute.
pub fn self_observation_of_set(
    body: BodyKind,
    set: PrimitiveSet,
    n_per_primitive: usize,
    seed: u64,
    config: &FieldConfig,
) -> Result<Vec<PrimitiveSequence>, FieldError> {
    config.check()?;
    let setup = EpisodeSetup::alone(body);
    let mut episode = Episode::new(&setup, config, derive_seed(seed, stream::SESSION, 0))?;
    let mut babbler = Babbler::of_set(body, set, seed);
    let mut counts = [0usize; Primitive::ALL.len()];
    let n_primitives = set.primitives().len();
    let mut out = Vec::with_capacity(n_primitives * n_per_primitive);
    // Uniform choice needs about 5n primitives; a generous cap guards against endless dropouts.
    let max_primitives = 4 * n_primitives * n_per_primitive + 1000;
    let frames_per = Babbler::PRIMITIVE_FRAMES as usize;
    let mut executed = 0;
    while set.primitives().iter().any(|p| counts[p.index()] < n_per_primitive) {
        if executed >= max_primitives {
            return Err(FieldError::RetriesExhausted {
                valid: out.len(),
                requested: n_primitives * n_per_primitive,
                attempts: executed,
            });
        }
        executed += 1;
        if let Some(pose) = babbler.reposition(&episode.observation()) {
            episode.place_robot(pose)?;
        }
        if let (Primitive::Kick, Command::Humanoid(kick)) = babbler.upcoming() {
            let kicked =
                kick_with_ball(&mut episode, &mut babbler, kick, derive_seed(seed, stream::SESSION, executed as u64))?;
            if let Some(frames) = kicked.filter(|_| counts[Primitive::Kick.index()] < n_per_primitive) {
                counts[Primitive::Kick.index()] += 1;
                out.push(PrimitiveSequence { primitive: Primitive::Kick, frames });
            }
            continue;
        }
        let mut frames = Vec::with_capacity(frames_per);
        let mut lost = false;
        for _ in 0..frames_per {
            let command = babbler.command(&episode.observation());
            let r = episode.step(command)?;
            lost |= r.tracking_lost;
            frames.push(r.frame);
        }
        let p = babbler.current();
        if !lost && counts[p.index()] < n_per_primitive {
            counts[p.index()] += 1;
            out.push(PrimitiveSequence { primitive: p, frames });
        }
    }
    Ok(out)
}

/// Where the experimenter puts the ball before a kick, in the robot's frame, mm: in line with
/// the kicking foot, as far ahead as the humanoid's own controller kicks from.
const KICKED_BALL_AHEAD_MM: f64 = 107.5;

/// One second of `kick` on a copy of the session's field holding a ball before the kicking foot;
/// the session's robot is then put where the kick left it. `None` if the ball left the field or
/// tracking dropped out.
fn kick_with_ball(
    session: &mut Episode,
    babbler: &mut Babbler,
    kick: HumanoidCommand,
    seed: u64,
) -> Result<Option<Vec<Frame>>, FieldError> {
    let robot = session.robot_pose();
    let side = if kick == HumanoidCommand::KickLeft { 1.0 } else { -1.0 };
    let ball = robot.field_from_robot(Point::new(KICKED_BALL_AHEAD_MM, side * session.config().humanoid.foot_side_mm));
    let setup = EpisodeSetup { ball: Some(ball), ..EpisodeSetup { robot, ..*session.setup() } };
    let mut episode = Episode::new(&setup, session.config(), seed)?;
    let start_s = session.t_s();
    let mut frames = Vec::with_capacity(Babbler::PRIMITIVE_FRAMES as usize);
    let mut lost = false;
    for _ in 0..Babbler::PRIMITIVE_FRAMES {
        let command = babbler.command(&episode.observation());
        if episode.is_finished() {
            continue;
        }
        let r = episode.step(command)?;
        lost |= r.tracking_lost;
        frames.push(Frame { t_s: start_s + r.frame.t_s, ..r.frame });
    }
    let at: Pose = episode.robot_pose();
    if session.field().contains(at.point()) {
        session.place_robot(at)?;
    }
    let whole = !lost && !episode.is_finished() && frames.len() == Babbler::PRIMITIVE_FRAMES as usize;
    Ok(whole.then_some(frames))
}

/// Independent self-observation sessions, one per seed, in parallel (results in seed order and
/// independent of the number of threads).
///
/// # Errors
/// As [`self_observation`].
pub fn self_observation_batch(
    seeds: &[u64],
    n_per_primitive: usize,
    config: &FieldConfig,
) -> Result<Vec<Vec<PrimitiveSequence>>, FieldError> {
    seeds.par_iter().map(|&seed| self_observation(n_per_primitive, seed, config)).collect()
}

/// Run a controller until the episode ends (or `max_frames`), the experimenter's hand included.
///
/// # Errors
/// Whatever [`Episode::step`] reports (a command the body cannot execute, …).
pub fn run_controller(
    episode: &mut Episode,
    controller: &mut dyn Controller,
    max_frames: usize,
) -> Result<(), FieldError> {
    for _ in 0..max_frames {
        if episode.is_finished() {
            break;
        }
        if let Some(pose) = controller.reposition(&episode.observation()) {
            episode.place_robot(pose)?;
        }
        let command = controller.command(&episode.observation());
        episode.step(command)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn self_observation_returns_n_of_each_primitive_of_thirty_frames() {
        let seqs = self_observation(20, 3, &FieldConfig::default()).expect("runs");
        assert_eq!(seqs.len(), 100);
        for p in Primitive::WHEELED {
            assert_eq!(seqs.iter().filter(|s| s.primitive == p).count(), 20);
        }
        for s in &seqs {
            assert_eq!(s.frames.len(), 30);
            assert!(s.frames.iter().all(|f| f.command == s.primitive as u16));
            assert!(s.frames.iter().all(|f| f.ball_x_mm.is_nan()));
        }
    }

    #[test]
    fn self_observation_is_deterministic() {
        let a = self_observation(5, 11, &FieldConfig::default()).expect("runs");
        let b = self_observation(5, 11, &FieldConfig::default()).expect("runs");
        // Bits, not ==: the missing ball is NaN.
        let bits = |s: &[PrimitiveSequence]| -> Vec<u64> {
            s.iter()
                .flat_map(|q| q.frames.iter())
                .flat_map(|f| [f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad, f.ball_x_mm])
                .map(f64::to_bits)
                .collect()
        };
        assert_eq!(bits(&a), bits(&b));
        assert_eq!(a.len(), b.len());
    }

    /// The mean over a primitive's sequences of its forward travel along the starting heading
    /// (mm) and its turn (rad, left positive).
    fn travel_and_turn(seqs: &[PrimitiveSequence], p: Primitive) -> (f64, f64) {
        let of_p: Vec<_> = seqs.iter().filter(|s| s.primitive == p).collect();
        let (mut along, mut turn) = (0.0, 0.0);
        for s in &of_p {
            let (first, last) = (&s.frames[0], &s.frames[s.frames.len() - 1]);
            let (dx, dy) = (last.robot_x_mm - first.robot_x_mm, last.robot_y_mm - first.robot_y_mm);
            along += dx * first.robot_theta_rad.cos() + dy * first.robot_theta_rad.sin();
            turn += crate::math::wrap_angle_rad(last.robot_theta_rad - first.robot_theta_rad);
        }
        (along / of_p.len() as f64, turn / of_p.len() as f64)
    }

    #[test]
    fn every_body_babbles_its_own_commands_and_moves_as_they_say() {
        use crate::command::{Command, HumanoidCommand};
        let config = FieldConfig::default();
        for body in [BodyKind::Tiny, BodyKind::Humanoid] {
            let seqs = self_observation_of(body, 8, 5, &config).expect("runs");
            assert_eq!(seqs.len(), 40);
            let (forward, _) = travel_and_turn(&seqs, Primitive::Forward);
            let (backward, _) = travel_and_turn(&seqs, Primitive::Backward);
            let (_, left) = travel_and_turn(&seqs, Primitive::Left);
            let (_, right) = travel_and_turn(&seqs, Primitive::Right);
            let (still, _) = travel_and_turn(&seqs, Primitive::Stop);
            assert!(forward > 10.0 && backward < -5.0, "{body:?}: forward {forward} mm, backward {backward} mm");
            assert!(left > 0.1 && right < -0.1, "{body:?}: left {left} rad, right {right} rad");
            assert!(still.abs() < forward / 5.0, "{body:?}: a stop travels {still} mm");
            for s in &seqs {
                let sent = crate::controller::primitive_command(s.primitive, body).id();
                assert!(s.frames.iter().all(|f| f.command == sent), "{body:?} {:?}", s.primitive);
            }
        }
        let humanoid = self_observation_of(BodyKind::Humanoid, 2, 5, &config).expect("runs");
        let walk = Command::Humanoid(HumanoidCommand::WalkForward).id();
        assert!(humanoid.iter().any(|s| s.frames[0].command == walk));
        // The Lego's self-observation is the thesis's, bit for bit (Debug: the missing ball is NaN).
        let lego = self_observation_of(BodyKind::Lego, 5, 11, &config).expect("runs");
        assert_eq!(format!("{lego:?}"), format!("{:?}", self_observation(5, 11, &config).expect("runs")));
    }
}

#[cfg(test)]
mod own_set_tests {
    use super::*;

    /// The mean displacement over a primitive's sequences in the robot's frame at its start,
    /// (ahead, to the left), mm.
    fn mean_shift_mm(seqs: &[PrimitiveSequence], p: Primitive) -> (f64, f64) {
        let of_p: Vec<_> = seqs.iter().filter(|s| s.primitive == p).collect();
        let (mut ahead, mut left) = (0.0, 0.0);
        for s in &of_p {
            let (first, last) = (&s.frames[0], &s.frames[s.frames.len() - 1]);
            let start = Pose::new(first.robot_x_mm, first.robot_y_mm, first.robot_theta_rad);
            let moved = start.robot_from_field(Point::new(last.robot_x_mm, last.robot_y_mm));
            ahead += moved.x_mm();
            left += moved.y_mm();
        }
        (ahead / of_p.len() as f64, left / of_p.len() as f64)
    }

    #[test]
    fn the_humanoid_babbles_its_own_eight_and_kicks_a_ball_put_before_its_foot() {
        let seqs = self_observation_of_set(BodyKind::Humanoid, PrimitiveSet::Humanoid, 10, 4, &FieldConfig::default())
            .expect("runs");
        assert_eq!(seqs.len(), 80);
        for s in &seqs {
            assert_eq!(s.frames.len(), 30);
            let class = Command::from_id(s.frames[0].command).map(|c| match c {
                Command::Humanoid(h) => h.own_primitive(),
                other => other.primitive(),
            });
            assert_eq!(class, Ok(s.primitive));
            // Only a kick has a ball, and every kick moves it.
            let first_ball = s.frames[0].ball_x_mm;
            if s.primitive == Primitive::Kick {
                let (b0, b1) = (&s.frames[0], &s.frames[29]);
                let rolled_mm = (b1.ball_x_mm - b0.ball_x_mm).hypot(b1.ball_y_mm - b0.ball_y_mm);
                assert!(rolled_mm > 20.0, "a kick moved the ball {rolled_mm} mm");
            } else {
                assert!(first_ball.is_nan(), "{:?} has a ball", s.primitive);
            }
        }
        let (_, sidestep_left) = mean_shift_mm(&seqs, Primitive::SidestepLeft);
        let (_, sidestep_right) = mean_shift_mm(&seqs, Primitive::SidestepRight);
        assert!(sidestep_left > 10.0 && sidestep_right < -10.0, "{sidestep_left} mm, {sidestep_right} mm");
        // The kick leans back 15 mm and keeps 10 of it.
        let (kick_ahead, _) = mean_shift_mm(&seqs, Primitive::Kick);
        assert!((-14.0..-6.0).contains(&kick_ahead), "a kick moved {kick_ahead} mm ahead");
    }
}
