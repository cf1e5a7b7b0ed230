//! Many Lego-robot episodes stepped together, one primitive held for a number of frames in
//! each: the engine of the vector environment. Every episode is its own, seeded as a single
//! one is, so a batch gives the same frames as the episodes run one by one, on any number of
//! threads.

use rayon::prelude::*;

use crate::body::BodyKind;
use crate::command::Command;
use crate::episode::Episode;
use crate::error::{FieldError, FieldParamError};
use crate::setup::{Configuration, EpisodeSetup, FieldConfig};
use polymimic_types::Primitive;

/// A fixed number of episode slots, each empty or holding an episode.
pub struct EpisodeBatch {
    episodes: Vec<Option<Episode>>,
    config: FieldConfig,
    frames_per_action: usize,
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
        Ok(Self { episodes: (0..n).map(|_| None).collect(), config: *config, frames_per_action })
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

    /// Starts a new episode of the Lego robot in slot `index`, from `configuration`, seeded
    /// with `seed` (as `Episode::new` is).
    ///
    /// # Errors
    /// A slot out of range.
    pub fn reset(&mut self, index: usize, configuration: Configuration, seed: u64) -> Result<(), FieldError> {
        let n = self.episodes.len();
        let slot = self.episodes.get_mut(index).ok_or(FieldParamError::OutOfRange {
            name: "index",
            value: index as f64,
            expected: if n == 1 { "0, the batch's one slot" } else { "a slot of the batch, from 0" },
        })?;
        let setup = EpisodeSetup::configuration(BodyKind::Lego, configuration, &self.config);
        *slot = Some(Episode::new(&setup, &self.config, seed)?);
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
        let frames = self.frames_per_action;
        self.episodes.par_iter_mut().zip(actions.par_iter()).enumerate().try_for_each(|(index, (slot, &action))| {
            let Some(action) = action else { return Ok(()) };
            let episode = slot.as_mut().ok_or(FieldError::NotStarted { index })?;
            for frame in 0..frames {
                if frame > 0 && episode.is_finished() {
                    break;
                }
                episode.step(Command::Primitive(action))?;
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

    #[test]
    fn a_batch_gives_the_frames_of_its_episodes_run_one_by_one() {
        let config = FieldConfig::default();
        let mut batch = EpisodeBatch::new(3, 30, &config).unwrap();
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
            let setup = EpisodeSetup::configuration(BodyKind::Lego, configuration, &config);
            let mut alone = Episode::new(&setup, &config, seed).unwrap();
            for k in 0..plan.len() {
                for _ in 0..30 {
                    alone.step(Command::Primitive(plan[(k + i) % plan.len()])).unwrap();
                }
            }
            assert_eq!(batch.episodes()[i].as_ref().unwrap().frames(), alone.frames(), "episode {i}");
        }
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
