//! Baum-Welch at the thesis's size: 5000 sequences of 25–30 symbols over 512 symbols,
//! left-right models of 1, 5 and 20 states. One iteration per measurement.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use polymimic_hmm::{DiscreteHmm, HmmParams, Init};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

const SEQUENCES: usize = 5000;
const SYMBOLS: usize = 512;

fn thesis_sized_sequences() -> Vec<Vec<u32>> {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    (0..SEQUENCES)
        .map(|_| {
            let len = rng.random_range(25..=30);
            // Symbols drift through the alphabet over time, as quantised motion does.
            let offset = rng.random_range(0..SYMBOLS as u32);
            (0..len).map(|t| (offset + t * 7 + rng.random_range(0..16)) % SYMBOLS as u32).collect()
        })
        .collect()
}

fn one_iteration(c: &mut Criterion) {
    let data = thesis_sized_sequences();
    let refs: Vec<&[u32]> = data.iter().map(Vec::as_slice).collect();
    let mut group = c.benchmark_group("baum_welch_iteration_5000x25-30_512_symbols");
    group.sample_size(20);
    for n_states in [1, 5, 20] {
        let mut params = HmmParams::new(n_states, SYMBOLS);
        params.max_iter = 0;
        let mut start = DiscreteHmm::new(params.check().expect("valid"));
        start.fit(&refs, Init::Segments).expect("initialises");
        let mut params = (**start.params()).clone();
        params.max_iter = 1;
        params.tol = f64::NEG_INFINITY;
        let p = start.probabilities().expect("initialised").clone();
        let model =
            DiscreteHmm::from_probabilities(params.check().expect("valid"), p.startprob, p.transmat, p.emissionprob)
                .expect("valid");
        group.bench_with_input(BenchmarkId::new("left_right_states", n_states), &model, |b, model| {
            b.iter(|| {
                let mut m = model.clone();
                m.fit(&refs, Init::Given).expect("trains");
                m
            });
        });
    }
    group.finish();
}

fn scoring(c: &mut Criterion) {
    let data = thesis_sized_sequences();
    let refs: Vec<&[u32]> = data.iter().map(Vec::as_slice).collect();
    let mut params = HmmParams::new(5, SYMBOLS);
    params.max_iter = 5;
    let mut model = DiscreteHmm::new(params.check().expect("valid"));
    model.fit(&refs, Init::Segments).expect("trains");
    c.bench_function("score_5000_sequences_5_states", |b| b.iter(|| model.score_many(&refs).expect("scores")));
}

criterion_group!(benches, one_iteration, scoring);
criterion_main!(benches);
