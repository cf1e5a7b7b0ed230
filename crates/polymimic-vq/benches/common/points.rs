/// Points along short random arcs, like tracker frames relative to a sequence's start:
/// (dx mm, dy mm, 16·dθ rad), row-major. Written with full paths, so that the benches and the
/// crate's own tests can `include!` it.
pub fn tracker_like_points(n_points: usize, seed: u64) -> Vec<f64> {
    use rand::{RngExt as _, SeedableRng as _};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut data = Vec::with_capacity(n_points * 3);
    while data.len() < n_points * 3 {
        let speed_mm = rng.random_range(-50.0..50.0);
        let turn_rad: f64 = rng.random_range(-0.6..0.6);
        for t in 0..25 {
            let s = f64::from(t) / 25.0;
            let heading = turn_rad * s;
            data.push(speed_mm * s * heading.cos() + rng.random_range(-1.0..1.0));
            data.push(speed_mm * s * heading.sin() + rng.random_range(-1.0..1.0));
            data.push(16.0 * heading + rng.random_range(-0.8..0.8));
        }
    }
    data.truncate(n_points * 3);
    data
}
