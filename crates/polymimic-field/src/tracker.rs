//! The overhead tracker ("global vision", Ergo in the thesis): 30 frames/s of robot x, y, θ and
//! ball x, y with jitter, rare interlacing spikes in the heading, and occasional dropouts.

use polymimic_types::{Point, Pose, TrackedFrame};
use serde::{Deserialize, Serialize};

use crate::error::{FieldParamError, check_range};
use crate::math::{Rng, deg, gaussian, uniform, wrap_angle_rad};

/// Tracker frames per second (fixed: a one-second primitive is 30 frames).
pub const FRAME_RATE_HZ: u32 = 30;

/// Tracker frame period, s.
pub const FRAME_DT_S: f64 = 1.0 / FRAME_RATE_HZ as f64;

/// One tracker frame: what the camera saw, and the command the robot was sending (recorded for
/// evaluation only). Values are NaN while tracking is lost, and the ball's are NaN when there is
/// no ball on the field.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Frame {
    /// Time since the episode started, s.
    pub t_s: f64,
    /// Robot x, mm.
    pub robot_x_mm: f64,
    /// Robot y, mm.
    pub robot_y_mm: f64,
    /// Robot heading, rad in (−π, π].
    pub robot_theta_rad: f64,
    /// Ball x, mm.
    pub ball_x_mm: f64,
    /// Ball y, mm.
    pub ball_y_mm: f64,
    /// Id of the command being sent during this frame (see [`crate::command_table`]).
    pub command: u16,
}

impl Frame {
    /// The robot's tracked pose.
    #[must_use]
    pub fn robot(&self) -> Pose {
        Pose::new(self.robot_x_mm, self.robot_y_mm, self.robot_theta_rad)
    }

    /// The frame as the recogniser and the learner read it: the robot's pose and the ball's
    /// position (NaN where not tracked), without the time and the command.
    #[must_use]
    pub fn tracked(&self) -> TrackedFrame {
        TrackedFrame { robot: self.robot(), ball_x_mm: self.ball_x_mm, ball_y_mm: self.ball_y_mm }
    }

    /// The ball's tracked position, if there is one and it is tracked.
    #[must_use]
    pub fn ball(&self) -> Option<Point> {
        let p = Point::new(self.ball_x_mm, self.ball_y_mm);
        p.is_finite().then_some(p)
    }
}

/// Tracker noise model. Defaults, calibrated against the thesis's own numbers
/// (`studies/which_world_matches_the_thesis.py`, its best world rounded): σ 0.107 mm in x and y,
/// σ 0.186° in θ, a spike of 1.49°–4.46° in θ on 0.091 % of frames, and a dropout starting on
/// 0.005 % of frames. [`TrackerConfig::before_calibration`] is the noisier tracker that was
/// the default before.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TrackerConfig {
    /// sd of the position jitter (robot and ball), mm.
    pub position_sigma_mm: f64,
    /// sd of the heading jitter, rad.
    pub heading_sigma_rad: f64,
    /// Per-frame probability of an interlacing spike in the heading.
    pub spike_probability: f64,
    /// Largest spike, rad (a spike is uniform in [max/3, max] with a random sign).
    pub spike_max_rad: f64,
    /// Per-frame probability that tracking drops out (for 3–15 frames); a demonstration with a
    /// dropout is invalid (§3.2.1).
    pub loss_probability: f64,
}

impl Default for TrackerConfig {
    fn default() -> Self {
        Self {
            position_sigma_mm: 0.107,
            heading_sigma_rad: deg(0.186),
            spike_probability: 0.000_91,
            spike_max_rad: deg(4.46),
            loss_probability: 5e-5,
        }
    }
}

impl TrackerConfig {
    /// The default tracker before the calibration: σ 0.3 mm, σ 3° in θ, a 5°–15° spike on 1 %
    /// of frames (`docs/configs/world_before_calibration.toml`).
    #[must_use]
    pub fn before_calibration() -> Self {
        Self {
            position_sigma_mm: 0.3,
            heading_sigma_rad: deg(3.0),
            spike_probability: 0.01,
            spike_max_rad: deg(15.0),
            loss_probability: 5e-5,
        }
    }

    /// A perfect tracker: ground truth, never lost.
    #[must_use]
    pub fn noiseless() -> Self {
        Self {
            position_sigma_mm: 0.0,
            heading_sigma_rad: 0.0,
            spike_probability: 0.0,
            spike_max_rad: 0.0,
            loss_probability: 0.0,
        }
    }

    /// Validate.
    ///
    /// # Errors
    /// `OutOfRange` for a negative or non-finite value, or a probability above 1.
    pub fn check(&self) -> Result<(), FieldParamError> {
        check_range("position_sigma_mm", self.position_sigma_mm, 0.0, 1e3, "0 ≤ σ ≤ 1000 mm")?;
        check_range("heading_sigma_rad", self.heading_sigma_rad, 0.0, 10.0, "0 ≤ σ ≤ 10 rad")?;
        check_range("spike_probability", self.spike_probability, 0.0, 1.0, "a probability")?;
        check_range("spike_max_rad", self.spike_max_rad, 0.0, 10.0, "0 ≤ spike ≤ 10 rad")?;
        check_range("loss_probability", self.loss_probability, 0.0, 1.0, "a probability")
    }
}

/// What the tracker reports for one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Measurement {
    pub robot: Pose,
    pub ball: Option<Point>,
    pub lost: bool,
}

#[derive(Debug, Clone)]
pub(crate) struct Tracker {
    config: TrackerConfig,
    rng: Rng,
    lost_frames_left: u32,
}

impl Tracker {
    pub(crate) fn new(config: TrackerConfig, rng: Rng) -> Self {
        Self { config, rng, lost_frames_left: 0 }
    }

    /// Measure the true state. The same number of random draws every frame, whatever the config.
    pub(crate) fn measure(&mut self, robot: Pose, ball: Option<Point>) -> Measurement {
        let c = self.config;
        let r = &mut self.rng;
        let (nx, ny, nt) = (gaussian(r), gaussian(r), gaussian(r));
        let (spike_u, spike_mag, spike_sign) = (uniform(r), uniform(r), uniform(r));
        let (bx, by) = (gaussian(r), gaussian(r));
        let (loss_u, loss_len) = (uniform(r), uniform(r));
        if self.lost_frames_left == 0 && loss_u < c.loss_probability {
            self.lost_frames_left = 3 + (loss_len * 13.0) as u32;
        }
        let lost = self.lost_frames_left > 0;
        if lost {
            self.lost_frames_left -= 1;
            let nan = Point::new(f64::NAN, f64::NAN);
            return Measurement { robot: Pose::new(f64::NAN, f64::NAN, f64::NAN), ball: ball.map(|_| nan), lost };
        }
        let mut theta = robot.theta_rad() + c.heading_sigma_rad * nt;
        if spike_u < c.spike_probability {
            let magnitude = c.spike_max_rad * (1.0 + 2.0 * spike_mag) / 3.0;
            theta += if spike_sign < 0.5 { -magnitude } else { magnitude };
        }
        Measurement {
            robot: Pose::new(
                robot.x_mm() + c.position_sigma_mm * nx,
                robot.y_mm() + c.position_sigma_mm * ny,
                wrap_angle_rad(theta),
            ),
            ball: ball.map(|b| Point::new(b.x_mm() + c.position_sigma_mm * bx, b.y_mm() + c.position_sigma_mm * by)),
            lost,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng;

    #[test]
    fn noiseless_tracker_reports_ground_truth() {
        let mut t = Tracker::new(TrackerConfig::noiseless(), rng(1, 0));
        let pose = Pose::new(1.0, 2.0, 0.5);
        let m = t.measure(pose, Some(Point::new(3.0, 4.0)));
        assert_eq!(m.robot, pose);
        assert_eq!(m.ball, Some(Point::new(3.0, 4.0)));
        assert!(!m.lost);
    }

    #[test]
    fn default_jitter_matches_its_sigmas() {
        let config = TrackerConfig { spike_probability: 0.0, loss_probability: 0.0, ..TrackerConfig::default() };
        let mut t = Tracker::new(config, rng(2, 0));
        let n = 20_000;
        let (mut sx, mut st) = (0.0, 0.0);
        for _ in 0..n {
            let m = t.measure(Pose::default(), None);
            sx += m.robot.x_mm() * m.robot.x_mm();
            st += m.robot.theta_rad() * m.robot.theta_rad();
        }
        let (sdx, sdt) = ((sx / f64::from(n)).sqrt(), (st / f64::from(n)).sqrt());
        assert!((sdx / config.position_sigma_mm - 1.0).abs() < 0.03, "{sdx}");
        assert!((sdt / config.heading_sigma_rad - 1.0).abs() < 0.03, "{sdt}");
    }

    #[test]
    fn dropouts_last_several_frames() {
        let cfg = TrackerConfig { loss_probability: 1.0, ..TrackerConfig::default() };
        let mut t = Tracker::new(cfg, rng(3, 0));
        let m = t.measure(Pose::default(), None);
        assert!(m.lost && m.robot.x_mm().is_nan());
        assert!(TrackerConfig { loss_probability: 2.0, ..cfg }.check().is_err());
    }
}
