//! Wrapping angles into (−π, π]. Two ways exist because the field and the recogniser always
//! wrapped differently, and their saved results depend on the last bit.

use std::f64::consts::{PI, TAU};

use nalgebra::{UnitComplex, Vector2};

/// An angle wrapped into (−π, π], exactly: the remainder of a division by 2π is exact, and an
/// angle already in range comes back unchanged. Non-finite angles pass through. The field's
/// wrap (bodies, tracker, bearings).
#[must_use]
pub fn wrap_angle_rad(angle_rad: f64) -> f64 {
    if !angle_rad.is_finite() {
        return angle_rad;
    }
    let mut wrapped = angle_rad % TAU;
    if wrapped <= -PI {
        wrapped += TAU;
    } else if wrapped > PI {
        wrapped -= TAU;
    }
    wrapped
}

/// An angle wrapped into (−π, π] through [0, 2π) (`rem_euclid`, then 2π off anything above π):
/// a negative angle comes back rounded to the spacing of numbers near 2π, and a non-finite one
/// as NaN. The recogniser's and the learner's wrap (representations, segment rotations,
/// predictions), kept so that their saved models and results stay bit-identical.
#[must_use]
pub fn wrap_angle_euclid_rad(angle_rad: f64) -> f64 {
    let wrapped = angle_rad.rem_euclid(TAU);
    if wrapped > PI { wrapped - TAU } else { wrapped }
}

/// A rotation by `angle_rad`, from `libm`'s cosine and sine (the field's maths; nalgebra's
/// `UnitComplex::new` would take std's). `libm::sincos` reduces the angle once for both and
/// gives `libm::sin`'s and `libm::cos`'s values to the bit.
#[must_use]
pub fn rotation_by_rad(angle_rad: f64) -> UnitComplex<f64> {
    let (sin, cos) = libm::sincos(angle_rad);
    UnitComplex::from_cos_sin_unchecked(cos, sin)
}

/// The unit vector at `angle_rad` from +x: the x axis turned by [`rotation_by_rad`], read off
/// the rotation (`rotation * Vector2::x()` would add products with zero, which can flip the
/// sign of a zero component).
#[must_use]
pub fn direction_rad(angle_rad: f64) -> Vector2<f64> {
    let rotation = rotation_by_rad(angle_rad);
    Vector2::new(rotation.cos_angle(), rotation.sin_angle())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_keeps_the_half_open_interval_at_its_edges() {
        assert_eq!(wrap_angle_rad(PI), PI);
        assert_eq!(wrap_angle_rad(-PI), PI);
        assert_eq!(wrap_angle_rad(0.0), 0.0);
        assert_eq!(wrap_angle_rad(TAU), 0.0);
        assert!((wrap_angle_rad(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-15);
        assert!((wrap_angle_rad(-3.0 * PI / 2.0) - PI / 2.0).abs() < 1e-15);
        for k in -20..=20 {
            let a = f64::from(k) * 0.7;
            let w = wrap_angle_rad(a);
            assert!(w > -PI && w <= PI, "{a} -> {w}");
            assert!((w.sin() - a.sin()).abs() < 1e-12 && (w.cos() - a.cos()).abs() < 1e-12);
        }
    }

    #[test]
    fn wrap_returns_an_angle_in_range_unchanged() {
        for a in [-3.0, -0.1, -1e-20, 1e-20, 0.1, 3.0] {
            assert_eq!(wrap_angle_rad(a).to_bits(), a.to_bits());
        }
        assert_eq!(wrap_angle_rad(-0.0).to_bits(), (-0.0_f64).to_bits());
    }

    #[test]
    fn wrap_passes_non_finite_angles_through() {
        assert!(wrap_angle_rad(f64::NAN).is_nan());
        assert_eq!(wrap_angle_rad(f64::INFINITY), f64::INFINITY);
        assert_eq!(wrap_angle_rad(f64::NEG_INFINITY), f64::NEG_INFINITY);
    }

    #[test]
    fn euclid_wrap_keeps_the_half_open_interval_at_its_edges() {
        assert_eq!(wrap_angle_euclid_rad(PI), PI);
        assert_eq!(wrap_angle_euclid_rad(-PI), PI);
        assert_eq!(wrap_angle_euclid_rad(0.0), 0.0);
        assert!((wrap_angle_euclid_rad(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-12);
        assert!((wrap_angle_euclid_rad(-3.0 * PI / 2.0) - PI / 2.0).abs() < 1e-12);
        assert!(wrap_angle_euclid_rad(f64::INFINITY).is_nan());
    }

    #[test]
    fn sincos_gives_sin_and_cos_to_the_bit() {
        let mut state = 0x2545_F491_4F6C_DD1D_u64;
        let mut check = |x: f64| {
            let (s, c) = libm::sincos(x);
            assert_eq!((s.to_bits(), c.to_bits()), (libm::sin(x).to_bits(), libm::cos(x).to_bits()), "{x:e}");
        };
        for _ in 0..300_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let unit = (state >> 11) as f64 / (1u64 << 53) as f64;
            check((unit - 0.5) * 4.0 * TAU); // the field's angles, and a turn beyond
            check((unit - 0.5) * 3e-8); // where the two take their tiny-angle shortcuts
        }
        for x in [0.0, -0.0, PI, -PI, std::f64::consts::FRAC_PI_4, 1.5e-8, 1.05e-8, 1e300, f64::MIN_POSITIVE] {
            check(x);
        }
    }

    #[test]
    fn rotation_by_a_quarter_turn_takes_x_to_y() {
        let r = rotation_by_rad(std::f64::consts::FRAC_PI_2);
        assert_eq!((r.cos_angle(), r.sin_angle()), (libm::cos(std::f64::consts::FRAC_PI_2), 1.0));
        let v = r * nalgebra::Vector2::new(2.0, 0.0);
        assert_eq!(v.y, 2.0);
        assert!(v.x.abs() < 1e-15);
    }

    #[test]
    fn the_two_wraps_differ_in_the_last_bits_of_negative_angles() {
        // Through [0, 2π) a tiny negative angle is lost against 2π; the exact wrap keeps it.
        assert_eq!(wrap_angle_euclid_rad(-1e-20), 0.0);
        assert_eq!(wrap_angle_rad(-1e-20), -1e-20);
        assert_ne!(wrap_angle_euclid_rad(-0.1).to_bits(), wrap_angle_rad(-0.1).to_bits());
        // Positive angles in range agree to the bit.
        for a in [1e-20, 0.1, 1.0, 3.0] {
            assert_eq!(wrap_angle_euclid_rad(a).to_bits(), wrap_angle_rad(a).to_bits());
        }
    }
}
