//! Recording: self-observation data (§3.1.1) and demonstrations (§3.2.1).

use polymimic_types::Primitive;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::body::BodyKind;
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
    config.check()?;
    let setup = EpisodeSetup::alone(body);
    let mut episode = Episode::new(&setup, config, derive_seed(seed, stream::SESSION, 0))?;
    let mut babbler = Babbler::new(body, seed);
    let mut counts = [0usize; 5];
    let mut out = Vec::with_capacity(5 * n_per_primitive);
    // Uniform choice needs about 5n primitives; a generous cap guards against endless dropouts.
    let max_primitives = 20 * n_per_primitive + 1000;
    let frames_per = Babbler::PRIMITIVE_FRAMES as usize;
    let mut executed = 0;
    while counts.iter().any(|&c| c < n_per_primitive) {
        if executed >= max_primitives {
            return Err(FieldError::RetriesExhausted {
                valid: out.len(),
                requested: 5 * n_per_primitive,
                attempts: executed,
            });
        }
        executed += 1;
        if let Some(pose) = babbler.reposition(&episode.observation()) {
            episode.place_robot(pose)?;
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
        for p in Primitive::ALL {
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
