//! Robot bodies: what a command does to the robot's pose, and the robot's shape for contacts.

mod humanoid;
mod wheeled;

use polymimic_types::{Point, Pose, PrimitiveSet};
use serde::Serialize;

pub use humanoid::{HUMANOID, HUMANOID_BEFORE_CALIBRATION, HumanoidParams};
pub use wheeled::{LEGO, TINY, Traction, WheeledParams};

pub(crate) use humanoid::{Foot, HumanoidBody};
pub(crate) use wheeled::WheeledBody;

use crate::command::Command;
use crate::error::FieldParamError;
use crate::geometry::{FieldGeometry, FieldSize};
use crate::math::Rng;

/// The robots of the thesis, and wheeled robots described as data (docs/guides/own-data.md).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum BodyKind {
    /// The Lego Mindstorms two-wheeled robot: the imitator, and the Expert and Poor demonstrators.
    Lego,
    /// The tiny two-wheeled robot (1/10 scale), on the small field.
    Tiny,
    /// The humanoid, with a head camera.
    Humanoid,
    /// A two-wheeled robot of the user's, on a field of the user's (or one of the thesis's).
    Wheeled(WheeledParams, FieldGeometry),
}

impl BodyKind {
    /// The field this body plays on.
    #[must_use]
    pub const fn field(self) -> FieldGeometry {
        match self {
            BodyKind::Tiny => FieldGeometry::of(FieldSize::Small),
            BodyKind::Lego | BodyKind::Humanoid => FieldGeometry::of(FieldSize::Large),
            BodyKind::Wheeled(_, field) => field,
        }
    }

    /// Footprint (length along the heading, width), mm.
    #[must_use]
    pub const fn footprint_mm(self) -> (f64, f64) {
        match self {
            BodyKind::Lego => (LEGO.length_mm, LEGO.width_mm),
            BodyKind::Tiny => (TINY.length_mm, TINY.width_mm),
            BodyKind::Humanoid => (HUMANOID.length_mm, HUMANOID.width_mm),
            BodyKind::Wheeled(params, _) => (params.length_mm, params.width_mm),
        }
    }

    /// Whether it drives on two wheels (and so takes the primitives).
    #[must_use]
    pub const fn is_wheeled(self) -> bool {
        !matches!(self, BodyKind::Humanoid)
    }

    /// Its own primitives: the classes of its commands an overhead tracker tells apart.
    #[must_use]
    pub const fn primitive_set(self) -> PrimitiveSet {
        match self {
            BodyKind::Humanoid => PrimitiveSet::Humanoid,
            BodyKind::Lego | BodyKind::Tiny | BodyKind::Wheeled(..) => PrimitiveSet::Wheeled,
        }
    }

    /// Name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            BodyKind::Lego => "lego",
            BodyKind::Tiny => "tiny",
            BodyKind::Humanoid => "humanoid",
            BodyKind::Wheeled(params, _) => params.name,
        }
    }
}

/// A body being simulated.
#[derive(Debug, Clone)]
pub(crate) enum Body {
    Wheeled(WheeledBody),
    Humanoid(HumanoidBody),
}

impl Body {
    pub(crate) fn new(kind: BodyKind, pose: Pose, humanoid: &HumanoidParams) -> Self {
        match kind {
            BodyKind::Lego => Body::Wheeled(WheeledBody::new(LEGO, pose)),
            BodyKind::Tiny => Body::Wheeled(WheeledBody::new(TINY, pose)),
            BodyKind::Humanoid => Body::Humanoid(HumanoidBody::new(*humanoid, pose)),
            BodyKind::Wheeled(params, _) => Body::Wheeled(WheeledBody::new(params, pose)),
        }
    }

    pub(crate) fn command(&mut self, command: Command, rng: &mut Rng) -> Result<(), FieldParamError> {
        match self {
            Body::Wheeled(b) => b.command(command, rng),
            Body::Humanoid(b) => b.command(command, rng),
        }
    }

    pub(crate) fn substep(&mut self, dt_s: f64, rng: &mut Rng) {
        match self {
            Body::Wheeled(b) => b.substep(dt_s),
            Body::Humanoid(b) => b.substep(dt_s, rng),
        }
    }

    pub(crate) fn pose(&self) -> Pose {
        match self {
            Body::Wheeled(b) => b.pose(),
            Body::Humanoid(b) => b.pose(),
        }
    }

    pub(crate) fn place(&mut self, pose: Pose) {
        match self {
            Body::Wheeled(b) => b.place(pose),
            Body::Humanoid(b) => b.place(pose),
        }
    }

    /// Footprint (length, width), mm.
    pub(crate) fn footprint_mm(&self) -> (f64, f64) {
        match self {
            Body::Wheeled(b) => (b.params().length_mm, b.params().width_mm),
            Body::Humanoid(b) => (b.params().length_mm, b.params().width_mm),
        }
    }

    /// Foot size (length, width), mm, if the body can kick.
    pub(crate) fn foot_size_mm(&self) -> Option<(f64, f64)> {
        match self {
            Body::Wheeled(_) => None,
            Body::Humanoid(b) => Some(b.params().foot_size_mm),
        }
    }

    pub(crate) fn foot(&self) -> Option<Foot> {
        match self {
            Body::Wheeled(_) => None,
            Body::Humanoid(b) => Some(b.foot()),
        }
    }

    /// Whether the robot's own sensing sees the ball (wheeled robots use global vision).
    pub(crate) fn sees(&self, ball: Point) -> bool {
        match self {
            Body::Wheeled(_) => true,
            Body::Humanoid(b) => b.sees(ball),
        }
    }

    pub(crate) fn is_kicking(&self) -> bool {
        match self {
            Body::Wheeled(_) => false,
            Body::Humanoid(b) => b.is_kicking(),
        }
    }
}
