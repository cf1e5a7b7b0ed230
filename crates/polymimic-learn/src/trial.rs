//! One learning trial: both training phases and the final pruning (thesis §3.4, §4.1).

use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::config::{ImitatorWeighting, LearningConfig};
use crate::error::{LearnError, LearnParamsError};
use crate::model::{Event, ForwardModel};
use crate::prediction::MotionTable;
use crate::round::SegmentedDemonstration;
use crate::shaping::LpCause;
use crate::weighting::imitator_weights;
use polymimic_types::Primitive;

/// How phase 1 presents demonstrations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PhaseOne {
    /// Each demonstrator's model learns all of its demonstrations, models in the ordering
    /// (the heterogeneous experiment).
    #[default]
    ByModel,
    /// The demonstrations of all demonstrators interleaved at random, each learned by its
    /// own demonstrator's model (the varying-skill experiment).
    Interleaved,
}

/// What a trial produced: every demonstrator's model (in the ordering) and the imitator's.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TrialResult {
    pub models: Vec<ForwardModel>,
    pub imitator: ForwardModel,
}

/// The model streams of a trial's random generator.
fn stream_rng(seed: u64, stream: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(stream);
    rng
}

/// Runs one trial on segmented demonstrations.
///
/// # Errors
/// An empty ordering or demonstration set, an ordering naming a demonstrator twice or one
/// without demonstrations, or a config value out of range.
pub fn run_trial(
    demonstrations: &[SegmentedDemonstration],
    ordering: &[String],
    motion: &MotionTable,
    config: &LearningConfig,
    phase_one: PhaseOne,
    seed: u64,
) -> Result<TrialResult, LearnError> {
    config.check()?;
    if demonstrations.is_empty() {
        return Err(LearnParamsError::NoDemonstrations.into());
    }
    if ordering.is_empty() {
        return Err(LearnParamsError::EmptyOrdering.into());
    }
    for (i, name) in ordering.iter().enumerate() {
        if ordering[..i].contains(name) {
            return Err(LearnParamsError::DuplicateDemonstrator(name.clone()).into());
        }
        if !demonstrations.iter().any(|d| &d.demonstrator == name) {
            return Err(LearnParamsError::UnknownDemonstrator(name.clone()).into());
        }
    }
    if let Some((index, d)) = demonstrations.iter().enumerate().find(|(_, d)| !ordering.contains(&d.demonstrator)) {
        return Err(LearnParamsError::OutsideOrdering { index, demonstrator: d.demonstrator.clone() }.into());
    }
    // Every model starts from the imitator's own primitives, those its motion table knows.
    let primitives: Vec<Primitive> = motion.primitives().collect();
    let model = |name: &str, lp, fixed| ForwardModel::of_primitives(name, lp, fixed, &primitives, config);
    let mut models: Vec<ForwardModel> =
        ordering.iter().map(|name| model(name, config.initial_lp, config.hold_lp)).collect();
    let mut imitator = model("imitator", config.imitator_lp, true);
    let mut rngs: Vec<ChaCha8Rng> = (0..=models.len() as u64).map(|s| stream_rng(seed, s + 1)).collect();
    let mut order_rng = stream_rng(seed, 0);
    let model_of = |d: &SegmentedDemonstration| ordering.iter().position(|n| n == &d.demonstrator);

    // Phase 1: each demonstrator's model learns its own demonstrations; the imitator's model
    // only collects candidates.
    let mut phase_one_order: Vec<(usize, usize)> = Vec::new();
    for (m, _) in ordering.iter().enumerate() {
        let mut own: Vec<usize> =
            (0..demonstrations.len()).filter(|&i| model_of(&demonstrations[i]) == Some(m)).collect();
        own.shuffle(&mut order_rng);
        phase_one_order.extend(own.into_iter().map(|i| (m, i)));
    }
    if phase_one == PhaseOne::Interleaved {
        phase_one_order.shuffle(&mut order_rng);
    }
    for (m, i) in phase_one_order {
        let events = models[m].process(&demonstrations[i], motion, config, &mut rngs[m]);
        nominate(&events, m, &mut models, &mut imitator, config);
    }

    // Phase 2: every demonstration in random order, to every demonstrator's model first.
    let mut all: Vec<usize> = (0..demonstrations.len()).filter(|&i| model_of(&demonstrations[i]).is_some()).collect();
    all.shuffle(&mut order_rng);
    let imitator_stream = models.len();
    for i in all {
        for m in 0..models.len() {
            let events = models[m].process(&demonstrations[i], motion, config, &mut rngs[m]);
            nominate(&events, m, &mut models, &mut imitator, config);
        }
        let weight = match (config.imitator_weighting, model_of(&demonstrations[i])) {
            (ImitatorWeighting::Even, _) | (_, None) => 1.0,
            (weighting, Some(m)) => {
                let lps: Vec<f64> = models.iter().map(|model| model.lp).collect();
                imitator_weights(weighting, &lps, config.initial_lp)[m]
            }
        };
        let events = imitator.process_weighted(&demonstrations[i], weight, motion, config, &mut rngs[imitator_stream]);
        judge_candidates(&events, &mut models, config);
    }
    imitator.prune();
    Ok(TrialResult { models, imitator })
}

/// Behaviours that became permanent in model `m` are nominated to the imitator's model.
fn nominate(
    events: &[Event],
    m: usize,
    models: &mut [ForwardModel],
    imitator: &mut ForwardModel,
    config: &LearningConfig,
) {
    for event in events {
        if let Event::BecamePermanent { primitives, .. } = event {
            models[m].metrics.candidates += 1;
            if imitator.nominate(primitives, m, config) {
                models[m].metrics.duplicates += 1;
            }
        }
    }
}

/// A candidate made permanent in the imitator's model raises its nominator's LP; one deleted
/// there lowers it.
fn judge_candidates(events: &[Event], models: &mut [ForwardModel], config: &LearningConfig) {
    for event in events {
        match event {
            Event::BecamePermanent { nominated_by: Some(m), .. } => {
                models[*m].metrics.candidates_permanent += 1;
                models[*m].shape_lp(LpCause::CandidatePermanent, config);
            }
            Event::Deleted { nominated_by: Some(m), .. } => models[*m].shape_lp(LpCause::CandidateDeleted, config),
            _ => {}
        }
    }
}
