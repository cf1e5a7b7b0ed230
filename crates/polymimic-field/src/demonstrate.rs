//! Demonstrations (§3.2.1): each demonstrator takes shots on goal from the two configurations;
//! demonstrations with a tracking dropout are discarded and re-recorded, deterministically.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::body::{BodyKind, HumanoidParams};
use crate::controller::{Controller, Expert, HumanoidController, LapseRate, Lapsing, Poor, TinyController};
use crate::episode::{Episode, Outcome};
use crate::error::{FieldError, FieldParamError};
use crate::math::derive_seed;
use crate::record::run_controller;
use crate::setup::{Configuration, EpisodeSetup, FieldConfig};
use crate::tracker::{FRAME_RATE_HZ, Frame};

/// The built-in demonstrators (the thesis's Average demonstrator is a trained forward model:
/// drive it through [`Episode::step`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Demonstrator {
    /// The competition controller on the Lego body (the thesis's RC2004).
    Expert,
    /// Drives straight at the ball with primitives (Lego body).
    Poor,
    /// The tiny robot's skilled primitive controller (small field).
    Tiny,
    /// The humanoid with its head camera.
    Humanoid,
}

impl Demonstrator {
    /// All of them.
    pub const ALL: [Demonstrator; 4] =
        [Demonstrator::Expert, Demonstrator::Poor, Demonstrator::Tiny, Demonstrator::Humanoid];

    /// Lower-case name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Demonstrator::Expert => "expert",
            Demonstrator::Poor => "poor",
            Demonstrator::Tiny => "tiny",
            Demonstrator::Humanoid => "humanoid",
        }
    }

    /// The demonstrator with this (case-insensitive) name.
    ///
    /// # Errors
    /// `UnknownDemonstrator` otherwise.
    pub fn from_name(name: &str) -> Result<Self, FieldParamError> {
        Self::ALL
            .into_iter()
            .find(|d| d.name().eq_ignore_ascii_case(name))
            .ok_or_else(|| FieldParamError::UnknownDemonstrator(name.to_owned()))
    }

    /// Its body.
    #[must_use]
    pub const fn body(self) -> BodyKind {
        match self {
            Demonstrator::Expert | Demonstrator::Poor => BodyKind::Lego,
            Demonstrator::Tiny => BodyKind::Tiny,
            Demonstrator::Humanoid => BodyKind::Humanoid,
        }
    }

    /// A fresh controller; the humanoid's plays as `humanoid` says.
    #[must_use]
    pub fn controller(self, humanoid: &HumanoidParams) -> Box<dyn Controller> {
        match self {
            Demonstrator::Expert => Box::new(Expert::new()),
            Demonstrator::Poor => Box::new(Poor::new()),
            Demonstrator::Tiny => Box::new(TinyController::new()),
            Demonstrator::Humanoid => Box::new(HumanoidController::new(*humanoid)),
        }
    }

    /// Whether its controller can drive `body`: the humanoid's only the humanoid, the Expert's
    /// wheel speeds a wheeled body that takes them, Poor's and Tiny's primitives any wheeled one.
    #[must_use]
    pub const fn can_drive(self, body: BodyKind) -> bool {
        match (self, body) {
            (Demonstrator::Humanoid, b) => matches!(b, BodyKind::Humanoid),
            (Demonstrator::Expert, BodyKind::Lego) => true,
            (Demonstrator::Expert, BodyKind::Wheeled(params, _)) => params.accepts_expert_commands,
            (Demonstrator::Expert, _) => false,
            (Demonstrator::Poor | Demonstrator::Tiny, b) => b.is_wheeled(),
        }
    }

    const fn stream(self, configuration: Configuration) -> u64 {
        100 + 10 * self as u64 + configuration.number() as u64
    }
}

/// One recorded shot on goal.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Demonstration {
    /// Who demonstrated.
    pub demonstrator: Demonstrator,
    /// From which configuration.
    pub configuration: Configuration,
    /// The episode seed: [`demonstrate`] with it and [`Demonstration::lapse`] replays this
    /// demonstration bit for bit.
    pub seed: u64,
    /// The demonstrator's lapse rate (docs/guides/crowd.md); absent in older files, which had none.
    #[serde(default)]
    pub lapse: LapseRate,
    /// How it ended.
    pub outcome: Outcome,
    /// Whether tracking held throughout (always true in what [`record`] returns).
    pub valid: bool,
    /// The tracker frames, one per 1/30 s, ending with the final state.
    pub frames: Vec<Frame>,
}

/// Run one demonstration episode with the given episode seed (valid or not), the demonstrator
/// lapsing at `lapse` (docs/guides/crowd.md; [`LapseRate::NONE`] is its controller alone, bit for bit).
///
/// # Errors
/// A parameter error for an invalid config.
pub fn demonstrate(
    demonstrator: Demonstrator,
    configuration: Configuration,
    seed: u64,
    lapse: LapseRate,
    config: &FieldConfig,
) -> Result<Demonstration, FieldError> {
    demonstrate_on(demonstrator, demonstrator.body(), configuration, seed, lapse, config)
}

/// [`demonstrate`] with the demonstrator's controller on another body (docs/guides/own-data.md), which it
/// must be able to drive ([`Demonstrator::can_drive`]).
///
/// # Errors
/// `ControllerNotSupported` for a body the controller cannot drive; a parameter error for an
/// invalid config.
pub fn demonstrate_on(
    demonstrator: Demonstrator,
    body: BodyKind,
    configuration: Configuration,
    seed: u64,
    lapse: LapseRate,
    config: &FieldConfig,
) -> Result<Demonstration, FieldError> {
    if !demonstrator.can_drive(body) {
        return Err(
            FieldParamError::ControllerNotSupported { controller: demonstrator.name(), body: body.name() }.into()
        );
    }
    let setup = EpisodeSetup::configuration(body, configuration, config);
    let mut episode = Episode::new(&setup, config, seed)?;
    let mut controller = Lapsing::new(demonstrator.controller(&config.humanoid), lapse, seed);
    let max_frames = (config.time_limit_s * f64::from(FRAME_RATE_HZ)).ceil() as usize + 1;
    run_controller(&mut episode, &mut controller, max_frames)?;
    let outcome = episode.outcome().unwrap_or(Outcome::TimeUp);
    let valid = episode.is_valid();
    Ok(Demonstration { demonstrator, configuration, seed, lapse, outcome, valid, frames: episode.into_frames() })
}

/// Record `n_valid` valid demonstrations, the demonstrator lapsing at `lapse`. Attempt `i`
/// runs with episode seed `derive_seed(seed, stream, i)` (whatever `lapse` is); invalid
/// attempts are skipped, so the result is the first `n_valid` valid attempts in order: the
/// same bits on any number of threads.
///
/// # Errors
/// A parameter error for an invalid config; `RetriesExhausted` if too many attempts lose
/// tracking.
pub fn record(
    demonstrator: Demonstrator,
    configuration: Configuration,
    n_valid: usize,
    seed: u64,
    lapse: LapseRate,
    config: &FieldConfig,
) -> Result<Vec<Demonstration>, FieldError> {
    record_on(demonstrator, demonstrator.body(), configuration, n_valid, seed, lapse, config)
}

/// [`record`] with the demonstrator's controller on another body (docs/guides/own-data.md); the same episode
/// seeds as on its own.
///
/// # Errors
/// As [`record`]; `ControllerNotSupported` for a body the controller cannot drive.
pub fn record_on(
    demonstrator: Demonstrator,
    body: BodyKind,
    configuration: Configuration,
    n_valid: usize,
    seed: u64,
    lapse: LapseRate,
    config: &FieldConfig,
) -> Result<Vec<Demonstration>, FieldError> {
    config.check()?;
    if !demonstrator.can_drive(body) {
        return Err(
            FieldParamError::ControllerNotSupported { controller: demonstrator.name(), body: body.name() }.into()
        );
    }
    let stream = demonstrator.stream(configuration);
    let max_attempts = attempts_for(n_valid);
    let mut out = Vec::with_capacity(n_valid);
    let mut next = 0;
    while out.len() < n_valid {
        if next >= max_attempts {
            return Err(FieldError::RetriesExhausted { valid: out.len(), requested: n_valid, attempts: next });
        }
        // Enough attempts for what is missing, plus a few spares for dropouts.
        let batch = ((n_valid - out.len()) + 2).min(max_attempts - next);
        let results: Vec<Result<Demonstration, FieldError>> = (next..next + batch)
            .into_par_iter()
            .map(|i| {
                demonstrate_on(demonstrator, body, configuration, derive_seed(seed, stream, i as u64), lapse, config)
            })
            .collect();
        next += batch;
        for r in results {
            let d = r?;
            if d.valid && out.len() < n_valid {
                out.push(d);
            }
        }
    }
    Ok(out)
}

/// How many attempts a recording of `n_valid` valid demonstrations may make before it gives up:
/// dropouts are rare, so four times as many and a few more mean tracking cannot be had.
pub(crate) const fn attempts_for(n_valid: usize) -> usize {
    4 * n_valid + 20
}

/// [`record`] for several demonstrators, `n_valid` per configuration each, all lapsing at
/// `lapse`, in parallel; the result is ordered by demonstrator (as given), then configuration 1
/// before 2.
///
/// # Errors
/// As [`record`].
pub fn record_all(
    demonstrators: &[Demonstrator],
    n_valid: usize,
    seed: u64,
    lapse: LapseRate,
    config: &FieldConfig,
) -> Result<Vec<Demonstration>, FieldError> {
    let jobs: Vec<(Demonstrator, Configuration)> =
        demonstrators.iter().flat_map(|d| Configuration::ALL.map(|c| (*d, c))).collect();
    let parts: Vec<Result<Vec<Demonstration>, FieldError>> =
        jobs.par_iter().map(|&(d, c)| record(d, c, n_valid, seed, lapse, config)).collect();
    let mut out = Vec::with_capacity(jobs.len() * n_valid);
    for p in parts {
        out.extend(p?);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for d in Demonstrator::ALL {
            assert_eq!(Demonstrator::from_name(d.name()), Ok(d));
        }
        assert!(Demonstrator::from_name("average").is_err());
    }

    #[test]
    fn record_retries_invalid_demonstrations() {
        let mut config = FieldConfig::default();
        config.tracker.loss_probability = 0.002;
        let demos = record(Demonstrator::Poor, Configuration::Two, 3, 9, LapseRate::NONE, &config).expect("records");
        assert_eq!(demos.len(), 3);
        assert!(demos.iter().all(|d| d.valid));
        // Replaying a seed gives the same frames.
        let again = demonstrate(Demonstrator::Poor, Configuration::Two, demos[0].seed, LapseRate::NONE, &config)
            .expect("replays");
        assert_eq!(again.frames.len(), demos[0].frames.len());
        assert_eq!(again.outcome, demos[0].outcome);
    }

    #[test]
    fn the_lego_as_data_is_the_lego_bit_for_bit() {
        let config = FieldConfig::default();
        let json = crate::body::LEGO.to_json().replace("\"lego\"", "\"lego_as_data\"");
        let params = crate::body::WheeledParams::from_json(&json).expect("the Lego's constants are valid");
        assert_eq!(params.name, "lego_as_data");
        let as_data = BodyKind::Wheeled(params, crate::FieldGeometry::of(crate::FieldSize::Large));
        for who in [Demonstrator::Expert, Demonstrator::Poor] {
            let ours = record_on(who, as_data, Configuration::Two, 2, 5, LapseRate::NONE, &config).expect("records");
            let theirs = record(who, Configuration::Two, 2, 5, LapseRate::NONE, &config).expect("records");
            let bits = |d: &[Demonstration]| -> Vec<u64> {
                d.iter()
                    .flat_map(|x| x.frames.iter().flat_map(|f| [f.robot_x_mm.to_bits(), f.ball_y_mm.to_bits()]))
                    .collect()
            };
            assert_eq!(bits(&ours), bits(&theirs), "{who:?}");
        }
    }

    #[test]
    fn a_controller_is_refused_a_body_it_cannot_drive() {
        let config = FieldConfig::default();
        let mut slow = crate::body::TINY;
        slow.name = "slow";
        let slow = BodyKind::Wheeled(slow, crate::FieldGeometry::of(crate::FieldSize::Small));
        for (who, body) in [
            (Demonstrator::Expert, slow),
            (Demonstrator::Expert, BodyKind::Tiny),
            (Demonstrator::Humanoid, BodyKind::Lego),
            (Demonstrator::Poor, BodyKind::Humanoid),
        ] {
            let r = record_on(who, body, Configuration::One, 1, 0, LapseRate::NONE, &config);
            assert!(
                matches!(r, Err(FieldError::Param(FieldParamError::ControllerNotSupported { .. }))),
                "{who:?} on {}",
                body.name()
            );
        }
        assert!(record_on(Demonstrator::Poor, slow, Configuration::One, 1, 0, LapseRate::NONE, &config).is_ok());
    }

    #[test]
    fn hopeless_tracking_is_reported_not_looped() {
        let mut config = FieldConfig::default();
        config.tracker.loss_probability = 1.0;
        let r = record(Demonstrator::Poor, Configuration::One, 2, 1, LapseRate::NONE, &config);
        assert!(matches!(r, Err(FieldError::RetriesExhausted { .. })));
    }
}
