//! The imitator's one-second primitives (thesis §1.3, §3.1.1): the wheeled bodies' five and the
//! humanoid's own classes beyond them, and a body's set of them as data (docs/guides/bodies.md).

use serde::{Deserialize, Serialize};

/// One of the imitator's primitives. The wheeled five keep ids 0–4 (the discriminant is also the
/// field's command id for them); the humanoid's side-steps and kick follow from 5. Serialises
/// in lower case (`"forward"`), as saved recognisers and forward models spell it; the field's
/// commands spell it capitalised through [`capitalised`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
#[repr(u8)]
pub enum Primitive {
    /// Both wheels forward.
    Forward = 0,
    /// Both wheels backward.
    Backward = 1,
    /// Spin counter-clockwise.
    Left = 2,
    /// Spin clockwise.
    Right = 3,
    /// Motors off; on the humanoid, standing still (waiting and scanning look alike from above).
    Stop = 4,
    /// The humanoid side-stepping to its left (a shuffle).
    #[serde(rename = "sidestep_left")]
    SidestepLeft = 5,
    /// The humanoid side-stepping to its right.
    #[serde(rename = "sidestep_right")]
    SidestepRight = 6,
    /// The humanoid kicking, with either foot (a left and a right kick look alike from above).
    Kick = 7,
}

impl Primitive {
    /// Every primitive of every body, in id order.
    pub const ALL: [Self; 8] = [
        Self::Forward,
        Self::Backward,
        Self::Left,
        Self::Right,
        Self::Stop,
        Self::SidestepLeft,
        Self::SidestepRight,
        Self::Kick,
    ];

    /// The wheeled bodies' five, in id order (the thesis's primitives).
    pub const WHEELED: [Self; 5] = [Self::Forward, Self::Backward, Self::Left, Self::Right, Self::Stop];

    /// The wheeled primitives an HMM recognises; stop is recognised by the lack of motion instead.
    pub const MOVING: [Self; 4] = [Self::Forward, Self::Backward, Self::Left, Self::Right];

    /// Every primitive but stop, in id order: the slots of a recogniser's scores.
    pub const ALL_MOVING: [Self; 7] =
        [Self::Forward, Self::Backward, Self::Left, Self::Right, Self::SidestepLeft, Self::SidestepRight, Self::Kick];

    /// Position in [`Primitive::ALL`] (for the wheeled five, also the field's command id).
    #[must_use]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The primitive at an index of [`Primitive::ALL`]; `None` from 8 on.
    #[must_use]
    pub fn from_index(index: usize) -> Option<Self> {
        Self::ALL.get(index).copied()
    }

    /// Position in [`Primitive::ALL_MOVING`]; `None` for stop.
    #[must_use]
    pub const fn moving_index(self) -> Option<usize> {
        match self {
            Self::Stop => None,
            Self::Forward | Self::Backward | Self::Left | Self::Right => Some(self as usize),
            Self::SidestepLeft | Self::SidestepRight | Self::Kick => Some(self as usize - 1),
        }
    }

    /// Full name, lower case.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Forward => "forward",
            Self::Backward => "backward",
            Self::Left => "left",
            Self::Right => "right",
            Self::Stop => "stop",
            Self::SidestepLeft => "sidestep_left",
            Self::SidestepRight => "sidestep_right",
            Self::Kick => "kick",
        }
    }

    /// The primitive with this (lower-case) name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }

    /// One capital letter (how behaviours are written): F B L R S for the wheeled five; A and
    /// D for the side-steps left and right (the keys that strafe in games) and K for the kick.
    #[must_use]
    pub const fn letter(self) -> char {
        match self {
            Self::Forward => 'F',
            Self::Backward => 'B',
            Self::Left => 'L',
            Self::Right => 'R',
            Self::Stop => 'S',
            Self::SidestepLeft => 'A',
            Self::SidestepRight => 'D',
            Self::Kick => 'K',
        }
    }
}

/// Serde for a primitive spelled capitalised (`"Forward"`), as the field's commands, command
/// table and self-observation sequences have always written it: use with
/// `#[serde(with = "polymimic_types::capitalised")]`.
pub mod capitalised {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    use super::Primitive;

    #[derive(Serialize, Deserialize)]
    enum Capitalised {
        Forward,
        Backward,
        Left,
        Right,
        Stop,
        SidestepLeft,
        SidestepRight,
        Kick,
    }

    /// Writes the primitive's capitalised name.
    ///
    /// # Errors
    /// Only as the serializer fails.
    pub fn serialize<S: Serializer>(primitive: &Primitive, serializer: S) -> Result<S::Ok, S::Error> {
        match primitive {
            Primitive::Forward => Capitalised::Forward,
            Primitive::Backward => Capitalised::Backward,
            Primitive::Left => Capitalised::Left,
            Primitive::Right => Capitalised::Right,
            Primitive::Stop => Capitalised::Stop,
            Primitive::SidestepLeft => Capitalised::SidestepLeft,
            Primitive::SidestepRight => Capitalised::SidestepRight,
            Primitive::Kick => Capitalised::Kick,
        }
        .serialize(serializer)
    }

    /// Reads a capitalised name.
    ///
    /// # Errors
    /// Anything but one of the capitalised names.
    pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Primitive, D::Error> {
        Ok(match Capitalised::deserialize(deserializer)? {
            Capitalised::Forward => Primitive::Forward,
            Capitalised::Backward => Primitive::Backward,
            Capitalised::Left => Primitive::Left,
            Capitalised::Right => Primitive::Right,
            Capitalised::Stop => Primitive::Stop,
            Capitalised::SidestepLeft => Primitive::SidestepLeft,
            Capitalised::SidestepRight => Primitive::SidestepRight,
            Capitalised::Kick => Primitive::Kick,
        })
    }
}

#[cfg(test)]
mod tests {
    use serde::{Deserialize, Serialize};

    use super::*;

    #[test]
    fn index_is_the_position_in_all_and_round_trips() {
        for (i, p) in Primitive::ALL.into_iter().enumerate() {
            assert_eq!(p.index(), i);
            assert_eq!(Primitive::from_index(i), Some(p));
            assert_eq!(Primitive::from_name(p.name()), Some(p));
        }
        assert_eq!(Primitive::from_index(8), None);
        assert_eq!(Primitive::from_name("Forward"), None);
        let letters: String = Primitive::ALL.iter().map(|p| p.letter()).collect();
        assert_eq!(letters, "FBLRSADK");
    }

    #[test]
    fn the_wheeled_five_keep_their_ids_and_moving_slots_skip_stop() {
        assert_eq!(Primitive::WHEELED, Primitive::ALL[..5]);
        assert_eq!(Primitive::MOVING, Primitive::ALL_MOVING[..4]);
        for (slot, p) in Primitive::ALL_MOVING.into_iter().enumerate() {
            assert_eq!(p.moving_index(), Some(slot));
        }
        assert_eq!(Primitive::Stop.moving_index(), None);
        assert_eq!(Primitive::Kick.index(), 7);
    }

    #[test]
    fn serialises_lower_case_for_saved_models() {
        assert_eq!(serde_json::to_string(&Primitive::Forward).expect("unit"), r#""forward""#);
        assert_eq!(serde_json::from_str::<Primitive>(r#""stop""#).expect("valid"), Primitive::Stop);
        assert!(serde_json::from_str::<Primitive>(r#""Stop""#).is_err());
        assert_eq!(serde_json::to_string(&Primitive::SidestepLeft).expect("unit"), r#""sidestep_left""#);
        assert_eq!(serde_json::from_str::<Primitive>(r#""kick""#).expect("valid"), Primitive::Kick);
    }

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct FieldRow {
        #[serde(with = "capitalised")]
        primitive: Primitive,
    }

    #[test]
    fn capitalised_keeps_the_fields_spelling() {
        for p in Primitive::ALL {
            let text = serde_json::to_string(&FieldRow { primitive: p }).expect("unit");
            let capitalised: String = p.name().split('_').map(|w| w[..1].to_uppercase() + &w[1..]).collect();
            let expected = format!(r#"{{"primitive":"{capitalised}"}}"#);
            assert_eq!(text, expected);
            assert_eq!(serde_json::from_str::<FieldRow>(&text).expect("valid"), FieldRow { primitive: p });
        }
        assert!(serde_json::from_str::<FieldRow>(r#"{"primitive":"forward"}"#).is_err());
    }
}
