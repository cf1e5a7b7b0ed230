//! The thesis's codebook: 125 000 three-dimensional points quantised to 512 codewords.

mod common;

use criterion::{Criterion, criterion_group, criterion_main};
use polymimic_vq::{Codebook, LbgParams};

const POINTS: usize = 125_000;

fn lbg_512(c: &mut Criterion) {
    let data = common::tracker_like_points(POINTS, 2);
    let mut group = c.benchmark_group("lbg_125000x3_to_512");
    group.sample_size(10);
    group.bench_function("fit", |b| b.iter(|| Codebook::fit(&data, 3, LbgParams::new(512)).expect("grows")));
    let codebook = Codebook::fit(&data, 3, LbgParams::new(512)).expect("grows");
    group.bench_function("encode", |b| b.iter(|| codebook.encode(&data, 3).expect("encodes")));
    group.finish();
}

criterion_group!(benches, lbg_512);
criterion_main!(benches);
