//! The imitator's five one-second primitives (thesis §1.3, §3.1.1).

use serde::{Deserialize, Serialize};

/// One of the imitator's primitives. The discriminant is the field's command id. Serialises
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
    /// Motors off.
    Stop = 4,
}

impl Primitive {
    /// All five, in id order.
    pub const ALL: [Self; 5] = [Self::Forward, Self::Backward, Self::Left, Self::Right, Self::Stop];

    /// The primitives an HMM recognises; stop is recognised by the lack of motion instead.
    pub const MOVING: [Self; 4] = [Self::Forward, Self::Backward, Self::Left, Self::Right];

    /// Position in [`Primitive::ALL`] (also the field's command id).
    #[must_use]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The primitive at an index of [`Primitive::ALL`]; `None` from 5 on.
    #[must_use]
    pub fn from_index(index: usize) -> Option<Self> {
        Self::ALL.get(index).copied()
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
        }
    }

    /// The primitive with this (lower-case) name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }

    /// One capital letter: F B L R S (how behaviours are written).
    #[must_use]
    pub const fn letter(self) -> char {
        match self {
            Self::Forward => 'F',
            Self::Backward => 'B',
            Self::Left => 'L',
            Self::Right => 'R',
            Self::Stop => 'S',
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
        }
        .serialize(serializer)
    }

    /// Reads a capitalised name.
    ///
    /// # Errors
    /// Anything but one of the five capitalised names.
    pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Primitive, D::Error> {
        Ok(match Capitalised::deserialize(deserializer)? {
            Capitalised::Forward => Primitive::Forward,
            Capitalised::Backward => Primitive::Backward,
            Capitalised::Left => Primitive::Left,
            Capitalised::Right => Primitive::Right,
            Capitalised::Stop => Primitive::Stop,
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
        assert_eq!(Primitive::from_index(5), None);
        assert_eq!(Primitive::from_name("Forward"), None);
        let letters: String = Primitive::ALL.iter().map(|p| p.letter()).collect();
        assert_eq!(letters, "FBLRS");
    }

    #[test]
    fn serialises_lower_case_for_saved_models() {
        assert_eq!(serde_json::to_string(&Primitive::Forward).expect("unit"), r#""forward""#);
        assert_eq!(serde_json::from_str::<Primitive>(r#""stop""#).expect("valid"), Primitive::Stop);
        assert!(serde_json::from_str::<Primitive>(r#""Stop""#).is_err());
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
            let name = p.name();
            let expected = format!(r#"{{"primitive":"{}{}"}}"#, name[..1].to_uppercase(), &name[1..]);
            assert_eq!(text, expected);
            assert_eq!(serde_json::from_str::<FieldRow>(&text).expect("valid"), FieldRow { primitive: p });
        }
        assert!(serde_json::from_str::<FieldRow>(r#"{"primitive":"forward"}"#).is_err());
    }
}
