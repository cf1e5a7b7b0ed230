//! The self-observation babbler (§3.1.1): one primitive per second chosen uniformly from a set
//! (F B L R S, or a body's own), sent as the body's own command for it; near an edge the robot
//! is put back at the centre with a random heading.

use polymimic_types::{Pose, Primitive, PrimitiveSet};

use crate::body::BodyKind;
use crate::command::{Command, HumanoidCommand};
use crate::episode::Observation;
use crate::math::{Rng, TAU, rng, stream, uniform, wrap_angle_rad};

use super::Controller;
use super::lapse::primitive_command;

/// Random-primitive babbler.
pub struct Babbler {
    body: BodyKind,
    set: PrimitiveSet,
    rng: Rng,
    current: Primitive,
    command: Command,
    frames_left: u32,
    margin_mm: f64,
}

impl Babbler {
    /// Frames per primitive (one second).
    pub const PRIMITIVE_FRAMES: u32 = 30;

    /// A babbler for `body` over the wheeled five (on the humanoid, their walking, turning and
    /// waiting equivalents), seeded.
    #[must_use]
    pub fn new(body: BodyKind, seed: u64) -> Self {
        Self::of_set(body, PrimitiveSet::Wheeled, seed)
    }

    /// A babbler for `body` over `set`, seeded. On the wheeled set it babbles as [`Babbler::new`]
    /// always has, draw for draw.
    #[must_use]
    pub fn of_set(body: BodyKind, set: PrimitiveSet, seed: u64) -> Self {
        // Room for the body's half-diagonal plus a couple of primitives' travel.
        let (l, w) = body.footprint_mm();
        let margin_mm = 0.5 * l.hypot(w) + 1.5 * l.max(w).max(60.0);
        let current = Primitive::Stop;
        let command = primitive_command(current, body);
        Self { body, set, rng: rng(seed, stream::CONTROLLER), current, command, frames_left: 0, margin_mm }
    }

    /// The primitive being executed.
    #[must_use]
    pub fn current(&self) -> Primitive {
        self.current
    }

    /// The primitive and command of the second under way, or of the next one, drawn now, when
    /// none is under way. A kick's foot is drawn too: either foot kicks the same class.
    pub fn upcoming(&mut self) -> (Primitive, Command) {
        if self.frames_left == 0 {
            let primitives = self.set.primitives();
            let n = primitives.len();
            let i = ((uniform(&mut self.rng) * n as f64) as usize).min(n - 1);
            self.current = primitives[i];
            self.command = match (self.current, self.body) {
                (Primitive::Kick, BodyKind::Humanoid) if uniform(&mut self.rng) < 0.5 => {
                    Command::Humanoid(HumanoidCommand::KickLeft)
                }
                (p, body) => primitive_command(p, body),
            };
            self.frames_left = Self::PRIMITIVE_FRAMES;
        }
        (self.current, self.command)
    }
}

impl Controller for Babbler {
    fn command(&mut self, _observation: &Observation) -> Command {
        let (_, command) = self.upcoming();
        self.frames_left -= 1;
        command
    }

    fn reposition(&mut self, observation: &Observation) -> Option<Pose> {
        let near_edge = observation.field.margin_mm(observation.robot.point()) < self.margin_mm;
        (self.frames_left == 0 && near_edge).then(|| {
            let heading = wrap_angle_rad(TAU * uniform(&mut self.rng));
            Pose::new(0.0, 0.0, heading)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{FieldGeometry, FieldSize};
    use polymimic_types::Point;

    fn obs(robot: Pose) -> Observation {
        Observation {
            t_s: 0.0,
            frame_index: 0,
            robot,
            ball: None::<Point>,
            field: FieldGeometry::of(FieldSize::Large),
            body: BodyKind::Lego,
        }
    }

    #[test]
    fn holds_each_primitive_for_one_second_and_uses_all_five() {
        let mut b = Babbler::new(BodyKind::Lego, 1);
        let o = obs(Pose::default());
        let mut seen = [0usize; 5];
        for _ in 0..200 {
            let first = b.command(&o);
            for _ in 1..30 {
                assert_eq!(b.command(&o), first);
            }
            seen[first.primitive().index()] += 1;
        }
        assert!(seen.iter().all(|&n| n > 20), "{seen:?}");
    }

    #[test]
    fn babbles_the_humanoids_own_set_with_both_feet_kicking() {
        let mut b = Babbler::of_set(BodyKind::Humanoid, PrimitiveSet::Humanoid, 3);
        let o = obs(Pose::default());
        let mut seen = [0usize; 8];
        let mut kicks = Vec::new();
        for _ in 0..400 {
            let first = b.command(&o);
            for _ in 1..30 {
                assert_eq!(b.command(&o), first);
            }
            let Command::Humanoid(h) = first else { panic!("the humanoid takes its own commands") };
            assert_eq!(h.own_primitive(), b.current());
            seen[b.current().index()] += 1;
            if b.current() == Primitive::Kick {
                kicks.push(h);
            }
        }
        assert!(seen.iter().all(|&n| n > 30), "{seen:?}");
        assert!(kicks.contains(&HumanoidCommand::KickLeft) && kicks.contains(&HumanoidCommand::KickRight));
    }

    #[test]
    fn puts_the_robot_back_near_an_edge_between_primitives() {
        let mut b = Babbler::new(BodyKind::Lego, 2);
        assert!(b.reposition(&obs(Pose::new(0.0, 0.0, 0.0))).is_none());
        let edge = obs(Pose::new(480.0, 0.0, 0.0));
        let placed = b.reposition(&edge).expect("near the edge");
        assert_eq!(placed.point(), Point::new(0.0, 0.0));
        b.command(&edge);
        assert!(b.reposition(&edge).is_none(), "not in the middle of a primitive");
    }
}
