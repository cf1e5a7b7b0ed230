//! Controllers: whatever chooses a command each tracker frame from an observation.

mod babbler;
mod expert;
mod humanoid;
mod lapse;
mod planner;
mod poor;
mod tiny;

pub use babbler::Babbler;
pub use expert::Expert;
pub use humanoid::HumanoidController;
pub use lapse::{LapseRate, Lapsing, primitive_command, primitive_command_seeing};
pub use poor::Poor;
pub use tiny::TinyController;

use polymimic_types::Pose;

use crate::command::Command;
use crate::episode::Observation;

/// Chooses a command every tracker frame.
pub trait Controller: Send {
    /// The command to send during the coming frame.
    fn command(&mut self, observation: &Observation) -> Command;

    /// Called before [`Controller::command`]: a pose to lift the robot to (the experimenter's
    /// hand), if any. Only the self-observation babbler uses it.
    fn reposition(&mut self, _observation: &Observation) -> Option<Pose> {
        None
    }
}
