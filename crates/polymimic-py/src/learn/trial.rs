//! `polymimic.ModelResult` and `polymimic.TrialResult`: what a trial leaves behind, typed, and
//! saved as the same JSON text earlier versions wrote.
// The docstrings are Python's: their examples quote Python lists, not Rust doc links.
#![allow(clippy::doc_link_with_quotes)]

use std::path::PathBuf;
use std::sync::Arc;

use polymimic_learn::{BehaviourRecord, ForwardModel, Json, ModelRecord, TrialRecord};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple, PyType};

use crate::convert::{read_text, write_atomically};
use crate::errors::ModelFileError;

/// Python data as JSON, for the checks the record's reader makes; `key` names it in errors.
fn json_of(value: &Bound<'_, PyAny>, key: &str) -> PyResult<Json> {
    if value.is_none() {
        Ok(Json::Null)
    } else if let Ok(b) = value.cast::<PyBool>() {
        Ok(Json::Bool(b.is_true()))
    } else if value.is_instance_of::<PyInt>() {
        Ok(Json::Int(value.extract::<i64>().map(i128::from).or_else(|_| value.extract::<u64>().map(i128::from))?))
    } else if let Ok(x) = value.cast::<PyFloat>() {
        Ok(Json::Float(x.value()))
    } else if let Ok(s) = value.cast::<PyString>() {
        Ok(Json::Str(s.to_string()))
    } else if let Ok(d) = value.cast::<PyDict>() {
        d.iter()
            .map(|(k, v)| {
                let name: String =
                    k.extract().map_err(|_| PyTypeError::new_err(format!("{key}: keys must be strings")))?;
                let inner = json_of(&v, &format!("{key}.{name}"))?;
                Ok((name, inner))
            })
            .collect::<PyResult<_>>()
            .map(Json::Object)
    } else if let Ok(items) = value.try_iter() {
        items.enumerate().map(|(i, v)| json_of(&v?, &format!("{key}[{i}]"))).collect::<PyResult<_>>().map(Json::List)
    } else {
        Err(PyTypeError::new_err(format!("{key}: {} is not plain data", value.repr()?)))
    }
}

fn behaviour_dict<'py>(py: Python<'py>, b: &BehaviourRecord) -> PyResult<Bound<'py, PyDict>> {
    let row = PyDict::new(py);
    row.set_item("primitives", &b.primitives)?;
    row.set_item("permanency", b.permanency)?;
    row.set_item("permanent", b.permanent)?;
    row.set_item("age", b.age)?;
    row.set_item("selected", b.selected)?;
    row.set_item("ball_samples", b.ball_samples)?;
    row.set_item("ball_angle_deg", b.ball_angle_deg.to_vec())?;
    row.set_item("ball_distance_mm", b.ball_distance_mm.to_vec())?;
    Ok(row)
}

/// One forward model at the end of a trial: its LP (and every change of it), the share of
/// prediction rounds with a match, the counts of Tables 4.1 and 4.2, its behaviours (one
/// dictionary each: ``primitives``, ``permanency``, ``permanent``, ``age``, ``selected``,
/// ``ball_samples``, ``ball_angle_deg`` and ``ball_distance_mm`` as ``[mean, sd]``) and how
/// often each cause of Table 3.3 changed the LP (``lp_causes``: ``goal``, ``own_goal``,
/// ``ball_nearer_goal``, ``ball_farther_from_goal``, ``robot_nearer_ball``,
/// ``robot_farther_from_ball``, ``ball_predicted``, ``candidate_permanent``,
/// ``candidate_deleted``).
///
/// Every value is checked when made: a ``ValueError`` names the field.
///
/// Examples
/// --------
/// >>> model = ModelResult("expert", 0.6, [0.5, 0.6], 0.25, 3, 1, 2, 1, 0, 1, 8, 2, [])
/// >>> model.lp, model.rounds_matched, model.lp_causes
/// (0.6, 2, {})
/// >>> ModelResult("expert", 1.5, [0.5], 0.25, 3, 1, 2, 1, 0, 1, 8, 2, [])
/// Traceback (most recent call last):
/// ...
/// ValueError: lp: 1.5 is not a number in [0, 1]
#[pyclass(name = "ModelResult", module = "polymimic", frozen)]
pub struct PyModelResult {
    record: Arc<ModelRecord>,
}

impl PyModelResult {
    fn wrap(record: ModelRecord) -> Self {
        Self { record: Arc::new(record) }
    }

    fn dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let r = &self.record;
        let out = PyDict::new(py);
        out.set_item("name", &r.name)?;
        out.set_item("lp", r.lp)?;
        out.set_item("lp_history", r.lp_history.clone())?;
        out.set_item("match_rate", r.match_rate)?;
        for (key, value) in r.counts() {
            out.set_item(key, value)?;
        }
        out.set_item("behaviours", self.behaviours(py)?)?;
        out.set_item("lp_causes", self.lp_causes(py)?)?;
        Ok(out)
    }
}

#[pymethods]
impl PyModelResult {
    #[new]
    #[pyo3(signature = (name, lp, lp_history, match_rate, created, deleted, permanent, candidates, duplicates,
                        candidates_permanent, rounds, rounds_matched, behaviours, lp_causes=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        name: &Bound<'_, PyAny>,
        lp: &Bound<'_, PyAny>,
        lp_history: &Bound<'_, PyAny>,
        match_rate: &Bound<'_, PyAny>,
        created: &Bound<'_, PyAny>,
        deleted: &Bound<'_, PyAny>,
        permanent: &Bound<'_, PyAny>,
        candidates: &Bound<'_, PyAny>,
        duplicates: &Bound<'_, PyAny>,
        candidates_permanent: &Bound<'_, PyAny>,
        rounds: &Bound<'_, PyAny>,
        rounds_matched: &Bound<'_, PyAny>,
        behaviours: &Bound<'_, PyAny>,
        lp_causes: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let values = PyDict::new(py);
        for (key, value) in [
            ("name", name),
            ("lp", lp),
            ("lp_history", lp_history),
            ("match_rate", match_rate),
            ("created", created),
            ("deleted", deleted),
            ("permanent", permanent),
            ("candidates", candidates),
            ("duplicates", duplicates),
            ("candidates_permanent", candidates_permanent),
            ("rounds", rounds),
            ("rounds_matched", rounds_matched),
            ("behaviours", behaviours),
        ] {
            values.set_item(key, value)?;
        }
        if let Some(causes) = lp_causes {
            values.set_item("lp_causes", causes)?;
        }
        let record = ModelRecord::from_value(&json_of(values.as_any(), "")?, "")
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(Self::wrap(record))
    }

    /// The demonstrator the model represents (`"imitator"` for the imitator's own).
    #[getter]
    fn name(&self) -> &str {
        &self.record.name
    }

    /// The final learning preference, in [0, 1] under the default bounds (the imitator's is fixed).
    #[getter]
    fn lp(&self) -> f64 {
        self.record.lp
    }

    /// The LP after every change, from the first.
    #[getter]
    fn lp_history(&self) -> Vec<f64> {
        self.record.lp_history.clone()
    }

    /// Share of prediction rounds in which the model's prediction matched the demonstration
    /// (thesis Tables 4.7 and 4.10), in [0, 1].
    #[getter]
    fn match_rate(&self) -> f64 {
        self.record.match_rate
    }

    /// Behaviours the model created over the trial (thesis Figs. 4.7 and 4.19).
    #[getter]
    fn created(&self) -> u64 {
        self.record.created
    }

    /// Behaviours the model deleted over the trial (thesis Figs. 4.8 and 4.20).
    #[getter]
    fn deleted(&self) -> u64 {
        self.record.deleted
    }

    /// Behaviours permanent in the model at the end of the trial (thesis Figs. 4.9 and 4.21).
    #[getter]
    fn permanent(&self) -> u64 {
        self.record.permanent
    }

    /// Candidate behaviours moved from this model to the imitator's (thesis Figs. 4.10 and 4.22).
    #[getter]
    fn candidates(&self) -> u64 {
        self.record.candidates
    }

    /// Candidates not moved because the imitator's model already held them (thesis Figs. 4.11
    /// and 4.23).
    #[getter]
    fn duplicates(&self) -> u64 {
        self.record.duplicates
    }

    /// Moved candidates that became permanent in the imitator's model (thesis Figs. 4.12 and 4.24).
    #[getter]
    fn candidates_permanent(&self) -> u64 {
        self.record.candidates_permanent
    }

    /// Prediction rounds the model took part in.
    #[getter]
    fn rounds(&self) -> u64 {
        self.record.rounds
    }

    /// Prediction rounds in which its prediction matched (`match_rate` = this / `rounds`).
    #[getter]
    fn rounds_matched(&self) -> u64 {
        self.record.rounds_matched
    }

    /// One dictionary per behaviour (a copy).
    #[getter]
    fn behaviours<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let out = PyList::empty(py);
        for b in &self.record.behaviours {
            out.append(behaviour_dict(py, b)?)?;
        }
        Ok(out)
    }

    /// How often each cause changed the LP (a copy).
    #[getter]
    fn lp_causes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for (key, value) in &self.record.lp_causes {
            out.set_item(key, value)?;
        }
        Ok(out)
    }

    /// Every field by name, as plain data.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.dict(py)
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.record == other.record
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let d = slf.get().dict(py)?;
        let args: Vec<Bound<'py, PyAny>> = d.values().iter().collect();
        Ok((slf.get_type().into_any(), PyTuple::new(py, args)?))
    }

    fn __repr__(&self) -> String {
        let r = &self.record;
        format!(
            "ModelResult(name={:?}, lp={}, match_rate={}, behaviours={}, lp_changes={})",
            r.name,
            r.lp,
            r.match_rate,
            r.behaviours.len(),
            r.lp_history.len().saturating_sub(1)
        )
    }
}

/// Every demonstrator's model (by name, in the ordering) and the imitator's, the trial's seed
/// and the imitator's final model as versioned JSON (``imitator_model``: what
/// :class:`ImitatorPolicy` drives).
///
/// ``save``/``load`` (and ``to_json``/``from_json``) keep the trial files of a run: loading
/// checks every value's type and range and raises :class:`ModelFileError` naming the file and
/// the key of anything damaged, truncated or foreign.
///
/// Examples
/// --------
/// >>> model = ModelResult("imitator", 0.9, [0.9], 0.0, 5, 0, 0, 0, 0, 0, 0, 0, [])
/// >>> trial = TrialResult({}, model, 7)
/// >>> TrialResult.from_json(trial.to_json()) == trial, trial.seed
/// (True, 7)
/// >>> TrialResult.from_json(trial.to_json().replace('"lp": 0.9', '"lp": "high"'))
/// Traceback (most recent call last):
/// ...
/// polymimic.ModelFileError: not a saved trial result: imitator.lp: "high" is not a number
#[pyclass(name = "TrialResult", module = "polymimic", frozen)]
pub struct PyTrialResult {
    pub(crate) record: Arc<TrialRecord>,
}

impl PyTrialResult {
    pub(crate) fn wrap(record: TrialRecord) -> Self {
        Self { record: Arc::new(record) }
    }

    fn parse(text: &str) -> Result<TrialRecord, String> {
        TrialRecord::from_json(text).map_err(|e| format!("not a saved trial result: {e}"))
    }

    /// The imitator's model, or a `ModelFileError` when the record keeps none.
    pub(crate) fn imitator_forward_model(&self) -> PyResult<Arc<ForwardModel>> {
        self.record.imitator_model.clone().ok_or_else(|| {
            ModelFileError::new_err("imitator model: this trial result keeps none (its imitator_model is empty)")
        })
    }

    fn models_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for model in &self.record.models {
            out.set_item(&model.name, PyModelResult::wrap(model.clone()))?;
        }
        Ok(out)
    }
}

#[pymethods]
impl PyTrialResult {
    #[new]
    #[pyo3(signature = (models, imitator, seed, imitator_model=""))]
    fn new(models: &Bound<'_, PyDict>, imitator: &PyModelResult, seed: i128, imitator_model: &str) -> PyResult<Self> {
        let mut records = Vec::with_capacity(models.len());
        for (key, value) in models.iter() {
            let name: String =
                key.extract().map_err(|_| PyTypeError::new_err("models: keys must be the models' names (str)"))?;
            let model = value
                .cast::<PyModelResult>()
                .map_err(|_| PyTypeError::new_err(format!("models.{name}: not a ModelResult")))?;
            if model.get().record.name != name {
                return Err(PyValueError::new_err(format!(
                    "models.{name}: the model is named '{}'",
                    model.get().record.name
                )));
            }
            records.push((*model.get().record).clone());
        }
        let seed = u64::try_from(seed)
            .map_err(|_| PyValueError::new_err(format!("seed must be a whole number in 0..2**64, got {seed}")))?;
        let parsed = if imitator_model.is_empty() {
            None
        } else {
            Some(Arc::new(
                ForwardModel::from_json(imitator_model)
                    .map_err(|e| PyValueError::new_err(format!("imitator_model: {e}")))?,
            ))
        };
        Ok(Self::wrap(TrialRecord {
            models: records,
            imitator: (*imitator.record).clone(),
            seed,
            imitator_model_json: imitator_model.to_owned(),
            imitator_model: parsed,
        }))
    }

    /// Every demonstrator's model by name, in the ordering (a new dictionary).
    #[getter]
    fn models<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.models_dict(py)
    }

    /// The imitator's own model's record (a `ModelResult`).
    #[getter]
    fn imitator(&self) -> PyModelResult {
        PyModelResult::wrap(self.record.imitator.clone())
    }

    /// The trial's seed: the trial depends on it alone.
    #[getter]
    fn seed(&self) -> u64 {
        self.record.seed
    }

    /// The imitator's final model, as versioned JSON.
    #[getter]
    fn imitator_model(&self) -> &str {
        &self.record.imitator_model_json
    }

    /// Every field as plain data (``models`` a dictionary of dictionaries).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        let models = PyDict::new(py);
        for model in &self.record.models {
            models.set_item(&model.name, PyModelResult::wrap(model.clone()).dict(py)?)?;
        }
        out.set_item("models", models)?;
        out.set_item("imitator", PyModelResult::wrap(self.record.imitator.clone()).dict(py)?)?;
        out.set_item("seed", self.record.seed)?;
        out.set_item("imitator_model", &self.record.imitator_model_json)?;
        Ok(out)
    }

    /// The trial as JSON text (what ``save`` writes).
    fn to_json(&self) -> String {
        self.record.to_json()
    }

    /// A trial from ``to_json`` text, every value checked.
    #[classmethod]
    fn from_json(_cls: &Bound<'_, PyType>, py: Python<'_>, text: &str) -> PyResult<Self> {
        py.detach(|| Self::parse(text)).map(Self::wrap).map_err(ModelFileError::new_err)
    }

    /// Writes the trial to ``path`` (JSON), atomically.
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn save(&self, path: PathBuf) -> PyResult<()> {
        write_atomically(&path, &self.record.to_json())
    }

    /// Reads a trial written by ``save``.
    #[classmethod]
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn load(_cls: &Bound<'_, PyType>, py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let text = read_text(&path)?;
        py.detach(|| Self::parse(&text))
            .map(Self::wrap)
            .map_err(|e| ModelFileError::new_err(format!("{}: {e}", path.display())))
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.record == other.record
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        Ok((slf.get_type().getattr("from_json")?, PyTuple::new(py, [slf.get().record.to_json()])?))
    }

    fn __repr__(&self) -> String {
        let names: Vec<&str> = self.record.models.iter().map(|m| m.name.as_str()).collect();
        format!(
            "TrialResult(seed={}, models={names:?}, imitator: {} behaviours)",
            self.record.seed,
            self.record.imitator.behaviours.len()
        )
    }
}
