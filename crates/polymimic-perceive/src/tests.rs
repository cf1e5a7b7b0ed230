//! Recognition and segmentation of synthetic unicycle motion whose truth is known.

use polymimic_types::wrap_angle_euclid_rad;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::*;

const FRAMES: usize = 30;

/// Speed (mm/s) and turn rate (deg/s) of each primitive.
fn motion(primitive: Primitive) -> (f64, f64) {
    match primitive {
        Primitive::Forward => (42.0, -1.0),
        Primitive::Backward => (-48.0, 2.0),
        Primitive::Left => (4.0, 30.0),
        Primitive::Right => (3.0, -29.0),
        Primitive::Stop => (0.0, 0.0),
        other => panic!("no synthetic motion for {other:?}"),
    }
}

/// Poses of `primitive` run for `frames` frames from `start`, with mild noise.
fn run(primitive: Primitive, start: Pose, frames: usize, rng: &mut ChaCha8Rng) -> Vec<Pose> {
    let (speed, turn) = motion(primitive);
    let speed = speed * (1.0 + 0.2 * (rng.random::<f64>() - 0.5));
    let turn = turn * (1.0 + 0.2 * (rng.random::<f64>() - 0.5));
    let mut pose = start;
    let mut poses = Vec::with_capacity(frames);
    for _ in 0..frames {
        poses.push(pose);
        pose = Pose::new(
            pose.x_mm() + speed / 30.0 * pose.theta_rad().cos(),
            pose.y_mm() + speed / 30.0 * pose.theta_rad().sin(),
            wrap_angle_euclid_rad(pose.theta_rad() + turn.to_radians() / 30.0),
        );
    }
    poses
}

fn self_observation(per_primitive: usize, seed: u64) -> Vec<LabelledSequence> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut sequences = Vec::new();
    for primitive in Primitive::WHEELED {
        for _ in 0..per_primitive {
            let x_mm = rng.random_range(-300.0..300.0);
            let y_mm = rng.random_range(-200.0..200.0);
            let start = Pose::new(x_mm, y_mm, rng.random_range(-3.1..3.1));
            sequences.push(LabelledSequence { primitive, poses: run(primitive, start, FRAMES, &mut rng) });
        }
    }
    sequences
}

fn small_config() -> RecognizerConfig {
    RecognizerConfig { codebook_size: 64, n_states: 3, ..RecognizerConfig::default() }
}

fn trained() -> Recognizer {
    Recognizer::train(&self_observation(60, 1), small_config()).unwrap()
}

#[test]
fn recognises_held_out_primitives() {
    let recognizer = trained();
    let test = self_observation(30, 2);
    for primitive in Primitive::MOVING {
        let correct = test
            .iter()
            .filter(|s| s.primitive == primitive)
            .filter(|s| recognizer.classify(&s.poses).unwrap() == primitive)
            .count();
        assert!(correct >= 27, "{primitive:?}: {correct}/30");
    }
}

#[test]
fn measures_table_3_1_from_the_training_set() {
    let recognizer = trained();
    let forward = recognizer.motion_stats()[0];
    assert_eq!(forward.primitive, Primitive::Forward);
    // 29 steps of 42 mm/s / 30, with ±10 % speed noise.
    assert!((forward.distance_mean_mm - 42.0 * 29.0 / 30.0).abs() < 2.0, "{forward:?}");
    let left = recognizer.motion_stats()[2];
    assert!((left.rotation_mean_deg - 29.0).abs() < 1.5, "{left:?}");
}

fn demonstration(plan: &[(Primitive, usize)], seed: u64) -> Vec<TrackedFrame> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut pose = Pose::new(-200.0, 0.0, 0.3);
    let mut frames = Vec::new();
    for &(primitive, count) in plan {
        let poses = run(primitive, pose, count + 1, &mut rng);
        pose = *poses.last().unwrap();
        frames.extend(poses[..count].iter().map(|&robot| TrackedFrame { robot, ball_x_mm: 100.0, ball_y_mm: 0.0 }));
    }
    frames
}

#[test]
fn segments_name_what_the_robot_did_and_stops_do_not_chain() {
    let recognizer = trained();
    // Segments are cut only when the motion outgrows every primitive, so a long turn is
    // needed for segments made of turning alone.
    let frames = demonstration(&[(Primitive::Stop, 25), (Primitive::Left, 200)], 4);
    let segments = segment(&frames, &recognizer, &SegmenterConfig::default()).unwrap();
    let labels: Vec<&str> = segments.iter().map(|s| s.label.name()).collect();
    assert_eq!(labels[0], "stop");
    assert_eq!(segments[0].first_frame, 0);
    assert!(segments[0].last_frame >= 18, "two stops in a row merge: {segments:?}");
    assert!(labels[1..].iter().all(|&l| l == "left"), "{labels:?}");
    assert!(labels.len() >= 3, "{labels:?}");
    for pair in segments.windows(2) {
        assert_eq!(pair[0].last_frame, pair[1].first_frame, "segments share their boundary frame");
        assert!(pair[1].last_frame - pair[1].first_frame + 1 >= 10);
    }
    for window in labels.windows(2) {
        assert!(!(window[0] == "stop" && window[1] == "stop"));
    }
}

#[test]
fn long_motion_is_cut_at_the_largest_primitive_motion() {
    let recognizer = trained();
    let frames = demonstration(&[(Primitive::Forward, 150)], 5);
    let segments = segment(&frames, &recognizer, &SegmenterConfig::default()).unwrap();
    let limits = MotionLimits::from_stats(recognizer.motion_stats(), 2.0);
    assert!(segments.len() >= 2);
    for s in &segments[..segments.len() - 1] {
        let moved = s.end.robot.distance_from_mm(&s.start.robot);
        assert!(moved <= limits.max_distance_mm, "{moved} > {}", limits.max_distance_mm);
        assert!(moved > limits.max_distance_mm - 3.0, "cut one frame before the limit: {moved}");
        assert_eq!(s.label, Label::Primitive(Primitive::Forward));
    }
}

#[test]
fn equal_scores_make_a_gap() {
    let recognizer = trained();
    let config = SegmenterConfig { gap_margin: f64::MAX, ..SegmenterConfig::default() };
    let frames = demonstration(&[(Primitive::Forward, 40)], 6);
    let segments = segment(&frames, &recognizer, &config).unwrap();
    assert!(segments.iter().all(|s| s.label == Label::Gap));
}

#[test]
fn bad_input_is_named() {
    let recognizer = trained();
    let mut frames = demonstration(&[(Primitive::Forward, 20)], 7);
    assert!(matches!(
        segment(&frames[..5], &recognizer, &SegmenterConfig::default()),
        Err(PerceiveError::TooFewFrames { frames: 5, needed: 10, .. })
    ));
    frames[7].robot = Pose::new(frames[7].robot.x_mm(), frames[7].robot.y_mm(), f64::NAN);
    assert!(matches!(
        segment(&frames, &recognizer, &SegmenterConfig::default()),
        Err(PerceiveError::NotFinite { frame: 7, .. })
    ));
    let only_forward: Vec<LabelledSequence> =
        self_observation(5, 1).into_iter().filter(|s| s.primitive == Primitive::Forward).collect();
    assert_eq!(
        Recognizer::train(&only_forward, small_config()).unwrap_err(),
        PerceiveError::MissingPrimitive("backward")
    );
}

#[test]
fn saved_recognisers_round_trip_and_foreign_files_are_refused() {
    let recognizer = trained();
    let text = recognizer.to_json().unwrap();
    assert_eq!(Recognizer::from_json(&text).unwrap(), recognizer);
    // The envelope's own version comes last, after the payload.
    let at = text.rfind("\"version\":1").unwrap();
    let other_version = format!("{}\"version\":3{}", &text[..at], &text[at + "\"version\":1".len()..]);
    assert!(matches!(Recognizer::from_json(&other_version), Err(PerceiveError::Corrupt(m)) if m.contains("version 3")));
}

#[test]
fn a_saved_recogniser_without_its_motion_statistics_is_damaged() {
    let text = trained().to_json().unwrap();
    let start = text.find("\"motion\":[").unwrap() + "\"motion\":[".len();
    let end = start + text[start..].find(']').unwrap();
    let emptied = format!("{}{}", &text[..start], &text[end..]);
    assert!(
        matches!(Recognizer::from_json(&emptied), Err(PerceiveError::Corrupt(m)) if m.contains("motion statistics")),
        "an empty Table 3.1 is refused"
    );
}

/// How many moving primitives of `test` the recogniser names correctly.
fn moving_correct(recognizer: &Recognizer, test: &[LabelledSequence]) -> usize {
    test.iter()
        .filter(|s| s.primitive != Primitive::Stop)
        .filter(|s| recognizer.classify(&s.poses).unwrap() == s.primitive)
        .count()
}

#[test]
fn egocentric_representation_recognises_too() {
    let config = RecognizerConfig {
        forward_backward_representation: Representation::Egocentric,
        left_right_representation: Representation::Egocentric,
        ..small_config()
    };
    let recognizer = Recognizer::train(&self_observation(60, 1), config).unwrap();
    let correct = moving_correct(&recognizer, &self_observation(20, 3));
    assert!(correct >= 76, "{correct}/80");
}

#[test]
fn gaussian_emissions_recognise_without_a_codebook() {
    let config = RecognizerConfig { emissions: Emissions::Gaussian, ..small_config() };
    let recognizer = Recognizer::train(&self_observation(60, 1), config).unwrap();
    assert!(recognizer.codebook(Representation::Positional).is_none());
    let correct = moving_correct(&recognizer, &self_observation(20, 3));
    assert!(correct >= 76, "{correct}/80");
    let text = recognizer.to_json().unwrap();
    assert_eq!(Recognizer::from_json(&text).unwrap(), recognizer);
}
