//! Segmenting every demonstration of an experiment: 300 demonstrations (Expert, Poor, Tiny,
//! Humanoid, and Expert and Poor again from other seeds; 25 per configuration each) with the
//! recogniser trained on 1000 self-observed primitives of each type.

use criterion::{Criterion, criterion_group, criterion_main};
use polymimic_field::{Demonstrator, FieldConfig, Frame, LapseRate, PrimitiveSequence, record_all, self_observation};
use polymimic_perceive::{LabelledSequence, Recognizer, RecognizerConfig, SegmenterConfig, TrackedFrame, segment_many};

fn labelled(s: &PrimitiveSequence) -> LabelledSequence {
    LabelledSequence { primitive: s.primitive, poses: s.frames.iter().map(Frame::robot).collect() }
}

fn segment_300(c: &mut Criterion) {
    let config = FieldConfig::default();
    let training: Vec<LabelledSequence> =
        self_observation(1000, 1, &config).expect("records").iter().map(labelled).collect();
    let recognizer = Recognizer::train(&training, RecognizerConfig::default()).expect("trains");
    let everyone = [Demonstrator::Expert, Demonstrator::Poor, Demonstrator::Tiny, Demonstrator::Humanoid];
    let mut demonstrations = record_all(&everyone, 25, 1, LapseRate::NONE, &config).expect("records");
    demonstrations.extend(record_all(&everyone[..2], 25, 2, LapseRate::NONE, &config).expect("records"));
    assert_eq!(demonstrations.len(), 300);
    let frames: Vec<Vec<TrackedFrame>> =
        demonstrations.iter().map(|d| d.frames.iter().map(Frame::tracked).collect()).collect();
    let refs: Vec<&[TrackedFrame]> = frames.iter().map(Vec::as_slice).collect();
    let mut group = c.benchmark_group("segmentation");
    group.sample_size(20);
    group.bench_function("segment_300_demonstrations", |b| {
        b.iter(|| segment_many(&refs, &recognizer, &SegmenterConfig::default()).expect("segments"));
    });
    group.finish();
}

criterion_group!(benches, segment_300);
criterion_main!(benches);
