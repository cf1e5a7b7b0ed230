//! Motion statistics of one-second primitives (Table 3.1): distance along the initial heading
//! and heading change, from tracker frames.

use serde::{Deserialize, Serialize};

use crate::command::Primitive;
use crate::math::{cos, deg, sin, wrap_angle_rad};
use crate::record::PrimitiveSequence;
use crate::tracker::Frame;

/// Mean and sd of a primitive's one-second motion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MotionStats {
    /// Sequences measured.
    pub n: usize,
    /// Mean signed distance along the initial heading, mm.
    pub distance_mean_mm: f64,
    /// Sample sd of the distance, mm.
    pub distance_sd_mm: f64,
    /// Mean heading change, rad.
    pub rotation_mean_rad: f64,
    /// Sample sd of the heading change, rad.
    pub rotation_sd_rad: f64,
}

/// Table 3.1 of the thesis for F B L R: distance mean, sd (mm); rotation mean, sd (rad).
pub const THESIS_TABLE_3_1: [(Primitive, MotionStats); 4] = [
    (Primitive::Forward, thesis(42.25, 12.98, -1.15, 0.57)),
    (Primitive::Backward, thesis(-48.58, 12.33, 2.29, 12.6)),
    (Primitive::Left, thesis(3.95, 5.16, 30.37, 18.33)),
    (Primitive::Right, thesis(3.28, 4.46, -29.22, 8.59)),
];

const fn thesis(d: f64, d_sd: f64, r_deg: f64, r_sd_deg: f64) -> MotionStats {
    MotionStats {
        n: 1000,
        distance_mean_mm: d,
        distance_sd_mm: d_sd,
        rotation_mean_rad: deg(r_deg),
        rotation_sd_rad: deg(r_sd_deg),
    }
}

/// Motion from the first to the last frame: (signed distance along the first frame's heading,
/// mm; heading change wrapped to (−π, π], rad). None for fewer than two frames or lost tracking.
#[must_use]
pub fn primitive_motion(frames: &[Frame]) -> Option<(f64, f64)> {
    let (first, last) = (frames.first()?, frames.last()?);
    if frames.len() < 2 {
        return None;
    }
    let (a, b) = (first.robot(), last.robot());
    let (dx, dy) = (b.x_mm - a.x_mm, b.y_mm - a.y_mm);
    let distance = dx * cos(a.theta_rad) + dy * sin(a.theta_rad);
    let rotation = wrap_angle_rad(b.theta_rad - a.theta_rad);
    (distance.is_finite() && rotation.is_finite()).then_some((distance, rotation))
}

fn mean_sd(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    if xs.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let mean = xs.iter().sum::<f64>() / n;
    let ss = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>();
    let sd = if xs.len() > 1 { (ss / (n - 1.0)).sqrt() } else { 0.0 };
    (mean, sd)
}

/// Table 3.1 for every primitive (indexed by [`Primitive::index`]) from labelled sequences.
#[must_use]
pub fn primitive_stats(sequences: &[PrimitiveSequence]) -> [MotionStats; 5] {
    Primitive::ALL.map(|p| {
        let (dist, rot): (Vec<f64>, Vec<f64>) =
            sequences.iter().filter(|s| s.primitive == p).filter_map(|s| primitive_motion(&s.frames)).unzip();
        let (dm, ds) = mean_sd(&dist);
        let (rm, rs) = mean_sd(&rot);
        MotionStats {
            n: dist.len(),
            distance_mean_mm: dm,
            distance_sd_mm: ds,
            rotation_mean_rad: rm,
            rotation_sd_rad: rs,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(x: f64, y: f64, th: f64) -> Frame {
        Frame {
            t_s: 0.0,
            robot_x_mm: x,
            robot_y_mm: y,
            robot_theta_rad: th,
            ball_x_mm: f64::NAN,
            ball_y_mm: f64::NAN,
            command: 0,
        }
    }

    #[test]
    fn distance_is_along_the_initial_heading() {
        let f = [frame(0.0, 0.0, deg(90.0)), frame(3.0, 40.0, deg(80.0))];
        let (d, r) = primitive_motion(&f).expect("two frames");
        assert!((d - 40.0).abs() < 1e-9);
        assert!((r - deg(-10.0)).abs() < 1e-12);
        let back = [frame(0.0, 0.0, 0.0), frame(-20.0, 0.0, 0.0)];
        assert!((primitive_motion(&back).expect("ok").0 + 20.0).abs() < 1e-12);
        assert!(primitive_motion(&f[..1]).is_none());
    }

    #[test]
    fn rotation_wraps_across_pi() {
        let f = [frame(0.0, 0.0, deg(170.0)), frame(0.0, 0.0, deg(-170.0))];
        let (_, r) = primitive_motion(&f).expect("ok");
        assert!((r - deg(20.0)).abs() < 1e-9);
    }
}
