//! The tiny robot's skilled controller: the same attacker plan as the Expert, but only the
//! primitive commands F B L R S (the tiny robot's command set).

use polymimic_types::Primitive;

use crate::body::TINY;

use crate::command::Command;
use crate::episode::Observation;
use crate::geometry::FieldGeometry;
use crate::math::{deg, wrap_angle_rad};

use super::Controller;
use super::planner::{Plan, Sizes, plan};

/// The Tiny demonstrator's controller (tiny body, small field, global vision).
#[derive(Debug, Clone)]
pub struct TinyController {
    pushing: bool,
    turning: bool,
    sizes: Sizes,
}

impl Default for TinyController {
    fn default() -> Self {
        Self::new()
    }
}

impl TinyController {
    /// A fresh controller.
    #[must_use]
    pub fn new() -> Self {
        let ball = FieldGeometry::of(crate::FieldSize::Small).ball_diameter_mm;
        Self {
            pushing: false,
            turning: false,
            sizes: Sizes {
                ball_r: ball / 2.0,
                front: TINY.length_mm / 2.0,
                reach: 0.5 * TINY.length_mm.hypot(TINY.width_mm),
                gap: 8.0,
                spot_tol: 6.0,
                face_tol_rad: deg(15.0),
            },
        }
    }

    /// Turn toward `err` (rad) if it is off by more than the (hysteretic) tolerance.
    fn turn_or(&mut self, err: f64, tol: f64, otherwise: Primitive) -> Command {
        let limit = if self.turning { 0.5 * tol } else { tol };
        self.turning = err.abs() > limit;
        let p = if !self.turning {
            otherwise
        } else if err > 0.0 {
            Primitive::Left
        } else {
            Primitive::Right
        };
        Command::Primitive(p)
    }
}

impl Controller for TinyController {
    fn command(&mut self, observation: &Observation) -> Command {
        let Some(ball) = observation.ball else {
            return Command::Primitive(Primitive::Stop);
        };
        let robot = observation.robot;
        let p = plan(robot, ball, &observation.field, &self.sizes, self.pushing);
        self.pushing = matches!(p, Plan::Push(_));
        match p {
            Plan::GoTo(t) | Plan::Push(t) => self.turn_or(robot.relative_bearing_rad(t), deg(20.0), Primitive::Forward),
            Plan::Face(h) => {
                let e = wrap_angle_rad(h - robot.theta_rad());
                self.turn_or(e, deg(10.0), Primitive::Forward)
            }
        }
    }
}
