//! What a trial leaves behind (thesis Tables 4.1, 4.2): every model's LP and its history, its
//! match rate and counts, its behaviours, and the imitator's final model, as the trial files
//! of a run keep them. Written as Python's `json.dumps` wrote the same record, so files stay
//! byte for byte; read back with every value's type and range checked and the key named.

mod python_json;
mod read;
mod validate;

use std::sync::Arc;

use thiserror::Error;

use crate::model::ForwardModel;
use crate::trial::TrialResult;
use python_json::{Object, push_float, push_list, push_string};
pub use read::Json;

/// A trial record that cannot be read: where, and why.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum RecordError {
    /// Not JSON, or JSON that ends early; `at` is the key path where it broke.
    #[error("{}{why}", if at.is_empty() { String::new() } else { format!("{at}: ") })]
    Syntax { at: String, why: String },
    /// A value of the wrong type or out of range, or a key missing or unknown.
    #[error("{key}: {why}")]
    Value { key: String, why: String },
}

/// One behaviour at the end of a trial.
#[derive(Debug, Clone, PartialEq)]
pub struct BehaviourRecord {
    /// Its primitives' letters (`"FFL"`).
    pub primitives: String,
    pub permanency: f64,
    pub permanent: bool,
    pub age: u64,
    pub selected: u64,
    pub ball_samples: u64,
    /// Mean and sd of the ball's bearing where this behaviour moved it.
    pub ball_angle_deg: [f64; 2],
    /// Mean and sd of the ball's distance.
    pub ball_distance_mm: [f64; 2],
}

/// One forward model at the end of a trial.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelRecord {
    pub name: String,
    pub lp: f64,
    pub lp_history: Vec<f64>,
    pub match_rate: f64,
    pub created: u64,
    pub deleted: u64,
    pub permanent: u64,
    pub candidates: u64,
    pub duplicates: u64,
    pub candidates_permanent: u64,
    pub rounds: u64,
    pub rounds_matched: u64,
    pub behaviours: Vec<BehaviourRecord>,
    /// How often each cause of Table 3.3 changed the LP, in the order the file gave them.
    pub lp_causes: Vec<(String, u64)>,
}

/// A whole trial: every demonstrator's model in the ordering, the imitator's, the seed, and
/// the imitator's final model (its versioned JSON and the model it reads as).
#[derive(Debug, Clone)]
pub struct TrialRecord {
    pub models: Vec<ModelRecord>,
    pub imitator: ModelRecord,
    pub seed: u64,
    /// The imitator's model as saved (empty if the record keeps none).
    pub imitator_model_json: String,
    /// That model, read once.
    pub imitator_model: Option<Arc<ForwardModel>>,
}

impl PartialEq for TrialRecord {
    fn eq(&self, other: &Self) -> bool {
        self.models == other.models
            && self.imitator == other.imitator
            && self.seed == other.seed
            && self.imitator_model_json == other.imitator_model_json
    }
}

impl BehaviourRecord {
    fn of(b: &crate::behaviour::Behaviour) -> Self {
        Self {
            primitives: b.letters(),
            permanency: b.permanency,
            permanent: b.permanent,
            age: b.age,
            selected: b.selected as u64,
            ball_samples: b.ball_angle_deg.count as u64,
            ball_angle_deg: [b.ball_angle_deg.mean, b.ball_angle_deg.sd()],
            ball_distance_mm: [b.ball_distance_mm.mean, b.ball_distance_mm.sd()],
        }
    }

    fn write(&self, out: &mut String) {
        let pair = |out: &mut String, p: &[f64; 2]| push_list(out, p, |o, x| push_float(o, *x));
        Object::new(out)
            .field("primitives", |o| push_string(o, &self.primitives))
            .field("permanency", |o| push_float(o, self.permanency))
            .field("permanent", |o| o.push_str(if self.permanent { "true" } else { "false" }))
            .field("age", |o| o.push_str(&self.age.to_string()))
            .field("selected", |o| o.push_str(&self.selected.to_string()))
            .field("ball_samples", |o| o.push_str(&self.ball_samples.to_string()))
            .field("ball_angle_deg", |o| pair(o, &self.ball_angle_deg))
            .field("ball_distance_mm", |o| pair(o, &self.ball_distance_mm))
            .end();
    }
}

impl ModelRecord {
    /// The record of a model at the end of its trial.
    #[must_use]
    pub fn of(model: &ForwardModel) -> Self {
        let m = &model.metrics;
        Self {
            name: model.name.clone(),
            lp: model.lp,
            lp_history: model.lp_history.clone(),
            match_rate: model.match_rate(),
            created: m.created as u64,
            deleted: m.deleted as u64,
            permanent: m.made_permanent as u64,
            candidates: m.candidates as u64,
            duplicates: m.duplicates as u64,
            candidates_permanent: m.candidates_permanent as u64,
            rounds: m.rounds as u64,
            rounds_matched: m.rounds_matched as u64,
            behaviours: model.behaviours.iter().map(BehaviourRecord::of).collect(),
            lp_causes: m.lp_causes.named().iter().map(|(k, v)| ((*k).to_owned(), *v as u64)).collect(),
        }
    }

    /// A record from plain data (as [`Self::to_json`] writes one model), every value checked;
    /// errors name the key under `key`.
    ///
    /// # Errors
    /// A value of the wrong type or out of range, or a key missing or unknown.
    pub fn from_value(value: &Json, key: &str) -> Result<Self, RecordError> {
        validate::model(value, key, None)
    }

    /// The counts, by the names the record uses.
    #[must_use]
    pub fn counts(&self) -> [(&'static str, u64); 8] {
        [
            ("created", self.created),
            ("deleted", self.deleted),
            ("permanent", self.permanent),
            ("candidates", self.candidates),
            ("duplicates", self.duplicates),
            ("candidates_permanent", self.candidates_permanent),
            ("rounds", self.rounds),
            ("rounds_matched", self.rounds_matched),
        ]
    }

    fn write(&self, out: &mut String) {
        let mut object = Object::new(out);
        object
            .field("name", |o| push_string(o, &self.name))
            .field("lp", |o| push_float(o, self.lp))
            .field("lp_history", |o| push_list(o, &self.lp_history, |o, x| push_float(o, *x)))
            .field("match_rate", |o| push_float(o, self.match_rate));
        for (key, value) in self.counts() {
            object.field(key, |o| o.push_str(&value.to_string()));
        }
        object
            .field("behaviours", |o| push_list(o, &self.behaviours, |o, b| b.write(o)))
            .field("lp_causes", |o| {
                let mut causes = Object::new(o);
                for (key, value) in &self.lp_causes {
                    causes.field(key, |o| o.push_str(&value.to_string()));
                }
                causes.end();
            })
            .end();
    }
}

impl TrialRecord {
    /// The record of a finished trial run with `seed`.
    #[must_use]
    pub fn of(result: &TrialResult, seed: u64) -> Self {
        let model = Arc::new(result.imitator.clone());
        Self {
            models: result.models.iter().map(ModelRecord::of).collect(),
            imitator: ModelRecord::of(&result.imitator),
            seed,
            imitator_model_json: model.to_json(),
            imitator_model: Some(model),
        }
    }

    /// The model named `name` (a demonstrator's; not the imitator's).
    #[must_use]
    pub fn model(&self, name: &str) -> Option<&ModelRecord> {
        self.models.iter().find(|m| m.name == name)
    }

    /// The record as JSON text, exactly as `json.dumps` wrote it for earlier versions.
    #[must_use]
    pub fn to_json(&self) -> String {
        let mut out = String::with_capacity(64 * 1024);
        Object::new(&mut out)
            .field("models", |o| {
                let mut models = Object::new(o);
                for model in &self.models {
                    models.field(&model.name, |o| model.write(o));
                }
                models.end();
            })
            .field("imitator", |o| self.imitator.write(o))
            .field("seed", |o| o.push_str(&self.seed.to_string()))
            .field("imitator_model", |o| push_string(o, &self.imitator_model_json))
            .end();
        out
    }

    /// A record from [`Self::to_json`] text, every value checked.
    ///
    /// # Errors
    /// Text that is not JSON, ends early, or holds a value of the wrong type or out of range,
    /// a key missing or unknown, or an imitator model that does not read: named by its key.
    pub fn from_json(text: &str) -> Result<Self, RecordError> {
        let value = read::parse(text).map_err(|(at, why)| RecordError::Syntax { at, why })?;
        validate::trial(&value)
    }
}

#[cfg(test)]
mod tests;
