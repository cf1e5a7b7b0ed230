//! What each fuzz target does with its input, and the valid files its corpus starts from.
//!
//! Every target hands the text to one reader; whatever the reader accepts must then work:
//! round-trip through `to_json`, and score, encode, segment or drive as the type does. A panic
//! anywhere (an assertion here included), an abort, a hang or an allocation past libFuzzer's
//! limit is a crash.

use polymimic_field::{
    BodyKind, Command, Configuration, Episode, EpisodeSetup, FieldConfig, Primitive as FieldPrimitive,
};
use polymimic_hmm::{DiscreteHmm, GaussianHmm, GaussianHmmParams, HmmParams, Init, Topology};
use polymimic_learn::{ControlMode, ForwardModel, ImitatorPolicy, LearningConfig, LpCause, MotionTable, Pitch};
use polymimic_perceive::{
    Emissions, LabelledSequence, MotionStats, Pose, Primitive, Recognizer, RecognizerConfig, SegmenterConfig,
    TrackedFrame, segment, wrap_angle_rad,
};
use polymimic_vq::{Codebook, LbgParams};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The envelope read as an untyped payload and as a few typed ones.
pub fn envelope(text: &str) {
    if let Ok(value) = polymimic_persist::from_envelope::<serde_json::Value>(text, "polymimic.Test", 1) {
        let again = polymimic_persist::to_envelope("polymimic.Test", 1, &value).expect("a JSON value serialises");
        assert_eq!(polymimic_persist::from_envelope::<serde_json::Value>(&again, "polymimic.Test", 1), Ok(value));
    }
    let _ = polymimic_persist::from_envelope::<Vec<Vec<f64>>>(text, "polymimic.Test", 1);
    let _ = polymimic_persist::from_envelope::<(String, usize, Option<bool>)>(text, "polymimic.Test", 1);
}

pub fn discrete_hmm(text: &str) {
    let Ok(model) = DiscreteHmm::from_json(text) else { return };
    assert_eq!(DiscreteHmm::from_json(&model.to_json().expect("serialises")).as_ref(), Ok(&model));
    let Ok(probs) = model.probabilities() else { return };
    let (n, m) = (model.params().n_states, model.params().n_symbols);
    assert_eq!((probs.startprob.len(), probs.transmat.len()), (n, n * n));
    assert_eq!(Some(probs.emissionprob.len()), n.checked_mul(m));
    let tables = probs.startprob.iter().chain(&probs.transmat).chain(&probs.emissionprob);
    assert!(tables.clone().all(|p| p.is_finite() && (0.0..=1.0).contains(p)));
    let symbols: Vec<u32> = (0..8).map(|t| (t % m) as u32).collect();
    if let Ok(score) = model.score(&symbols) {
        assert!(score <= 1e-9, "log-likelihood {score} > 0");
    }
    let _ = model.decode(&symbols);
    let (sampled, states) = model.sample(2, 8, 7).expect("a fitted model samples");
    assert!(states.iter().flatten().all(|&s| s < n));
    let refs: Vec<&[u32]> = sampled.iter().map(Vec::as_slice).collect();
    let _ = model.score_many(&refs);
    let _ = model.with_emission_floor(0.0);
}

pub fn gaussian_hmm(text: &str) {
    let Ok(model) = GaussianHmm::from_json(text) else { return };
    assert_eq!(GaussianHmm::from_json(&model.to_json().expect("serialises")).as_ref(), Ok(&model));
    let Ok((start, transmat, means, variances)) = model.parts() else { return };
    let (n, d) = (model.params().n_states, model.params().dim);
    assert_eq!((start.len(), transmat.len()), (n, n * n));
    assert_eq!((Some(means.len()), Some(variances.len())), (n.checked_mul(d), n.checked_mul(d)));
    assert!(means.iter().all(|x| x.is_finite()) && variances.iter().all(|v| v.is_finite() && *v > 0.0));
    let frames: Vec<f64> = (0..4 * d).map(|i| (i as f64).sin()).collect();
    if let Ok(score) = model.score(&frames) {
        assert!(!score.is_nan(), "log-likelihood is NaN");
    }
}

pub fn codebook(text: &str) {
    let Ok(codebook) = Codebook::from_json(text) else { return };
    assert_eq!(Codebook::from_json(&codebook.to_json().expect("serialises")).as_ref(), Ok(&codebook));
    let dim = codebook.dim();
    assert!(dim >= 1 && !codebook.is_empty() && codebook.codewords().len() % dim == 0);
    let points: Vec<f64> = (0..5 * dim).map(|i| (i as f64).cos() * 10.0).collect();
    let symbols = codebook.encode(&points, dim).expect("points of the codebook's dimension encode");
    assert!(symbols.len() == 5 && symbols.iter().all(|&s| (s as usize) < codebook.len()));
    assert!(codebook.distortion(&points, dim).expect("distortion") >= 0.0);
}

pub fn recognizer(text: &str) {
    let Ok(recognizer) = Recognizer::from_json(text) else { return };
    let saved = recognizer.to_json().expect("serialises");
    assert_eq!(Recognizer::from_json(&saved).as_ref(), Ok(&recognizer));
    assert!(recognizer.models().iter().map(|m| m.primitive).eq(Primitive::MOVING));
    let frames = demonstration();
    let poses: Vec<Pose> = frames.iter().map(|f| f.robot).collect();
    let scores = recognizer.log_likelihoods(&poses[..20]).expect("finite poses score");
    assert!(scores.iter().all(|s| !s.is_nan()), "scores {scores:?}");
    let _ = recognizer.classify(&poses[30..50]);
    let segments = segment(&frames, &recognizer, &SegmenterConfig::default()).expect("a valid demonstration");
    assert!(segments.iter().all(|s| s.first_frame <= s.last_frame && s.last_frame < frames.len()));
}

pub fn field_config(text: &str) {
    let Ok(field) = FieldConfig::from_json(text) else { return };
    assert!(field.check().is_ok());
    assert_eq!(FieldConfig::from_json(&field.to_json()), Ok(field));
    let setup = EpisodeSetup::configuration(BodyKind::Lego, Configuration::One, &field);
    let mut episode = Episode::new(&setup, &field, 3).expect("a checked config runs");
    for primitive in [FieldPrimitive::Forward, FieldPrimitive::Left] {
        if !episode.is_finished() {
            episode.step(Command::Primitive(primitive)).expect("a step");
        }
    }
}

pub fn learning_config(text: &str) {
    let Ok(config) = LearningConfig::from_json(text) else { return };
    assert!(config.check().is_ok());
    assert_eq!(LearningConfig::from_json(&config.to_json()).as_ref(), Ok(&config));
    static MODEL: std::sync::OnceLock<ForwardModel> = std::sync::OnceLock::new();
    let model = MODEL.get_or_init(|| ForwardModel::from_json(&seed_forward_model()).expect("the seed model reads"));
    choose(model, &config);
}

pub fn forward_model(text: &str) {
    let Ok(mut model) = ForwardModel::from_json(text) else { return };
    assert_eq!(ForwardModel::from_json(&model.to_json()).as_ref(), Ok(&model));
    let n = model.behaviours.len();
    assert!(model.frequency.len() == n && model.frequency.iter().all(|row| row.len() == n));
    let config = LearningConfig::default();
    choose(&model, &config);
    let _ = model.match_rate();
    model.shape_lp(LpCause::BallNearerGoal, &config);
    model.nominate(&[Primitive::Left, Primitive::Stop], 2, &config);
    model.prune();
    assert_eq!(model.frequency.len(), model.behaviours.len());
}

/// The thesis's rule picks a behaviour the model has, from two states.
fn choose(model: &ForwardModel, config: &LearningConfig) {
    let motion = motion_table();
    let policy =
        ImitatorPolicy { model, motion: &motion, config, pitch: Pitch::LARGE, mode: ControlMode::Thesis, world: None };
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for state in [frame(-150.0, 0.0, 150.0), frame(300.0, 3.0, -200.0)] {
        if let Some(index) = policy.choose(&state, &mut rng) {
            assert!(index < model.behaviours.len());
        }
    }
}

fn frame(x_mm: f64, theta_rad: f64, ball_x_mm: f64) -> TrackedFrame {
    TrackedFrame { robot: Pose { x_mm, y_mm: 20.0, theta_rad }, ball_x_mm, ball_y_mm: -10.0 }
}

fn motion_of(primitive: Primitive) -> (f64, f64) {
    match primitive {
        Primitive::Forward => (42.0, -1.0),
        Primitive::Backward => (-48.0, 2.0),
        Primitive::Left => (4.0, 30.0),
        Primitive::Right => (3.0, -29.0),
        Primitive::Stop => (0.0, 0.0),
    }
}

fn motion_table() -> MotionTable {
    let stats = Primitive::WHEELED.map(|primitive| {
        let (distance_mean_mm, rotation_mean_deg) = motion_of(primitive);
        MotionStats {
            primitive,
            count: 10,
            distance_mean_mm,
            distance_sd_mm: 3.0,
            rotation_mean_deg,
            rotation_sd_deg: 2.0,
        }
    });
    MotionTable::new(&stats).expect("finite statistics for every primitive")
}

/// `frames` poses of `primitive` from `start`, its speed and turn scaled by `scale`.
fn run(primitive: Primitive, start: Pose, frames: usize, scale: f64) -> Vec<Pose> {
    let (speed, turn) = motion_of(primitive);
    let mut pose = start;
    let mut poses = Vec::with_capacity(frames);
    for _ in 0..frames {
        poses.push(pose);
        pose.x_mm += speed * scale / 30.0 * pose.theta_rad.cos();
        pose.y_mm += speed * scale / 30.0 * pose.theta_rad.sin();
        pose.theta_rad = wrap_angle_rad(pose.theta_rad + (turn * scale).to_radians() / 30.0);
    }
    poses
}

fn demonstration() -> Vec<TrackedFrame> {
    let mut poses = run(Primitive::Forward, Pose { x_mm: 0.0, y_mm: 0.0, theta_rad: 0.0 }, 30, 1.0);
    let last = poses[poses.len() - 1];
    poses.extend(run(Primitive::Left, last, 30, 1.0));
    let last = poses[poses.len() - 1];
    poses.extend(run(Primitive::Stop, last, 15, 1.0));
    poses.into_iter().map(|robot| TrackedFrame { robot, ball_x_mm: 200.0, ball_y_mm: 10.0 }).collect()
}

/// Valid files for each target's corpus, by target name (written by `examples/seed_corpus.rs`).
#[must_use]
pub fn seeds() -> Vec<(&'static str, &'static str, String)> {
    let mut left_right = HmmParams::new(3, 5);
    left_right.topology = Topology::LeftRight { links: 1 };
    let mut ergodic = HmmParams::new(2, 4);
    ergodic.topology = Topology::Ergodic;
    let discrete = |params: HmmParams, sequences: &[&[u32]]| {
        let mut model = DiscreteHmm::new(params.check().expect("valid params"));
        model.fit(sequences, Init::Segments).expect("fits");
        model.to_json().expect("serialises")
    };
    let mut gaussian = GaussianHmm::new(GaussianHmmParams::new(2, 3)).expect("valid params");
    let (a, b): (Vec<f64>, Vec<f64>) =
        ((0..30).map(|i| f64::from(i).sin()).collect(), (0..24).map(|i| f64::from(i).cos() * 2.0).collect());
    gaussian.fit(&[&a, &b]).expect("fits");
    let data: Vec<f64> = (0..240).map(|i| f64::from(i).sin() * 7.3).collect();
    let codebook = Codebook::fit(&data, 3, LbgParams::new(8)).expect("fits");
    let field = FieldConfig { substeps_per_frame: 4, time_limit_s: 30.0, ..FieldConfig::default() };
    vec![
        (
            "envelope",
            "seed-payload.json",
            polymimic_persist::to_envelope("polymimic.Test", 1, &(vec![[0.5, 1e-300]], "x", 3, Some(true)))
                .expect("serialises"),
        ),
        (
            "discrete_hmm",
            "seed-left-right.json",
            discrete(left_right, &[&[0, 0, 1, 2, 2, 3, 4], &[0, 1, 1, 2, 3, 3, 4, 4]]),
        ),
        ("discrete_hmm", "seed-ergodic.json", discrete(ergodic, &[&[0, 1, 2, 3, 0, 1], &[3, 2, 1, 0]])),
        (
            "discrete_hmm",
            "seed-unfitted.json",
            DiscreteHmm::new(HmmParams::new(2, 4).check().expect("valid")).to_json().expect("serialises"),
        ),
        ("gaussian_hmm", "seed-fitted.json", gaussian.to_json().expect("serialises")),
        ("codebook", "seed-8x3.json", codebook.to_json().expect("serialises")),
        ("recognizer", "seed-discrete.json", seed_recognizer(Emissions::Discrete)),
        ("recognizer", "seed-gaussian.json", seed_recognizer(Emissions::Gaussian)),
        ("field_config", "seed-default.json", FieldConfig::default().to_json()),
        ("field_config", "seed-changed.json", field.to_json()),
        ("learning_config", "seed-default.json", LearningConfig::default().to_json()),
        ("forward_model", "seed-nominated.json", seed_forward_model()),
    ]
}

fn seed_recognizer(emissions: Emissions) -> String {
    let mut sequences = Vec::new();
    for primitive in Primitive::WHEELED {
        for i in 0..8 {
            let k = f64::from(i);
            let start = Pose { x_mm: 40.0 * k - 150.0, y_mm: 25.0 * k - 100.0, theta_rad: 0.7 * k - 2.8 };
            sequences.push(LabelledSequence { primitive, poses: run(primitive, start, 30, 0.9 + 0.03 * k) });
        }
    }
    let config = RecognizerConfig { codebook_size: 8, n_states: 2, max_iter: 10, emissions, ..Default::default() };
    Recognizer::train(&sequences, config).expect("trains").to_json().expect("serialises")
}

fn seed_forward_model() -> String {
    let config = LearningConfig::default();
    let mut model = ForwardModel::new("expert", 0.5, false, &config);
    model.nominate(&[Primitive::Forward, Primitive::Forward, Primitive::Left], 0, &config);
    model.nominate(&[Primitive::Backward, Primitive::Right], 1, &config);
    model.shape_lp(LpCause::Goal, &config);
    for (i, behaviour) in model.behaviours.iter_mut().enumerate() {
        for k in 0..3 {
            let x = f64::from(k) * 30.0 - 100.0 + i as f64;
            behaviour.record_span(&frame(x, 0.1, 150.0), &frame(x + 40.0, 0.2, 190.0 + x), &Pitch::LARGE, &config);
        }
    }
    model.to_json()
}
