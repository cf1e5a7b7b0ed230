//! The humanoid (the Bioloid): a kinematic walker. Walking advances in bursts, one per step,
//! with the heading swaying from foot to foot and a small random yaw at every footfall; it can
//! side-step (shuffle), turn on the spot, and kick: it leans back while one foot swings forward
//! (the foot is a short-lived kinematic collider, so its contact with the ball is physical).
//! It sees through a head camera: a forward cone that the head can pan left, right or down.
//! Every constant is configurable (`FieldConfig::humanoid`); some choices beyond the default,
//! each off unless asked for, make it walk more like a biped: turning about the stance foot,
//! landing the kicking foot off its aim, and a camera that sees nothing while it walks.

use nalgebra::Vector2;
use polymimic_types::{Point, Pose, rotation_by_rad};
use serde::{Deserialize, Serialize};

use crate::command::{Command, HumanoidCommand};
use crate::error::{FieldParamError, check_range};
use crate::math::{PI, Rng, cos, deg, exp, gaussian, sin, wrap_angle_rad};

/// Constants of the humanoid body.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HumanoidParams {
    /// Footprint depth along the heading, mm.
    pub length_mm: f64,
    /// Footprint width, mm.
    pub width_mm: f64,
    /// Mean walking speed, mm/s.
    pub walk_mm_s: f64,
    /// Backward stepping speed, mm/s.
    pub backward_mm_s: f64,
    /// Side-step speed, mm/s.
    pub shuffle_mm_s: f64,
    /// Turn rate on the spot, rad/s.
    pub turn_rad_s: f64,
    /// Turn rate of a curved walk, rad/s.
    pub arc_rad_s: f64,
    /// Slow torso twist while the head pans left or right, rad/s.
    pub scan_twist_rad_s: f64,
    /// Duration of one step, s.
    pub step_s: f64,
    /// Heading sway amplitude while stepping, rad.
    pub sway_rad: f64,
    /// sd of the random yaw at each footfall, rad.
    pub step_yaw_sd_rad: f64,
    /// sd of the relative length of each step.
    pub step_length_sd: f64,
    /// Lag of the walking velocities behind the command, s.
    pub tau_s: f64,
    /// Distance to the side of the body centre of the foot it pivots on while turning, mm
    /// (the stance foot, alternating step by step; 0 turns about the centre).
    pub turn_pivot_mm: f64,
    /// Whole kick, s.
    pub kick_s: f64,
    /// How far the body leans back during a kick, mm.
    pub kick_lean_mm: f64,
    /// How much of the lean it keeps after landing the foot, mm.
    pub kick_net_back_mm: f64,
    /// Foot swing window within the kick, s.
    pub foot_window_s: (f64, f64),
    /// Foot centre travel in the robot frame (start, end), mm ahead of the body centre.
    pub foot_reach_mm: (f64, f64),
    /// Foot centre offset to the side of the kicking leg, mm.
    pub foot_side_mm: f64,
    /// Foot size (length, width), mm.
    pub foot_size_mm: (f64, f64),
    /// sd of where the swinging foot lands to the side of where it was aimed, drawn once per
    /// kick, mm: balancing on one leg, the humanoid places its foot only roughly.
    pub foot_aim_sd_mm: f64,
    /// Camera half field of view, rad.
    pub camera_half_fov_rad: f64,
    /// Gait (0 standing, 1 stepping) above which the bobbing camera sees nothing; 1 sees
    /// while walking.
    pub blind_gait: f64,
    /// Camera range, mm.
    pub camera_range_mm: f64,
    /// Head pan while scanning left or right, rad.
    pub head_pan_rad: f64,
    /// Head pan speed, rad/s.
    pub head_pan_rate_rad_s: f64,
    /// Range of the downward look, mm (half field of view twice the forward one).
    pub scan_down_range_mm: f64,
    /// How its controller plays: the ball may be this far ahead of the body centre, mm…
    pub lineup_ahead_mm: f64,
    /// …and this far to its side for it to line a foot up with side-steps rather than walk
    /// round, mm.
    pub lineup_side_mm: f64,
    /// It side-steps until the ball is this close in line with the kicking foot, mm.
    pub lineup_tolerance_mm: f64,
    /// Farther than this from its spot behind the ball, it walks to the spot, mm.
    pub spot_tolerance_mm: f64,
    /// Gap it leaves between its front and the ball at that spot, mm.
    pub spot_gap_mm: f64,
    /// After walking blind this long it stands still to look, s (0: never; only a camera that
    /// is blind while walking needs it).
    pub look_after_s: f64,
    /// How long it stands still to look, s.
    pub look_s: f64,
}

/// The Bioloid-like humanoid.
pub const HUMANOID: HumanoidParams = HumanoidParams {
    length_mm: 70.0,
    width_mm: 110.0,
    walk_mm_s: 60.0,
    backward_mm_s: 25.0,
    shuffle_mm_s: 30.0,
    turn_rad_s: deg(35.0),
    arc_rad_s: deg(18.0),
    scan_twist_rad_s: deg(8.0),
    step_s: 0.5,
    sway_rad: deg(4.0),
    step_yaw_sd_rad: deg(1.5),
    step_length_sd: 0.15,
    tau_s: 0.1,
    turn_pivot_mm: 0.0,
    kick_s: 1.0,
    kick_lean_mm: 15.0,
    kick_net_back_mm: 10.0,
    foot_window_s: (0.3, 0.55),
    foot_reach_mm: (20.0, 110.0),
    foot_side_mm: 28.0,
    foot_size_mm: (40.0, 30.0),
    foot_aim_sd_mm: 0.0,
    camera_half_fov_rad: deg(35.0),
    blind_gait: 1.0,
    camera_range_mm: 1400.0,
    head_pan_rad: deg(60.0),
    head_pan_rate_rad_s: deg(180.0),
    scan_down_range_mm: 350.0,
    lineup_ahead_mm: 260.0,
    lineup_side_mm: 90.0,
    lineup_tolerance_mm: 10.0,
    spot_tolerance_mm: 35.0,
    spot_gap_mm: 70.0,
    look_after_s: 0.0,
    look_s: 0.4,
};

impl Default for HumanoidParams {
    fn default() -> Self {
        HUMANOID
    }
}

impl HumanoidParams {
    /// Whether its camera sees nothing while it walks (a gait below full stride blinds it).
    #[must_use]
    pub fn walks_blind(&self) -> bool {
        self.blind_gait < 1.0
    }

    /// Whether these are the thesis's humanoid's constants.
    #[must_use]
    pub fn is_thesis(&self) -> bool {
        *self == HUMANOID
    }

    /// Validate: every length, time and rate finite and in a sensible range.
    ///
    /// # Errors
    /// `OutOfRange` naming the first parameter (as `humanoid.<name>`) outside its range.
    pub fn check(&self) -> Result<(), FieldParamError> {
        // (smallest, largest, what is allowed), as the wheeled bodies' check words it.
        const MM: (f64, f64, &str) = (0.0, 1e4, "0 ≤ mm ≤ 10000");
        const MM_POSITIVE: (f64, f64, &str) = (f64::MIN_POSITIVE, 1e4, "positive, at most 10000 mm");
        const MM_S: (f64, f64, &str) = (0.0, 1e4, "0 ≤ mm/s ≤ 10000");
        const RAD: (f64, f64, &str) = (0.0, PI, "0 ≤ rad ≤ π");
        const RAD_POSITIVE: (f64, f64, &str) = (f64::MIN_POSITIVE, PI, "positive, at most π rad");
        const RAD_S: (f64, f64, &str) = (0.0, 100.0, "0 ≤ rad/s ≤ 100");
        const RAD_S_POSITIVE: (f64, f64, &str) = (f64::MIN_POSITIVE, 100.0, "positive, at most 100 rad/s");
        const S: (f64, f64, &str) = (0.0, 3600.0, "0 ≤ s ≤ 3600");
        const S_POSITIVE: (f64, f64, &str) = (f64::MIN_POSITIVE, 3600.0, "positive, at most 3600 s");
        let p = self;
        let ranges = [
            ("humanoid.length_mm", p.length_mm, MM_POSITIVE),
            ("humanoid.width_mm", p.width_mm, MM_POSITIVE),
            ("humanoid.walk_mm_s", p.walk_mm_s, MM_S),
            ("humanoid.backward_mm_s", p.backward_mm_s, MM_S),
            ("humanoid.shuffle_mm_s", p.shuffle_mm_s, MM_S),
            ("humanoid.turn_rad_s", p.turn_rad_s, RAD_S),
            ("humanoid.arc_rad_s", p.arc_rad_s, RAD_S),
            ("humanoid.scan_twist_rad_s", p.scan_twist_rad_s, RAD_S),
            ("humanoid.step_s", p.step_s, S_POSITIVE),
            ("humanoid.sway_rad", p.sway_rad, RAD),
            ("humanoid.step_yaw_sd_rad", p.step_yaw_sd_rad, RAD),
            ("humanoid.step_length_sd", p.step_length_sd, (0.0, 10.0, "0 ≤ sd ≤ 10")),
            ("humanoid.tau_s", p.tau_s, S_POSITIVE),
            ("humanoid.turn_pivot_mm", p.turn_pivot_mm, MM),
            ("humanoid.kick_s", p.kick_s, S_POSITIVE),
            ("humanoid.kick_lean_mm", p.kick_lean_mm, MM),
            ("humanoid.kick_net_back_mm", p.kick_net_back_mm, MM),
            ("humanoid.foot_reach_mm[0]", p.foot_reach_mm.0, MM),
            ("humanoid.foot_reach_mm[1]", p.foot_reach_mm.1, MM),
            ("humanoid.foot_side_mm", p.foot_side_mm, MM),
            ("humanoid.foot_size_mm[0]", p.foot_size_mm.0, MM_POSITIVE),
            ("humanoid.foot_size_mm[1]", p.foot_size_mm.1, MM_POSITIVE),
            ("humanoid.foot_aim_sd_mm", p.foot_aim_sd_mm, MM),
            ("humanoid.camera_half_fov_rad", p.camera_half_fov_rad, RAD_POSITIVE),
            ("humanoid.blind_gait", p.blind_gait, (0.0, 1.0, "0 ≤ gait ≤ 1")),
            ("humanoid.camera_range_mm", p.camera_range_mm, MM_POSITIVE),
            ("humanoid.head_pan_rad", p.head_pan_rad, RAD),
            ("humanoid.head_pan_rate_rad_s", p.head_pan_rate_rad_s, RAD_S_POSITIVE),
            ("humanoid.scan_down_range_mm", p.scan_down_range_mm, MM_POSITIVE),
            ("humanoid.lineup_ahead_mm", p.lineup_ahead_mm, MM),
            ("humanoid.lineup_side_mm", p.lineup_side_mm, MM),
            ("humanoid.lineup_tolerance_mm", p.lineup_tolerance_mm, MM),
            ("humanoid.spot_tolerance_mm", p.spot_tolerance_mm, MM),
            ("humanoid.spot_gap_mm", p.spot_gap_mm, MM),
            ("humanoid.look_after_s", p.look_after_s, S),
            ("humanoid.look_s", p.look_s, S),
        ];
        for (name, value, (low, high, expected)) in ranges {
            check_range(name, value, low, high, expected)?;
        }
        let (swing_start, swing_end) = p.foot_window_s;
        let start_ok = swing_start >= 0.0 && swing_start < swing_end;
        if !(start_ok && swing_end <= p.kick_s) {
            return Err(FieldParamError::OutOfRange {
                name: "humanoid.foot_window_s",
                value: if start_ok { swing_end } else { swing_start },
                expected: "0 ≤ start < end ≤ kick_s",
            });
        }
        Ok(())
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng;

    fn run(b: &mut HumanoidBody, h: HumanoidCommand, frames: u32, r: &mut Rng) {
        for _ in 0..frames {
            b.command(Command::Humanoid(h), r).expect("humanoid command");
            for _ in 0..8 {
                b.substep(1.0 / 240.0, r);
            }
        }
    }

    #[test]
    fn walking_advances_and_sways() {
        let mut r = rng(1, 0);
        let mut b = HumanoidBody::new(HUMANOID, Pose::default());
        let mut max_sway: f64 = 0.0;
        for _ in 0..60 {
            run(&mut b, HumanoidCommand::WalkForward, 1, &mut r);
            max_sway = max_sway.max(b.pose().theta_rad().abs());
        }
        assert!(b.pose().x_mm() > 80.0, "{:?}", b.pose());
        assert!(max_sway > deg(2.0), "sway {max_sway}");
    }

    #[test]
    fn shuffle_moves_sideways() {
        let mut r = rng(2, 0);
        let mut b = HumanoidBody::new(HUMANOID, Pose::default());
        run(&mut b, HumanoidCommand::ShuffleLeft, 60, &mut r);
        assert!(b.pose().y_mm() > 30.0 && b.pose().x_mm().abs() < 15.0, "{:?}", b.pose());
    }

    #[test]
    fn kick_leans_back_and_swings_the_foot() {
        let mut r = rng(3, 0);
        let mut b = HumanoidBody::new(HUMANOID, Pose::default());
        let mut foot_seen = false;
        for _ in 0..30 {
            run(&mut b, HumanoidCommand::KickLeft, 1, &mut r);
            let f = b.foot();
            if f.active {
                foot_seen = true;
                assert!(f.pose.y_mm() > 0.0);
            }
        }
        assert!(foot_seen);
        assert!(!b.is_kicking());
        assert!(b.pose().x_mm() < -5.0, "{:?}", b.pose());
    }

    #[test]
    fn turning_about_a_foot_moves_the_centre_on_a_circle_round_it() {
        let params = HumanoidParams { turn_pivot_mm: 28.0, step_yaw_sd_rad: 0.0, ..HUMANOID };
        let mut r = rng(5, 0);
        let mut b = HumanoidBody::new(params, Pose::default());
        let mut c = HumanoidBody::new(HumanoidParams { step_yaw_sd_rad: 0.0, ..HUMANOID }, Pose::default());
        // Within the first step it pivots about the left foot, (0, 28) mm.
        run(&mut b, HumanoidCommand::TurnLeft, 10, &mut r);
        run(&mut c, HumanoidCommand::TurnLeft, 10, &mut r);
        let (moved, still) = (b.base.point().dist_mm(Point::new(0.0, 28.0)), c.base.point().dist_mm(Point::default()));
        assert!((moved - 28.0).abs() < 1e-9, "{:?}", b.base);
        assert!(b.base.point().dist_mm(Point::default()) > 1.0 && still < 1e-9, "{:?} {:?}", b.base, c.base);
        assert!((b.base.theta_rad() - c.base.theta_rad()).abs() < 1e-12);
    }

    #[test]
    fn the_foot_lands_off_its_aim_by_a_fresh_error_every_kick() {
        let params = HumanoidParams { foot_aim_sd_mm: 15.0, ..HUMANOID };
        let mut r = rng(6, 0);
        let mut sides = Vec::new();
        for _ in 0..4 {
            let mut b = HumanoidBody::new(params, Pose::default());
            b.command(Command::Humanoid(HumanoidCommand::KickLeft), &mut r).expect("humanoid command");
            while !b.foot().active {
                b.substep(1.0 / 240.0, &mut r);
            }
            sides.push(b.foot().pose.y_mm());
        }
        assert!(sides.iter().all(|y| (y - HUMANOID.foot_side_mm).abs() > 1e-6), "{sides:?}");
        assert!(sides.windows(2).all(|w| w[0] != w[1]), "{sides:?}");
    }

    #[test]
    fn a_camera_blind_while_walking_sees_only_standing() {
        let mut r = rng(7, 0);
        let mut b = HumanoidBody::new(HumanoidParams { blind_gait: 0.5, ..HUMANOID }, Pose::default());
        let ahead = Point::new(300.0, 0.0);
        assert!(b.sees(ahead));
        run(&mut b, HumanoidCommand::WalkForward, 10, &mut r);
        assert!(!b.sees(ahead));
        run(&mut b, HumanoidCommand::Wait, 10, &mut r);
        assert!(b.sees(ahead));
    }

    #[test]
    fn bad_constants_are_refused_by_name() {
        assert!(HUMANOID.check().is_ok());
        let bad = |p: HumanoidParams| match p.check() {
            Err(FieldParamError::OutOfRange { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(bad(HumanoidParams { walk_mm_s: -1.0, ..HUMANOID }), "humanoid.walk_mm_s");
        assert_eq!(bad(HumanoidParams { step_s: 0.0, ..HUMANOID }), "humanoid.step_s");
        assert_eq!(bad(HumanoidParams { blind_gait: f64::NAN, ..HUMANOID }), "humanoid.blind_gait");
        assert_eq!(bad(HumanoidParams { foot_window_s: (0.3, 1.5), ..HUMANOID }), "humanoid.foot_window_s");
        assert_eq!(bad(HumanoidParams { foot_window_s: (0.6, 0.3), ..HUMANOID }), "humanoid.foot_window_s");
    }

    #[test]
    fn camera_sees_ahead_and_pans() {
        let mut r = rng(4, 0);
        let mut b = HumanoidBody::new(HUMANOID, Pose::default());
        assert!(b.sees(Point::new(300.0, 0.0)));
        assert!(!b.sees(Point::new(0.0, 300.0)));
        run(&mut b, HumanoidCommand::ScanLeft, 15, &mut r);
        assert!(b.sees(Point::new(150.0, 300.0)));
        assert!(b.command(Command::Primitive(crate::Primitive::Forward), &mut r).is_err());
    }
}
