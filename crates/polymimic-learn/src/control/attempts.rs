//! The imitator's attempts on the field: from the thesis's configurations or from chosen starts,
//! each with an episode seed derived from the evaluation's, so that any policy evaluated under
//! the same seed meets the same starts and the same noise.

use polymimic_field::{
    Configuration, Episode, EpisodeSetup, FieldConfig, FieldError, Frame, Outcome, Start, derive_seed,
};
use polymimic_types::Point;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::policy::ImitatorPolicy;

/// One attempt of the imitator at the penalty kick.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Attempt {
    /// The thesis's configuration it started from, if it did.
    pub configuration: Option<Configuration>,
    /// Where it started.
    pub start: Start,
    pub seed: u64,
    pub outcome: Outcome,
    pub frames: Vec<Frame>,
    /// What was executed, in order, as letters: whole behaviours by the thesis's rule, single
    /// primitives by the improved one.
    pub behaviours: Vec<String>,
}

impl ImitatorPolicy<'_> {
    /// One attempt from `configuration` with the imitator's body (a primitive runs as
    /// [`primitive_command`](polymimic_field::controller::primitive_command) has the body
    /// execute it).
    ///
    /// # Errors
    /// A field configuration that does not validate.
    pub fn attempt(&self, configuration: Configuration, field: &FieldConfig, seed: u64) -> Result<Attempt, FieldError> {
        let setup = EpisodeSetup::configuration(self.body, configuration, field);
        self.attempt_from(&setup, Some(configuration), field, seed)
    }

    /// One attempt from a chosen `start` (see [`Start::check`]).
    ///
    /// # Errors
    /// A start the body cannot play from, or a field configuration that does not validate.
    pub fn attempt_at(&self, start: Start, field: &FieldConfig, seed: u64) -> Result<Attempt, FieldError> {
        let setup = EpisodeSetup::starting(self.body, start, field)?;
        self.attempt_from(&setup, None, field, seed)
    }

    /// The player stepped through the field from `setup`, one tracker reading at a time.
    fn attempt_from(
        &self,
        setup: &EpisodeSetup,
        configuration: Option<Configuration>,
        field: &FieldConfig,
        seed: u64,
    ) -> Result<Attempt, FieldError> {
        let mut episode = Episode::new(setup, field, seed)?;
        let start = Start { robot: setup.robot, ball: setup.ball.unwrap_or(Point::new(0.0, 0.0)) };
        let mut stepping = self.start(&start, seed);
        while !episode.is_finished() {
            let command = self.act(&mut stepping, &episode.observation());
            episode.step(command)?;
        }
        let outcome = episode.outcome().unwrap_or(Outcome::TimeUp);
        Ok(Attempt {
            configuration,
            start,
            seed,
            outcome,
            frames: episode.into_frames(),
            behaviours: stepping.into_executed(),
        })
    }

    /// `attempts_per_configuration` attempts from each configuration, in parallel; attempt i
    /// of configuration c runs with a seed derived from (`seed`, c, i).
    ///
    /// # Errors
    /// A field configuration that does not validate.
    pub fn evaluate(
        &self,
        attempts_per_configuration: usize,
        field: &FieldConfig,
        seed: u64,
    ) -> Result<Vec<Attempt>, FieldError> {
        let named = [StartAt::Configuration(Configuration::One), StartAt::Configuration(Configuration::Two)];
        self.evaluate_from(&named, attempts_per_configuration, field, seed)
    }

    /// `attempts_per_start` attempts from each of `starts`, in parallel, in order; a named
    /// configuration's attempts run with the seeds [`Self::evaluate`] gives it, the k-th chosen
    /// start's with seeds of their own (see [`start_attempt_seeds`]).
    ///
    /// # Errors
    /// A chosen start the body cannot play from, or a field configuration that does not
    /// validate.
    pub fn evaluate_from(
        &self,
        starts: &[StartAt],
        attempts_per_start: usize,
        field: &FieldConfig,
        seed: u64,
    ) -> Result<Vec<Attempt>, FieldError> {
        for start in starts {
            if let StartAt::Chosen(start) = start {
                start.check(self.body)?;
            }
        }
        let jobs = start_attempt_seeds(starts, attempts_per_start, seed);
        jobs.par_iter()
            .map(|&(start, s)| match start {
                StartAt::Configuration(configuration) => self.attempt(configuration, field, s),
                StartAt::Chosen(start) => self.attempt_at(start, field, s),
            })
            .collect()
    }
}

/// Where an evaluated attempt starts: one of the thesis's two configurations, or a start of
/// one's own.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StartAt {
    /// Configuration 1 or 2 (Fig 4.4) on the body's field.
    Configuration(Configuration),
    /// A chosen robot pose and ball position.
    Chosen(Start),
}

/// The start and episode seed of every attempt an evaluation from `starts` under `seed` makes,
/// `attempts_per_start` from each in order: configuration c's attempt i with a seed derived
/// from (`seed`, 100 + c − 1, i), as [`attempt_seeds`] gives; the k-th chosen start's (counting
/// chosen starts only) from (`seed`, 1000 + k, i).
#[must_use]
pub fn start_attempt_seeds(starts: &[StartAt], attempts_per_start: usize, seed: u64) -> Vec<(StartAt, u64)> {
    let mut chosen = 0_u64;
    let mut jobs = Vec::with_capacity(starts.len() * attempts_per_start);
    for &start in starts {
        let stream = match start {
            StartAt::Configuration(c) => 99 + u64::from(c.number()),
            StartAt::Chosen(_) => {
                chosen += 1;
                999 + chosen
            }
        };
        jobs.extend((0..attempts_per_start as u64).map(|i| (start, derive_seed(seed, stream, i))));
    }
    jobs
}

/// The configuration and episode seed of every attempt an evaluation under `seed` makes:
/// `attempts_per_configuration` from configuration 1, then as many from configuration 2;
/// attempt i of configuration c runs with a seed derived from (`seed`, c, i). Any policy
/// evaluated on these meets the same starts and the same noise.
#[must_use]
pub fn attempt_seeds(attempts_per_configuration: usize, seed: u64) -> Vec<(Configuration, u64)> {
    Configuration::ALL
        .iter()
        .enumerate()
        .flat_map(|(c, &configuration)| {
            (0..attempts_per_configuration as u64).map(move |i| (configuration, derive_seed(seed, 100 + c as u64, i)))
        })
        .collect()
}
