//! The Expert's command language: named wheel-speed pairs for the Lego body.

use serde::{Deserialize, Serialize};

use crate::error::FieldParamError;

/// The Expert's command language: named wheel-speed pairs (left, right), mm/s, for the Lego body.
/// The thesis's RC2004 controller used over a hundred; 35 cover straights, spins, nudges, pivots
/// and arcs at several speeds.
const EXPERT_COMMANDS: [(&str, f64, f64); 35] = [
    ("forward_crawl", 25.0, 25.0),
    ("forward_slow", 45.0, 45.0),
    ("forward_medium", 70.0, 70.0),
    ("forward_fast", 100.0, 100.0),
    ("forward_sprint", 130.0, 130.0),
    ("backward_slow", -45.0, -45.0),
    ("backward_medium", -70.0, -70.0),
    ("backward_fast", -100.0, -100.0),
    ("spin_left_slow", -20.0, 20.0),
    ("spin_left_medium", -40.0, 40.0),
    ("spin_left_fast", -70.0, 70.0),
    ("spin_right_slow", 20.0, -20.0),
    ("spin_right_medium", 40.0, -40.0),
    ("spin_right_fast", 70.0, -70.0),
    ("nudge_left", -10.0, 10.0),
    ("nudge_right", 10.0, -10.0),
    ("arc_left_wide_slow", 48.0, 60.0),
    ("arc_left_medium_slow", 33.0, 60.0),
    ("arc_left_tight_slow", 18.0, 60.0),
    ("arc_left_wide_fast", 80.0, 100.0),
    ("arc_left_medium_fast", 55.0, 100.0),
    ("arc_left_tight_fast", 30.0, 100.0),
    ("arc_right_wide_slow", 60.0, 48.0),
    ("arc_right_medium_slow", 60.0, 33.0),
    ("arc_right_tight_slow", 60.0, 18.0),
    ("arc_right_wide_fast", 100.0, 80.0),
    ("arc_right_medium_fast", 100.0, 55.0),
    ("arc_right_tight_fast", 100.0, 30.0),
    ("back_arc_left", -70.0, -45.0),
    ("back_arc_right", -45.0, -70.0),
    ("pivot_forward_left", 0.0, 50.0),
    ("pivot_forward_right", 50.0, 0.0),
    ("pivot_back_left", -50.0, 0.0),
    ("pivot_back_right", 0.0, -50.0),
    ("brake", 0.0, 0.0),
];

/// One command of the Expert's language (an index into its table; deserialising checks it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(try_from = "u8", into = "u8")]
pub struct ExpertCommand(u8);

impl TryFrom<u8> for ExpertCommand {
    type Error = FieldParamError;

    fn try_from(index: u8) -> Result<Self, Self::Error> {
        Self::from_index(usize::from(index))
    }
}

impl From<ExpertCommand> for u8 {
    fn from(c: ExpertCommand) -> u8 {
        c.0
    }
}

impl ExpertCommand {
    /// Number of commands in the language.
    pub const COUNT: usize = EXPERT_COMMANDS.len();

    /// The command at an index.
    ///
    /// # Errors
    /// `UnknownCommand` past the end of the table.
    pub fn from_index(index: usize) -> Result<Self, FieldParamError> {
        if index < Self::COUNT {
            Ok(Self(index as u8))
        } else {
            Err(FieldParamError::UnknownCommand((100 + index).min(u16::MAX as usize) as u16))
        }
    }

    /// The command with this name, if any.
    #[must_use]
    pub fn by_name(name: &str) -> Option<Self> {
        EXPERT_COMMANDS.iter().position(|(n, _, _)| *n == name).map(|i| Self(i as u8))
    }

    /// Every command, in id order.
    pub fn all() -> impl Iterator<Item = ExpertCommand> {
        (0..Self::COUNT).map(|i| Self(i as u8))
    }

    /// Index in the table.
    #[must_use]
    pub const fn index(self) -> usize {
        self.0 as usize
    }

    /// Name.
    #[must_use]
    pub fn name(self) -> &'static str {
        EXPERT_COMMANDS[self.index()].0
    }

    /// Nominal (left, right) wheel speeds, mm/s.
    #[must_use]
    pub fn wheels_mm_s(self) -> (f64, f64) {
        let (_, l, r) = EXPERT_COMMANDS[self.index()];
        (l, r)
    }
}
