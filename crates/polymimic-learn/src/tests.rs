//! Learning on synthetic demonstrations whose segments follow the primitives exactly.

use polymimic_perceive::{Label, Segment};
use polymimic_types::{Pose, Primitive, TrackedFrame};

use crate::*;

/// Forward moves 50 mm (more than the 40 mm match tolerance, so one forward never matches
/// two segments), left turns 90°, without spread: predictions are exact.
fn exact_motion() -> MotionTable {
    MotionTable::exact(50.0, 90.0)
}

/// A demonstration driving straight along +x toward a ball ahead for `count` forward
/// segments, each ending exactly 50 mm further.
fn straight(count: usize, name: &str, ending: Ending) -> SegmentedDemonstration {
    let frame = |x: f64| TrackedFrame { robot: Pose::new(x, 0.0, 0.0), ball_x_mm: 480.0, ball_y_mm: 0.0 };
    let segments = (0..count)
        .map(|i| Segment {
            label: Label::Primitive(Primitive::Forward),
            first_frame: i * 30,
            last_frame: (i + 1) * 30,
            start: frame(-400.0 + 50.0 * i as f64),
            end: frame(-400.0 + 50.0 * (i + 1) as f64),
            scores: [0.0; 7],
        })
        .collect();
    SegmentedDemonstration { demonstrator: name.to_owned(), pitch: Pitch::LARGE, reach_mm: None, ending, segments }
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
    for primitive in Primitive::WHEELED {
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
    assert!(expert.lp > 0.8, "a demonstrator scoring every time is preferred: {}", expert.lp);
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
    assert_eq!(
        run(&demos, &["z"], &config).unwrap_err(),
        LearnError::Params(LearnParamsError::UnknownDemonstrator("z".to_owned()))
    );
    assert_eq!(
        run(&demos, &["a", "a"], &config).unwrap_err(),
        LearnError::Params(LearnParamsError::DuplicateDemonstrator("a".to_owned()))
    );
    assert_eq!(run(&[], &["a"], &config).unwrap_err(), LearnError::Params(LearnParamsError::NoDemonstrations));
    let two = vec![straight(3, "a", Ending::Other), straight(3, "b", Ending::Goal)];
    assert_eq!(
        run(&two, &["a"], &config).unwrap_err(),
        LearnError::Params(LearnParamsError::OutsideOrdering { index: 1, demonstrator: "b".to_owned() })
    );
    assert_eq!(run(&demos, &[], &config).unwrap_err(), LearnError::Params(LearnParamsError::EmptyOrdering));
    let bad = LearningConfig { creation_threshold: 1.5, ..LearningConfig::default() };
    assert!(matches!(
        run(&demos, &["a"], &bad).unwrap_err(),
        LearnError::Params(LearnParamsError::Config { name: "creation_threshold", .. })
    ));
}

#[test]
fn soft_bounds_take_the_thesis_step_at_the_midpoint_and_none_at_a_bound() {
    let config = LearningConfig::default();
    let mut model = ForwardModel::new("x", 0.5, false, &config);
    model.shape_lp(LpCause::Goal, &config);
    assert!((model.lp - 0.51).abs() < 1e-15, "{}", model.lp);
    // From 0.51 a fall of 0.005 is scaled by 2 · 0.51.
    model.shape_lp(LpCause::BallFartherFromGoal, &config);
    assert!((model.lp - (0.51 - 0.005 * 1.02)).abs() < 1e-15, "{}", model.lp);
    let mut top = ForwardModel::new("x", 1.0, false, &config);
    top.shape_lp(LpCause::Goal, &config);
    assert!((top.lp - 1.0).abs() < f64::EPSILON);
    assert_eq!(top.metrics.lp_causes.goal, 1);
    let clamp = LearningConfig { lp_bounds: LpBounds::Clamp, ..LearningConfig::default() };
    let mut near_top = ForwardModel::new("x", 0.995, false, &clamp);
    near_top.shape_lp(LpCause::Goal, &clamp);
    assert!((near_top.lp - 1.0).abs() < f64::EPSILON, "clamped");
}

#[test]
fn soft_bounds_settle_where_gains_balance_losses() {
    // Three goals for every own goal, each as heavy: gains 3a·2(1 − LP) = losses a·2LP at LP = 3/4.
    let config = LearningConfig { lp_own_goal_weight: 1.0, ..LearningConfig::default() };
    let mut model = ForwardModel::new("x", 0.5, false, &config);
    for _ in 0..5000 {
        for cause in [LpCause::Goal, LpCause::Goal, LpCause::Goal, LpCause::OwnGoal] {
            model.shape_lp(cause, &config);
        }
    }
    assert!((model.lp - 0.75).abs() < 0.01, "{}", model.lp);
}

#[test]
fn an_own_goal_weighs_lp_own_goal_weight_goals() {
    let heavy = LearningConfig::default();
    assert_eq!(heavy.lp_own_goal_weight, 3.0, "the default");
    let mirror = LearningConfig { lp_own_goal_weight: 1.0, ..LearningConfig::default() };
    assert_eq!(LpCause::OwnGoal.amount(&mirror), -0.01, "the thesis's mirror of a goal");
    assert!((LpCause::OwnGoal.amount(&heavy) + 0.03).abs() < 1e-15);
    assert_eq!(LpCause::Goal.amount(&heavy), 0.01, "a goal is unchanged");
    assert_eq!(LpCause::BallFartherFromGoal.amount(&heavy), -0.005, "so is every other fall");
    // From 0.5, under soft bounds, the fall is 0.03 · 2 · 0.5.
    let mut model = ForwardModel::new("x", 0.5, false, &heavy);
    model.shape_lp(LpCause::OwnGoal, &heavy);
    assert!((model.lp - 0.47).abs() < 1e-15, "{}", model.lp);
    assert_eq!(model.metrics.lp_causes.own_goal, 1);
}

#[test]
fn a_heavier_own_goal_settles_one_who_concedes_as_often_as_it_scores_below_the_start() {
    // A goal then an own goal, a = 0.01, k = 3: LP' = (LP(1 − 2a) + 2a)(1 − 2ka), whose fixed
    // point is (1 − 2ka) / (1 + k − 2ka) = 0.94 / 3.94 (≈ 1 / (1 + k) for small steps).
    let heavy = LearningConfig { lp_own_goal_weight: 3.0, ..LearningConfig::default() };
    let settle = |config: &LearningConfig| {
        let mut model = ForwardModel::new("x", 0.5, false, config);
        for _ in 0..2000 {
            model.shape_lp(LpCause::Goal, config);
            model.shape_lp(LpCause::OwnGoal, config);
        }
        model.lp
    };
    assert!((settle(&heavy) - 0.94 / 3.94).abs() < 1e-12, "{}", settle(&heavy));
    // The thesis's mirror: (1 − 2a) / (2 − 2a) = 0.98 / 1.98, just below the start.
    let mirror = LearningConfig { lp_own_goal_weight: 1.0, ..LearningConfig::default() };
    assert!((settle(&mirror) - 0.98 / 1.98).abs() < 1e-12);
}

#[test]
fn only_the_models_own_demonstrator_shapes_its_lp_by_the_task_criteria() {
    let config = LearningConfig::default();
    let process = |config: &LearningConfig, who: &str| {
        let mut model = ForwardModel::new("a", 0.5, false, config);
        let mut rng = rand::SeedableRng::seed_from_u64(4);
        model.process(&straight(4, who, Ending::Goal), &exact_motion(), config, &mut rng);
        model.metrics.lp_causes
    };
    // Three rounds: two bring the robot nearer the ball, the last ends in the goal.
    let own = process(&config, "a");
    assert_eq!((own.goal, own.robot_nearer_ball), (1, 2), "{own:?}");
    assert_eq!(process(&config, "b"), LpCauseCounts::default());
    let every = LearningConfig { lp_scope: LpScope::Every, ..LearningConfig::default() };
    assert_eq!(process(&every, "b"), own);
}

#[test]
fn the_foremost_criterion_is_the_ball_when_it_moved() {
    let frame = |robot_x: f64, ball_x: f64| TrackedFrame {
        robot: Pose::new(robot_x, 0.0, 0.0),
        ball_x_mm: ball_x,
        ball_y_mm: 0.0,
    };
    let config = LearningConfig::default();
    // The robot backs away (20 mm) while the ball rolls 50 mm toward the target goal (+x).
    let (before, after) = (frame(0.0, 100.0), frame(-20.0, 150.0));
    let foremost = crate::shaping::approach_causes(&before, &after, &Pitch::LARGE, &config);
    assert_eq!(foremost, [Some(LpCause::BallNearerGoal), None]);
    let both = LearningConfig { lp_criteria: LpCriteria::Both, ..LearningConfig::default() };
    let added = crate::shaping::approach_causes(&before, &after, &Pitch::LARGE, &both);
    assert_eq!(added, [Some(LpCause::BallNearerGoal), Some(LpCause::RobotFartherFromBall)]);
    // Within the dead bands nothing counts: the ball 5 mm, the robot 5 mm.
    assert_eq!(crate::shaping::approach_causes(&before, &frame(5.0, 105.0), &Pitch::LARGE, &config), [None, None]);
}

#[test]
fn per_demonstration_weighting_shares_one_step_among_a_demonstrations_spans() {
    // Five segments, four spans (one segment each, nothing longer yet), every one bringing the
    // robot nearer the ball: each earns a quarter of the 0.002 step under the default.
    let demo = straight(5, "a", Ending::Other);
    let run = |config: &LearningConfig| {
        let mut model = ForwardModel::new("a", 0.5, false, config);
        let mut rng = rand::SeedableRng::seed_from_u64(5);
        model.process(&demo, &exact_motion(), config, &mut rng);
        assert_eq!(model.metrics.lp_causes.robot_nearer_ball, 4);
        model.lp
    };
    let shared = run(&LearningConfig::default());
    let mut expected = 0.5;
    for _ in 0..4 {
        expected += 0.002 / 4.0 * 2.0 * (1.0 - expected);
    }
    assert!((shared - expected).abs() < 1e-12, "{shared} vs {expected}");
    let per_span = LearningConfig { lp_approach_weight: LpApproachWeight::PerSpan, ..LearningConfig::default() };
    let mut whole = 0.5;
    for _ in 0..4 {
        whole += 0.002 * 2.0 * (1.0 - whole);
    }
    assert!((run(&per_span) - whole).abs() < 1e-12);
}

#[test]
fn a_saved_model_with_an_lp_outside_zero_to_one_is_damaged() {
    let model = ForwardModel::new("a", 0.5, false, &LearningConfig::default());
    let text = model.to_json();
    assert!(ForwardModel::from_json(&text).is_ok());
    let damaged = text.replace("\"lp\":0.5", "\"lp\":1.5");
    assert_ne!(damaged, text);
    assert!(
        matches!(ForwardModel::from_json(&damaged), Err(LearnError::Corrupt(m)) if m.contains("lp must be in [0, 1]"))
    );
}

/// A demonstration backing away from a ball ahead along −x for `count` backward segments, each
/// ending exactly 50 mm further back.
fn backing(count: usize, name: &str, ending: Ending) -> SegmentedDemonstration {
    let mut demo = straight(count, name, ending);
    for (i, segment) in demo.segments.iter_mut().enumerate() {
        segment.label = Label::Primitive(Primitive::Backward);
        segment.start.robot = Pose::new(100.0 - 50.0 * i as f64, 0.0, 0.0);
        segment.end.robot = Pose::new(100.0 - 50.0 * (i + 1) as f64, 0.0, 0.0);
    }
    demo
}

/// A scorer driving at the ball and a demonstrator backing away from it into its own goal,
/// thirty demonstrations each, under clamped LPs (so the second's falls to 0).
fn scorer_and_loser(config: &LearningConfig) -> TrialResult {
    let config = LearningConfig { lp_bounds: LpBounds::Clamp, ..config.clone() };
    let demos: Vec<SegmentedDemonstration> =
        (0..30).flat_map(|_| [straight(12, "scorer", Ending::Goal), backing(12, "loser", Ending::OwnGoal)]).collect();
    let ordering = ["scorer".to_owned(), "loser".to_owned()];
    run_trial(&demos, &ordering, &exact_motion(), &config, PhaseOne::Interleaved, 11).unwrap()
}

#[test]
fn held_lps_stay_where_they_started_throughout_the_trial() {
    let held = scorer_and_loser(&LearningConfig { hold_lp: true, ..LearningConfig::default() });
    for model in &held.models {
        assert_eq!(model.lp_history, vec![0.5], "{}", model.name);
        assert_eq!(model.lp, 0.5);
        assert_eq!(model.metrics.lp_causes, LpCauseCounts::default());
    }
    let moving = scorer_and_loser(&LearningConfig::default());
    assert!(moving.models.iter().all(|m| m.lp_history.len() > 1 && m.lp != 0.5));
    let other_start = LearningConfig { hold_lp: true, initial_lp: 0.3, ..LearningConfig::default() };
    assert!(scorer_and_loser(&other_start).models.iter().all(|m| m.lp_history == [0.3]));
}

#[test]
fn weighting_by_lp_starves_what_only_the_least_preferred_demonstrator_shows() {
    let letters_of = |result: &TrialResult| letters(&result.imitator);
    let even = scorer_and_loser(&LearningConfig::default());
    let by_lp =
        scorer_and_loser(&LearningConfig { imitator_weighting: ImitatorWeighting::Lp, ..LearningConfig::default() });
    // The weighting acts on the imitator only: the demonstrators' LPs end where they did.
    for result in [&even, &by_lp] {
        assert_eq!(result.models[0].lp, 1.0, "the scorer");
        assert_eq!(result.models[1].lp, 0.0, "the loser");
    }
    // Backing up is shown only by the loser: counted evenly, the imitator makes it permanent;
    // weighted by the loser's LP it gains nothing from it, decays and is pruned.
    let backing_up = |names: &[String]| names.iter().any(|n| n.len() > 1 && n.chars().all(|c| c == 'B'));
    assert!(backing_up(&letters_of(&even)), "{:?}", letters_of(&even));
    assert!(!backing_up(&letters_of(&by_lp)), "{:?}", letters_of(&by_lp));
    let permanency = |result: &TrialResult| {
        result.imitator.index_of(&[Primitive::Backward; 2]).map_or(0.0, |i| result.imitator.behaviours[i].permanency)
    };
    assert!(permanency(&by_lp) < permanency(&even));
}

#[test]
fn weighting_by_equal_lps_is_bit_for_bit_the_even_trial() {
    let held = LearningConfig { hold_lp: true, ..LearningConfig::default() };
    let weighted = LearningConfig { imitator_weighting: ImitatorWeighting::Lp, ..held.clone() };
    assert_eq!(scorer_and_loser(&weighted), scorer_and_loser(&held));
    let zero = LearningConfig { initial_lp: 0.0, ..weighted.clone() };
    assert_eq!(
        scorer_and_loser(&zero),
        scorer_and_loser(&LearningConfig { initial_lp: 0.0, ..held }),
        "all at 0: all weigh 1"
    );
    let gain = LearningConfig { imitator_weighting: ImitatorWeighting::LpGain, ..weighted };
    assert_eq!(scorer_and_loser(&gain), scorer_and_loser(&held), "no LP rose: all weigh 1");
}
