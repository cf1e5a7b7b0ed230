//! The experiments of thesis §4.4 from Rust, for studying learning-preference shaping and
//! control quickly: `cargo run --release -p polymimic-learn --example experiment -- [trials]
//! [attempts_per_configuration] [key=value …]`, where each `key=value` overrides a
//! [`LearningConfig`] field (for instance `lp_robot_to_ball=0`).
//!
//! Prints, per experiment, the mean (sd) final LP and match rate of each model, the trials
//! whose final LPs follow the true skill order, the candidates made permanent, and the goals
//! and own goals of the trained imitators.

use polymimic_field::{Configuration, Demonstrator, FieldConfig, Frame, Outcome, record_all, self_observation};
use polymimic_learn::{
    ControlMode, Ending, ImitatorPolicy, LearningConfig, MotionTable, PhaseOne, Pitch, Running, SegmentedDemonstration,
    TrialResult, WorldModel, run_trial,
};
use polymimic_perceive::{
    LabelledSequence, Pose, Primitive, Recognizer, RecognizerConfig, SegmenterConfig, TrackedFrame, segment,
};

fn pose(f: &Frame) -> Pose {
    Pose { x_mm: f.robot_x_mm, y_mm: f.robot_y_mm, theta_rad: f.robot_theta_rad }
}

fn ending(outcome: Outcome) -> Ending {
    match outcome {
        Outcome::Goal => Ending::Goal,
        Outcome::OwnGoal => Ending::OwnGoal,
        _ => Ending::Other,
    }
}

fn segmented(
    who: &str,
    pitch: Pitch,
    outcome: Outcome,
    frames: &[Frame],
    recognizer: &Recognizer,
) -> SegmentedDemonstration {
    let tracked: Vec<TrackedFrame> = frames
        .iter()
        .map(|f| TrackedFrame { robot: pose(f), ball_x_mm: f.ball_x_mm, ball_y_mm: f.ball_y_mm })
        .collect();
    SegmentedDemonstration {
        demonstrator: who.to_owned(),
        pitch,
        ending: ending(outcome),
        segments: segment(&tracked, recognizer, &SegmenterConfig::default()).expect("segments"),
    }
}

fn tracked_throughout(frames: &[Frame]) -> bool {
    frames.iter().all(|f| {
        [f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad, f.ball_x_mm, f.ball_y_mm].iter().all(|v| v.is_finite())
    })
}

struct Setup {
    recognizer: Recognizer,
    motion: MotionTable,
    field: FieldConfig,
    config: LearningConfig,
}

impl Setup {
    fn policy<'a>(&'a self, trial: &'a TrialResult, world: &'a WorldModel, mode: ControlMode) -> ImitatorPolicy<'a> {
        ImitatorPolicy {
            model: &trial.imitator,
            motion: &self.motion,
            config: &self.config,
            pitch: Pitch::LARGE,
            mode,
            world: Some(world),
        }
    }

    /// Goals and own goals of a trial's imitator over `n` attempts per configuration.
    fn score(
        &self,
        trial: &TrialResult,
        world: &WorldModel,
        n: usize,
        seed: u64,
        mode: ControlMode,
    ) -> (usize, usize, Vec<polymimic_learn::Attempt>) {
        let attempts = self.policy(trial, world, mode).evaluate(n, &self.field, seed).expect("runs");
        let count = |o: Outcome| attempts.iter().filter(|a| a.outcome == o).count();
        (count(Outcome::Goal), count(Outcome::OwnGoal), attempts)
    }
}

fn summarise(
    name: &str,
    setup: &Setup,
    trials: &[TrialResult],
    world: &WorldModel,
    truth: Option<&[&str]>,
    attempts: usize,
) {
    println!("\n== {name} ({} trials)", trials.len());
    let names: Vec<String> = trials[0].models.iter().map(|m| m.name.clone()).collect();
    for (k, model_name) in names.iter().enumerate() {
        let (mut lp, mut rate, mut permanent_candidates) = (Running::default(), Running::default(), Running::default());
        for t in trials {
            lp.push(t.models[k].lp);
            rate.push(t.models[k].match_rate());
            permanent_candidates.push(t.models[k].metrics.candidates_permanent as f64);
        }
        println!(
            "{model_name:9} final LP {:.3} ({:.3})  match {:.3} ({:.3})  candidates made permanent {:.2} ({:.2})",
            lp.mean,
            lp.sd(),
            rate.mean,
            rate.sd(),
            permanent_candidates.mean,
            permanent_candidates.sd()
        );
    }
    println!(
        "LP changes per trial, by cause (goal own  ball+ ball-  robot+ robot-  ball-predicted  candidate+ candidate-):"
    );
    for (k, model_name) in names.iter().enumerate() {
        let mean = |f: fn(&polymimic_learn::LpCauseCounts) -> usize| {
            trials.iter().map(|t| f(&t.models[k].metrics.lp_causes) as f64).sum::<f64>() / trials.len() as f64
        };
        println!(
            "  {model_name:9} {:5.1} {:4.1} {:6.1} {:5.1} {:6.1} {:6.1} {:8.1} {:6.1} {:5.1}",
            mean(|c| c.goal),
            mean(|c| c.own_goal),
            mean(|c| c.ball_nearer_goal),
            mean(|c| c.ball_farther_from_goal),
            mean(|c| c.robot_nearer_ball),
            mean(|c| c.robot_farther_from_ball),
            mean(|c| c.ball_predicted),
            mean(|c| c.candidate_permanent),
            mean(|c| c.candidate_deleted)
        );
    }
    let mut imitator_rate = Running::default();
    for t in trials {
        imitator_rate.push(t.imitator.match_rate());
    }
    println!("imitator  match {:.3} ({:.3})", imitator_rate.mean, imitator_rate.sd());
    if let Some(order) = truth {
        let lp_of = |t: &TrialResult, who: &str| t.models.iter().find(|m| m.name == who).map_or(f64::NAN, |m| m.lp);
        let hits = trials.iter().filter(|t| order.windows(2).all(|w| lp_of(t, w[0]) < lp_of(t, w[1]))).count();
        println!("final LP in the true order ({}): {hits} of {}", order.join(" < "), trials.len());
    }
    for mode in [ControlMode::Thesis, ControlMode::Improved] {
        if attempts == 0 {
            break;
        }
        let (mut goals, mut own) = (Running::default(), Running::default());
        let mut outcomes = std::collections::BTreeMap::new();
        for (i, t) in trials.iter().enumerate() {
            let (g, o, runs) = setup.score(t, world, attempts, 1000 + i as u64, mode);
            for a in &runs {
                *outcomes.entry(format!("{:?}/{}", a.outcome, a.configuration.number())).or_insert(0) += 1;
            }
            goals.push(g as f64);
            own.push(o as f64);
        }
        println!(
            "imitators ({mode:?} control): goals {:.1} ({:.1}), own goals {:.1} ({:.1}) in {} attempts",
            goals.mean,
            goals.sd(),
            own.mean,
            own.sd(),
            2 * attempts
        );
        println!("  outcomes: {outcomes:?}");
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let trials: u64 = args.get(1).map_or(Ok(20), |s| s.parse())?;
    let attempts: usize = args.get(2).map_or(Ok(0), |s| s.parse())?;
    let mut config = serde_json::to_value(LearningConfig::default())?;
    for pair in args.iter().skip(3) {
        let (key, value) = pair.split_once('=').ok_or("overrides are key=value")?;
        config[key] = serde_json::from_str(value)?;
    }
    let config = LearningConfig::from_json(&config.to_string())?;
    let field = FieldConfig::default();
    let training: Vec<LabelledSequence> = self_observation(1000, 1, &field)?
        .iter()
        .map(|s| LabelledSequence {
            primitive: Primitive::from_name(s.primitive.name()).expect("same names"),
            poses: s.frames.iter().map(pose).collect(),
        })
        .collect();
    let recognizer = Recognizer::train(&training, RecognizerConfig::default())?;
    let motion = MotionTable::new(recognizer.motion_stats())?;
    let setup = Setup { recognizer, motion, field, config };
    let everyone = [Demonstrator::Expert, Demonstrator::Tiny, Demonstrator::Humanoid, Demonstrator::Poor];
    let mut demos: Vec<SegmentedDemonstration> = record_all(&everyone, 25, 1, &setup.field)?
        .iter()
        .map(|d| {
            let pitch = if d.demonstrator == Demonstrator::Tiny { Pitch::SMALL } else { Pitch::LARGE };
            segmented(d.demonstrator.name(), pitch, d.outcome, &d.frames, &setup.recognizer)
        })
        .collect();
    let goals_of = |who: &str| demos.iter().filter(|d| d.demonstrator == who && d.ending == Ending::Goal).count();
    let (poor_goals, expert_goals) = (goals_of("poor"), goals_of("expert"));

    let ordering = |names: &[&str]| names.iter().map(|s| (*s).to_owned()).collect::<Vec<String>>();
    let rcb = ordering(&["expert", "tiny", "humanoid"]);
    let run = |order: &[String], phase: PhaseOne, demos: &[SegmentedDemonstration]| -> Vec<TrialResult> {
        (0..trials)
            .map(|seed| run_trial(demos, order, &setup.motion, &setup.config, phase, seed).expect("runs"))
            .collect()
    };
    let heterogeneous = run(&rcb, PhaseOne::ByModel, &demos);
    let watched: Vec<SegmentedDemonstration> = demos.iter().filter(|d| d.demonstrator != "poor").cloned().collect();
    let heterogeneous_world = WorldModel::learn(&watched, &Pitch::LARGE, &setup.config);
    summarise("heterogeneous RCB", &setup, &heterogeneous, &heterogeneous_world, None, attempts);
    let bcr: Vec<String> = rcb.iter().rev().cloned().collect();
    let reversed = run(&bcr, PhaseOne::ByModel, &demos);
    summarise("heterogeneous BCR", &setup, &reversed, &heterogeneous_world, None, attempts);

    // The Average demonstrator: the first RCB imitator scoring between the Poor and the Expert.
    let average = heterogeneous
        .iter()
        .enumerate()
        .find_map(|(i, t)| {
            let (goals, _, attempts) = setup.score(t, &heterogeneous_world, 30, i as u64, ControlMode::Thesis);
            let valid = |c: Configuration| -> Vec<&polymimic_learn::Attempt> {
                attempts.iter().filter(|a| a.configuration == c && tracked_throughout(&a.frames)).take(25).collect()
            };
            let chosen: Vec<&polymimic_learn::Attempt> = Configuration::ALL.iter().flat_map(|&c| valid(c)).collect();
            (poor_goals < goals && goals < expert_goals && chosen.len() == 50).then(|| {
                println!("average: imitator of RCB trial {i}, {goals} goals in 60 attempts");
                chosen
                    .into_iter()
                    .map(|a| segmented("average", Pitch::LARGE, a.outcome, &a.frames, &setup.recognizer))
                    .collect::<Vec<_>>()
            })
        })
        .ok_or("no imitator fell between the Poor and the Expert")?;
    demos.retain(|d| d.demonstrator != "tiny" && d.demonstrator != "humanoid");
    demos.extend(average);
    let skill = ordering(&["poor", "average", "expert"]);
    let varying = run(&skill, PhaseOne::Interleaved, &demos);
    let world = WorldModel::learn(&demos, &Pitch::LARGE, &setup.config);
    summarise("varying skill", &setup, &varying, &world, Some(&["poor", "average", "expert"]), attempts);
    Ok(())
}
