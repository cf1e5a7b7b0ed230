//! A body's primitives as data (docs/guides/bodies.md): the classes of its commands that an overhead tracker
//! can tell apart. The wheeled bodies share the thesis's five; the humanoid adds side-steps and a
//! kick.

use serde::{Deserialize, Serialize};

use crate::primitive::Primitive;

/// Which primitives a body has. Serialises in lower case (`"wheeled"`, `"humanoid"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PrimitiveSet {
    /// Forward, backward, left, right and stop: every two-wheeled body's.
    #[default]
    Wheeled,
    /// The wheeled five as walking, turning and standing still, and side-steps and a kick.
    Humanoid,
}

const HUMANOID_MOVING: [Primitive; 7] = Primitive::ALL_MOVING;

impl PrimitiveSet {
    /// Both sets, the wheeled first.
    pub const ALL: [Self; 2] = [Self::Wheeled, Self::Humanoid];

    /// Its primitives, in id order.
    #[must_use]
    pub const fn primitives(self) -> &'static [Primitive] {
        match self {
            Self::Wheeled => &Primitive::WHEELED,
            Self::Humanoid => &Primitive::ALL,
        }
    }

    /// Its primitives an HMM recognises (all but stop), in id order: a prefix of
    /// [`Primitive::ALL_MOVING`], so a score's slot is the same in every set.
    #[must_use]
    pub const fn moving(self) -> &'static [Primitive] {
        match self {
            Self::Wheeled => &Primitive::MOVING,
            Self::Humanoid => &HUMANOID_MOVING,
        }
    }

    /// Whether `primitive` is one of its own.
    #[must_use]
    pub fn contains(self, primitive: Primitive) -> bool {
        self.primitives().contains(&primitive)
    }

    /// Lower-case name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Wheeled => "wheeled",
            Self::Humanoid => "humanoid",
        }
    }

    /// The set with this name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Whether it is the wheeled set (saved files leave the default out, so that files written
    /// before sets existed and files written now for wheeled bodies are the same bytes).
    #[must_use]
    pub fn is_wheeled(&self) -> bool {
        *self == Self::Wheeled
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moving_sets_are_prefixes_of_the_score_slots() {
        for set in PrimitiveSet::ALL {
            let moving = set.moving();
            assert_eq!(moving, &Primitive::ALL_MOVING[..moving.len()]);
            assert!(set.contains(Primitive::Stop) && !moving.contains(&Primitive::Stop));
            assert_eq!(set.primitives().len(), moving.len() + 1);
            assert_eq!(PrimitiveSet::from_name(set.name()), Some(set));
        }
        assert_eq!(PrimitiveSet::Wheeled.primitives().len(), 5);
        assert_eq!(PrimitiveSet::Humanoid.primitives().len(), 8);
        assert!(!PrimitiveSet::Wheeled.contains(Primitive::Kick));
        assert_eq!(PrimitiveSet::from_name("Wheeled"), None);
    }
}
