//! Learning on synthetic demonstrations whose segments follow the primitives exactly.

use polymimic_perceive::{Label, MotionStats, Pose, Primitive, Segment, TrackedFrame};

use crate::*;

/// Forward moves 50 mm (more than the 40 mm match tolerance, so one forward never matches
/// two segments), left turns 90°, without spread: predictions are exact.
fn exact_motion() -> MotionTable {
    let stat = |primitive, d: f64, r: f64| MotionStats {
        primitive,
        count: 100,
        distance_mean_mm: d,
        distance_sd_mm: 0.0,
        rotation_mean_deg: r,
        rotation_sd_deg: 0.0,
    };
    MotionTable::new(&[
        stat(Primitive::Forward, 50.0, 0.0),
        stat(Primitive::Backward, -50.0, 0.0),
        stat(Primitive::Left, 0.0, 90.0),
        stat(Primitive::Right, 0.0, -90.0),
        stat(Primitive::Stop, 0.0, 0.0),
    ])
    .unwrap()
}

/// A demonstration driving straight along +x toward a ball ahead for `count` forward
/// segments, each ending exactly 50 mm further.
fn straight(count: usize, name: &str, ending: Ending) -> SegmentedDemonstration {
    let frame =
        |x: f64| TrackedFrame { robot: Pose { x_mm: x, y_mm: 0.0, theta_rad: 0.0 }, ball_x_mm: 480.0, ball_y_mm: 0.0 };
    let segments = (0..count)
        .map(|i| Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: i * 30,
            last_frame: (i + 1) * 30,
            start: frame(-400.0 + 50.0 * i as f64),
            end: frame(-400.0 + 50.0 * (i + 1) as f64),
            scores: [0.0; 4],
        })
        .collect();
    SegmentedDemonstration { demonstrator: name.to_owned(), pitch: Pitch::LARGE, ending, segments }
}

fn letters(model: &ForwardModel) -> Vec<String> {
    model.behaviours.iter().map(Behaviour::letters).collect()
}

#[test]
fn repeated_pairs_form_a_behaviour_once_their_frequency_passes_the_threshold() {
    let config = LearningConfig::default();
    let mut model = ForwardModel::new("expert", 0.5, false, &config);
    let mut rng = rand::SeedableRng::seed_from_u64(1);
    // Each round adds 0.05 · (1 + LP) ≈ 0.075 to F→F (LP creeps up as the robot nears the
    // ball): three rounds stay below 0.3, the fourth passes it.
    model.process(&straight(4, "expert", Ending::Other), &exact_motion(), &config, &mut rng);
    assert!(!letters(&model).contains(&"FF".to_owned()), "{:?}", letters(&model));
    model.process(&straight(2, "expert", Ending::Other), &exact_motion(), &config, &mut rng);
    assert!(letters(&model).contains(&"FF".to_owned()), "{:?}", letters(&model));
    assert_eq!(model.metrics.created, 1);
    assert_eq!(model.metrics.rounds, model.metrics.rounds_matched);
}

#[test]
fn longer_behaviours_span_more_segments_and_become_permanent_with_use() {
    let config = LearningConfig::default();
    let mut model = ForwardModel::new("expert", 0.5, false, &config);
    let mut rng = rand::SeedableRng::seed_from_u64(2);
    for _ in 0..150 {
        model.process(&straight(12, "expert", Ending::Other), &exact_motion(), &config, &mut rng);
    }
    let names = letters(&model);
    assert!(names.iter().any(|n| n.len() >= 4 && n.chars().all(|c| c == 'F')), "{names:?}");
    assert!(model.metrics.made_permanent >= 1, "{:?}", model.metrics);
    for primitive in Primitive::ALL {
        assert!(model.index_of(&[primitive]).is_some(), "primitives are never deleted");
    }
}

#[test]
fn goals_raise_the_learning_preference_and_own_goals_lower_it() {
    let config = LearningConfig::default();
    let run = |ending| {
        let mut model = ForwardModel::new("x", 0.5, false, &config);
        let mut rng = rand::SeedableRng::seed_from_u64(3);
        for _ in 0..10 {
            model.process(&straight(4, "x", ending), &exact_motion(), &config, &mut rng);
        }
        model.lp
    };
    assert!(run(Ending::Goal) > run(Ending::Other));
    assert!(run(Ending::OwnGoal) < run(Ending::Other));
    // Robot driving at the ball raises it a little even without a goal.
    assert!(run(Ending::Other) > 0.5);
}

#[test]
fn the_imitator_keeps_only_permanent_behaviours_and_candidates_flow_to_it() {
    let config = LearningConfig::default();
    let demos: Vec<SegmentedDemonstration> = (0..30).map(|_| straight(12, "expert", Ending::Goal)).collect();
    let result = run_trial(&demos, &["expert".to_owned()], &exact_motion(), &config, PhaseOne::ByModel, 7).unwrap();
    let expert = &result.models[0];
    assert!(expert.metrics.candidates >= 1, "{:?}", expert.metrics);
    assert!(result.imitator.behaviours.iter().all(|b| b.permanent));
    assert_eq!(result.imitator.lp, 0.9, "the imitator's LP is fixed");
    assert!(expert.lp > 0.9, "{}", expert.lp);
}

#[test]
fn trials_are_reproducible_from_their_seed() {
    let config = LearningConfig::default();
    let demos: Vec<SegmentedDemonstration> =
        (0..10).map(|i| straight(6 + i % 3, if i % 2 == 0 { "a" } else { "b" }, Ending::Other)).collect();
    let ordering = ["a".to_owned(), "b".to_owned()];
    let run = |seed| run_trial(&demos, &ordering, &exact_motion(), &config, PhaseOne::Interleaved, seed).unwrap();
    assert_eq!(run(5), run(5));
}

#[test]
fn bad_input_is_named() {
    let config = LearningConfig::default();
    let demos = vec![straight(3, "a", Ending::Other)];
    let motion = exact_motion();
    let run = |demos: &[SegmentedDemonstration], ordering: &[&str], config: &LearningConfig| {
        let ordering: Vec<String> = ordering.iter().map(|s| (*s).to_owned()).collect();
        run_trial(demos, &ordering, &motion, config, PhaseOne::ByModel, 0)
    };
    assert_eq!(run(&demos, &["z"], &config).unwrap_err(), LearnError::UnknownDemonstrator("z".to_owned()));
    assert_eq!(run(&demos, &["a", "a"], &config).unwrap_err(), LearnError::DuplicateDemonstrator("a".to_owned()));
    assert_eq!(run(&[], &["a"], &config).unwrap_err(), LearnError::NoDemonstrations);
    assert_eq!(run(&demos, &[], &config).unwrap_err(), LearnError::EmptyOrdering);
    let bad = LearningConfig { creation_threshold: 1.5, ..LearningConfig::default() };
    assert!(matches!(run(&demos, &["a"], &bad).unwrap_err(), LearnError::Config { name: "creation_threshold", .. }));
}
