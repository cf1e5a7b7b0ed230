//! How far each primitive moves and turns in one second (thesis Table 3.1), and the most
//! motion any primitive can produce, which bounds a demonstration segment.

use polymimic_types::{MotionStats, Pose, Primitive, Sideways};
use serde::{Deserialize, Serialize};

/// The displacement (mm, along the starting heading) and rotation (deg) from the first to the
/// last pose.
#[must_use]
pub fn motion_of(poses: &[Pose]) -> (f64, f64) {
    match (poses.first(), poses.last()) {
        (Some(first), Some(last)) => (last.advance_from_mm(first), last.rotation_from_rad(first).to_degrees()),
        _ => (0.0, 0.0),
    }
}

/// The displacement to the left of the starting heading (mm) from the first to the last pose.
#[must_use]
pub fn sideways_of(poses: &[Pose]) -> f64 {
    match (poses.first(), poses.last()) {
        (Some(first), Some(last)) => first.robot_from_field(last.point()).y_mm(),
        _ => 0.0,
    }
}

/// Table 3.1 for one primitive's sequences (sample standard deviations).
#[must_use]
pub fn motion_stats<'a>(primitive: Primitive, sequences: impl IntoIterator<Item = &'a [Pose]>) -> MotionStats {
    let motions: Vec<(f64, f64)> = sequences.into_iter().map(motion_of).collect();
    let (distance_mean_mm, distance_sd_mm) = mean_sd(motions.iter().map(|m| m.0));
    let (rotation_mean_deg, rotation_sd_deg) = mean_sd(motions.iter().map(|m| m.1));
    MotionStats {
        primitive,
        count: motions.len(),
        distance_mean_mm,
        distance_sd_mm,
        rotation_mean_deg,
        rotation_sd_deg,
        sideways: None,
    }
}

/// [`motion_stats`] with the displacement across the starting heading too, for a body that
/// side-steps.
#[must_use]
pub fn motion_stats_with_sideways<'a>(
    primitive: Primitive,
    sequences: impl IntoIterator<Item = &'a [Pose]> + Clone,
) -> MotionStats {
    let sideways: Vec<f64> = sequences.clone().into_iter().map(sideways_of).collect();
    let (mean_mm, sd_mm) = mean_sd(sideways.iter().copied());
    MotionStats { sideways: Some(Sideways { mean_mm, sd_mm }), ..motion_stats(primitive, sequences) }
}

fn mean_sd(values: impl Iterator<Item = f64> + Clone) -> (f64, f64) {
    let n = values.clone().count() as f64;
    if n == 0.0 {
        return (0.0, 0.0);
    }
    let mean = values.clone().sum::<f64>() / n;
    let var = if n > 1.0 { values.map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0) } else { 0.0 };
    (mean, var.sqrt())
}

/// The most motion any primitive produces: a segment is cut once it moves or turns more.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MotionLimits {
    pub max_distance_mm: f64,
    pub max_rotation_deg: f64,
}

impl MotionLimits {
    /// Mean + `sds` standard deviations of the largest primitive distance and of the largest
    /// primitive rotation (in magnitude).
    #[must_use]
    pub fn from_stats(stats: &[MotionStats], sds: f64) -> Self {
        let max_distance_mm =
            stats.iter().map(|s| s.distance_mean_mm.abs() + sds * s.distance_sd_mm).fold(0.0, f64::max);
        let max_rotation_deg =
            stats.iter().map(|s| s.rotation_mean_deg.abs() + sds * s.rotation_sd_deg).fold(0.0, f64::max);
        Self { max_distance_mm, max_rotation_deg }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stats_of_known_motions() {
        let a = [Pose::new(0.0, 0.0, 0.0), Pose::new(40.0, 3.0, 0.1)];
        let b = [Pose::new(0.0, 0.0, 0.0), Pose::new(44.0, -3.0, -0.1)];
        let s = motion_stats(Primitive::Forward, [&a[..], &b[..]]);
        assert!((s.distance_mean_mm - 42.0).abs() < 1e-12);
        assert!((s.distance_sd_mm - 8.0_f64.sqrt()).abs() < 1e-12);
        assert!(s.rotation_mean_deg.abs() < 1e-12);
        let limits = MotionLimits::from_stats(&[s], 2.0);
        let aside = [Pose::new(0.0, 0.0, 1.0), Pose::new(-2.0 * 1.0_f64.sin(), 2.0 * 1.0_f64.cos(), 1.0)];
        let stepped = motion_stats_with_sideways(Primitive::SidestepLeft, [&aside[..], &aside[..]]);
        let sideways = stepped.sideways.expect("measured");
        assert!((sideways.mean_mm - 2.0).abs() < 1e-12 && sideways.sd_mm.abs() < 1e-12, "{sideways:?}");
        assert!(stepped.distance_mean_mm.abs() < 1e-12);
        assert!((limits.max_distance_mm - (42.0 + 2.0 * 8.0_f64.sqrt())).abs() < 1e-12);
    }
}
