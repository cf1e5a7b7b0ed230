//! A deterministic simulated robot-soccer field with an overhead tracker, replacing the physical
//! lab of "Imitation Learning from Multiple Demonstrators Using Global Vision" (§3.1.1, §4.1).
//!
//! Robots (a Lego two-wheeled imitator calibrated to Table 3.1, a tiny two-wheeled robot and a
//! humanoid) push or kick a ball toward a goal on a rapier2d field, watched by a 30 frames/s
//! tracker with jitter, heading spikes and dropouts. Built-in controllers (a babbler for
//! self-observation, Expert, Poor, Tiny and Humanoid demonstrators) or an external policy
//! through [`Episode::step`] choose one command per frame.
//!
//! Units: mm, s, rad; field origin at the centre, +x toward the target goal.
//!
//! ```
//! use polymimic_field::{
//!     BodyKind, Command, Configuration, Demonstrator, Episode, EpisodeSetup, FieldConfig,
//!     LapseRate, Primitive, primitive_stats, record, self_observation,
//! };
//!
//! let config = FieldConfig::default();
//! // Self-observation: one-second primitives of the imitator, labelled (§3.1.1).
//! let seqs = self_observation(10, 7, &config)?;
//! assert_eq!(seqs.len(), 50);
//! let table = primitive_stats(&seqs); // Table 3.1, indexed by Primitive::index()
//! assert!(table[Primitive::Forward.index()].distance_mean_mm > 0.0);
//!
//! // Demonstrations: valid shots on goal with the outcome and the commands sent.
//! let demos = record(Demonstrator::Expert, Configuration::One, 2, 7, LapseRate::NONE, &config)?;
//! assert_eq!(demos.len(), 2);
//! // The same Expert, spending about half of its seconds on a random primitive (docs/guides/crowd.md).
//! let sloppy = record(Demonstrator::Expert, Configuration::One, 2, 7, LapseRate::new(0.5)?, &config)?;
//! assert_eq!(sloppy.len(), 2);
//!
//! // An external policy drives the imitator frame by frame.
//! let setup = EpisodeSetup::configuration(BodyKind::Lego, Configuration::One, &config);
//! let mut episode = Episode::new(&setup, &config, 7)?;
//! while !episode.is_finished() {
//!     let seen = episode.observation();
//!     let turn = seen.ball.map_or(0.0, |b| seen.robot.relative_bearing_rad(b));
//!     let p = if turn > 0.3 { Primitive::Left } else if turn < -0.3 { Primitive::Right } else { Primitive::Forward };
//!     episode.step(Command::Primitive(p))?;
//! }
//! println!("{:?} after {} frames", episode.outcome(), episode.frames().len());
//! # Ok::<(), polymimic_field::FieldError>(())
//! ```

mod batch;
pub mod body;
pub mod command;
pub mod controller;
mod demonstrate;
mod episode;
mod error;
mod geometry;
mod math;
mod physics;
mod policy;
mod record;
mod setup;
mod stats;
mod tracker;

pub use batch::EpisodeBatch;
pub use body::BodyKind;
pub use command::{Command, CommandInfo, ExpertCommand, HumanoidCommand, Language, WheelSpeeds, command_table};
pub use controller::{Controller, LapseRate};
pub use demonstrate::{Demonstration, Demonstrator, demonstrate, demonstrate_on, record, record_all, record_on};
pub use episode::{Episode, Observation, Outcome, StepResult};
pub use error::{FieldError, FieldParamError};
pub use geometry::{FieldGeometry, FieldSize};
pub use math::derive_seed;
pub use physics::BallParams;
pub use policy::{
    ControllerPolicy, DecisionRate, EpisodeStart, Policy, PolicyFailure, PolicyFault, PolicyRecording,
    demonstrate_policy, policy_episode_seed, record_policy,
};
/// The domain types the field shares with every crate, re-exported for the field's users.
pub use polymimic_types::{MotionStats, Point, Pose, Primitive, PrimitiveSet, TrackedFrame, wrap_angle_rad};
pub use record::{
    PrimitiveSequence, run_controller, self_observation, self_observation_batch, self_observation_of,
    self_observation_of_set,
};
pub use setup::{Configuration, EpisodeSetup, FieldConfig, Start};
pub use stats::{THESIS_TABLE_3_1, primitive_motion, primitive_stats, table_3_1_row};
pub use tracker::{FRAME_DT_S, FRAME_RATE_HZ, Frame, TrackerConfig};
