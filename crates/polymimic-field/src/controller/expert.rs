//! The Expert (the thesis's RC2004): a competition-style attacker that gets behind the ball on
//! the ball–goal line and pushes it in, speaking its own language of named wheel-speed pairs.
//! It plans a continuous (speed, turn rate) and sends the nearest command of its language.

use polymimic_types::{Point, Pose};

use crate::body::LEGO;
use crate::command::{Command, ExpertCommand};
use crate::episode::Observation;
use crate::math::{PI, deg, wrap_angle_rad};

use super::Controller;
use super::planner::{Plan, Sizes, plan};

/// The Expert demonstrator's controller (Lego body, global vision).
#[derive(Debug, Clone)]
pub struct Expert {
    pushing: bool,
    /// Direction of the current spin (+1 left), kept until the target is well off the tail,
    /// so heading jitter near ±180° does not flip it.
    spin: f64,
    sizes: Sizes,
    vocabulary: Vec<(ExpertCommand, f64, f64)>,
}

impl Default for Expert {
    fn default() -> Self {
        Self::new()
    }
}

impl Expert {
    /// A fresh Expert.
    #[must_use]
    pub fn new() -> Self {
        Self {
            pushing: false,
            spin: 0.0,
            sizes: Sizes {
                ball_r: 50.0,
                front: LEGO.length_mm / 2.0,
                reach: 0.5 * LEGO.length_mm.hypot(LEGO.width_mm),
                gap: 40.0,
                spot_tol: 25.0,
                face_tol_rad: deg(12.0),
            },
            vocabulary: ExpertCommand::all()
                .map(|c| {
                    let (l, r) = c.wheels_mm_s();
                    (c, l, r)
                })
                .collect(),
        }
    }

    /// The command whose wheel speeds are nearest to (speed, turn rate).
    fn nearest(&self, v_mm_s: f64, omega_rad_s: f64) -> Command {
        let half_base = LEGO.wheel_base_mm / 2.0;
        let (l, r) = (v_mm_s - omega_rad_s * half_base, v_mm_s + omega_rad_s * half_base);
        let mut best = (f64::INFINITY, self.vocabulary[0].0);
        for &(c, cl, cr) in &self.vocabulary {
            let d = (cl - l).powi(2) + (cr - r).powi(2);
            if d < best.0 {
                best = (d, c);
            }
        }
        Command::Expert(best.1)
    }
}

/// (speed, turn rate) toward a point: spin first if it is well off the nose. `spin` keeps the
/// direction of a spin under way.
fn drive_to(robot: Pose, target: Point, v_max_mm_s: f64, spin: &mut f64) -> (f64, f64) {
    let e = robot.relative_bearing_rad(target);
    let d = robot.point().dist_mm(target);
    if e.abs() > deg(50.0) {
        if *spin == 0.0 || e.abs() < deg(150.0) {
            *spin = e.signum();
        }
        return (0.0, 0.9 * *spin);
    }
    *spin = 0.0;
    let v = (1.2 * d + 15.0).min(v_max_mm_s) * (1.0 - e.abs() / (PI / 2.0));
    (v, 2.5 * e)
}

impl Controller for Expert {
    fn command(&mut self, observation: &Observation) -> Command {
        let Some(ball) = observation.ball else {
            return self.nearest(0.0, 0.0);
        };
        let robot = observation.robot;
        let p = plan(robot, ball, &observation.field, &self.sizes, self.pushing);
        self.pushing = matches!(p, Plan::Push(_));
        let (v, w) = match p {
            Plan::GoTo(t) => drive_to(robot, t, 100.0, &mut self.spin),
            Plan::Face(h) => {
                let e = wrap_angle_rad(h - robot.theta_rad());
                (0.0, (2.0 * e).clamp(-0.9, 0.9))
            }
            Plan::Push(t) => {
                let e = robot.relative_bearing_rad(t);
                (70.0, 2.0 * e)
            }
        };
        self.nearest(v, w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_command_matches_simple_requests() {
        let e = Expert::new();
        assert_eq!(e.nearest(0.0, 0.0).name(), "brake");
        assert_eq!(e.nearest(100.0, 0.0).name(), "forward_fast");
        assert_eq!(e.nearest(0.0, 0.8).name(), "spin_left_fast");
        assert_eq!(e.nearest(-45.0, 0.0).name(), "backward_slow");
    }
}
