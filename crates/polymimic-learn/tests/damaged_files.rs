//! A damaged learning config or saved forward model is refused with an `Err` or read as one the
//! imitator can drive a robot with; reading never panics. Each property starts from a file
//! written by `to_json`: the config with every number off its default, and a model holding
//! nominated behaviours with statistics.

use polymimic_damage::{arbitrary, config, flipped, reshaped, truncated};
use polymimic_field::{BodyKind, Configuration, FieldConfig};
use polymimic_learn::{
    ControlMode, ForwardModel, ImitatorPolicy, LearningConfig, LpBounds, LpCause, MotionTable, Pitch,
};
use polymimic_types::{MotionStats, Pose, Primitive, TrackedFrame};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn learning_config() -> LearningConfig {
    LearningConfig {
        creation_threshold: 0.25,
        decay_step: 0.01,
        ball_min_samples: 2,
        ball_max_angle_sd_deg: 45.0,
        lp_bounds: LpBounds::Clamp,
        ..LearningConfig::default()
    }
}

fn config_file() -> String {
    learning_config().to_json()
}

fn frame(x_mm: f64, theta_rad: f64, ball_x_mm: f64) -> TrackedFrame {
    TrackedFrame { robot: Pose::new(x_mm, 20.0, theta_rad), ball_x_mm, ball_y_mm: -10.0 }
}

fn model_file() -> String {
    let config = learning_config();
    let mut model = ForwardModel::new("expert", 0.5, false, &config);
    model.nominate(&[Primitive::Forward, Primitive::Forward, Primitive::Left], 0, &config);
    model.nominate(&[Primitive::Backward, Primitive::Right], 1, &config);
    model.shape_lp(LpCause::Goal, &config);
    model.shape_lp(LpCause::RobotFartherFromBall, &config);
    for (i, behaviour) in model.behaviours.iter_mut().enumerate() {
        for k in 0..3 {
            let x = f64::from(k) * 30.0 - 100.0 + i as f64;
            behaviour.record_span(&frame(x, 0.1, 150.0), &frame(x + 40.0, 0.2, 190.0 + x), &Pitch::LARGE, &config);
        }
    }
    model.to_json()
}

fn motion_table() -> MotionTable {
    let stats = Primitive::WHEELED.map(|primitive| {
        let (distance, rotation) = match primitive {
            Primitive::Forward => (42.0, -1.0),
            Primitive::Backward => (-48.0, 2.0),
            Primitive::Left => (4.0, 30.0),
            Primitive::Right => (3.0, -29.0),
            Primitive::Stop => (0.0, 0.0),
            other => panic!("no synthetic motion for {other:?}"),
        };
        MotionStats {
            primitive,
            count: 10,
            distance_mean_mm: distance,
            distance_sd_mm: 3.0,
            rotation_mean_deg: rotation,
            rotation_sd_deg: 2.0,
            sideways: None,
        }
    });
    MotionTable::new(&stats).unwrap()
}

/// One second on the field, so that an attempt is cheap.
fn short_field() -> FieldConfig {
    FieldConfig { time_limit_s: 1.0, ..FieldConfig::default() }
}

/// `model` with `config` drives the robot for an attempt by either rule without panicking.
fn drive(model: &ForwardModel, config: &LearningConfig) -> Result<(), TestCaseError> {
    let motion = motion_table();
    for mode in [ControlMode::Thesis, ControlMode::Improved] {
        let policy = ImitatorPolicy { model, motion: &motion, config, body: BodyKind::Lego, mode, world: None };
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        if let Some(index) = policy.choose(&frame(-150.0, 0.0, 150.0), &mut rng) {
            prop_assert!(index < model.behaviours.len());
        }
        let attempt =
            policy.attempt(Configuration::One, &short_field(), 9).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(!attempt.frames.is_empty());
    }
    Ok(())
}

/// A config read from `text` must pass its own check, round-trip, and drive the robot.
fn config_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(config) = LearningConfig::from_json(text) else { return Ok(()) };
    prop_assert!(config.check().is_ok());
    let again = LearningConfig::from_json(&config.to_json());
    prop_assert_eq!(again.as_ref(), Ok(&config));
    let model = ForwardModel::from_json(&model_file()).map_err(|e| TestCaseError::fail(e.to_string()))?;
    drive(&model, &config)
}

/// A model read from `text` must round-trip, hold a square frequency matrix, take nominations
/// and LP changes, and drive the robot.
fn model_is_refused_or_valid(text: &str) -> Result<(), TestCaseError> {
    let Ok(mut model) = ForwardModel::from_json(text) else { return Ok(()) };
    let again = ForwardModel::from_json(&model.to_json());
    prop_assert_eq!(again.as_ref(), Ok(&model));
    let n = model.behaviours.len();
    prop_assert!(model.frequency.len() == n && model.frequency.iter().all(|row| row.len() == n));
    let config = learning_config();
    drive(&model, &config)?;
    let _ = model.match_rate();
    model.shape_lp(LpCause::BallNearerGoal, &config);
    model.nominate(&[Primitive::Left, Primitive::Stop], 2, &config);
    model.prune();
    prop_assert!(model.frequency.len() == model.behaviours.len());
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn truncated_learning_config_is_refused_or_valid(text in truncated(&config_file())) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_learning_config_is_refused_or_valid(text in flipped(&config_file())) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_learning_config_is_refused_or_valid(text in reshaped(&config_file())) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_learning_config_is_refused_or_valid(text in arbitrary("polymimic.LearningConfig")) {
        config_is_refused_or_valid(&text)?;
    }

    #[test]
    fn truncated_forward_model_is_refused_or_valid(text in truncated(&model_file())) {
        model_is_refused_or_valid(&text)?;
    }

    #[test]
    fn flipped_forward_model_is_refused_or_valid(text in flipped(&model_file())) {
        model_is_refused_or_valid(&text)?;
    }

    #[test]
    fn reshaped_forward_model_is_refused_or_valid(text in reshaped(&model_file())) {
        model_is_refused_or_valid(&text)?;
    }

    #[test]
    fn arbitrary_text_as_forward_model_is_refused_or_valid(text in arbitrary("polymimic.ForwardModel")) {
        model_is_refused_or_valid(&text)?;
    }
}

#[test]
fn valid_files_are_read_back() {
    config_is_refused_or_valid(&config_file()).unwrap();
    assert!(LearningConfig::from_json(&config_file()).is_ok());
    model_is_refused_or_valid(&model_file()).unwrap();
    assert!(ForwardModel::from_json(&model_file()).is_ok());
}
