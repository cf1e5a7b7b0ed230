//! Wheel speeds as a command: a pair of its own choosing, and the primitive a pair resembles.

use polymimic_types::Primitive;
use serde::{Deserialize, Serialize};

use crate::error::{FieldParamError, check_range};

/// The Lego body's wheel base, mm: the Expert's wheel speeds are written for it, and its
/// equivalent primitives are read through it.
pub(crate) const LEGO_WHEEL_BASE_MM: f64 = 175.0;

/// Wheel speeds of a policy's own choosing (left, right), kept to the micrometre per second so
/// that two commands compare exactly (a command held is not a new one).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct WheelSpeeds {
    left_um_s: i32,
    right_um_s: i32,
}

impl WheelSpeeds {
    /// Fastest wheel speed a command may name, mm/s (a body's top speed is checked when it runs).
    pub const LIMIT_MM_S: f64 = 10_000.0;

    /// `(left, right)` wheel speeds, mm/s.
    ///
    /// # Errors
    /// `OutOfRange` for a speed that is not finite or beyond ±[`WheelSpeeds::LIMIT_MM_S`].
    pub fn new(left_mm_s: f64, right_mm_s: f64) -> Result<Self, FieldParamError> {
        let um = |name, v: f64| {
            check_range(name, v, -Self::LIMIT_MM_S, Self::LIMIT_MM_S, "a finite wheel speed within ±10 000 mm/s")
                .map(|()| (v * 1000.0).round() as i32)
        };
        Ok(Self { left_um_s: um("left_mm_s", left_mm_s)?, right_um_s: um("right_mm_s", right_mm_s)? })
    }

    /// `(left, right)`, mm/s.
    #[must_use]
    pub fn mm_s(self) -> (f64, f64) {
        (f64::from(self.left_um_s) / 1000.0, f64::from(self.right_um_s) / 1000.0)
    }
}

/// The primitive a wheel-speed pair resembles over one second on the Lego body: stop if it
/// barely moves, else whichever of distance and rotation is larger relative to the primitives'
/// own (Table 3.1: about 45 mm and 30° per second).
pub(crate) fn primitive_of_wheels(left_mm_s: f64, right_mm_s: f64) -> Primitive {
    let v_mm_s = 0.5 * (left_mm_s + right_mm_s);
    let omega_deg_s = (right_mm_s - left_mm_s) / LEGO_WHEEL_BASE_MM * 180.0 / std::f64::consts::PI;
    let (lin, rot) = (v_mm_s.abs() / 45.0, omega_deg_s.abs() / 30.0);
    if lin < 0.1 && rot < 0.1 {
        Primitive::Stop
    } else if rot > lin {
        if omega_deg_s > 0.0 { Primitive::Left } else { Primitive::Right }
    } else if v_mm_s > 0.0 {
        Primitive::Forward
    } else {
        Primitive::Backward
    }
}
