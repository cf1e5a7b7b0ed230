//! The thesis's codebook: 125 000 three-dimensional points quantised to 512 codewords.

use criterion::{Criterion, criterion_group, criterion_main};
use polymimic_vq::{Codebook, LbgParams};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

const POINTS: usize = 125_000;

/// Points along short random arcs, like tracker frames relative to a sequence's start.
fn tracker_like_points() -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    let mut data = Vec::with_capacity(POINTS * 3);
    while data.len() < POINTS * 3 {
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
    data.truncate(POINTS * 3);
    data
}

fn lbg_512(c: &mut Criterion) {
    let data = tracker_like_points();
    let mut group = c.benchmark_group("lbg_125000x3_to_512");
    group.sample_size(10);
    group.bench_function("fit", |b| b.iter(|| Codebook::fit(&data, 3, LbgParams::new(512)).expect("grows")));
    let codebook = Codebook::fit(&data, 3, LbgParams::new(512)).expect("grows");
    group.bench_function("encode", |b| b.iter(|| codebook.encode(&data, 3).expect("encodes")));
    group.finish();
}

criterion_group!(benches, lbg_512);
criterion_main!(benches);
