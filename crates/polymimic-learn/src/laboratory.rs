//! The experiments of thesis §4.4 end to end in Rust: a recogniser trained on the imitator's
//! own primitives, demonstrations recorded and segmented, trials, the Average demonstrator, and
//! the trained imitators scored on the field. Python's `polymimic.experiments` orchestrates the
//! same steps at scale; this is the quick path for studying learning itself.

use polymimic_field::{
    BodyKind, Demonstrator, FieldConfig, FieldError, Frame, LapseRate, Outcome, record_all, self_observation,
};
use polymimic_perceive::{LabelledSequence, Recognizer, RecognizerConfig, SegmenterConfig, segment};
use polymimic_types::TrackedFrame;

use crate::average::AverageSearch;
use crate::config::LearningConfig;
use crate::control::{Attempt, ControlMode, ImitatorPolicy};
use crate::correspondence::{Setting, onto_setting};
use crate::error::{LaboratoryError, LearnError};
use crate::prediction::MotionTable;
use crate::record::TrialRecord;
use crate::round::{Ending, SegmentedDemonstration};
use crate::running::Running;
use crate::trial::{PhaseOne, TrialResult, run_trial};
use crate::world::WorldModel;

/// A trained imitator's score on the field.
#[derive(Debug, Clone, PartialEq)]
pub struct Score {
    pub goals: usize,
    pub own_goals: usize,
    pub attempts: Vec<Attempt>,
}

/// Everything the experiments share: the recogniser, the primitives' motion, the field and the
/// learning constants.
pub struct Laboratory {
    pub recognizer: Recognizer,
    pub motion: MotionTable,
    pub field: FieldConfig,
    pub config: LearningConfig,
}

impl Laboratory {
    /// Trains the recogniser on `per_primitive` self-observed sequences of each primitive.
    ///
    /// # Errors
    /// A field, recogniser or config error.
    pub fn new(per_primitive: usize, seed: u64, config: LearningConfig) -> Result<Self, LaboratoryError> {
        Self::on_field(per_primitive, seed, config, FieldConfig::default())
    }

    /// As [`Laboratory::new`], on a field of its own (another tracker, another humanoid).
    ///
    /// # Errors
    /// A field, recogniser or config error.
    pub fn on_field(
        per_primitive: usize,
        seed: u64,
        config: LearningConfig,
        field: FieldConfig,
    ) -> Result<Self, LaboratoryError> {
        config.check().map_err(LearnError::from)?;
        field.check().map_err(FieldError::from)?;
        let training: Vec<LabelledSequence> = self_observation(per_primitive, seed, &field)?
            .iter()
            .map(|s| LabelledSequence { primitive: s.primitive, poses: s.frames.iter().map(Frame::robot).collect() })
            .collect();
        let recognizer = Recognizer::train(&training, RecognizerConfig::default())?;
        let motion = MotionTable::new(recognizer.motion_stats()).map_err(LearnError::from)?;
        Ok(Self { recognizer, motion, field, config })
    }

    /// A recording as the learner takes it.
    ///
    /// # Errors
    /// Frames the segmenter refuses.
    pub fn segmented(
        &self,
        who: &str,
        setting: Setting,
        outcome: Outcome,
        frames: &[Frame],
    ) -> Result<SegmentedDemonstration, LaboratoryError> {
        let tracked: Vec<TrackedFrame> = frames.iter().map(Frame::tracked).collect();
        let ending = Ending::from(outcome);
        let segments = segment(&tracked, &self.recognizer, &SegmenterConfig::default())?;
        Ok(SegmentedDemonstration {
            demonstrator: who.to_owned(),
            pitch: setting.pitch,
            reach_mm: setting.reach_mm,
            ending,
            segments,
        })
    }

    /// `per_configuration` valid demonstrations from each configuration by each demonstrator.
    ///
    /// # Errors
    /// A field or segmenter error.
    pub fn record(
        &self,
        demonstrators: &[Demonstrator],
        per_configuration: usize,
        seed: u64,
    ) -> Result<Vec<SegmentedDemonstration>, LaboratoryError> {
        record_all(demonstrators, per_configuration, seed, LapseRate::NONE, &self.field)?
            .iter()
            .map(|d| {
                self.segmented(d.demonstrator.name(), Setting::of_body(d.demonstrator.body()), d.outcome, &d.frames)
            })
            .collect()
    }

    /// `trials` trials with seeds 0, 1, ….
    ///
    /// # Errors
    /// A bad ordering or empty demonstrations.
    pub fn trials(
        &self,
        demonstrations: &[SegmentedDemonstration],
        ordering: &[&str],
        phase_one: PhaseOne,
        trials: u64,
    ) -> Result<Vec<TrialResult>, LaboratoryError> {
        let ordering: Vec<String> = ordering.iter().map(|s| (*s).to_owned()).collect();
        // The laboratory's imitator is the Lego robot: it learns on its own field.
        let demonstrations = &onto_setting(demonstrations, &Setting::of_imitator(BodyKind::Lego));
        (0..trials)
            .map(|seed| Ok(run_trial(demonstrations, &ordering, &self.motion, &self.config, phase_one, seed)?))
            .collect()
    }

    /// A trial's imitator on the field, `per_configuration` attempts from each configuration.
    ///
    /// # Errors
    /// A field configuration that does not validate.
    pub fn score(
        &self,
        trial: &TrialResult,
        world: &WorldModel,
        mode: ControlMode,
        per_configuration: usize,
        seed: u64,
    ) -> Result<Score, LaboratoryError> {
        let policy = ImitatorPolicy {
            model: &trial.imitator,
            motion: &self.motion,
            config: &self.config,
            body: BodyKind::Lego,
            mode,
            world: Some(world),
        };
        let attempts = policy.evaluate(per_configuration, &self.field, seed)?;
        let count = |o: Outcome| attempts.iter().filter(|a| a.outcome == o).count();
        Ok(Score { goals: count(Outcome::Goal), own_goals: count(Outcome::OwnGoal), attempts })
    }

    /// The thesis's Average demonstrator (§4.4.2): of the imitators of the `heterogeneous`
    /// trials, driven by the thesis's rule, the one whose net goals (goals less own goals) over
    /// `per_configuration` attempts from each configuration lie nearest the middle of the
    /// Poor's and the Expert's, strictly between them (the earliest trial on a tie) — the
    /// thesis's Average scored fewer goals than its Poor but far fewer own goals. Attempts whose
    /// tracking was lost are left out, as for every demonstrator, and spare attempts stand in
    /// for them. Returns the chosen attempts as demonstrations named "average".
    ///
    /// # Errors
    /// No imitator falls between the two, or a field error.
    pub fn average_demonstrator(
        &self,
        heterogeneous: &[TrialResult],
        per_configuration: usize,
        (poor_net_goals, expert_net_goals): (i64, i64),
    ) -> Result<Vec<SegmentedDemonstration>, LaboratoryError> {
        let search = AverageSearch {
            motion: &self.motion,
            config: &self.config,
            field: &self.field,
            body: BodyKind::Lego,
            per_configuration,
            poor_net_goals,
            expert_net_goals,
        };
        let candidates = heterogeneous.iter().enumerate().map(|(i, trial)| Ok((i as u64, trial)));
        let chosen = search.choose(candidates)?;
        chosen
            .attempts
            .iter()
            .map(|a| self.segmented("average", Setting::of_body(BodyKind::Lego), a.outcome, &a.frames))
            .collect()
    }
}

/// One model's figures over the trials of an experiment, each a mean and sd.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelSummary {
    pub name: String,
    pub final_lp: Running,
    pub match_rate: Running,
    pub candidates_permanent: Running,
}

/// Every model's summary, in the ordering, then the imitator's.
#[must_use]
pub fn summarise(trials: &[TrialResult]) -> Vec<ModelSummary> {
    let Some(first) = trials.first() else { return Vec::new() };
    let names: Vec<&str> = first.models.iter().map(|m| m.name.as_str()).chain([first.imitator.name.as_str()]).collect();
    names
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let mut summary = ModelSummary {
                name: (*name).to_owned(),
                final_lp: Running::default(),
                match_rate: Running::default(),
                candidates_permanent: Running::default(),
            };
            for trial in trials {
                let model = trial.models.get(k).unwrap_or(&trial.imitator);
                summary.final_lp.push(model.lp);
                summary.match_rate.push(model.match_rate());
                summary.candidates_permanent.push(model.metrics.candidates_permanent as f64);
            }
            summary
        })
        .collect()
}

/// A trial, as far as its demonstrators' final LPs go: a finished one or its record.
pub trait FinalLps {
    /// The final LP of `who`'s model, if the trial had one.
    fn final_lp(&self, who: &str) -> Option<f64>;
}

impl FinalLps for TrialResult {
    fn final_lp(&self, who: &str) -> Option<f64> {
        self.models.iter().find(|m| m.name == who).map(|m| m.lp)
    }
}

impl FinalLps for TrialRecord {
    fn final_lp(&self, who: &str) -> Option<f64> {
        self.model(who).map(|m| m.lp)
    }
}

impl<T: FinalLps> FinalLps for &T {
    fn final_lp(&self, who: &str) -> Option<f64> {
        (**self).final_lp(who)
    }
}

/// Trials whose final LPs rise strictly along `order` (least skilled first); a trial without
/// one of them is no hit.
#[must_use]
pub fn lp_order_hits<T: FinalLps>(trials: &[T], order: &[&str]) -> usize {
    let lp = |t: &T, who: &str| t.final_lp(who).unwrap_or(f64::NAN);
    trials.iter().filter(|t| order.windows(2).all(|w| lp(t, w[0]) < lp(t, w[1]))).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_field_that_does_not_validate_is_refused_before_anything_is_simulated() {
        let mut field = FieldConfig::default();
        field.tracker.heading_sigma_rad = -1.0;
        let refused = Laboratory::on_field(1000, 1, LearningConfig::default(), field).err().expect("refused");
        assert!(refused.to_string().contains("heading_sigma_rad"), "{refused}");
    }
}
