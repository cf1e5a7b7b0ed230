//! A parsed trial record checked value by value: the right type, in range, no key missing
//! (but the two earlier versions could leave out) and none unknown.

use std::sync::Arc;

use polymimic_perceive::Primitive;

use super::read::Json;
use super::{BehaviourRecord, ModelRecord, RecordError, TrialRecord};
use crate::model::ForwardModel;
use crate::shaping::LpCauseCounts;

const MODEL_KEYS: [&str; 14] = [
    "name",
    "lp",
    "lp_history",
    "match_rate",
    "created",
    "deleted",
    "permanent",
    "candidates",
    "duplicates",
    "candidates_permanent",
    "rounds",
    "rounds_matched",
    "behaviours",
    "lp_causes",
];
const BEHAVIOUR_KEYS: [&str; 8] =
    ["primitives", "permanency", "permanent", "age", "selected", "ball_samples", "ball_angle_deg", "ball_distance_mm"];

fn bad(key: &str, why: impl Into<String>) -> RecordError {
    RecordError::Value { key: key.to_owned(), why: why.into() }
}

/// An object's entries by key, refusing keys not in `known` and missing ones not `optional`.
struct Fields<'a> {
    key: String,
    entries: &'a [(String, Json)],
}

impl<'a> Fields<'a> {
    fn of(value: &'a Json, key: &str, known: &[&str]) -> Result<Self, RecordError> {
        let Json::Object(entries) = value else {
            return Err(bad(key, format!("{} is not an object", value.describe())));
        };
        if let Some((unknown, _)) = entries.iter().find(|(k, _)| !known.contains(&k.as_str())) {
            return Err(bad(&Self::join(key, unknown), format!("unknown key; expected {}", known.join(", "))));
        }
        Ok(Self { key: key.to_owned(), entries })
    }

    fn join(key: &str, child: &str) -> String {
        if key.is_empty() { child.to_owned() } else { format!("{key}.{child}") }
    }

    fn path(&self, child: &str) -> String {
        Self::join(&self.key, child)
    }

    fn get(&self, child: &str) -> Option<&'a Json> {
        self.entries.iter().find(|(k, _)| k == child).map(|(_, v)| v)
    }

    fn need(&self, child: &str) -> Result<&'a Json, RecordError> {
        self.get(child).ok_or_else(|| bad(&self.path(child), "missing"))
    }

    fn float(&self, child: &str, range: Range) -> Result<f64, RecordError> {
        number(self.need(child)?, &self.path(child), range)
    }

    fn count(&self, child: &str) -> Result<u64, RecordError> {
        count(self.need(child)?, &self.path(child))
    }

    fn string(&self, child: &str) -> Result<&'a str, RecordError> {
        match self.need(child)? {
            Json::Str(s) => Ok(s),
            other => Err(bad(&self.path(child), format!("{} is not a string", other.describe()))),
        }
    }

    fn list(&self, child: &str) -> Result<&'a [Json], RecordError> {
        match self.need(child)? {
            Json::List(items) => Ok(items),
            other => Err(bad(&self.path(child), format!("{} is not a list", other.describe()))),
        }
    }
}

#[derive(Clone, Copy)]
enum Range {
    /// A share or preference: [0, 1].
    Unit,
    /// Any finite number.
    Finite,
    /// A finite number ≥ 0.
    NonNegative,
}

fn number(value: &Json, key: &str, range: Range) -> Result<f64, RecordError> {
    let x = match value {
        Json::Float(x) => *x,
        Json::Int(i) => *i as f64,
        other => return Err(bad(key, format!("{} is not a number", other.describe()))),
    };
    let (fits, allowed) = match range {
        Range::Unit => ((0.0..=1.0).contains(&x), "a number in [0, 1]"),
        Range::Finite => (x.is_finite(), "a finite number"),
        Range::NonNegative => (x.is_finite() && x >= 0.0, "a finite number ≥ 0"),
    };
    if fits { Ok(x) } else { Err(bad(key, format!("{} is not {allowed}", value.describe()))) }
}

fn count(value: &Json, key: &str) -> Result<u64, RecordError> {
    match value {
        Json::Int(i) => u64::try_from(*i).map_err(|_| bad(key, format!("{i} is not a whole number ≥ 0"))),
        other => Err(bad(key, format!("{} is not a whole number ≥ 0", other.describe()))),
    }
}

fn pair(fields: &Fields<'_>, child: &str) -> Result<[f64; 2], RecordError> {
    let key = fields.path(child);
    match fields.list(child)? {
        [mean, sd] => Ok([
            number(mean, &format!("{key}[0]"), Range::Finite)?,
            number(sd, &format!("{key}[1]"), Range::NonNegative)?,
        ]),
        items => Err(bad(&key, format!("a list of {} is not [mean, sd]", items.len()))),
    }
}

fn behaviour(value: &Json, key: &str) -> Result<BehaviourRecord, RecordError> {
    let f = Fields::of(value, key, &BEHAVIOUR_KEYS)?;
    let primitives = f.string("primitives")?;
    let letters_ok =
        !primitives.is_empty() && primitives.chars().all(|c| Primitive::ALL.iter().any(|p| p.letter() == c));
    if !letters_ok {
        return Err(bad(
            &f.path("primitives"),
            format!("{primitives:?} is not a sequence of the letters F, B, L, R, S (A, D, K on the humanoid)"),
        ));
    }
    let permanent = match f.need("permanent")? {
        Json::Bool(b) => *b,
        other => return Err(bad(&f.path("permanent"), format!("{} is not true or false", other.describe()))),
    };
    Ok(BehaviourRecord {
        primitives: primitives.to_owned(),
        permanency: f.float("permanency", Range::Finite)?,
        permanent,
        age: f.count("age")?,
        selected: f.count("selected")?,
        ball_samples: f.count("ball_samples")?,
        ball_angle_deg: pair(&f, "ball_angle_deg")?,
        ball_distance_mm: pair(&f, "ball_distance_mm")?,
    })
}

pub(super) fn model(value: &Json, key: &str, name_of_key: Option<&str>) -> Result<ModelRecord, RecordError> {
    let f = Fields::of(value, key, &MODEL_KEYS)?;
    let name = f.string("name")?;
    if let Some(expected) = name_of_key.filter(|expected| *expected != name) {
        return Err(bad(&f.path("name"), format!("{name:?} differs from the model's key {expected:?}")));
    }
    let lp_history = f
        .list("lp_history")?
        .iter()
        .enumerate()
        .map(|(i, v)| number(v, &format!("{}[{i}]", f.path("lp_history")), Range::Unit))
        .collect::<Result<Vec<_>, _>>()?;
    let behaviours = f
        .list("behaviours")?
        .iter()
        .enumerate()
        .map(|(i, v)| behaviour(v, &format!("{}[{i}]", f.path("behaviours"))))
        .collect::<Result<Vec<_>, _>>()?;
    let known_causes: Vec<&str> = LpCauseCounts::default().named().iter().map(|(k, _)| *k).collect();
    let lp_causes = match f.get("lp_causes") {
        None => Vec::new(),
        Some(causes) => {
            let causes = Fields::of(causes, &f.path("lp_causes"), &known_causes)?;
            causes.entries.iter().map(|(k, v)| Ok((k.clone(), count(v, &causes.path(k))?))).collect::<Result<_, _>>()?
        }
    };
    Ok(ModelRecord {
        name: name.to_owned(),
        lp: f.float("lp", Range::Unit)?,
        lp_history,
        match_rate: f.float("match_rate", Range::Unit)?,
        created: f.count("created")?,
        deleted: f.count("deleted")?,
        permanent: f.count("permanent")?,
        candidates: f.count("candidates")?,
        duplicates: f.count("duplicates")?,
        candidates_permanent: f.count("candidates_permanent")?,
        rounds: f.count("rounds")?,
        rounds_matched: f.count("rounds_matched")?,
        behaviours,
        lp_causes,
    })
}

pub(super) fn trial(value: &Json) -> Result<TrialRecord, RecordError> {
    let f = Fields::of(value, "", &["models", "imitator", "seed", "imitator_model"])?;
    let models = match f.need("models")? {
        Json::Object(entries) => entries
            .iter()
            .map(|(name, v)| model(v, &format!("models.{name}"), Some(name)))
            .collect::<Result<Vec<_>, _>>()?,
        other => return Err(bad("models", format!("{} is not an object", other.describe()))),
    };
    let imitator = model(f.need("imitator")?, "imitator", None)?;
    let imitator_model_json = match f.get("imitator_model") {
        None => String::new(),
        Some(_) => f.string("imitator_model")?.to_owned(),
    };
    let imitator_model = if imitator_model_json.is_empty() {
        None
    } else {
        Some(Arc::new(ForwardModel::from_json(&imitator_model_json).map_err(|e| bad("imitator_model", e.to_string()))?))
    };
    Ok(TrialRecord { models, imitator, seed: f.count("seed")?, imitator_model_json, imitator_model })
}
