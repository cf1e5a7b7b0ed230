//! One learning trial of the heterogeneous experiment (Expert, Tiny, Humanoid; 25
//! demonstrations per configuration each: 150 in all), both phases and the pruning.
//! Run with RAYON_NUM_THREADS=1 for the one-core figure: the trial itself is sequential.
//! Also what the improved control learns from the same demonstrations before it drives (the
//! ball response, state values and the route table to the push region).

use criterion::{Criterion, criterion_group, criterion_main};
use polymimic_field::Demonstrator;
use polymimic_learn::{Laboratory, LearningConfig, PhaseOne, Pitch, WorldModel, run_trial};

fn trial(c: &mut Criterion) {
    let lab = Laboratory::new(1000, 1, LearningConfig::default()).expect("the recogniser trains");
    let everyone = [Demonstrator::Expert, Demonstrator::Tiny, Demonstrator::Humanoid];
    let demonstrations = lab.record(&everyone, 25, 1).expect("records");
    assert_eq!(demonstrations.len(), 150);
    let ordering: Vec<String> = everyone.iter().map(|d| d.name().to_owned()).collect();
    let mut seed = 0;
    c.bench_function("learning_trial_150_demonstrations", |b| {
        b.iter(|| {
            seed += 1;
            run_trial(&demonstrations, &ordering, &lab.motion, &lab.config, PhaseOne::ByModel, seed).expect("runs")
        });
    });
    c.bench_function("world_model_150_demonstrations", |b| {
        b.iter(|| WorldModel::learn(&demonstrations, &Pitch::LARGE, &lab.motion, &lab.config));
    });
}

criterion_group!(benches, trial);
criterion_main!(benches);
