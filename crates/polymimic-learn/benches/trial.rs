//! One learning trial of the heterogeneous experiment (Expert, Tiny, Humanoid; 25
//! demonstrations per configuration each: 150 in all), both phases and the pruning.
//! Run with RAYON_NUM_THREADS=1 for the one-core figure: the trial itself is sequential.

use criterion::{Criterion, criterion_group, criterion_main};
use polymimic_field::{Demonstrator, FieldConfig, Frame, Outcome, PrimitiveSequence, record_all, self_observation};
use polymimic_learn::{Ending, LearningConfig, MotionTable, PhaseOne, Pitch, SegmentedDemonstration, run_trial};
use polymimic_perceive::{
    LabelledSequence, Pose, Primitive, Recognizer, RecognizerConfig, SegmenterConfig, TrackedFrame, segment,
};

fn pose(f: &Frame) -> Pose {
    Pose { x_mm: f.robot_x_mm, y_mm: f.robot_y_mm, theta_rad: f.robot_theta_rad }
}

fn labelled(s: &PrimitiveSequence) -> LabelledSequence {
    let primitive = Primitive::from_name(s.primitive.name()).expect("same names");
    LabelledSequence { primitive, poses: s.frames.iter().map(pose).collect() }
}

fn trial(c: &mut Criterion) {
    let field = FieldConfig::default();
    let training: Vec<LabelledSequence> =
        self_observation(1000, 1, &field).expect("records").iter().map(labelled).collect();
    let recognizer = Recognizer::train(&training, RecognizerConfig::default()).expect("trains");
    let everyone = [Demonstrator::Expert, Demonstrator::Tiny, Demonstrator::Humanoid];
    let demonstrations: Vec<SegmentedDemonstration> = record_all(&everyone, 25, 1, &field)
        .expect("records")
        .iter()
        .map(|d| {
            let frames: Vec<TrackedFrame> = d
                .frames
                .iter()
                .map(|f| TrackedFrame { robot: pose(f), ball_x_mm: f.ball_x_mm, ball_y_mm: f.ball_y_mm })
                .collect();
            SegmentedDemonstration {
                demonstrator: d.demonstrator.name().to_owned(),
                pitch: if d.demonstrator == Demonstrator::Tiny { Pitch::SMALL } else { Pitch::LARGE },
                ending: match d.outcome {
                    Outcome::Goal => Ending::Goal,
                    Outcome::OwnGoal => Ending::OwnGoal,
                    _ => Ending::Other,
                },
                segments: segment(&frames, &recognizer, &SegmenterConfig::default()).expect("segments"),
            }
        })
        .collect();
    assert_eq!(demonstrations.len(), 150);
    let motion = MotionTable::new(recognizer.motion_stats()).expect("complete");
    let ordering: Vec<String> = everyone.iter().map(|d| d.name().to_owned()).collect();
    let config = LearningConfig::default();
    let mut seed = 0;
    c.bench_function("learning_trial_150_demonstrations", |b| {
        b.iter(|| {
            seed += 1;
            run_trial(&demonstrations, &ordering, &motion, &config, PhaseOne::ByModel, seed).expect("runs")
        });
    });
}

criterion_group!(benches, trial);
criterion_main!(benches);
