//! Many episodes of one body (the Lego robot unless told otherwise) stepped together, one
//! primitive held for a number of frames in each: the engine of the vector environment. Every episode is its own, seeded as a single
//! one is, so a batch gives the same frames as the episodes run one by one, on any number of
//! threads.

use rayon::prelude::*;

use crate::body::BodyKind;
use crate::controller::{primitive_command, primitive_command_seeing};
use crate::episode::Episode;
use crate::error::{FieldError, FieldParamError};
use crate::setup::{Configuration, EpisodeSetup, FieldConfig, Start};
use polymimic_types::Primitive;

/// A fixed number of episode slots, each empty or holding an episode.
pub struct EpisodeBatch {
    episodes: Vec<Option<Episode>>,
    config: FieldConfig,
    frames_per_action: usize,
    body: BodyKind,
}

impl EpisodeBatch {
    /// `n` empty slots; every step holds an action for `frames_per_action` frames.
    ///
    /// # Errors
    /// No slot, no frame per action, or a field configuration that does not validate.
    pub fn new(n: usize, frames_per_action: usize, config: &FieldConfig) -> Result<Self, FieldError> {
        if n == 0 {
            return Err(FieldParamError::OutOfRange { name: "n", value: 0.0, expected: "at least 1 episode" }.into());
        }
        if frames_per_action == 0 {
            let expected = "at least 1 frame";
            return Err(FieldParamError::OutOfRange { name: "frames_per_action", value: 0.0, expected }.into());
        }
        config.check()?;
        Ok(Self { episodes: (0..n).map(|_| None).collect(), config: *config, frames_per_action, body: BodyKind::Lego })
    }

    /// The same slots for `body`'s episodes, on its field, each primitive sent as
    /// [`primitive_command`] has the body execute it.
    #[must_use]
    pub fn with_body(self, body: BodyKind) -> Self {
        Self { body, ..self }
    }

    /// The body every episode of the batch drives.
    #[must_use]
    pub const fn body(&self) -> BodyKind {
        self.body
    }

    /// How many slots.
    #[must_use]
    pub fn len(&self) -> usize {
        self.episodes.len()
    }

    /// Never: a batch has at least one slot.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.episodes.is_empty()
    }

    /// Starts a new episode of the batch's body in slot `index`, from `configuration`, seeded
    /// with `seed` (as `Episode::new` is).
    ///
    /// # Errors
    /// A slot out of range.
    pub fn reset(&mut self, index: usize, configuration: Configuration, seed: u64) -> Result<(), FieldError> {
        let setup = EpisodeSetup::configuration(self.body, configuration, &self.config);
        self.place(index, &setup, seed)
    }

    /// [`Self::reset`] from a chosen start.
    ///
    /// # Errors
    /// A slot out of range, or a start the body cannot play from (see [`Start::check`]).
    pub fn reset_at(&mut self, index: usize, start: Start, seed: u64) -> Result<(), FieldError> {
        let setup = EpisodeSetup::starting(self.body, start, &self.config)?;
        self.place(index, &setup, seed)
    }

    fn place(&mut self, index: usize, setup: &EpisodeSetup, seed: u64) -> Result<(), FieldError> {
        let n = self.episodes.len();
        let slot = self.episodes.get_mut(index).ok_or(FieldParamError::OutOfRange {
            name: "index",
            value: index as f64,
            expected: if n == 1 { "0, the batch's one slot" } else { "a slot of the batch, from 0" },
        })?;
        *slot = Some(Episode::new(setup, &self.config, seed)?);
        Ok(())
    }

    /// Holds `actions[i]` for the batch's frames per action in episode `i`, every episode at
    /// once (in parallel), stopping any that ends; a slot whose action is None is left as it is.
    ///
    /// # Errors
    /// As many actions as slots are needed, and every slot given an action must hold an
    /// episode that is still running.
    pub fn step(&mut self, actions: &[Option<Primitive>]) -> Result<(), FieldError> {
        if actions.len() != self.episodes.len() {
            return Err(FieldParamError::OutOfRange {
                name: "actions",
                value: actions.len() as f64,
                expected: "one action per episode of the batch",
            }
            .into());
        }
        if let Some(index) = self.episodes.iter().zip(actions).position(|(slot, a)| a.is_some() && slot.is_none()) {
            return Err(FieldError::NotStarted { index });
        }
        let (frames, body) = (self.frames_per_action, self.body);
        self.episodes.par_iter_mut().zip(actions.par_iter()).enumerate().try_for_each(|(index, (slot, &action))| {
            let Some(action) = action else { return Ok(()) };
            let episode = slot.as_mut().ok_or(FieldError::NotStarted { index })?;
            // A kick is the foot on the ball's side, as the robot sees it now.
            let command = if action == Primitive::Kick {
                primitive_command_seeing(action, &episode.observation())
            } else {
                primitive_command(action, body)
            };
            for frame in 0..frames {
                if frame > 0 && episode.is_finished() {
                    break;
                }
                episode.step(command)?;
            }
            Ok(())
        })
    }

    /// The episodes, slot by slot (None where none was started).
    #[must_use]
    pub fn episodes(&self) -> &[Option<Episode>] {
        &self.episodes
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::command::Command;

    /// A batch of `body`'s episodes against the same episodes run one by one, each primitive
    /// sent as the body executes it.
    fn batch_matches_episodes_alone(body: BodyKind) {
        let config = FieldConfig::default();
        let mut batch = EpisodeBatch::new(3, 30, &config).unwrap().with_body(body);
        let starts = [(Configuration::One, 5), (Configuration::Two, 6), (Configuration::One, 7)];
        for (i, &(configuration, seed)) in starts.iter().enumerate() {
            batch.reset(i, configuration, seed).unwrap();
        }
        let plan = [Primitive::Forward, Primitive::Left, Primitive::Right, Primitive::Forward];
        for (k, _) in plan.iter().enumerate() {
            let actions: Vec<Option<Primitive>> = (0..3).map(|i| Some(plan[(k + i) % plan.len()])).collect();
            batch.step(&actions).unwrap();
        }
        for (i, &(configuration, seed)) in starts.iter().enumerate() {
            let setup = EpisodeSetup::configuration(body, configuration, &config);
            let mut alone = Episode::new(&setup, &config, seed).unwrap();
            for k in 0..plan.len() {
                for _ in 0..30 {
                    if alone.is_finished() {
                        break;
                    }
                    alone.step(primitive_command(plan[(k + i) % plan.len()], body)).unwrap();
                }
            }
            assert_eq!(batch.episodes()[i].as_ref().unwrap().frames(), alone.frames(), "{} episode {i}", body.name());
        }
    }

    #[test]
    fn a_batch_gives_the_frames_of_its_episodes_run_one_by_one() {
        batch_matches_episodes_alone(BodyKind::Lego);
        let lego = EpisodeBatch::new(1, 30, &FieldConfig::default()).unwrap();
        assert_eq!(lego.body(), BodyKind::Lego);
        // A wheeled primitive is the command itself on the Lego robot.
        assert_eq!(primitive_command(Primitive::Left, BodyKind::Lego), Command::Primitive(Primitive::Left));
    }

    #[test]
    fn a_batch_of_another_body_plays_that_body_on_its_field() {
        for body in [BodyKind::Tiny, BodyKind::Humanoid] {
            batch_matches_episodes_alone(body);
        }
        let mut tiny = EpisodeBatch::new(1, 30, &FieldConfig::default()).unwrap().with_body(BodyKind::Tiny);
        tiny.reset(0, Configuration::One, 1).unwrap();
        let start_x_mm = tiny.episodes()[0].as_ref().unwrap().observation().robot.x_mm();
        // The tiny's field is 560 mm long: it starts a sixth of that behind the centre.
        assert!((start_x_mm + 560.0 / 6.0).abs() < 5.0, "{start_x_mm}");
    }

    #[test]
    fn misuse_is_named() {
        let config = FieldConfig::default();
        assert!(EpisodeBatch::new(0, 30, &config).is_err());
        assert!(EpisodeBatch::new(2, 0, &config).is_err());
        let mut batch = EpisodeBatch::new(2, 30, &config).unwrap();
        let stop = Some(Primitive::Stop);
        assert!(matches!(batch.step(&[stop, stop]), Err(FieldError::NotStarted { index: 0 })));
        batch.reset(0, Configuration::One, 1).unwrap();
        batch.step(&[stop, None]).unwrap(); // a slot left alone may be empty
        batch.reset(1, Configuration::Two, 2).unwrap();
        let error = batch.step(&[stop]).unwrap_err().to_string();
        assert!(error.contains("actions") && error.contains("one action per episode"), "{error}");
        assert!(batch.reset(2, Configuration::One, 1).unwrap_err().to_string().contains("index"));
    }
}
