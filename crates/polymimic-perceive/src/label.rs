//! The labels a demonstration segment can get: one of the imitator's primitives, or a gap.

use polymimic_types::Primitive;
use serde::{Deserialize, Serialize};

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
