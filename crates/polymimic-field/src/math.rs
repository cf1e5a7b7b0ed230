//! Portable maths: transcendental functions from `libm` (bit-identical on every platform, unlike
//! the system libm behind `f64::sin`), seed derivation and Gaussian draws. Angles wrap with
//! `polymimic_types::wrap_angle_rad`.

use polymimic_types::Point;
pub use polymimic_types::wrap_angle_rad;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

pub(crate) const TAU: f64 = std::f64::consts::TAU;
pub(crate) const PI: f64 = std::f64::consts::PI;

pub(crate) fn sin(x: f64) -> f64 {
    libm::sin(x)
}

pub(crate) fn cos(x: f64) -> f64 {
    libm::cos(x)
}

pub(crate) fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// Degrees to radians (for constants written in the thesis's degrees).
pub(crate) const fn deg(x: f64) -> f64 {
    x * PI / 180.0
}

/// `splitmix64`: a well-mixed 64-bit hash, used to derive independent seeds from (seed, index).
pub(crate) fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A seed for the `index`-th item of stream `stream` under the user's `seed`; independent of
/// which thread runs the item, so batches give the same bits on any number of threads.
#[must_use]
pub fn derive_seed(seed: u64, stream: u64, index: u64) -> u64 {
    splitmix64(splitmix64(seed ^ splitmix64(stream)) ^ index)
}

/// Named random streams, so that (for example) changing the tracker noise leaves the robot's
/// wheel slip unchanged.
pub(crate) mod stream {
    pub const BODY: u64 = 1;
    pub const TRACKER: u64 = 2;
    pub const CONTROLLER: u64 = 3;
    pub const SESSION: u64 = 5;
    pub const BALL: u64 = 6;
    /// A demonstrator's lapses (docs/guides/crowd.md), apart so that ε = 0 leaves every other stream as it was.
    pub const LAPSE: u64 = 7;
}

/// The crate's random generator: `ChaCha8`, seeded, identical on every platform.
pub(crate) type Rng = ChaCha8Rng;

pub(crate) fn rng(seed: u64, stream: u64) -> Rng {
    ChaCha8Rng::seed_from_u64(derive_seed(seed, stream, 0))
}

/// Distance, mm, from `p` (in the box's frame) to the box of half-sides `half_x_mm` and
/// `half_y_mm` centred at the origin; 0 inside it.
pub(crate) fn dist_to_box_mm(p: Point, half_x_mm: f64, half_y_mm: f64) -> f64 {
    let dx = (p.x_mm().abs() - half_x_mm).max(0.0);
    let dy = (p.y_mm().abs() - half_y_mm).max(0.0);
    libm::hypot(dx, dy)
}

/// Uniform in [0, 1).
pub(crate) fn uniform(rng: &mut Rng) -> f64 {
    rng.random::<f64>()
}

/// Standard normal draw (Box–Muller; one value per call keeps the stream easy to reason about).
pub(crate) fn gaussian(rng: &mut Rng) -> f64 {
    GaussianDraw::take(rng).value()
}

/// The two uniforms of a [`gaussian`] draw, taken from the stream now; the value costs a
/// logarithm and a cosine, so a caller that may not need it can leave it uncomputed while the
/// stream advances as if it had been.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GaussianDraw {
    u1: f64,
    u2: f64,
}

impl GaussianDraw {
    pub(crate) fn take(rng: &mut Rng) -> Self {
        // 1 − u lies in (0, 1], so the logarithm is finite.
        let u1 = 1.0 - uniform(rng);
        Self { u1, u2: uniform(rng) }
    }

    pub(crate) fn value(self) -> f64 {
        (-2.0 * libm::log(self.u1)).sqrt() * cos(TAU * self.u2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_seeds_differ_by_index_and_stream() {
        assert_ne!(derive_seed(1, 1, 0), derive_seed(1, 1, 1));
        assert_ne!(derive_seed(1, 1, 0), derive_seed(1, 2, 0));
        assert_eq!(derive_seed(9, 3, 4), derive_seed(9, 3, 4));
    }

    #[test]
    fn gaussian_has_unit_moments() {
        let mut r = rng(7, 0);
        let n = 200_000;
        let xs: Vec<f64> = (0..n).map(|_| gaussian(&mut r)).collect();
        let mean = xs.iter().sum::<f64>() / f64::from(n);
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / f64::from(n);
        assert!(mean.abs() < 0.01, "{mean}");
        assert!((var - 1.0).abs() < 0.01, "{var}");
    }
}
