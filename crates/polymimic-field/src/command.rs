//! Commands: the imitator's five primitives, the Expert's wheel-speed language and the
//! humanoid's language (Table 4.4), each with a stable numeric id and an equivalent primitive.

use polymimic_types::{Primitive, capitalised};
use serde::{Deserialize, Serialize};

use crate::error::FieldParamError;
pub use crate::wheels::WheelSpeeds;
use crate::wheels::primitive_of_wheels;

/// The Lego body's wheel base, mm: the Expert's wheel speeds are written for it, and its
/// equivalent primitives are read through it.
pub(crate) const LEGO_WHEEL_BASE_MM: f64 = 175.0;

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

/// The humanoid's command language (Table 4.4 plus walking and turning).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[repr(u8)]
pub enum HumanoidCommand {
    /// Stand still.
    Wait = 0,
    /// Get ready to walk (weight shift on the spot).
    Go,
    /// Look straight ahead.
    ScanForward,
    /// Look at the feet.
    ScanDown,
    /// Pan the head left; the torso twists slowly left with it.
    ScanLeft,
    /// Pan the head right; the torso twists slowly right with it.
    ScanRight,
    /// Ball lost: stand still.
    Lost,
    /// Kick with the left foot (leans back while the foot strikes).
    KickLeft,
    /// Kick with the right foot.
    KickRight,
    /// Side-step to the left.
    ShuffleLeft,
    /// Side-step to the right.
    ShuffleRight,
    /// Walk straight ahead.
    WalkForward,
    /// Walk ahead curving left.
    WalkForwardLeft,
    /// Walk ahead curving right.
    WalkForwardRight,
    /// Step backward.
    WalkBackward,
    /// Turn on the spot, left.
    TurnLeft,
    /// Turn on the spot, right.
    TurnRight,
}

impl HumanoidCommand {
    /// Every command, in id order.
    pub const ALL: [HumanoidCommand; 17] = [
        HumanoidCommand::Wait,
        HumanoidCommand::Go,
        HumanoidCommand::ScanForward,
        HumanoidCommand::ScanDown,
        HumanoidCommand::ScanLeft,
        HumanoidCommand::ScanRight,
        HumanoidCommand::Lost,
        HumanoidCommand::KickLeft,
        HumanoidCommand::KickRight,
        HumanoidCommand::ShuffleLeft,
        HumanoidCommand::ShuffleRight,
        HumanoidCommand::WalkForward,
        HumanoidCommand::WalkForwardLeft,
        HumanoidCommand::WalkForwardRight,
        HumanoidCommand::WalkBackward,
        HumanoidCommand::TurnLeft,
        HumanoidCommand::TurnRight,
    ];

    /// Whether the body steps to carry it out (walks, turns or side-steps).
    #[must_use]
    pub const fn steps(self) -> bool {
        matches!(
            self,
            HumanoidCommand::WalkForward
                | HumanoidCommand::WalkForwardLeft
                | HumanoidCommand::WalkForwardRight
                | HumanoidCommand::WalkBackward
                | HumanoidCommand::TurnLeft
                | HumanoidCommand::TurnRight
                | HumanoidCommand::ShuffleLeft
                | HumanoidCommand::ShuffleRight
        )
    }

    /// Name as the thesis writes it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            HumanoidCommand::Wait => "Wait",
            HumanoidCommand::Go => "Go",
            HumanoidCommand::ScanForward => "Scan Forward",
            HumanoidCommand::ScanDown => "Scan Down",
            HumanoidCommand::ScanLeft => "Scan Left",
            HumanoidCommand::ScanRight => "Scan Right",
            HumanoidCommand::Lost => "Lost",
            HumanoidCommand::KickLeft => "Kick Left",
            HumanoidCommand::KickRight => "Kick Right",
            HumanoidCommand::ShuffleLeft => "Shuffle Left",
            HumanoidCommand::ShuffleRight => "Shuffle Right",
            HumanoidCommand::WalkForward => "Walk Forward",
            HumanoidCommand::WalkForwardLeft => "Walk Forward Left",
            HumanoidCommand::WalkForwardRight => "Walk Forward Right",
            HumanoidCommand::WalkBackward => "Walk Backward",
            HumanoidCommand::TurnLeft => "Turn Left",
            HumanoidCommand::TurnRight => "Turn Right",
        }
    }

    /// The class of the humanoid's own primitives it belongs to: what an overhead tracker can
    /// tell apart. Waiting, getting ready and scanning all stand still (a scan's slow twist of
    /// the torso is far below a turn); a left and a right kick look alike, and walking ahead
    /// on a curve is walking forward.
    #[must_use]
    pub const fn own_primitive(self) -> Primitive {
        match self {
            HumanoidCommand::Wait
            | HumanoidCommand::Go
            | HumanoidCommand::ScanForward
            | HumanoidCommand::ScanDown
            | HumanoidCommand::ScanLeft
            | HumanoidCommand::ScanRight
            | HumanoidCommand::Lost => Primitive::Stop,
            HumanoidCommand::KickLeft | HumanoidCommand::KickRight => Primitive::Kick,
            HumanoidCommand::ShuffleLeft => Primitive::SidestepLeft,
            HumanoidCommand::ShuffleRight => Primitive::SidestepRight,
            HumanoidCommand::WalkForward | HumanoidCommand::WalkForwardLeft | HumanoidCommand::WalkForwardRight => {
                Primitive::Forward
            }
            HumanoidCommand::WalkBackward => Primitive::Backward,
            HumanoidCommand::TurnLeft => Primitive::Left,
            HumanoidCommand::TurnRight => Primitive::Right,
        }
    }

    /// The visually equivalent wheeled primitive (Table 4.4, extended to walking and turning).
    #[must_use]
    pub const fn primitive(self) -> Primitive {
        match self {
            HumanoidCommand::Wait
            | HumanoidCommand::Go
            | HumanoidCommand::ScanForward
            | HumanoidCommand::ScanDown
            | HumanoidCommand::Lost => Primitive::Stop,
            HumanoidCommand::KickLeft | HumanoidCommand::KickRight | HumanoidCommand::WalkBackward => {
                Primitive::Backward
            }
            HumanoidCommand::ScanLeft | HumanoidCommand::ShuffleLeft | HumanoidCommand::TurnLeft => Primitive::Left,
            HumanoidCommand::ScanRight | HumanoidCommand::ShuffleRight | HumanoidCommand::TurnRight => Primitive::Right,
            HumanoidCommand::WalkForward | HumanoidCommand::WalkForwardLeft | HumanoidCommand::WalkForwardRight => {
                Primitive::Forward
            }
        }
    }
}

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
            Command::Expert(e) => EXPERT_ID_BASE + u16::from(e.0),
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

    #[test]
    fn humanoid_equivalents_follow_table_4_4() {
        use HumanoidCommand as H;
        for h in [H::Wait, H::Go, H::ScanForward, H::ScanDown, H::Lost] {
            assert_eq!(h.primitive(), Primitive::Stop);
        }
        assert_eq!(H::KickLeft.primitive(), Primitive::Backward);
        assert_eq!(H::KickRight.primitive(), Primitive::Backward);
        assert_eq!(H::ScanLeft.primitive(), Primitive::Left);
        assert_eq!(H::ShuffleLeft.primitive(), Primitive::Left);
        assert_eq!(H::ScanRight.primitive(), Primitive::Right);
        assert_eq!(H::ShuffleRight.primitive(), Primitive::Right);
    }

    #[test]
    fn the_humanoids_own_classes_cover_its_set_and_merge_what_looks_alike() {
        use HumanoidCommand as H;
        let own: Vec<Primitive> = H::ALL.iter().map(|h| h.own_primitive()).collect();
        for p in polymimic_types::PrimitiveSet::Humanoid.primitives() {
            assert!(own.contains(p), "no command of class {p:?}");
        }
        assert_eq!(H::KickLeft.own_primitive(), H::KickRight.own_primitive());
        assert_eq!(H::ScanLeft.own_primitive(), H::Wait.own_primitive());
        assert_eq!(H::ShuffleLeft.own_primitive(), Primitive::SidestepLeft);
        // Each class's command, sent through the primitives, is back in its class.
        for p in Primitive::ALL {
            let Command::Humanoid(h) = crate::controller::primitive_command(p, crate::BodyKind::Humanoid) else {
                panic!("the humanoid takes its own commands");
            };
            assert_eq!(h.own_primitive(), p);
        }
    }
}
