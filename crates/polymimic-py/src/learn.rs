//! Learning trials from Python: segmented demonstrations in, models and metrics out.

use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use polymimic_learn::{
    ControlMode, Ending, ForwardModel, ImitatorPolicy, LearningConfig, MotionTable, PhaseOne, Pitch,
    SegmentedDemonstration, WorldModel, run_trial,
};
use polymimic_perceive::{Label, Segment};
use polymimic_types::{MotionStats, Pose, Primitive, TrackedFrame};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::convert::{non_negative, one_of};
use crate::errors::{learn_error, learn_params_error};

/// The learning constants with their defaults, as JSON.
#[pyfunction]
pub fn default_learning_config() -> String {
    LearningConfig::default().to_json()
}

/// Checks a learning config given as JSON; returns it with every field filled in.
#[pyfunction]
pub fn check_learning_config(config: &str) -> PyResult<String> {
    Ok(LearningConfig::from_json(config).map_err(learn_params_error)?.to_json())
}

/// The config a call passes as JSON, or the defaults.
fn learning_config(json: Option<&str>) -> PyResult<LearningConfig> {
    json.map_or_else(
        || Ok(LearningConfig::default()),
        |text| LearningConfig::from_json(text).map_err(learn_params_error),
    )
}

fn motion_table(stats: &Bound<'_, PyDict>) -> PyResult<MotionTable> {
    let mut rows = Vec::new();
    for primitive in Primitive::ALL {
        let row = stats
            .get_item(primitive.name())?
            .ok_or_else(|| PyValueError::new_err(format!("motion_stats has no row for {}", primitive.name())))?;
        let get = |key: &str| -> PyResult<f64> { row.get_item(key)?.extract() };
        rows.push(MotionStats {
            primitive,
            count: row.get_item("count").and_then(|c| c.extract()).unwrap_or(0),
            distance_mean_mm: get("distance_mean_mm")?,
            distance_sd_mm: get("distance_sd_mm")?,
            rotation_mean_deg: get("rotation_mean_deg")?,
            rotation_sd_deg: get("rotation_sd_deg")?,
        });
    }
    MotionTable::new(&rows).map_err(learn_params_error)
}

fn frame(row: &[f64]) -> TrackedFrame {
    TrackedFrame { robot: Pose::new(row[0], row[1], row[2]), ball_x_mm: row[3], ball_y_mm: row[4] }
}

fn demonstration(index: usize, item: &Bound<'_, PyAny>) -> PyResult<SegmentedDemonstration> {
    let what = |field: &str| format!("demonstration {index}: {field}");
    let demonstrator: String = item.get_item("demonstrator")?.extract()?;
    let pitch = match item.get_item("pitch")?.extract::<String>()?.as_str() {
        "large" => Pitch::LARGE,
        "small" => Pitch::SMALL,
        other => return Err(PyValueError::new_err(format!("{}: {other:?} is not large or small", what("pitch")))),
    };
    let ending = match item.get_item("outcome")?.extract::<String>()?.as_str() {
        "goal" => Ending::Goal,
        "own_goal" => Ending::OwnGoal,
        _ => Ending::Other,
    };
    let segments = item.get_item("segments")?;
    let labels: Vec<String> = segments.get_item("label")?.extract()?;
    let first: PyReadonlyArray1<i64> = segments.get_item("first_frame")?.extract()?;
    let last: PyReadonlyArray1<i64> = segments.get_item("last_frame")?.extract()?;
    let start: PyReadonlyArray2<f64> = segments.get_item("start")?.extract()?;
    let end: PyReadonlyArray2<f64> = segments.get_item("end")?.extract()?;
    let (first, last, start, end) = (first.as_array(), last.as_array(), start.as_array(), end.as_array());
    let k = labels.len();
    if first.len() != k || last.len() != k || start.shape() != [k, 5] || end.shape() != [k, 5] {
        return Err(PyValueError::new_err(format!("{}: columns of different lengths", what("segments"))));
    }
    let segments = (0..k)
        .map(|i| {
            let label = match labels[i].as_str() {
                "gap" => Label::Gap,
                name => Label::Primitive(
                    Primitive::from_name(name)
                        .ok_or_else(|| PyValueError::new_err(format!("{}: label {name:?}", what("segments"))))?,
                ),
            };
            let row = |a: &numpy::ndarray::ArrayView2<f64>| a.row(i).to_vec();
            Ok(Segment {
                label,
                first_frame: usize::try_from(first[i]).unwrap_or(0),
                last_frame: usize::try_from(last[i]).unwrap_or(0),
                start: frame(&row(&start)),
                end: frame(&row(&end)),
                scores: [f64::NEG_INFINITY; 4],
            })
        })
        .collect::<PyResult<Vec<_>>>()?;
    Ok(SegmentedDemonstration { demonstrator, pitch, ending, segments })
}

fn model_dict<'py>(py: Python<'py>, model: &ForwardModel) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let m = &model.metrics;
    out.set_item("name", &model.name)?;
    out.set_item("lp", model.lp)?;
    out.set_item("lp_history", model.lp_history.clone())?;
    out.set_item("match_rate", model.match_rate())?;
    for (key, value) in [
        ("created", m.created),
        ("deleted", m.deleted),
        ("permanent", m.made_permanent),
        ("candidates", m.candidates),
        ("duplicates", m.duplicates),
        ("candidates_permanent", m.candidates_permanent),
        ("rounds", m.rounds),
        ("rounds_matched", m.rounds_matched),
    ] {
        out.set_item(key, value)?;
    }
    let causes = PyDict::new(py);
    for (key, value) in m.lp_causes.named() {
        causes.set_item(key, value)?;
    }
    out.set_item("lp_causes", causes)?;
    let behaviours = PyList::empty(py);
    for b in &model.behaviours {
        let row = PyDict::new(py);
        row.set_item("primitives", b.letters())?;
        row.set_item("permanency", b.permanency)?;
        row.set_item("permanent", b.permanent)?;
        row.set_item("age", b.age)?;
        row.set_item("selected", b.selected)?;
        row.set_item("ball_samples", b.ball_angle_deg.count)?;
        row.set_item("ball_angle_deg", [b.ball_angle_deg.mean, b.ball_angle_deg.sd()])?;
        row.set_item("ball_distance_mm", [b.ball_distance_mm.mean, b.ball_distance_mm.sd()])?;
        behaviours.append(row)?;
    }
    out.set_item("behaviours", behaviours)?;
    Ok(out)
}

fn segmented_demonstrations(items: &Bound<'_, PyAny>) -> PyResult<Vec<SegmentedDemonstration>> {
    items.try_iter()?.enumerate().map(|(i, d)| demonstration(i, &d?)).collect()
}

/// One learning trial. `demonstrations` are dicts with `demonstrator`, `pitch` ("large" or
/// "small"), `outcome` and `segments` (as `PrimitiveRecognizer.segment` returns them);
/// `motion_stats` is the recogniser's Table 3.1. Returns the models' metrics, LP histories
/// and behaviours, for every demonstrator's model and the imitator's.
#[pyfunction]
#[pyo3(signature = (demonstrations, ordering, motion_stats, *, config=None, phase_one="by-model", seed=0))]
#[allow(clippy::needless_pass_by_value)] // pyo3 extracts the ordering by value
pub fn learning_trial<'py>(
    py: Python<'py>,
    demonstrations: &Bound<'py, PyAny>,
    ordering: Vec<String>,
    motion_stats: &Bound<'py, PyDict>,
    config: Option<&str>,
    phase_one: &str,
    seed: i64,
) -> PyResult<Bound<'py, PyDict>> {
    let demos = segmented_demonstrations(demonstrations)?;
    let config = learning_config(config)?;
    let phase_one =
        one_of("phase_one", phase_one, &[("by-model", PhaseOne::ByModel), ("interleaved", PhaseOne::Interleaved)])?;
    let motion = motion_table(motion_stats)?;
    let seed = non_negative("seed", seed)? as u64;
    let result = py.detach(|| run_trial(&demos, &ordering, &motion, &config, phase_one, seed)).map_err(learn_error)?;
    let out = PyDict::new(py);
    let models = PyList::empty(py);
    for model in &result.models {
        models.append(model_dict(py, model)?)?;
    }
    out.set_item("models", models)?;
    out.set_item("imitator", model_dict(py, &result.imitator)?)?;
    out.set_item("imitator_model", result.imitator.to_json())?;
    Ok(out)
}

/// The imitator's trained model driving the Lego robot on the field.
#[pyclass(name = "ImitatorPolicy", module = "polymimic", frozen)]
pub struct PyImitatorPolicy {
    model: ForwardModel,
    motion: MotionTable,
    config: LearningConfig,
    mode: ControlMode,
    world: Option<WorldModel>,
}

#[pymethods]
impl PyImitatorPolicy {
    /// A policy from a saved imitator model (`TrialResult.imitator_model`), the recogniser's
    /// Table 3.1 and the learning config (JSON) its constants come from; `control` is
    /// `"thesis"` (the thesis's rule) or `"improved"`, which learns how the ball responds, how
    /// good each state is and where pushes toward the goal are made from `demonstrations`
    /// (segmented, as for `learning_trial`).
    #[new]
    #[pyo3(signature = (model, motion_stats, *, config=None, control="thesis", demonstrations=None))]
    fn new(
        model: &str,
        motion_stats: &Bound<'_, PyDict>,
        config: Option<&str>,
        control: &str,
        demonstrations: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let mode =
            one_of("control mode", control, &[("thesis", ControlMode::Thesis), ("improved", ControlMode::Improved)])?;
        let model = ForwardModel::from_json(model).map_err(|e| learn_error(e.context("imitator model")))?;
        let config = learning_config(config)?;
        let motion = motion_table(motion_stats)?;
        let world = match (mode, demonstrations) {
            (ControlMode::Thesis, _) => None,
            (ControlMode::Improved, None) => {
                return Err(PyValueError::new_err(
                    "the improved control learns from the demonstrations the imitator watched: pass demonstrations=",
                ));
            }
            (ControlMode::Improved, Some(items)) => {
                let demos = segmented_demonstrations(items)?;
                if !demos.iter().any(|d| d.pitch == Pitch::LARGE) {
                    return Err(PyValueError::new_err(
                        "demonstrations: none was played on the imitator's (large) field, so there is nothing to learn the ball's response from",
                    ));
                }
                Some(WorldModel::learn(&demos, &Pitch::LARGE, &motion, &config))
            }
        };
        Ok(Self { model, motion, config, mode, world })
    }

    /// Attempts from each configuration; one dict per attempt with `frames`, `outcome`,
    /// `configuration`, `seed` and the `behaviours` executed.
    #[pyo3(signature = (attempts_per_configuration, *, seed=0, field_config=None))]
    fn evaluate<'py>(
        &self,
        py: Python<'py>,
        attempts_per_configuration: i64,
        seed: i64,
        field_config: Option<&str>,
    ) -> PyResult<Bound<'py, PyList>> {
        let attempts = non_negative("attempts_per_configuration", attempts_per_configuration)?;
        let field = crate::field::field_config(field_config)?;
        let policy = ImitatorPolicy {
            model: &self.model,
            motion: &self.motion,
            config: &self.config,
            pitch: Pitch::LARGE,
            mode: self.mode,
            world: self.world.as_ref(),
        };
        let seed = non_negative("seed", seed)? as u64;
        let results = py.detach(|| policy.evaluate(attempts, &field, seed)).map_err(crate::errors::field_error)?;
        let out = PyList::empty(py);
        for attempt in &results {
            let item = PyDict::new(py);
            item.set_item("frames", crate::field::frames_array(py, &attempt.frames)?)?;
            item.set_item("outcome", attempt.outcome.name())?;
            item.set_item("configuration", crate::field::configuration_number(attempt.configuration))?;
            item.set_item("seed", attempt.seed)?;
            item.set_item("behaviours", attempt.behaviours.clone())?;
            out.append(item)?;
        }
        Ok(out)
    }

    /// `"thesis"` or `"improved"`.
    #[getter]
    fn control(&self) -> &'static str {
        match self.mode {
            ControlMode::Thesis => "thesis",
            ControlMode::Improved => "improved",
        }
    }

    /// How many behaviours the model holds.
    fn __len__(&self) -> usize {
        self.model.behaviours.len()
    }
}
