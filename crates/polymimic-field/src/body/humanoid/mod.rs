//! The humanoid (the Bioloid): a kinematic walker. Walking advances in bursts, one per step,
//! with the heading swaying from foot to foot and a small random yaw at every footfall; it can
//! side-step (shuffle), turn on the spot, and kick: it leans back while one foot swings forward
//! (the foot is a short-lived kinematic collider, so its contact with the ball is physical).
//! It sees through a head camera: a forward cone that the head can pan left, right or down.
//! Every constant is configurable (`FieldConfig::humanoid`); some choices beyond the default,
//! each off unless asked for, make it walk more like a biped: turning about the stance foot,
//! landing the kicking foot off its aim, and a camera that sees nothing while it walks.

mod params;
#[cfg(test)]
mod tests;

use nalgebra::Vector2;
use polymimic_types::{Point, Pose, rotation_by_rad};

use crate::command::{Command, HumanoidCommand};
use crate::error::FieldParamError;
use crate::math::{PI, Rng, cos, exp, gaussian, sin, wrap_angle_rad};

pub use params::{HUMANOID, HUMANOID_BEFORE_CALIBRATION, HumanoidParams};

#[derive(Debug, Clone, Copy)]
struct Kick {
    /// +1 left foot, −1 right foot.
    side: f64,
    t_s: f64,
    /// Where the foot lands to the side of its aim, mm.
    aim_error_mm: f64,
}

/// The kicking foot, in field coordinates.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Foot {
    pub pose: Pose,
    pub active: bool,
}

/// State of the humanoid.
#[derive(Debug, Clone)]
pub(crate) struct HumanoidBody {
    params: HumanoidParams,
    /// Pose without the gait's sway.
    base: Pose,
    vel: (f64, f64, f64),
    target: (f64, f64, f64),
    stepping: bool,
    step_phase: f64,
    step_gain: f64,
    stance: f64,
    kick: Option<Kick>,
    head_pan_rad: f64,
    head_pan_target_rad: f64,
    looking_down: bool,
}

impl HumanoidBody {
    pub(crate) fn new(params: HumanoidParams, pose: Pose) -> Self {
        Self {
            params,
            base: pose,
            vel: (0.0, 0.0, 0.0),
            target: (0.0, 0.0, 0.0),
            stepping: false,
            step_phase: 0.0,
            step_gain: 1.0,
            stance: 0.0,
            kick: None,
            head_pan_rad: 0.0,
            head_pan_target_rad: 0.0,
            looking_down: false,
        }
    }

    pub(crate) fn params(&self) -> &HumanoidParams {
        &self.params
    }

    /// The pose the tracker sees: the base pose plus the gait's heading sway.
    pub(crate) fn pose(&self) -> Pose {
        let sway = self.params.sway_rad * self.stance * sin(PI * self.step_phase);
        Pose::new(self.base.x_mm(), self.base.y_mm(), wrap_angle_rad(self.base.theta_rad() + sway))
    }

    pub(crate) fn place(&mut self, pose: Pose) {
        self.base = pose;
        self.vel = (0.0, 0.0, 0.0);
        self.kick = None;
    }

    /// Is a kick under way (it runs to completion whatever is commanded)?
    pub(crate) fn is_kicking(&self) -> bool {
        self.kick.is_some()
    }

    pub(crate) fn command(&mut self, command: Command, rng: &mut Rng) -> Result<(), FieldParamError> {
        use HumanoidCommand as H;
        let Command::Humanoid(h) = command else {
            return Err(FieldParamError::CommandNotSupported { command: command.name(), body: "humanoid" });
        };
        if self.kick.is_some() {
            return Ok(());
        }
        let p = &self.params;
        self.head_pan_target_rad = match h {
            H::ScanLeft => p.head_pan_rad,
            H::ScanRight => -p.head_pan_rad,
            _ => 0.0,
        };
        self.looking_down = h == H::ScanDown;
        // (forward mm/s, left mm/s, turn rad/s)
        self.target = match h {
            H::WalkForward => (p.walk_mm_s, 0.0, 0.0),
            H::WalkForwardLeft => (0.8 * p.walk_mm_s, 0.0, p.arc_rad_s),
            H::WalkForwardRight => (0.8 * p.walk_mm_s, 0.0, -p.arc_rad_s),
            H::WalkBackward => (-p.backward_mm_s, 0.0, 0.0),
            H::TurnLeft => (0.0, 0.0, p.turn_rad_s),
            H::TurnRight => (0.0, 0.0, -p.turn_rad_s),
            H::ShuffleLeft => (0.0, p.shuffle_mm_s, 0.0),
            H::ShuffleRight => (0.0, -p.shuffle_mm_s, 0.0),
            H::ScanLeft => (0.0, 0.0, p.scan_twist_rad_s),
            H::ScanRight => (0.0, 0.0, -p.scan_twist_rad_s),
            H::KickLeft | H::KickRight | H::Wait | H::Go | H::ScanForward | H::ScanDown | H::Lost => (0.0, 0.0, 0.0),
        };
        self.stepping = h.steps();
        if matches!(h, H::KickLeft | H::KickRight) {
            let side = if h == H::KickLeft { 1.0 } else { -1.0 };
            let aim_error_mm = if p.foot_aim_sd_mm > 0.0 { p.foot_aim_sd_mm * gaussian(rng) } else { 0.0 };
            self.kick = Some(Kick { side, t_s: 0.0, aim_error_mm });
            self.stepping = false;
        }
        Ok(())
    }

    pub(crate) fn substep(&mut self, dt_s: f64, rng: &mut Rng) {
        let p = self.params;
        let pan_step = p.head_pan_rate_rad_s * dt_s;
        self.head_pan_rad += (self.head_pan_target_rad - self.head_pan_rad).clamp(-pan_step, pan_step);
        let a = 1.0 - exp(-dt_s / p.tau_s);
        self.stance += a * (f64::from(u8::from(self.stepping)) - self.stance);
        if let Some(kick) = self.kick.as_mut() {
            kick.t_s += dt_s;
            let (lean_end, land_start) = (p.foot_window_s.0, p.foot_window_s.1);
            // Lean back before the swing, creep partly forward again after landing the foot.
            let v = if kick.t_s < lean_end {
                -p.kick_lean_mm / lean_end
            } else if kick.t_s >= land_start {
                (p.kick_lean_mm - p.kick_net_back_mm) / (p.kick_s - land_start)
            } else {
                0.0
            };
            self.vel = (v, 0.0, 0.0);
            if kick.t_s >= p.kick_s - 1e-9 {
                self.kick = None;
                self.vel = (0.0, 0.0, 0.0);
            }
        } else {
            self.vel.0 += a * (self.target.0 - self.vel.0);
            self.vel.1 += a * (self.target.1 - self.vel.1);
            self.vel.2 += a * (self.target.2 - self.vel.2);
        }
        // Progress comes in bursts, one per step (mean factor 1 over a step).
        let burst = if self.stepping {
            let before = self.step_phase;
            self.step_phase += dt_s / p.step_s;
            if self.step_phase.floor() > before.floor() {
                // Footfall: a fresh step length and a small random yaw.
                self.step_gain = (1.0 + p.step_length_sd * gaussian(rng)).max(0.2);
                let yaw = self.base.theta_rad() + p.step_yaw_sd_rad * gaussian(rng);
                self.base = Pose::at(self.base.point(), yaw);
            }
            self.step_gain * (1.0 - cos(2.0 * PI * self.step_phase))
        } else {
            1.0
        };
        let (fwd, left, turn) = (self.vel.0 * burst, self.vel.1 * burst, self.vel.2);
        let theta_mid = self.base.theta_rad() + 0.5 * turn * dt_s;
        // The body's velocity turned into field axes at mid-step.
        let velocity = rotation_by_rad(theta_mid) * Vector2::new(fwd, left);
        let (mut x, mut y) = (self.base.x_mm() + velocity.x * dt_s, self.base.y_mm() + velocity.y * dt_s);
        if self.stepping && p.turn_pivot_mm > 0.0 && turn != 0.0 {
            // Turning about the stance foot, which alternates sides from step to step.
            let side = if (self.step_phase.floor() as i64) % 2 == 0 { 1.0 } else { -1.0 };
            let pivot = self.base.field_from_robot(Point::new(0.0, side * p.turn_pivot_mm));
            let offset = rotation_by_rad(turn * dt_s) * Vector2::new(x - pivot.x_mm(), y - pivot.y_mm());
            (x, y) = (pivot.x_mm() + offset.x, pivot.y_mm() + offset.y);
        }
        self.base = Pose::new(x, y, wrap_angle_rad(self.base.theta_rad() + turn * dt_s));
    }

    /// The kicking foot (inactive outside the swing window).
    pub(crate) fn foot(&self) -> Foot {
        let p = &self.params;
        let pose = self.pose();
        match self.kick {
            Some(k) if k.t_s >= p.foot_window_s.0 && k.t_s < p.foot_window_s.1 => {
                let f = (k.t_s - p.foot_window_s.0) / (p.foot_window_s.1 - p.foot_window_s.0);
                let x = p.foot_reach_mm.0 + f * (p.foot_reach_mm.1 - p.foot_reach_mm.0);
                let at = pose.field_from_robot(Point::new(x, k.side * p.foot_side_mm + k.aim_error_mm));
                Foot { pose: Pose::new(at.x_mm(), at.y_mm(), pose.theta_rad()), active: true }
            }
            _ => Foot { pose: Pose::new(pose.x_mm(), pose.y_mm(), pose.theta_rad()), active: false },
        }
    }

    /// Can the head camera see a ball at `ball`?
    pub(crate) fn sees(&self, ball: Point) -> bool {
        let p = &self.params;
        if self.stance > p.blind_gait {
            return false;
        }
        let pose = self.pose();
        let dist = pose.point().dist_mm(ball);
        let rel = wrap_angle_rad(pose.relative_bearing_rad(ball) - self.head_pan_rad);
        if self.looking_down {
            dist <= p.scan_down_range_mm && rel.abs() <= 2.0 * p.camera_half_fov_rad
        } else {
            dist <= p.camera_range_mm && rel.abs() <= p.camera_half_fov_rad
        }
    }
}
