//! Motion statistics of one-second primitives (Table 3.1): distance along the initial heading
//! and heading change, from tracker frames, with the field's maths (`libm`, the exact wrap).

use polymimic_types::{MotionStats, Primitive, wrap_angle_rad};

use crate::math::deg;
use crate::record::PrimitiveSequence;
use crate::tracker::Frame;

/// Table 3.1 of the thesis for F B L R (1000 sequences each). The rotations are the thesis's
/// degrees read back through the radians the field always held them in (12.6° comes back as
/// 12.599999999999998°), so that every consumer sees the bits it always did.
pub const THESIS_TABLE_3_1: [MotionStats; 4] = [
    thesis(Primitive::Forward, 42.25, 12.98, -1.15, 0.57),
    thesis(Primitive::Backward, -48.58, 12.33, 2.29, 12.6),
    thesis(Primitive::Left, 3.95, 5.16, 30.37, 18.33),
    thesis(Primitive::Right, 3.28, 4.46, -29.22, 8.59),
];

const fn thesis(primitive: Primitive, d: f64, d_sd: f64, r_deg: f64, r_sd_deg: f64) -> MotionStats {
    MotionStats {
        primitive,
        count: 1000,
        distance_mean_mm: d,
        distance_sd_mm: d_sd,
        rotation_mean_deg: deg(r_deg).to_degrees(),
        rotation_sd_deg: deg(r_sd_deg).to_degrees(),
        sideways: None,
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
    let distance = a.point().to(b.point()).dot(&a.heading());
    let rotation = wrap_angle_rad(b.theta_rad() - a.theta_rad());
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
/// Rotations are averaged in radians, then given in degrees.
#[must_use]
pub fn primitive_stats(sequences: &[PrimitiveSequence]) -> [MotionStats; 5] {
    Primitive::WHEELED.map(|p| {
        let (dist, rot): (Vec<f64>, Vec<f64>) =
            sequences.iter().filter(|s| s.primitive == p).filter_map(|s| primitive_motion(&s.frames)).unzip();
        let (dm, ds) = mean_sd(&dist);
        let (rm, rs) = mean_sd(&rot);
        MotionStats {
            primitive: p,
            count: dist.len(),
            distance_mean_mm: dm,
            distance_sd_mm: ds,
            rotation_mean_deg: rm.to_degrees(),
            rotation_sd_deg: rs.to_degrees(),
            sideways: None,
        }
    })
}

/// One primitive's row of Table 3.1 as text: ours (count, distance and rotation with their sds)
/// and, where given, the thesis's beside it.
#[must_use]
pub fn table_3_1_row(ours: &MotionStats, thesis: Option<&MotionStats>) -> String {
    let row = format!(
        "{:9} n={:5}  dist {:7.2} ({:5.2}) mm  rot {:7.2} ({:5.2})°",
        ours.primitive.name(),
        ours.count,
        ours.distance_mean_mm,
        ours.distance_sd_mm,
        ours.rotation_mean_deg,
        ours.rotation_sd_deg
    );
    match thesis {
        None => row,
        Some(t) => format!(
            "{row}  [thesis dist {:7.2} ({:5.2}) mm, rot {:7.2} ({:5.2})°]",
            t.distance_mean_mm, t.distance_sd_mm, t.rotation_mean_deg, t.rotation_sd_deg
        ),
    }
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
    fn distance_keeps_the_fields_order_of_operations() {
        let f = [frame(1.0, 2.0, 0.7), frame(35.5, 20.25, 0.9)];
        let (d, _) = primitive_motion(&f).expect("two frames");
        let (dx, dy) = (35.5 - 1.0, 20.25 - 2.0);
        assert_eq!(d.to_bits(), (dx * libm::cos(0.7) + dy * libm::sin(0.7)).to_bits());
    }

    #[test]
    fn thesis_rotations_read_back_through_radians() {
        let backward = THESIS_TABLE_3_1[1];
        assert_eq!(backward.primitive, Primitive::Backward);
        assert_eq!(backward.rotation_sd_deg, (12.6 * std::f64::consts::PI / 180.0).to_degrees());
        assert!((backward.rotation_sd_deg - 12.6).abs() < 1e-12);
        assert_eq!(THESIS_TABLE_3_1[0].rotation_mean_deg, -1.15);
    }

    #[test]
    fn rotation_wraps_across_pi() {
        let f = [frame(0.0, 0.0, deg(170.0)), frame(0.0, 0.0, deg(-170.0))];
        let (_, r) = primitive_motion(&f).expect("ok");
        assert!((r - deg(20.0)).abs() < 1e-9);
    }
}
