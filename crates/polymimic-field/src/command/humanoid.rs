//! The humanoid's command language (Table 4.4) and the primitives each command stands for.

use polymimic_types::Primitive;
use serde::{Deserialize, Serialize};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::command::Command;

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
