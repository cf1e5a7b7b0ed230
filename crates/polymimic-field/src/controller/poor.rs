//! Poor: drives straight at the ball with primitives (§3.2.1), with no thought for where the
//! ball will go, so in configuration 2 it pushes the ball toward its own goal.

use polymimic_types::Primitive;

use crate::command::Command;
use crate::episode::Observation;
use crate::math::deg;

use super::Controller;

/// The Poor demonstrator's controller (Lego body, global vision).
#[derive(Debug, Clone, Default)]
pub struct Poor {
    turning: Option<Primitive>,
}

impl Poor {
    /// A fresh Poor.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }
}

impl Controller for Poor {
    fn command(&mut self, observation: &Observation) -> Command {
        let Some(ball) = observation.ball else {
            return Command::Primitive(Primitive::Stop);
        };
        let e = observation.robot.relative_bearing_rad(ball);
        // Start turning when well off, keep turning until nearly on (hysteresis).
        let limit = if self.turning.is_some() { deg(8.0) } else { deg(20.0) };
        self.turning = (e.abs() > limit).then_some(if e > 0.0 { Primitive::Left } else { Primitive::Right });
        Command::Primitive(self.turning.unwrap_or(Primitive::Forward))
    }
}
