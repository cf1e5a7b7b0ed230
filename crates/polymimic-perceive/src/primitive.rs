//! The imitator's motion primitives, and the labels a demonstration segment can get.

use serde::{Deserialize, Serialize};

/// One of the imitator's one-second primitives (thesis §1.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Primitive {
    Forward,
    Backward,
    Left,
    Right,
    Stop,
}

impl Primitive {
    pub const ALL: [Self; 5] = [Self::Forward, Self::Backward, Self::Left, Self::Right, Self::Stop];
    /// The primitives an HMM recognises; stop is recognised by the lack of motion instead.
    pub const MOVING: [Self; 4] = [Self::Forward, Self::Backward, Self::Left, Self::Right];

    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Forward => "forward",
            Self::Backward => "backward",
            Self::Left => "left",
            Self::Right => "right",
            Self::Stop => "stop",
        }
    }

    /// The name's first letter, capital: F, B, L, R or S (how behaviours are written).
    #[must_use]
    pub fn letter(self) -> &'static str {
        match self {
            Self::Forward => "F",
            Self::Backward => "B",
            Self::Left => "L",
            Self::Right => "R",
            Self::Stop => "S",
        }
    }

    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }
}

/// What a demonstration segment was recognised as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Label {
    Primitive(Primitive),
    /// No primitive fits: the best two models scored too close to call.
    Gap,
}

impl Label {
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Primitive(p) => p.name(),
            Self::Gap => "gap",
        }
    }
}
