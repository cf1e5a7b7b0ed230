//! Simulated tracker frames per second: the imitator robot and the ball, scripted primitives
//! at 30 Hz (8 physics substeps per frame), default tracker.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use polymimic_field::{
    BodyKind, Command, Configuration, Demonstrator, Episode, EpisodeSetup, FieldConfig, LapseRate, Primitive,
    demonstrate,
};

const FRAMES: u64 = 900;

/// Run `FRAMES` frames of a fixed script, restarting the episode whenever it ends.
fn scripted(seed: u64) -> usize {
    let config = FieldConfig::default();
    let setup = EpisodeSetup::configuration(BodyKind::Lego, Configuration::One, &config);
    let script = [
        Primitive::Forward,
        Primitive::Forward,
        Primitive::Left,
        Primitive::Forward,
        Primitive::Right,
        Primitive::Backward,
        Primitive::Stop,
    ];
    let mut episode = Episode::new(&setup, &config, seed).expect("valid set-up");
    let mut recorded = 0;
    for i in 0..FRAMES {
        if episode.is_finished() {
            recorded += episode.frames().len();
            episode = Episode::new(&setup, &config, seed + i).expect("valid set-up");
        }
        let p = script[(i as usize / 30) % script.len()];
        episode.step(Command::Primitive(p)).expect("step");
    }
    recorded + episode.frames().len()
}

/// One Expert demonstration from configuration 2 (about 30 s of pushing round and along).
fn expert_demonstration(config: &FieldConfig) -> usize {
    demonstrate(Demonstrator::Expert, Configuration::Two, 11, LapseRate::NONE, config).expect("runs").frames.len()
}

fn bench_field(c: &mut Criterion) {
    let mut group = c.benchmark_group("field");
    group.throughput(Throughput::Elements(FRAMES));
    group.bench_function("lego_and_ball_frames", |b| b.iter(|| black_box(scripted(black_box(7)))));
    let config = FieldConfig::default();
    let frames = expert_demonstration(&config) as u64;
    group.throughput(Throughput::Elements(frames));
    group.bench_function("expert_demonstration_frames", |b| {
        b.iter(|| black_box(expert_demonstration(black_box(&config))));
    });
    let coarse = FieldConfig { substeps_per_frame: 4, ..FieldConfig::default() };
    let frames = expert_demonstration(&coarse) as u64;
    group.throughput(Throughput::Elements(frames));
    group.bench_function("expert_demonstration_frames_120hz", |b| {
        b.iter(|| black_box(expert_demonstration(black_box(&coarse))));
    });
    group.finish();
}

criterion_group!(benches, bench_field);
criterion_main!(benches);
