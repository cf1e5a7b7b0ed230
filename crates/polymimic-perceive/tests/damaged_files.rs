//! A damaged saved recogniser is refused with an `Err` or read as a recogniser that scores and
//! segments; reading never panics. Each property starts from a file written by `to_json` of a
//! recogniser trained on synthetic self-observation (the damage reaches into the codebooks and
//! HMMs it embeds as JSON strings too).

use polymimic_damage::{arbitrary, config, flipped, reshaped, truncated};
use polymimic_perceive::{Emissions, LabelledSequence, Recognizer, RecognizerConfig, SegmenterConfig, segment};
use polymimic_types::{Pose, Primitive, TrackedFrame, wrap_angle_euclid_rad};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

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

/// `frames` poses of `primitive` from `start`, its speed and turn scaled by `scale`.
fn run(primitive: Primitive, start: Pose, frames: usize, scale: f64) -> Vec<Pose> {
    let (speed, turn) = motion(primitive);
    let (mut x_mm, mut y_mm, mut theta_rad) = (start.x_mm(), start.y_mm(), start.theta_rad());
    let mut poses = Vec::with_capacity(frames);
    for _ in 0..frames {
        poses.push(Pose::new(x_mm, y_mm, theta_rad));
        x_mm += speed * scale / 30.0 * theta_rad.cos();
        y_mm += speed * scale / 30.0 * theta_rad.sin();
        theta_rad = wrap_angle_euclid_rad(theta_rad + (turn * scale).to_radians() / 30.0);
    }
    poses
}

fn self_observation() -> Vec<LabelledSequence> {
    let mut sequences = Vec::new();
    for primitive in Primitive::WHEELED {
        for i in 0..8 {
            let k = f64::from(i);
            let start = Pose::new(40.0 * k - 150.0, 25.0 * k - 100.0, 0.7 * k - 2.8);
            sequences.push(LabelledSequence { primitive, poses: run(primitive, start, 30, 0.9 + 0.03 * k) });
        }
    }
    sequences
}

fn recognizer_file(emissions: Emissions) -> String {
    let config = RecognizerConfig { codebook_size: 8, n_states: 2, max_iter: 10, emissions, ..Default::default() };
    Recognizer::train(&self_observation(), config).unwrap().to_json().unwrap()
}

fn discrete_file() -> String {
    recognizer_file(Emissions::Discrete)
}

fn gaussian_file() -> String {
    recognizer_file(Emissions::Gaussian)
}

/// A demonstration of a few primitives in a row, with a ball.
fn demonstration() -> Vec<TrackedFrame> {
    let mut poses = run(Primitive::Forward, Pose::new(0.0, 0.0, 0.0), 30, 1.0);
    let last = *poses.last().unwrap();
    poses.extend(run(Primitive::Left, last, 30, 1.0));
    let last = *poses.last().unwrap();
    poses.extend(run(Primitive::Stop, last, 15, 1.0));
    poses.into_iter().map(|robot| TrackedFrame { robot, ball_x_mm: 200.0, ball_y_mm: 10.0 }).collect()
}

/// A recogniser read from `text` must round-trip, hold four models, and score, classify and
/// segment without panicking.
fn recognizer_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(recognizer) = Recognizer::from_json(text) else { return Ok(()) };
    let saved = recognizer.to_json().map_err(|e| TestCaseError::fail(e.to_string()))?;
    let again = Recognizer::from_json(&saved);
    prop_assert_eq!(again.as_ref(), Ok(&recognizer));
    prop_assert!(recognizer.models().iter().map(|m| m.primitive).eq(Primitive::MOVING));
    let frames = demonstration();
    let poses: Vec<Pose> = frames.iter().map(|f| f.robot).collect();
    let scores = recognizer.log_likelihoods(&poses[..20]).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert!(scores.iter().all(|s| !s.is_nan()), "scores {scores:?}");
    let _ = recognizer.classify(&poses[30..50]);
    let _ = recognizer.log_likelihoods_many(&[&poses[..5], &poses[40..]]);
    let segments =
        segment(&frames, &recognizer, &SegmenterConfig::default()).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert!(segments.iter().all(|s| s.first_frame <= s.last_frame && s.last_frame < frames.len()));
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn truncated_recognizer_is_refused_or_valid(text in truncated(&discrete_file())) {
        recognizer_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_recognizer_is_refused_or_valid(text in flipped(&discrete_file())) {
        recognizer_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_discrete_recognizer_is_refused_or_valid(text in reshaped(&discrete_file())) {
        recognizer_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_gaussian_recognizer_is_refused_or_valid(text in reshaped(&gaussian_file())) {
        recognizer_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_recognizer_is_refused_or_valid(text in arbitrary("polymimic.PrimitiveRecognizer")) {
        recognizer_is_refused_or_valid(&text)?;
    }
}

#[test]
fn valid_files_are_read_back() {
    for text in [discrete_file(), gaussian_file()] {
        recognizer_is_refused_or_valid(&text).unwrap();
        assert!(Recognizer::from_json(&text).is_ok());
    }
}
