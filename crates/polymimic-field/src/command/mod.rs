//! Commands: the imitator's five primitives, the Expert's wheel-speed language (expert.rs), the
//! humanoid's language (Table 4.4, humanoid.rs) and wheel speeds of a policy's own choosing
//! (wheels.rs), each with a stable numeric id and an equivalent primitive.

use polymimic_types::{Primitive, capitalised};
use serde::{Deserialize, Serialize};

use crate::error::FieldParamError;

mod expert;
mod humanoid;
mod wheels;

pub use expert::ExpertCommand;
pub use humanoid::HumanoidCommand;
pub(crate) use wheels::LEGO_WHEEL_BASE_MM;
pub use wheels::WheelSpeeds;
use wheels::primitive_of_wheels;

/// Which language a command belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Language {
    /// The imitator's primitives (also used by Poor and Tiny).
    Primitive,
    /// The Expert's wheel-speed language.
    Expert,
    /// The humanoid's language.
    Humanoid,
    /// Wheel speeds of a policy's own choosing (any wheeled body).
    Wheels,
}

/// A command sent by a controller for one tracker frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Command {
    /// An imitator primitive; each wheeled body maps it to its own wheel speeds.
    Primitive(#[serde(with = "capitalised")] Primitive),
    /// A command of the Expert's language (Lego body only).
    Expert(ExpertCommand),
    /// A command of the humanoid's language (humanoid body only).
    Humanoid(HumanoidCommand),
    /// Wheel speeds of a policy's own choosing (any wheeled body, within its top speed).
    Wheels(WheelSpeeds),
}

const EXPERT_ID_BASE: u16 = 100;
const HUMANOID_ID_BASE: u16 = 200;
/// Frames record wheel speeds by the primitive they resemble: ids 300–304 (F B L R S).
const WHEELS_ID_BASE: u16 = 300;
const WHEELS_ID_LAST: u16 = WHEELS_ID_BASE + 4;
const WHEELS_NAMES: [&str; 5] = ["wheels_forward", "wheels_backward", "wheels_left", "wheels_right", "wheels_stop"];

impl Command {
    /// Stable numeric id: primitives 0–4, Expert 100–134, humanoid 200–216, wheel speeds 300–304
    /// by the primitive they resemble (the speeds themselves have no id).
    #[must_use]
    pub fn id(self) -> u16 {
        match self {
            Command::Primitive(p) => p as u16,
            Command::Expert(e) => EXPERT_ID_BASE + u16::from(u8::from(e)),
            Command::Humanoid(h) => HUMANOID_ID_BASE + h as u16,
            Command::Wheels(_) => WHEELS_ID_BASE + self.primitive() as u16,
        }
    }

    /// The command with this id.
    ///
    /// # Errors
    /// `UnknownCommand` if no language defines the id; `WheelSpeedsHaveNoId` for the ids frames
    /// record wheel speeds by.
    pub fn from_id(id: u16) -> Result<Self, FieldParamError> {
        let unknown = FieldParamError::UnknownCommand(id);
        match id {
            WHEELS_ID_BASE..=WHEELS_ID_LAST => Err(FieldParamError::WheelSpeedsHaveNoId(id)),
            0..=4 => Primitive::from_index(usize::from(id)).map(Command::Primitive).ok_or(unknown),
            EXPERT_ID_BASE..HUMANOID_ID_BASE => {
                ExpertCommand::from_index(usize::from(id - 100)).map(Command::Expert).map_err(|_| unknown)
            }
            _ => HumanoidCommand::ALL
                .get(usize::from(id.saturating_sub(HUMANOID_ID_BASE)))
                .filter(|_| id >= HUMANOID_ID_BASE)
                .map(|h| Command::Humanoid(*h))
                .ok_or(unknown),
        }
    }

    /// Name (unique across languages).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Command::Primitive(p) => p.name(),
            Command::Expert(e) => e.name(),
            Command::Humanoid(h) => h.name(),
            Command::Wheels(_) => WHEELS_NAMES[self.primitive().index()],
        }
    }

    /// The language it belongs to.
    #[must_use]
    pub const fn language(self) -> Language {
        match self {
            Command::Primitive(_) => Language::Primitive,
            Command::Expert(_) => Language::Expert,
            Command::Humanoid(_) => Language::Humanoid,
            Command::Wheels(_) => Language::Wheels,
        }
    }

    /// The imitator primitive that looks the same from above (for evaluation only, §4.3).
    #[must_use]
    pub fn primitive(self) -> Primitive {
        match self {
            Command::Primitive(p) => p,
            Command::Expert(e) => {
                let (l, r) = e.wheels_mm_s();
                primitive_of_wheels(l, r)
            }
            Command::Humanoid(h) => h.primitive(),
            Command::Wheels(w) => {
                let (l, r) = w.mm_s();
                primitive_of_wheels(l, r)
            }
        }
    }
}

impl From<Primitive> for Command {
    fn from(p: Primitive) -> Self {
        Command::Primitive(p)
    }
}

impl From<HumanoidCommand> for Command {
    fn from(h: HumanoidCommand) -> Self {
        Command::Humanoid(h)
    }
}

impl From<ExpertCommand> for Command {
    fn from(e: ExpertCommand) -> Self {
        Command::Expert(e)
    }
}

/// One row of the exported command table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CommandInfo {
    /// Stable numeric id (what [`crate::Frame::command`] holds).
    pub id: u16,
    /// Name.
    pub name: &'static str,
    /// Language.
    pub language: Language,
    /// Equivalent imitator primitive.
    #[serde(with = "capitalised")]
    pub primitive: Primitive,
}

/// Every command of every language with its id and equivalent primitive, in id order; the
/// wheel-speed rows stand for every pair of speeds that resembles their primitive.
#[must_use]
pub fn command_table() -> Vec<CommandInfo> {
    let wheels = Primitive::WHEELED.iter().map(|p| CommandInfo {
        id: WHEELS_ID_BASE + *p as u16,
        name: WHEELS_NAMES[p.index()],
        language: Language::Wheels,
        primitive: *p,
    });
    Primitive::WHEELED
        .iter()
        .map(|p| Command::Primitive(*p))
        .chain(ExpertCommand::all().map(Command::Expert))
        .chain(HumanoidCommand::ALL.iter().map(|h| Command::Humanoid(*h)))
        .map(|c| CommandInfo { id: c.id(), name: c.name(), language: c.language(), primitive: c.primitive() })
        .chain(wheels)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_round_trip_for_every_command() {
        let table = command_table();
        assert_eq!(table.len(), 5 + ExpertCommand::COUNT + HumanoidCommand::ALL.len() + 5);
        for row in table.iter().filter(|r| r.language != Language::Wheels) {
            let c = Command::from_id(row.id).expect("known id");
            assert_eq!(c.id(), row.id);
            assert_eq!(c.name(), row.name);
        }
        for id in 300..=304 {
            assert_eq!(Command::from_id(id), Err(FieldParamError::WheelSpeedsHaveNoId(id)));
        }
        for bad in [5, 99, 100 + ExpertCommand::COUNT as u16, 199, 217, u16::MAX] {
            assert_eq!(Command::from_id(bad), Err(FieldParamError::UnknownCommand(bad)));
        }
    }

    #[test]
    fn deserialising_an_out_of_range_expert_command_fails_cleanly() {
        let ok: Command = serde_json::from_str(r#"{"Expert":3}"#).expect("valid index");
        assert_eq!(ok.id(), 103);
        assert!(serde_json::from_str::<Command>(r#"{"Expert":200}"#).is_err());
    }

    #[test]
    fn primitives_keep_their_capitalised_spelling_in_commands() {
        let text = serde_json::to_string(&Command::Primitive(Primitive::Forward)).expect("unit");
        assert_eq!(text, r#"{"Primitive":"Forward"}"#);
        assert_eq!(serde_json::from_str::<Command>(&text).expect("valid"), Command::Primitive(Primitive::Forward));
        let row = serde_json::to_string(&command_table()[3]).expect("plain data");
        assert_eq!(row, r#"{"id":3,"name":"right","language":"Primitive","primitive":"Right"}"#);
    }

    #[test]
    fn wheel_speeds_are_recorded_by_the_primitive_they_resemble() {
        let w = |l, r| Command::Wheels(WheelSpeeds::new(l, r).expect("finite"));
        assert_eq!((w(60.0, 60.0).id(), w(60.0, 60.0).name()), (300, "wheels_forward"));
        assert_eq!(w(-50.0, -49.0).primitive(), Primitive::Backward);
        assert_eq!(w(-40.0, 40.0).primitive(), Primitive::Left);
        assert_eq!(w(0.5, -0.5).primitive(), Primitive::Stop);
        // The Expert's named pairs and the same speeds as numbers resemble the same primitive.
        for e in ExpertCommand::all() {
            let (l, r) = e.wheels_mm_s();
            assert_eq!(w(l, r).primitive(), Command::Expert(e).primitive(), "{}", e.name());
        }
        assert_eq!(WheelSpeeds::new(12.3456, -7.0).expect("finite").mm_s(), (12.346, -7.0));
        assert!(WheelSpeeds::new(f64::NAN, 0.0).is_err() && WheelSpeeds::new(0.0, 2e4).is_err());
    }

    #[test]
    fn names_are_unique() {
        let table = command_table();
        let mut names: Vec<&str> = table.iter().map(|r| r.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), table.len());
    }

    #[test]
    fn expert_language_is_rich_and_maps_to_every_primitive() {
        const { assert!(ExpertCommand::COUNT >= 30) };
        let prims: Vec<Primitive> = ExpertCommand::all().map(|e| Command::Expert(e).primitive()).collect();
        for p in Primitive::WHEELED {
            assert!(prims.contains(&p), "no expert command maps to {p:?}");
        }
        let spin = ExpertCommand::by_name("spin_left_fast").expect("exists");
        assert_eq!(Command::Expert(spin).primitive(), Primitive::Left);
        let arc = ExpertCommand::by_name("arc_right_wide_fast").expect("exists");
        assert_eq!(Command::Expert(arc).primitive(), Primitive::Forward);
    }
}
