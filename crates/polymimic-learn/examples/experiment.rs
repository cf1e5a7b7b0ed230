//! The experiments of thesis §4.4 from Rust, for studying learning-preference shaping and
//! control quickly: `cargo run --release -p polymimic-learn --example experiment -- [trials]
//! [attempts_per_configuration] [key=value …]`, where each `key=value` overrides a
//! [`LearningConfig`] field (for instance `lp_bounds=\"clamp\"`), or the seed of the
//! recorded demonstrations (`demonstrations_seed=0`, the default, as `polymimic reproduce`),
//! or, prefixed `field.`, a [`FieldConfig`] value by its path (`field.tracker.heading_sigma_rad=0.0026`).
//!
//! Prints, per experiment, the mean (sd) final LP, match rate and candidates made permanent of
//! each model, what changed the LPs, the trials whose final LPs follow the true skill order
//! (and those whose Poor ends below the initial LP), and the goals and own goals of the
//! trained imitators under the thesis's control rule and with each part of the improved
//! control added in turn.

use std::collections::BTreeMap;

use polymimic_field::{Demonstrator, FieldConfig};
use polymimic_learn::{
    ControlMode, Laboratory, LearningConfig, LpCauseCounts, PhaseOne, Pitch, Running, SegmentedDemonstration,
    TrialResult, WorldModel, lp_order_hits, net_goals_of, summarise,
};

fn report(name: &str, lab: &Laboratory, trials: &[TrialResult], world: &WorldModel, attempts: usize) {
    println!("\n== {name} ({} trials)", trials.len());
    if let Some(plan) = &world.approach {
        println!("push region {:?}", plan.push_region);
    }
    for s in summarise(trials) {
        println!(
            "{:9} final LP {:.3} ({:.3})  match {:.3} ({:.3})  candidates made permanent {:.2} ({:.2})",
            s.name,
            s.final_lp.mean,
            s.final_lp.sd(),
            s.match_rate.mean,
            s.match_rate.sd(),
            s.candidates_permanent.mean,
            s.candidates_permanent.sd()
        );
    }
    println!("LP changes per trial, by cause:");
    for (k, model) in trials[0].models.iter().enumerate() {
        let mut means = [0.0; 9];
        for t in trials {
            for (mean, (_, n)) in means.iter_mut().zip(t.models[k].metrics.lp_causes.named()) {
                *mean += n as f64 / trials.len() as f64;
            }
        }
        let names = LpCauseCounts::default().named().map(|(name, _)| name);
        let cells: Vec<String> = names.iter().zip(means).map(|(name, mean)| format!("{name} {mean:.1}")).collect();
        println!("  {:9} {}", model.name, cells.join(", "));
    }
    if attempts == 0 {
        return;
    }
    // What each part of the improved control buys, added one at a time.
    let unaided = WorldModel::default();
    let without_route = WorldModel { approach: None, ..world.clone() };
    let steps = [
        ("thesis rule", ControlMode::Thesis, &unaided),
        ("+ re-choose after every primitive", ControlMode::Improved, &unaided),
        ("+ learned ball response and state values", ControlMode::Improved, &without_route),
        ("+ route to the learned push region (improved)", ControlMode::Improved, world),
    ];
    for (label, mode, world) in steps {
        let (mut goals, mut own) = (Running::default(), Running::default());
        let mut outcomes = BTreeMap::new();
        for (i, t) in trials.iter().enumerate() {
            let score = lab.score(t, world, mode, attempts, 1000 + i as u64).expect("the field runs");
            goals.push(score.goals as f64);
            own.push(score.own_goals as f64);
            for a in &score.attempts {
                *outcomes
                    .entry(format!("{}/{}", a.outcome.name(), a.configuration.map_or(0, |c| c.number())))
                    .or_insert(0) += 1;
            }
        }
        println!(
            "imitators, {label}: goals {:.1} ({:.1}), own goals {:.1} ({:.1}) in {} attempts",
            goals.mean,
            goals.sd(),
            own.mean,
            own.sd(),
            2 * attempts
        );
        println!("  outcomes/configuration: {outcomes:?}");
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let trials: u64 = args.get(1).map_or(Ok(20), |s| s.parse())?;
    if trials == 0 {
        return Err("run at least one trial".into());
    }
    let attempts: usize = args.get(2).map_or(Ok(0), |s| s.parse())?;
    let mut config = serde_json::to_value(LearningConfig::default())?;
    let mut field = serde_json::from_str::<serde_json::Value>(&FieldConfig::default().to_json_in_full())?;
    let mut demonstrations_seed = 0;
    for pair in args.iter().skip(3) {
        match pair.split_once('=').ok_or("overrides are key=value")? {
            ("demonstrations_seed", value) => demonstrations_seed = value.parse()?,
            (key, value) if key.starts_with("field.") => {
                let pointer = key.replacen("field.", "/", 1).replace('.', "/");
                *field.pointer_mut(&pointer).ok_or_else(|| format!("no field parameter {key}"))? =
                    serde_json::from_str(value)?;
            }
            (key, value) => config[key] = serde_json::from_str(value)?,
        }
    }
    let field: FieldConfig = serde_json::from_value(field)?;
    let lab = Laboratory::on_field(1000, 1, LearningConfig::from_json(&config.to_string())?, field)?;
    let everyone = [Demonstrator::Expert, Demonstrator::Tiny, Demonstrator::Humanoid, Demonstrator::Poor];
    let recorded = lab.record(&everyone, 25, demonstrations_seed)?;
    let of = |names: &[&str]| -> Vec<SegmentedDemonstration> {
        recorded.iter().filter(|d| names.contains(&d.demonstrator.as_str())).cloned().collect()
    };

    let heterogeneous = of(&["expert", "tiny", "humanoid"]);
    let world = WorldModel::learn(&heterogeneous, &Pitch::LARGE, &lab.motion, &lab.config);
    let rcb = lab.trials(&heterogeneous, &["expert", "tiny", "humanoid"], PhaseOne::ByModel, trials)?;
    report("heterogeneous RCB", &lab, &rcb, &world, attempts);
    let bcr = lab.trials(&heterogeneous, &["humanoid", "tiny", "expert"], PhaseOne::ByModel, trials)?;
    report("heterogeneous BCR", &lab, &bcr, &world, attempts);

    let net_goals = (net_goals_of(&recorded, "poor"), net_goals_of(&recorded, "expert"));
    let mut skill = of(&["poor", "expert"]);
    skill.extend(lab.average_demonstrator(&rcb[..rcb.len().min(10)], 25, net_goals)?);
    let world = WorldModel::learn(&skill, &Pitch::LARGE, &lab.motion, &lab.config);
    let varying = lab.trials(&skill, &["poor", "average", "expert"], PhaseOne::Interleaved, trials)?;
    report("varying skill", &lab, &varying, &world, attempts);
    let hits = lp_order_hits(&varying, &["poor", "average", "expert"]);
    println!("final LP in the true order (poor < average < expert): {hits} of {}", varying.len());
    let below =
        varying.iter().filter(|t| t.models.iter().any(|m| m.name == "poor" && m.lp < lab.config.initial_lp)).count();
    println!("poor's final LP below the initial {}: {below} of {}", lab.config.initial_lp, varying.len());
    Ok(())
}
