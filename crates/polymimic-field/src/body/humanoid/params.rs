//! The humanoid's constants: its body, gait, kick and camera, and how its controller plays;
//! the thesis's Bioloid-like values and their ranges.

use serde::{Deserialize, Serialize};

use crate::error::{FieldParamError, check_range};
use crate::math::{PI, deg};

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

/// The Bioloid-like humanoid, its turn, sway, foot placement and lineup calibrated against the
/// thesis's own numbers (`studies/which_world_matches_the_thesis.py`, its best world rounded): it turns
/// about a stance foot 20 mm to the side, places its kicking foot only roughly and swings it
/// slowly, and walks only roughly behind the ball before side-stepping the rest of the way.
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
    sway_rad: deg(3.34),
    step_yaw_sd_rad: deg(1.52),
    step_length_sd: 0.15,
    tau_s: 0.1,
    turn_pivot_mm: 20.3,
    kick_s: 1.0,
    kick_lean_mm: 15.0,
    kick_net_back_mm: 10.0,
    foot_window_s: (0.3, 0.959),
    foot_reach_mm: (20.0, 110.0),
    foot_side_mm: 28.0,
    foot_size_mm: (40.0, 30.0),
    foot_aim_sd_mm: 21.7,
    camera_half_fov_rad: deg(35.0),
    blind_gait: 1.0,
    camera_range_mm: 1400.0,
    head_pan_rad: deg(60.0),
    head_pan_rate_rad_s: deg(180.0),
    scan_down_range_mm: 350.0,
    lineup_ahead_mm: 384.7,
    lineup_side_mm: 299.5,
    lineup_tolerance_mm: 10.0,
    spot_tolerance_mm: 138.5,
    spot_gap_mm: 70.0,
    look_after_s: 0.0,
    look_s: 0.4,
};

/// The humanoid that was the default before the calibration
/// (`docs/configs/world_before_calibration.toml`): it turned about its centre, swayed 4°, placed
/// its foot exactly and swung it in 0.25 s, and walked to within 35 mm of its spot.
pub const HUMANOID_BEFORE_CALIBRATION: HumanoidParams = HumanoidParams {
    turn_pivot_mm: 0.0,
    sway_rad: deg(4.0),
    step_yaw_sd_rad: deg(1.5),
    foot_window_s: (0.3, 0.55),
    foot_aim_sd_mm: 0.0,
    lineup_ahead_mm: 260.0,
    lineup_side_mm: 90.0,
    spot_tolerance_mm: 35.0,
    ..HUMANOID
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
        type Range = (f64, f64, &'static str);
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
        // Each allowed range with the constants it bounds.
        let ranges: [(Range, &[(&str, f64)]); 11] = [
            (
                MM_POSITIVE,
                &[
                    ("humanoid.length_mm", p.length_mm),
                    ("humanoid.width_mm", p.width_mm),
                    ("humanoid.foot_size_mm[0]", p.foot_size_mm.0),
                    ("humanoid.foot_size_mm[1]", p.foot_size_mm.1),
                    ("humanoid.camera_range_mm", p.camera_range_mm),
                    ("humanoid.scan_down_range_mm", p.scan_down_range_mm),
                ],
            ),
            (
                MM_S,
                &[
                    ("humanoid.walk_mm_s", p.walk_mm_s),
                    ("humanoid.backward_mm_s", p.backward_mm_s),
                    ("humanoid.shuffle_mm_s", p.shuffle_mm_s),
                ],
            ),
            (
                RAD_S,
                &[
                    ("humanoid.turn_rad_s", p.turn_rad_s),
                    ("humanoid.arc_rad_s", p.arc_rad_s),
                    ("humanoid.scan_twist_rad_s", p.scan_twist_rad_s),
                ],
            ),
            (S_POSITIVE, &[("humanoid.step_s", p.step_s), ("humanoid.tau_s", p.tau_s), ("humanoid.kick_s", p.kick_s)]),
            (
                RAD,
                &[
                    ("humanoid.sway_rad", p.sway_rad),
                    ("humanoid.step_yaw_sd_rad", p.step_yaw_sd_rad),
                    ("humanoid.head_pan_rad", p.head_pan_rad),
                ],
            ),
            ((0.0, 10.0, "0 ≤ sd ≤ 10"), &[("humanoid.step_length_sd", p.step_length_sd)]),
            (
                MM,
                &[
                    ("humanoid.turn_pivot_mm", p.turn_pivot_mm),
                    ("humanoid.kick_lean_mm", p.kick_lean_mm),
                    ("humanoid.kick_net_back_mm", p.kick_net_back_mm),
                    ("humanoid.foot_reach_mm[0]", p.foot_reach_mm.0),
                    ("humanoid.foot_reach_mm[1]", p.foot_reach_mm.1),
                    ("humanoid.foot_side_mm", p.foot_side_mm),
                    ("humanoid.foot_aim_sd_mm", p.foot_aim_sd_mm),
                    ("humanoid.lineup_ahead_mm", p.lineup_ahead_mm),
                    ("humanoid.lineup_side_mm", p.lineup_side_mm),
                    ("humanoid.lineup_tolerance_mm", p.lineup_tolerance_mm),
                    ("humanoid.spot_tolerance_mm", p.spot_tolerance_mm),
                    ("humanoid.spot_gap_mm", p.spot_gap_mm),
                ],
            ),
            (RAD_POSITIVE, &[("humanoid.camera_half_fov_rad", p.camera_half_fov_rad)]),
            ((0.0, 1.0, "0 ≤ gait ≤ 1"), &[("humanoid.blind_gait", p.blind_gait)]),
            (RAD_S_POSITIVE, &[("humanoid.head_pan_rate_rad_s", p.head_pan_rate_rad_s)]),
            (S, &[("humanoid.look_after_s", p.look_after_s), ("humanoid.look_s", p.look_s)]),
        ];
        for ((low, high, expected), constants) in ranges {
            for &(name, value) in constants {
                check_range(name, value, low, high, expected)?;
            }
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
