//! The shape of the thesis's experiments (§4.4) at a small scale: 20 trials each, on
//! demonstrations recorded and segmented here. The full runs (100 trials) are the
//! `experiment` example and `polymimic reproduce`.

use polymimic_field::{Configuration, Demonstrator, Outcome};
use polymimic_learn::{
    ControlMode, Ending, Laboratory, LearningConfig, PhaseOne, Pitch, Running, SegmentedDemonstration, TrialResult,
    WorldModel, lp_order_hits, net_goals_of, summarise,
};

const TRIALS: u64 = 20;

fn within_one_sd(a: &Running, b: &Running) -> bool {
    (a.mean - b.mean).abs() <= a.sd().max(b.sd())
}

#[test]
fn the_experiments_show_the_thesis_shape_and_improved_control_beats_the_thesis_rule() {
    let lab = Laboratory::new(1000, 1, LearningConfig::default()).expect("the recogniser trains");
    let everyone = [Demonstrator::Expert, Demonstrator::Tiny, Demonstrator::Humanoid, Demonstrator::Poor];
    let recorded = lab.record(&everyone, 25, 1).expect("demonstrations record");
    let of = |names: &[&str]| -> Vec<SegmentedDemonstration> {
        recorded.iter().filter(|d| names.contains(&d.demonstrator.as_str())).cloned().collect()
    };

    // Heterogeneous: every final LP at least 0.9, whatever the ordering.
    let heterogeneous = of(&["expert", "tiny", "humanoid"]);
    let rcb = lab.trials(&heterogeneous, &["expert", "tiny", "humanoid"], PhaseOne::ByModel, TRIALS).unwrap();
    let bcr = lab.trials(&heterogeneous, &["humanoid", "tiny", "expert"], PhaseOne::ByModel, TRIALS).unwrap();
    let (rcb_summary, bcr_summary) = (summarise(&rcb), summarise(&bcr));
    for trial in rcb.iter().chain(&bcr) {
        for model in &trial.models {
            assert!(model.lp >= 0.9, "{} ended at LP {}", model.name, model.lp);
        }
    }
    for a in &rcb_summary {
        let b = bcr_summary.iter().find(|b| b.name == a.name).expect("same models");
        assert!(within_one_sd(&a.final_lp, &b.final_lp), "{}: {:?} vs {:?}", a.name, a.final_lp, b.final_lp);
        assert!(within_one_sd(&a.match_rate, &b.match_rate), "{}: {:?} vs {:?}", a.name, a.match_rate, b.match_rate);
    }

    // Varying skill: the final LP orders Poor < Average < Expert, and the Expert's candidates
    // are the ones the imitator keeps.
    let net_goals = (net_goals_of(&recorded, "poor"), net_goals_of(&recorded, "expert"));
    let mut skill = of(&["poor", "expert"]);
    skill.extend(lab.average_demonstrator(&rcb[..10], 25, net_goals).expect("an Average"));
    let varying = lab.trials(&skill, &["poor", "average", "expert"], PhaseOne::Interleaved, TRIALS).unwrap();
    let hits = lp_order_hits(&varying, &["poor", "average", "expert"]);
    assert!(hits >= 19, "the LP order held in {hits} of {TRIALS} trials");
    let summary = summarise(&varying);
    let candidates = |who: &str| summary.iter().find(|s| s.name == who).unwrap().candidates_permanent.mean;
    assert!(candidates("expert") > candidates("average").max(candidates("poor")), "{summary:?}");

    // Control: the improved mode scores at least 22 goals with at most 5 own goals in 50
    // attempts, clearly more than the Poor demonstrator (who scores only from configuration
    // 1), and from both configurations; the thesis's rule concedes more.
    let world = WorldModel::learn(&skill, &Pitch::LARGE, &lab.motion, &lab.config);
    let scores = |mode: ControlMode, trials: &[TrialResult]| -> (Running, Running) {
        let (mut goals, mut own) = (Running::default(), Running::default());
        for (i, trial) in trials.iter().enumerate() {
            let score = lab.score(trial, &world, mode, 25, 1000 + i as u64).expect("the field runs");
            goals.push(score.goals as f64);
            own.push(score.own_goals as f64);
        }
        (goals, own)
    };
    let (goals, own) = scores(ControlMode::Improved, &varying[..5]);
    assert!(goals.mean >= 22.0 && own.mean <= 5.0, "improved: {goals:?} goals, {own:?} own goals");
    let poor_goals = recorded.iter().filter(|d| d.demonstrator == "poor" && d.ending == Ending::Goal).count();
    assert!(goals.mean >= poor_goals as f64 + 10.0, "improved {goals:?} vs the Poor's {poor_goals} goals");
    let from_configuration_two = lab
        .score(&varying[0], &world, ControlMode::Improved, 25, 1000)
        .expect("the field runs")
        .attempts
        .iter()
        .filter(|a| a.configuration == Some(Configuration::Two) && a.outcome == Outcome::Goal)
        .count();
    assert!(from_configuration_two >= 8, "{from_configuration_two} goals of 25 from configuration 2");
    let (_, thesis_own) = scores(ControlMode::Thesis, &varying[..5]);
    assert!(thesis_own.mean > own.mean + 3.0, "thesis rule {thesis_own:?} vs improved {own:?} own goals");
}
