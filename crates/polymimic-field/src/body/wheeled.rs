//! Two-wheeled differential-drive bodies (the Lego imitator and the tiny robot).
//!
//! Each command is a nominal wheel-speed pair. What the wheels actually deliver varies from one
//! command to the next: a common traction factor (carpet, battery) scales both wheels and a
//! differential factor makes one wheel slip or stick against the other. The spread of both
//! depends on the manoeuvre: reversing drags the rear skid sideways, so backward runs veer a
//! lot, and spins scrub the skid, so their rate varies far more than a straight run's.
//! The body's velocity follows the wheels through traction with a first-order lag: the robot's
//! mass makes translation lag noticeably (residual motion carries into the next primitive),
//! while its small yaw inertia and the skid's scrubbing make rotation settle quickly.

use std::collections::BTreeSet;
use std::sync::Mutex;

use polymimic_types::{Pose, Primitive, direction_rad};
use serde::{Deserialize, Serialize};

use crate::command::{Command, LEGO_WHEEL_BASE_MM};
use crate::error::{FieldParamError, check_counts, check_range};
use crate::math::{Rng, exp, gaussian, wrap_angle_rad};

/// Random traction of one manoeuvre class, drawn on every command onset.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Traction {
    /// sd of the common factor scaling both wheels. The factor is log-normal with mean 1:
    /// traction multiplies, so it is never negative, and a wheel rarely stalls outright while
    /// now and then it grips far better than usual.
    pub common_sd: f64,
    /// sd of the differential factor: left wheel × (1 − δ), right wheel × (1 + δ).
    pub differential_sd: f64,
}

/// Constants of a two-wheeled body. The Lego values are calibrated against Table 3.1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WheeledParams {
    /// Name (for errors and reports).
    pub name: &'static str,
    /// Body length along the heading, mm.
    pub length_mm: f64,
    /// Body width, mm.
    pub width_mm: f64,
    /// Effective distance between the wheels' contact points, mm.
    pub wheel_base_mm: f64,
    /// Nominal (left, right) wheel speeds of the primitives F B L R S, mm/s.
    pub primitive_wheels_mm_s: [(f64, f64); 5],
    /// Traction randomness per manoeuvre class (the command's equivalent primitive), F B L R S.
    pub traction: [Traction; 5],
    /// Lag of the forward speed behind the wheels, s.
    pub tau_linear_s: f64,
    /// Lag of the turn rate behind the wheels, s.
    pub tau_angular_s: f64,
    /// A command held this many frames gets fresh traction (the floor under it changes).
    pub traction_refresh_frames: u32,
    /// Whether the Expert's wheel-speed language can drive this body.
    pub accepts_expert_commands: bool,
    /// The fastest a wheel turns, mm/s: no command may ask for more.
    pub top_wheel_speed_mm_s: f64,
}

/// The Lego Mindstorms imitator (about 150 mm across), calibrated so that one-second primitives
/// executed in random order reproduce Table 3.1 (see `tests/calibration.rs`).
pub const LEGO: WheeledParams = WheeledParams {
    name: "lego",
    length_mm: 140.0,
    width_mm: 150.0,
    wheel_base_mm: LEGO_WHEEL_BASE_MM,
    primitive_wheels_mm_s: [(51.55, 47.86), (-61.45, -54.21), (-43.0, 53.2), (51.08, -42.9), (0.0, 0.0)],
    traction: [
        Traction { common_sd: 0.29, differential_sd: 0.008 },
        Traction { common_sd: 0.248, differential_sd: 0.343 },
        Traction { common_sd: 0.62, differential_sd: 0.069 },
        Traction { common_sd: 0.294, differential_sd: 0.055 },
        Traction { common_sd: 0.0, differential_sd: 0.0 },
    ],
    tau_linear_s: 0.12,
    tau_angular_s: 0.02,
    traction_refresh_frames: 30,
    accepts_expert_commands: true,
    // The Expert's sprint, its fastest command.
    top_wheel_speed_mm_s: 130.0,
};

/// The tiny robot (the Citizen Eco-Be): a tenth of the Lego's size, slow, erratic.
pub const TINY: WheeledParams = WheeledParams {
    name: "tiny",
    length_mm: 15.0,
    width_mm: 15.0,
    wheel_base_mm: 12.0,
    primitive_wheels_mm_s: [(25.0, 25.0), (-25.0, -25.0), (-8.0, 8.0), (8.0, -8.0), (0.0, 0.0)],
    traction: [Traction { common_sd: 0.2, differential_sd: 0.04 }; 5],
    tau_linear_s: 0.05,
    tau_angular_s: 0.03,
    traction_refresh_frames: 30,
    accepts_expert_commands: false,
    top_wheel_speed_mm_s: 25.0,
};

/// The Expert's fastest wheel speed, mm/s: a body that takes its commands must reach it.
const EXPERT_TOP_WHEEL_SPEED_MM_S: f64 = 130.0;

impl WheeledParams {
    /// Check every constant: sizes, the wheel base, the top speed and the lags positive,
    /// slip spreads non-negative, every primitive's wheels within the top speed, Stop still.
    ///
    /// # Errors
    /// `OutOfRange` naming the first constant that is not.
    pub fn check(&self) -> Result<(), FieldParamError> {
        let positive = |name, value: f64| check_range(name, value, f64::MIN_POSITIVE, 1e6, "positive");
        positive("length_mm", self.length_mm)?;
        positive("width_mm", self.width_mm)?;
        positive("wheel_base_mm", self.wheel_base_mm)?;
        positive("top_wheel_speed_mm_s", self.top_wheel_speed_mm_s)?;
        positive("tau_linear_s", self.tau_linear_s)?;
        positive("tau_angular_s", self.tau_angular_s)?;
        check_range("traction_refresh_frames", f64::from(self.traction_refresh_frames), 1.0, 1e6, "at least 1")?;
        let top = self.top_wheel_speed_mm_s;
        for &(left, right) in &self.primitive_wheels_mm_s {
            for wheel in [left, right] {
                check_range("primitive_wheels_mm_s", wheel, -top, top, "within ± top_wheel_speed_mm_s")?;
            }
        }
        let (stop_left, stop_right) = self.primitive_wheels_mm_s[Primitive::Stop.index()];
        check_range("primitive_wheels_mm_s (stop)", stop_left.abs() + stop_right.abs(), 0.0, 0.0, "0 for Stop")?;
        for t in &self.traction {
            check_range("traction.common_sd", t.common_sd, 0.0, 10.0, "0 ≤ sd ≤ 10")?;
            check_range("traction.differential_sd", t.differential_sd, 0.0, 1.0, "0 ≤ sd ≤ 1")?;
        }
        if self.accepts_expert_commands {
            check_range(
                "top_wheel_speed_mm_s",
                top,
                EXPERT_TOP_WHEEL_SPEED_MM_S,
                f64::INFINITY,
                "at least the Expert's 130 mm/s for a body that takes its commands",
            )?;
        }
        Ok(())
    }

    /// A body from JSON (the constants by name, as serialised), checked; its name is kept for
    /// the life of the process (names are few, and errors quote them).
    ///
    /// # Errors
    /// `Json` for malformed JSON or an unknown key; `NotACount` for a frame count that is not a
    /// whole number; `OutOfRange` as [`WheeledParams::check`].
    pub fn from_json(json: &str) -> Result<Self, FieldParamError> {
        check_counts(json, &[("traction_refresh_frames", "a whole number of frames, at least 1")])?;
        let data: WheeledParamsData = serde_json::from_str(json).map_err(|e| FieldParamError::Json(e.to_string()))?;
        let params = Self {
            name: interned(&data.name),
            length_mm: data.length_mm,
            width_mm: data.width_mm,
            wheel_base_mm: data.wheel_base_mm,
            primitive_wheels_mm_s: data.primitive_wheels_mm_s,
            traction: data.traction,
            tau_linear_s: data.tau_linear_s,
            tau_angular_s: data.tau_angular_s,
            traction_refresh_frames: data.traction_refresh_frames,
            accepts_expert_commands: data.accepts_expert_commands,
            top_wheel_speed_mm_s: data.top_wheel_speed_mm_s,
        };
        params.check()?;
        Ok(params)
    }

    /// The constants as JSON ([`WheeledParams::from_json`] reads them back).
    #[must_use]
    pub fn to_json(&self) -> String {
        // Serialising plain numbers and a name cannot fail.
        serde_json::to_string(self).unwrap_or_default()
    }
}

/// [`WheeledParams`] as read, with an owned name.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct WheeledParamsData {
    name: String,
    length_mm: f64,
    width_mm: f64,
    wheel_base_mm: f64,
    primitive_wheels_mm_s: [(f64, f64); 5],
    traction: [Traction; 5],
    tau_linear_s: f64,
    tau_angular_s: f64,
    traction_refresh_frames: u32,
    accepts_expert_commands: bool,
    top_wheel_speed_mm_s: f64,
}

/// `name` as a `'static` string, each distinct name allocated once.
fn interned(name: &str) -> &'static str {
    static NAMES: Mutex<BTreeSet<&'static str>> = Mutex::new(BTreeSet::new());
    let mut names = NAMES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some(known) = names.get(name) {
        return known;
    }
    let kept: &'static str = Box::leak(name.to_owned().into_boxed_str());
    names.insert(kept);
    kept
}

/// State of a two-wheeled body.
#[derive(Debug, Clone)]
pub(crate) struct WheeledBody {
    params: WheeledParams,
    pose: Pose,
    v_mm_s: f64,
    omega_rad_s: f64,
    target_v_mm_s: f64,
    target_omega_rad_s: f64,
    command: Option<Command>,
    frames_held: u32,
    /// The motor lags' share of the gap closed per substep, (linear, angular), for the step
    /// they were worked out for: every substep of an episode is as long, so two exponentials
    /// per episode do instead of two per substep.
    lag_shares: Option<(f64, f64, f64)>,
}

impl WheeledBody {
    pub(crate) fn new(params: WheeledParams, pose: Pose) -> Self {
        Self {
            params,
            pose,
            v_mm_s: 0.0,
            omega_rad_s: 0.0,
            target_v_mm_s: 0.0,
            target_omega_rad_s: 0.0,
            command: None,
            frames_held: 0,
            lag_shares: None,
        }
    }

    pub(crate) fn params(&self) -> &WheeledParams {
        &self.params
    }

    pub(crate) fn pose(&self) -> Pose {
        self.pose
    }

    /// Lift the robot and put it down at `pose`, at rest.
    pub(crate) fn place(&mut self, pose: Pose) {
        self.pose = pose;
        self.v_mm_s = 0.0;
        self.omega_rad_s = 0.0;
    }

    /// The command for the next frame; fresh traction on onset or after a long hold.
    pub(crate) fn command(&mut self, command: Command, rng: &mut Rng) -> Result<(), FieldParamError> {
        let (left, right) = match command {
            Command::Primitive(p) => *self
                .params
                .primitive_wheels_mm_s
                .get(p.index())
                .ok_or(FieldParamError::CommandNotSupported { command: p.name(), body: self.params.name })?,
            Command::Expert(e) if self.params.accepts_expert_commands => e.wheels_mm_s(),
            Command::Wheels(w) => {
                let (left, right) = w.mm_s();
                let top = self.params.top_wheel_speed_mm_s;
                if left.abs() > top || right.abs() > top {
                    return Err(FieldParamError::BeyondTopSpeed {
                        left_mm_s: left,
                        right_mm_s: right,
                        top_mm_s: top,
                        body: self.params.name,
                    });
                }
                (left, right)
            }
            _ => {
                return Err(FieldParamError::CommandNotSupported { command: command.name(), body: self.params.name });
            }
        };
        let onset = self.command != Some(command) || self.frames_held >= self.params.traction_refresh_frames;
        if onset {
            let traction = self.params.traction[command.primitive().index()];
            // Both draws always happen, so the random stream does not depend on the command.
            let (z_common, z_diff) = (gaussian(rng), gaussian(rng));
            let common = log_normal_factor(traction.common_sd, z_common);
            let diff = traction.differential_sd * z_diff;
            let (l, r) = (left * common * (1.0 - diff), right * common * (1.0 + diff));
            self.target_v_mm_s = 0.5 * (l + r);
            self.target_omega_rad_s = (r - l) / self.params.wheel_base_mm;
            self.command = Some(command);
            self.frames_held = 0;
        }
        self.frames_held += 1;
        Ok(())
    }

    /// Advance by `dt_s`: velocities relax toward the wheels, the pose integrates at mid-step.
    pub(crate) fn substep(&mut self, dt_s: f64) {
        let (a_v, a_w) = match self.lag_shares {
            Some((dt, a_v, a_w)) if dt.to_bits() == dt_s.to_bits() => (a_v, a_w),
            _ => {
                let shares =
                    (1.0 - exp(-dt_s / self.params.tau_linear_s), 1.0 - exp(-dt_s / self.params.tau_angular_s));
                self.lag_shares = Some((dt_s, shares.0, shares.1));
                shares
            }
        };
        self.v_mm_s += a_v * (self.target_v_mm_s - self.v_mm_s);
        self.omega_rad_s += a_w * (self.target_omega_rad_s - self.omega_rad_s);
        let theta_mid = self.pose.theta_rad() + 0.5 * self.omega_rad_s * dt_s;
        // The wheels carry the body along its mid-step heading.
        let moved = self.pose.point() + direction_rad(theta_mid) * self.v_mm_s * dt_s;
        self.pose = Pose::at(moved, wrap_angle_rad(self.pose.theta_rad() + self.omega_rad_s * dt_s));
    }
}

/// A log-normal factor with mean 1 and standard deviation `sd`, from a standard normal `z`.
fn log_normal_factor(sd: f64, z: f64) -> f64 {
    let sigma2 = libm::log(1.0 + sd * sd);
    exp(sigma2.sqrt() * z - 0.5 * sigma2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use polymimic_types::Primitive;

    use crate::command::{ExpertCommand, HumanoidCommand};
    use crate::math::rng;

    #[test]
    fn the_thesis_bodies_pass_their_own_checks_and_round_trip_through_json() {
        for params in [LEGO, TINY] {
            assert_eq!(params.check(), Ok(()));
            assert_eq!(WheeledParams::from_json(&params.to_json()), Ok(params));
        }
    }

    #[test]
    fn bad_constants_are_refused_by_name() {
        let refused = |edit: fn(&mut WheeledParams)| {
            let mut p = LEGO;
            edit(&mut p);
            match p.check() {
                Err(FieldParamError::OutOfRange { name, .. }) => name,
                other => panic!("expected a refusal, got {other:?}"),
            }
        };
        assert_eq!(refused(|p| p.length_mm = 0.0), "length_mm");
        assert_eq!(refused(|p| p.width_mm = -3.0), "width_mm");
        assert_eq!(refused(|p| p.wheel_base_mm = f64::NAN), "wheel_base_mm");
        assert_eq!(refused(|p| p.tau_linear_s = 0.0), "tau_linear_s");
        assert_eq!(refused(|p| p.primitive_wheels_mm_s[0] = (200.0, 40.0)), "primitive_wheels_mm_s");
        assert_eq!(refused(|p| p.primitive_wheels_mm_s[4] = (1.0, 0.0)), "primitive_wheels_mm_s (stop)");
        assert_eq!(refused(|p| p.traction[1].common_sd = -0.1), "traction.common_sd");
        assert_eq!(refused(|p| p.top_wheel_speed_mm_s = 100.0), "top_wheel_speed_mm_s");
        assert!(matches!(WheeledParams::from_json("{\"name\": \"x\"}"), Err(FieldParamError::Json(_))));
        let extra = LEGO.to_json().replace("{", "{\"wheels\": 3,");
        assert!(matches!(WheeledParams::from_json(&extra), Err(FieldParamError::Json(e)) if e.contains("wheels")));
        let negative = LEGO.to_json().replace("\"traction_refresh_frames\":30", "\"traction_refresh_frames\":-30");
        assert_eq!(
            WheeledParams::from_json(&negative).map_err(|e| e.to_string()),
            Err("parameter `traction_refresh_frames` = -30 is not a count: a whole number of frames, at least 1".into())
        );
    }

    fn run(body: &mut WheeledBody, command: Command, frames: u32, r: &mut Rng) {
        for _ in 0..frames {
            body.command(command, r).expect("supported");
            for _ in 0..8 {
                body.substep(1.0 / 240.0);
            }
        }
    }

    #[test]
    fn forward_moves_ahead_and_left_turns_counter_clockwise() {
        let mut r = rng(1, 0);
        let mut b = WheeledBody::new(LEGO, Pose::default());
        run(&mut b, Command::Primitive(Primitive::Forward), 30, &mut r);
        assert!(b.pose().x_mm() > 10.0 && b.pose().y_mm().abs() < 5.0);
        let theta0 = b.pose().theta_rad();
        run(&mut b, Command::Primitive(Primitive::Left), 30, &mut r);
        assert!(wrap_angle_rad(b.pose().theta_rad() - theta0) > 0.0);
    }

    #[test]
    fn residual_motion_carries_into_stop() {
        let mut r = rng(2, 0);
        let mut b = WheeledBody::new(LEGO, Pose::default());
        run(&mut b, Command::Primitive(Primitive::Forward), 30, &mut r);
        let x0 = b.pose().x_mm();
        run(&mut b, Command::Primitive(Primitive::Stop), 30, &mut r);
        let coast = b.pose().x_mm() - x0;
        assert!(coast > 1.0 && coast < 15.0, "coast {coast}");
    }

    #[test]
    fn bodies_reject_foreign_languages() {
        let mut r = rng(3, 0);
        let mut tiny = WheeledBody::new(TINY, Pose::default());
        let e = ExpertCommand::from_index(0).expect("exists");
        assert!(tiny.command(Command::Expert(e), &mut r).is_err());
        let mut lego = WheeledBody::new(LEGO, Pose::default());
        assert!(lego.command(Command::Expert(e), &mut r).is_ok());
        assert!(lego.command(Command::Humanoid(HumanoidCommand::KickLeft), &mut r).is_err());
        // The humanoid's own primitives are no wheeled body's.
        let kick = lego.command(Command::Primitive(polymimic_types::Primitive::Kick), &mut r);
        assert_eq!(kick, Err(FieldParamError::CommandNotSupported { command: "kick", body: "lego" }));
    }
}
