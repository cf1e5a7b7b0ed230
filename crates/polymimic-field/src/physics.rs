//! The rapier2d world: a dynamic ball rolling with damping (no gravity: the field is seen from
//! above), the robot as a kinematic body driven pose by pose, and the humanoid's foot as a
//! kinematic collider switched on only while it swings. Units are mm and s; rapier's tolerances
//! are scaled to the ball through `length_unit`.

use nalgebra::Vector2;
use polymimic_types::{Point, Pose, rotation_by_rad};
use rapier2d::math::Pose as RPose;
use rapier2d::prelude::{
    ColliderBuilder, ColliderHandle, PhysicsWorld, RigidBody, RigidBodyBuilder, RigidBodyHandle, Vector,
};
use serde::{Deserialize, Serialize};

use crate::error::{FieldParamError, check_range};
use crate::math::{GaussianDraw, Rng};

/// Ball material and rolling resistance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BallParams {
    /// Viscous rolling resistance, 1/s (speed decays as exp(−damping·t)).
    pub linear_damping_per_s: f64,
    /// Bounciness against the robot (foam: low).
    pub restitution: f64,
    /// Friction against the robot's bumper.
    pub friction: f64,
    /// Random wander of the rolling direction (an imperfect foam ball on carpet), rad/√s:
    /// after rolling for t seconds the direction has drifted by about this × √t.
    pub wobble_rad_per_sqrt_s: f64,
}

impl Default for BallParams {
    fn default() -> Self {
        Self { linear_damping_per_s: 0.4, restitution: 0.6, friction: 0.3, wobble_rad_per_sqrt_s: 0.35 }
    }
}

impl BallParams {
    /// Validate.
    ///
    /// # Errors
    /// `OutOfRange` for negative damping or a restitution/friction outside [0, 1] / [0, 10].
    pub fn check(&self) -> Result<(), FieldParamError> {
        check_range("linear_damping_per_s", self.linear_damping_per_s, 0.0, 100.0, "0 ≤ d ≤ 100 /s")?;
        check_range("restitution", self.restitution, 0.0, 1.0, "0 ≤ e ≤ 1")?;
        check_range("friction", self.friction, 0.0, 10.0, "0 ≤ μ ≤ 10")?;
        check_range("wobble_rad_per_sqrt_s", self.wobble_rad_per_sqrt_s, 0.0, 10.0, "0 ≤ w ≤ 10")
    }
}

/// A pose as rapier takes it (glam, f32): the one place our poses cross into the physics.
fn rpose(p: Pose) -> RPose {
    RPose::new(Vector::new(p.x_mm() as f32, p.y_mm() as f32), p.theta_rad() as f32)
}

/// A rapier velocity turned by `turn_rad`, in rapier's f32 (the rotation's cosine and sine
/// rounded to f32 first).
fn turned(v: Vector, turn_rad: f64) -> Vector {
    let turned = rotation_by_rad(turn_rad).cast::<f32>() * Vector2::new(v.x, v.y);
    Vector::new(turned.x, turned.y)
}

/// What the physics world starts with.
pub(crate) struct Scene {
    pub ball: Point,
    pub ball_diameter_mm: f64,
    pub ball_params: BallParams,
    pub robot: Pose,
    /// Robot (length, width), mm.
    pub footprint_mm: (f64, f64),
    /// Foot (length, width), mm, for a body that kicks.
    pub foot_size_mm: Option<(f64, f64)>,
}

/// Faster than the robot and a kicked ball ever close on each other, several times over, mm/s:
/// farther apart than this speed × one step, they cannot touch within the step (10 mm at
/// 240 steps a second).
const REACH_SPEED_MM_S: f64 = 2400.0;

/// A free ball slower than this is put to sleep, mm/s.
const SLEEP_SPEED_MM_S: f32 = 1.0;

pub(crate) struct Physics {
    world: PhysicsWorld,
    ball: RigidBodyHandle,
    robot: RigidBodyHandle,
    foot: Option<(RigidBodyHandle, ColliderHandle)>,
    /// The robot's half length and half width, and the ball's radius, mm.
    robot_half_mm: (f64, f64),
    ball_radius_mm: f64,
    /// The rapier robot lags behind the true pose (steps were skipped while nothing could touch
    /// the ball); it must be lifted, not swept, into place before the next step.
    robot_stale: bool,
    /// Direction noise per step, rad (wobble × √dt).
    wobble_rad: f64,
    /// Farther apart than this, the robot and the ball cannot touch within a step, mm.
    reach_margin_mm: f64,
    rng: Rng,
}

impl Physics {
    /// A world with the ball at rest at `ball` and the robot at `robot`.
    pub(crate) fn new(scene: &Scene, dt_s: f64, rng: Rng) -> Self {
        let Scene { ball, ball_diameter_mm, ball_params, robot, footprint_mm, foot_size_mm } = *scene;
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        world.integration_parameters.dt = dt_s as f32;
        world.integration_parameters.length_unit = ball_diameter_mm as f32;
        // One dynamic body against kinematic ones: a couple of iterations converge.
        world.integration_parameters.num_solver_iterations = 2;
        let r = (ball_diameter_mm / 2.0) as f32;
        let (ball_h, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(ball.x_mm() as f32, ball.y_mm() as f32))
                .linear_damping(ball_params.linear_damping_per_s as f32)
                // A ball rolling on the floor does not spin about the vertical axis.
                .lock_rotations(),
            ColliderBuilder::ball(r)
                .restitution(ball_params.restitution as f32)
                .friction(ball_params.friction as f32)
                .density(1e-3),
        );
        let (hx, hy) = ((footprint_mm.0 / 2.0) as f32, (footprint_mm.1 / 2.0) as f32);
        let corner = 0.1 * hx.min(hy);
        let (robot_h, _) = world.insert(
            RigidBodyBuilder::kinematic_position_based().pose(rpose(robot)),
            ColliderBuilder::round_cuboid(hx - corner, hy - corner, corner).friction(0.5),
        );
        let foot = foot_size_mm.map(|(l, w)| {
            let (fx, fy) = ((l / 2.0) as f32, (w / 2.0) as f32);
            let (h, c) = world.insert(
                RigidBodyBuilder::kinematic_position_based().pose(rpose(robot)),
                ColliderBuilder::cuboid(fx, fy).friction(0.5),
            );
            if let Some(col) = world.colliders.get_mut(c) {
                col.set_enabled(false);
            }
            (h, c)
        });
        Self {
            world,
            ball: ball_h,
            robot: robot_h,
            foot,
            robot_half_mm: (footprint_mm.0 / 2.0, footprint_mm.1 / 2.0),
            ball_radius_mm: ball_diameter_mm / 2.0,
            robot_stale: false,
            wobble_rad: ball_params.wobble_rad_per_sqrt_s * dt_s.sqrt(),
            reach_margin_mm: REACH_SPEED_MM_S * dt_s,
            rng,
        }
    }

    /// Advance one step with the robot (and foot) driven to these poses. While nothing can
    /// reach the ball (their gap exceeds what one step can close), rapier is not stepped at all:
    /// a sleeping ball is left alone, and a rolling one is moved here by rapier's own law for a
    /// body without contacts (velocity damped by 1/(1 + dt·damping), then position advanced by
    /// velocity × dt). Only steps where the robot may touch the ball pay for the solver.
    pub(crate) fn advance(&mut self, robot: Pose, foot: Option<(Pose, bool)>) {
        let foot_active = foot.is_some_and(|(_, active)| active);
        let ball_asleep = self.world.bodies.get(self.ball).is_some_and(RigidBody::is_sleeping);
        let far = self.beyond_reach(robot);
        if far && !foot_active {
            if !ball_asleep {
                self.roll_free();
                self.wobble();
            }
            self.robot_stale = true;
            return;
        }
        if self.robot_stale {
            self.teleport_robot(robot);
            self.robot_stale = false;
        }
        self.drive(robot, foot);
        self.step();
        self.wobble();
    }

    /// Whether the gap between the ball's surface and the robot's footprint exceeds what one
    /// step can close. The gap is the hypot of the ball centre's offsets outside the footprint,
    /// less the ball's radius; a hypot is never below the larger offset (exactly so in floating
    /// point, where rounding is monotone), so where that offset alone is beyond reach the hypot,
    /// a tenth of a stepping field's time, is skipped with the same answer.
    fn beyond_reach(&self, robot: Pose) -> bool {
        let ball = robot.robot_from_field(self.ball());
        let outside_x = (ball.x_mm().abs() - self.robot_half_mm.0).max(0.0);
        let outside_y = (ball.y_mm().abs() - self.robot_half_mm.1).max(0.0);
        let beyond = |distance_mm: f64| distance_mm - self.ball_radius_mm > self.reach_margin_mm;
        beyond(outside_x.max(outside_y)) || beyond(outside_x.hypot(outside_y))
    }

    /// One step of the ball with no contact possible: damping, then position. Below a crawl it
    /// is put to sleep, as rapier would after a while.
    fn roll_free(&mut self) {
        let dt = self.world.integration_parameters.dt;
        if let Some(b) = self.world.bodies.get_mut(self.ball) {
            let damping = b.linear_damping();
            let v = b.linvel() * (1.0 / (1.0 + dt * damping));
            if v.length() < SLEEP_SPEED_MM_S {
                b.set_linvel(Vector::ZERO, false);
                b.sleep();
                return;
            }
            let position = b.translation() + v * dt;
            b.set_linvel(v, false);
            b.set_translation(position, false);
        }
    }

    /// Turn the rolling ball's velocity by a small random angle (drawn every step, rolling or
    /// not, so the random stream does not depend on the motion).
    fn wobble(&mut self) {
        let draw = GaussianDraw::take(&mut self.rng);
        if let Some(b) = self.world.bodies.get_mut(self.ball) {
            let v = b.linvel();
            if v.length() > 1.0 && !b.is_sleeping() {
                b.set_linvel(turned(v, self.wobble_rad * draw.value()), false);
            }
        }
    }

    /// Drive the robot (and the foot, if any) to these poses over the next step.
    fn drive(&mut self, robot: Pose, foot: Option<(Pose, bool)>) {
        if let Some(b) = self.world.bodies.get_mut(self.robot) {
            b.set_next_kinematic_position(rpose(robot));
        }
        if let (Some((fh, fc)), Some((pose, active))) = (self.foot, foot) {
            if let Some(c) = self.world.colliders.get_mut(fc)
                && c.is_enabled() != active
            {
                c.set_enabled(active);
                // Appear where the swing starts rather than sweeping there from anywhere.
                if let Some(b) = self.world.bodies.get_mut(fh) {
                    b.set_position(rpose(pose), true);
                }
            }
            if let Some(b) = self.world.bodies.get_mut(fh) {
                b.set_next_kinematic_position(rpose(pose));
            }
        }
    }

    /// Lift the robot to `pose` (no sweep through the ball).
    pub(crate) fn teleport_robot(&mut self, pose: Pose) {
        if let Some(b) = self.world.bodies.get_mut(self.robot) {
            b.set_position(rpose(pose), true);
        }
    }

    fn step(&mut self) {
        self.world.step();
    }

    pub(crate) fn ball(&self) -> Point {
        self.world.bodies.get(self.ball).map_or(Point::new(f64::NAN, f64::NAN), |b| {
            let t = b.translation();
            Point::new(f64::from(t.x), f64::from(t.y))
        })
    }

    /// Ball speed, mm/s.
    #[cfg(test)]
    pub(crate) fn ball_speed_mm_s(&self) -> f64 {
        self.world.bodies.get(self.ball).map_or(0.0, |b| f64::from(b.linvel().length()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn world(robot: Pose) -> Physics {
        let scene = Scene {
            ball: Point::new(0.0, 0.0),
            ball_diameter_mm: 100.0,
            ball_params: BallParams::default(),
            robot,
            footprint_mm: (140.0, 150.0),
            foot_size_mm: None,
        };
        Physics::new(&scene, 1.0 / 240.0, crate::math::rng(0, 0))
    }

    #[test]
    fn the_wobble_turns_the_velocity_as_the_field_always_did() {
        for (turn, v) in
            [(0.01, Vector::new(250.0, -3.5)), (-0.3, Vector::new(-17.25, 99.0)), (2.0, Vector::new(1.5, 0.0))]
        {
            let (s, c) = (libm::sin(turn) as f32, libm::cos(turn) as f32);
            let by_hand = Vector::new(c * v.x - s * v.y, s * v.x + c * v.y);
            let t = turned(v, turn);
            assert_eq!((t.x.to_bits(), t.y.to_bits()), (by_hand.x.to_bits(), by_hand.y.to_bits()));
        }
    }

    #[test]
    fn the_larger_offset_alone_decides_reach_only_where_the_hypot_agrees() {
        // hypot(x, y) ≥ max(x, y) in floating point: the shortcut never says "beyond" wrongly.
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..200_000 {
            let (x, y) = (next() * 60.0, next() * next() * 60.0);
            let (radius, margin) = (21.0 + next(), next() * 8.0);
            if x.max(y) - radius > margin {
                assert!(x.hypot(y) - radius > margin, "{x} {y} {radius} {margin}");
            }
        }
    }

    #[test]
    fn ball_stays_put_without_contact() {
        let mut p = world(Pose::new(-300.0, 0.0, 0.0));
        for _ in 0..240 {
            p.step();
        }
        assert!(p.ball().dist_mm(Point::new(0.0, 0.0)) < 1e-6);
    }

    #[test]
    fn robot_pushes_ball_ahead() {
        let mut p = world(Pose::new(-130.0, 0.0, 0.0));
        let mut x = -130.0;
        for _ in 0..480 {
            x += 100.0 / 240.0;
            p.drive(Pose::new(x, 0.0, 0.0), None);
            p.step();
        }
        let b = p.ball();
        assert!(b.x_mm() > 60.0, "{b:?}");
        assert!(b.y_mm().abs() < 5.0, "{b:?}");
        assert!(p.ball_speed_mm_s() > 10.0);
    }

    #[test]
    fn rolling_ball_slows_down() {
        let mut p = world(Pose::new(-300.0, 0.0, 0.0));
        if let Some(b) = p.world.bodies.get_mut(p.ball) {
            b.set_linvel(Vector::new(300.0, 0.0), true);
        }
        for _ in 0..240 {
            p.step();
        }
        let v = p.ball_speed_mm_s();
        // exp(−0.4 · 1 s) ≈ 0.67.
        assert!(v < 300.0 * 0.75 && v > 300.0 * 0.6, "{v}");
    }
}
