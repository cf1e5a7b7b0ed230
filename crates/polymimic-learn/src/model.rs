//! A forward model: behaviours, the frequency with which one follows another, and a learning
//! preference (thesis §3.3, §3.4).

use polymimic_types::Primitive;
use serde::{Deserialize, Serialize};

use crate::behaviour::Behaviour;
use crate::config::{LearningConfig, LpBounds};
use crate::error::LearnError;
use crate::shaping::{LpCause, LpCauseCounts};

const FORMAT: &str = "polymimic.ForwardModel";
const VERSION: u32 = 1;

/// Counts behind Tables 4.1, 4.2, 4.7 and 4.10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct ModelMetrics {
    pub created: usize,
    pub deleted: usize,
    pub made_permanent: usize,
    /// Behaviours this model nominated to the imitator's model.
    pub candidates: usize,
    /// Nominations the imitator's model already held.
    pub duplicates: usize,
    /// Nominations that later became permanent in the imitator's model.
    pub candidates_permanent: usize,
    pub rounds: usize,
    pub rounds_matched: usize,
    /// What changed the LP, and how often.
    pub lp_causes: LpCauseCounts,
}

/// Something a model's processing did that the trial must act on.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    BecamePermanent { primitives: Vec<Primitive>, nominated_by: Option<usize> },
    Deleted { primitives: Vec<Primitive>, nominated_by: Option<usize> },
}

/// A forward model for one demonstrator, or for the imitator.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ForwardModel {
    pub name: String,
    pub behaviours: Vec<Behaviour>,
    /// `frequency[i][j]`: how often behaviour j followed behaviour i, since it last formed one.
    pub frequency: Vec<Vec<f64>>,
    pub lp: f64,
    /// The imitator's LP does not change.
    pub fixed_lp: bool,
    next_age: u64,
    pub metrics: ModelMetrics,
    /// The LP after every change.
    pub lp_history: Vec<f64>,
}

impl ForwardModel {
    /// A model holding the five wheeled primitives, with LP `lp` (fixed if `fixed`).
    #[must_use]
    pub fn new(name: &str, lp: f64, fixed: bool, config: &LearningConfig) -> Self {
        Self::of_primitives(name, lp, fixed, &Primitive::WHEELED, config)
    }

    /// A model holding a body's own `primitives`, each a behaviour of one, with LP `lp` (fixed
    /// if `fixed`).
    #[must_use]
    pub fn of_primitives(name: &str, lp: f64, fixed: bool, primitives: &[Primitive], config: &LearningConfig) -> Self {
        let mut model = Self {
            name: name.to_owned(),
            behaviours: Vec::new(),
            frequency: Vec::new(),
            lp,
            fixed_lp: fixed,
            next_age: 0,
            metrics: ModelMetrics::default(),
            lp_history: vec![lp],
        };
        for &primitive in primitives {
            model.insert(vec![primitive], config);
        }
        model.metrics.created = 0;
        model
    }

    #[must_use]
    pub fn index_of(&self, primitives: &[Primitive]) -> Option<usize> {
        self.behaviours.iter().position(|b| b.primitives == primitives)
    }

    /// Adds a new behaviour (with the next age); returns its index.
    pub(crate) fn insert(&mut self, primitives: Vec<Primitive>, config: &LearningConfig) -> usize {
        self.behaviours.push(Behaviour::new(primitives, self.next_age, config));
        self.next_age += 1;
        for row in &mut self.frequency {
            row.push(0.0);
        }
        self.frequency.push(vec![0.0; self.behaviours.len()]);
        self.metrics.created += 1;
        self.behaviours.len() - 1
    }

    fn remove(&mut self, index: usize) -> Behaviour {
        self.frequency.remove(index);
        for row in &mut self.frequency {
            row.remove(index);
        }
        self.metrics.deleted += 1;
        self.behaviours.remove(index)
    }

    /// Changes the LP for `cause` (eq 3.13) within [0, 1] as `config.lp_bounds` says, unless
    /// it is fixed.
    pub fn shape_lp(&mut self, cause: LpCause, config: &LearningConfig) {
        self.shape_lp_weighted(cause, 1.0, config);
    }

    /// [`Self::shape_lp`] by `weight` times the cause's step.
    pub fn shape_lp_weighted(&mut self, cause: LpCause, weight: f64, config: &LearningConfig) {
        let delta = cause.amount(config) * weight;
        if self.fixed_lp || delta == 0.0 || !delta.is_finite() {
            return;
        }
        self.metrics.lp_causes.count(cause);
        // Soft bounds take the thesis's step at the midpoint, shrinking to nothing at the bound.
        let room = match config.lp_bounds {
            LpBounds::Clamp => 1.0,
            LpBounds::Soft if delta > 0.0 => 2.0 * (1.0 - self.lp),
            LpBounds::Soft => 2.0 * self.lp,
        };
        self.lp = (self.lp + delta * room).clamp(0.0, 1.0);
        self.lp_history.push(self.lp);
    }

    /// Eq 3.11 on `frequency[from][to]`, its step scaled by `weight` (1 for the thesis's);
    /// returns whether it passed the creation threshold.
    pub(crate) fn strengthen(&mut self, from: usize, to: usize, weight: f64, config: &LearningConfig) -> bool {
        self.frequency[from][to] += (config.min_frequency + config.min_frequency * self.lp) * weight;
        self.frequency[from][to] > config.creation_threshold
    }

    /// Raises a behaviour's permanency by `weight` permanency steps (it may become permanent).
    pub(crate) fn reinforce(&mut self, index: usize, weight: f64, config: &LearningConfig) {
        let b = &mut self.behaviours[index];
        if !b.permanent {
            b.permanency += config.permanency_step * weight;
        }
    }

    /// Eq 3.12 on every non-permanent behaviour.
    pub(crate) fn decay(&mut self, config: &LearningConfig) {
        let amount = (1.0 - self.lp) * config.decay_step;
        for b in self.behaviours.iter_mut().filter(|b| !b.permanent) {
            b.permanency -= amount;
        }
    }

    /// Makes permanent what crossed the threshold and deletes what fell to the deletion
    /// threshold (never a primitive), reporting both.
    pub(crate) fn settle(&mut self, config: &LearningConfig) -> Vec<Event> {
        let mut events = Vec::new();
        for b in self.behaviours.iter_mut().filter(|b| !b.permanent && b.permanency >= config.permanency_threshold) {
            b.permanent = true;
            self.metrics.made_permanent += 1;
            events.push(Event::BecamePermanent { primitives: b.primitives.clone(), nominated_by: b.nominated_by });
        }
        let mut index = 0;
        while index < self.behaviours.len() {
            let b = &self.behaviours[index];
            if !b.permanent && !b.is_primitive() && b.permanency <= config.deletion_threshold {
                let removed = self.remove(index);
                events.push(Event::Deleted { primitives: removed.primitives, nominated_by: removed.nominated_by });
            } else {
                index += 1;
            }
        }
        events
    }

    /// Takes a nominated behaviour: a new copy with the default permanency, or, if the model
    /// holds it already, more permanency for that copy. Returns whether it was a duplicate.
    pub fn nominate(&mut self, primitives: &[Primitive], nominated_by: usize, config: &LearningConfig) -> bool {
        if let Some(index) = self.index_of(primitives) {
            self.reinforce(index, 1.0, config);
            return true;
        }
        let index = self.insert(primitives.to_vec(), config);
        self.behaviours[index].nominated_by = Some(nominated_by);
        false
    }

    /// Drops every behaviour that is not permanent (the end of training).
    pub fn prune(&mut self) {
        let mut index = 0;
        while index < self.behaviours.len() {
            if self.behaviours[index].permanent {
                index += 1;
            } else {
                self.remove(index);
            }
        }
    }

    /// The model as versioned JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        polymimic_persist::to_envelope(FORMAT, VERSION, self).unwrap_or_default()
    }

    /// A model from [`Self::to_json`] text.
    ///
    /// # Errors
    /// Another format or version, or a payload of the wrong shape.
    pub fn from_json(text: &str) -> Result<Self, LearnError> {
        let corrupt = |why: &str| LearnError::Corrupt(why.to_owned());
        let model: Self = polymimic_persist::from_envelope(text, FORMAT, VERSION).map_err(LearnError::Corrupt)?;
        if model.frequency.len() != model.behaviours.len()
            || model.frequency.iter().any(|r| r.len() != model.behaviours.len())
        {
            return Err(corrupt("the frequency matrix does not match the behaviours"));
        }
        if model.behaviours.iter().any(|b| b.primitives.is_empty()) {
            return Err(corrupt("a behaviour has no primitives"));
        }
        if !(0.0..=1.0).contains(&model.lp) {
            return Err(corrupt("lp must be in [0, 1]"));
        }
        Ok(model)
    }

    /// Share of prediction rounds with a match (Tables 4.7, 4.10).
    #[must_use]
    pub fn match_rate(&self) -> f64 {
        if self.metrics.rounds == 0 { 0.0 } else { self.metrics.rounds_matched as f64 / self.metrics.rounds as f64 }
    }
}
