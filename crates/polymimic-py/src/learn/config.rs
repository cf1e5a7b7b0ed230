//! `polymimic.LearningConfig`: every constant of learning, validated once at construction.
// The docstrings are Python's: their examples quote Python lists, not Rust doc links.
#![allow(clippy::doc_link_with_quotes)]

use std::hash::{DefaultHasher, Hash, Hasher};

use polymimic_learn::{
    ImitatorWeighting, LearningConfig, LpApproachWeight, LpBounds, LpCriteria, LpScope, WorldWeighting,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString, PyTuple, PyType};

use crate::convert::one_of;

/// Every constant, in the order `to_dict` and `repr` give them.
const NAMES: [&str; 32] = [
    "creation_threshold",
    "default_permanency",
    "permanency_threshold",
    "deletion_threshold",
    "min_frequency",
    "decay_step",
    "permanency_step",
    "initial_lp",
    "imitator_lp",
    "hold_lp",
    "imitator_weighting",
    "world_weighting",
    "lp_goal",
    "lp_own_goal_weight",
    "lp_ball_to_goal",
    "lp_robot_to_ball",
    "lp_event",
    "match_distance_mm",
    "match_rotation_deg",
    "ball_angle_tolerance_deg",
    "ball_min_samples",
    "ball_max_angle_sd_deg",
    "ball_moved_mm",
    "prediction_noise_divisor",
    "ball_dead_band_mm",
    "robot_dead_band_mm",
    "prefer_sooner_goals",
    "push_heading_tail",
    "lp_bounds",
    "lp_scope",
    "lp_criteria",
    "lp_approach_weight",
];

const BOUNDS: [(&str, LpBounds); 2] = [("soft", LpBounds::Soft), ("clamp", LpBounds::Clamp)];
const SCOPES: [(&str, LpScope); 2] = [("own_demonstrator", LpScope::OwnDemonstrator), ("every", LpScope::Every)];
const CRITERIA: [(&str, LpCriteria); 2] = [("foremost", LpCriteria::Foremost), ("both", LpCriteria::Both)];
const WEIGHTS: [(&str, LpApproachWeight); 2] =
    [("per_demonstration", LpApproachWeight::PerDemonstration), ("per_span", LpApproachWeight::PerSpan)];
const WEIGHTINGS: [(&str, ImitatorWeighting); 3] =
    [("even", ImitatorWeighting::Even), ("lp", ImitatorWeighting::Lp), ("lp_gain", ImitatorWeighting::LpGain)];

const WORLD_WEIGHTINGS: [(&str, WorldWeighting); 3] =
    [("every", WorldWeighting::Every), ("intent", WorldWeighting::Intent), ("outcome", WorldWeighting::Outcome)];

/// The Python name of an imitator weighting.
pub(crate) fn weighting_name(weighting: ImitatorWeighting) -> &'static str {
    name_of(&WEIGHTINGS, weighting)
}

fn name_of<T: PartialEq + Copy>(options: &[(&'static str, T)], value: T) -> &'static str {
    options.iter().find(|(_, o)| *o == value).map_or("", |(name, _)| name)
}

/// A number given for `name` (an int or a float, not a bool).
fn number(name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let refused =
        || -> PyResult<PyErr> { Ok(PyTypeError::new_err(format!("{name} must be a number, got {}", value.repr()?))) };
    if value.is_instance_of::<PyBool>() || value.is_instance_of::<PyString>() {
        return Err(refused()?);
    }
    match value.extract::<f64>() {
        Ok(x) => Ok(x),
        Err(_) => Err(refused()?),
    }
}

fn count(name: &str, value: &Bound<'_, PyAny>) -> PyResult<usize> {
    if value.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!("{name} must be a whole number, got {}", value.repr()?)));
    }
    let Ok(whole) = value.extract::<i64>() else {
        return Err(PyTypeError::new_err(format!("{name} must be a whole number, got {}", value.repr()?)));
    };
    usize::try_from(whole).map_err(|_| PyValueError::new_err(format!("config: {name} = {whole} must be ≥ 0")))
}

/// A switch given for `name`: `True` or `False` only.
fn flag(name: &str, value: &Bound<'_, PyAny>) -> PyResult<bool> {
    if !value.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!("{name} must be True or False, got {}", value.repr()?)));
    }
    value.extract()
}

fn choice<T: Copy>(name: &str, value: &Bound<'_, PyAny>, options: &[(&str, T)]) -> PyResult<T> {
    let text: String = value.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} must be a string, got {}",
            value.repr().map_or_else(|_| String::new(), |r| r.to_string())
        ))
    })?;
    one_of(name, &text, options)
}

/// Sets one constant by name.
fn set(c: &mut LearningConfig, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
    let float = |field: &mut f64| -> PyResult<()> {
        *field = number(name, value)?;
        Ok(())
    };
    match name {
        "creation_threshold" => float(&mut c.creation_threshold),
        "default_permanency" => float(&mut c.default_permanency),
        "permanency_threshold" => float(&mut c.permanency_threshold),
        "deletion_threshold" => float(&mut c.deletion_threshold),
        "min_frequency" => float(&mut c.min_frequency),
        "decay_step" => float(&mut c.decay_step),
        "permanency_step" => float(&mut c.permanency_step),
        "initial_lp" => float(&mut c.initial_lp),
        "imitator_lp" => float(&mut c.imitator_lp),
        "hold_lp" => flag(name, value).map(|v| c.hold_lp = v),
        "prefer_sooner_goals" => flag(name, value).map(|v| c.prefer_sooner_goals = v),
        "imitator_weighting" => choice(name, value, &WEIGHTINGS).map(|v| c.imitator_weighting = v),
        "world_weighting" => choice(name, value, &WORLD_WEIGHTINGS).map(|v| c.world_weighting = v),
        "lp_goal" => float(&mut c.lp_goal),
        "lp_own_goal_weight" => float(&mut c.lp_own_goal_weight),
        "lp_ball_to_goal" => float(&mut c.lp_ball_to_goal),
        "lp_robot_to_ball" => float(&mut c.lp_robot_to_ball),
        "lp_event" => float(&mut c.lp_event),
        "match_distance_mm" => float(&mut c.match_distance_mm),
        "match_rotation_deg" => float(&mut c.match_rotation_deg),
        "ball_angle_tolerance_deg" => float(&mut c.ball_angle_tolerance_deg),
        "ball_min_samples" => count(name, value).map(|n| c.ball_min_samples = n),
        "ball_max_angle_sd_deg" => float(&mut c.ball_max_angle_sd_deg),
        "ball_moved_mm" => float(&mut c.ball_moved_mm),
        "prediction_noise_divisor" => float(&mut c.prediction_noise_divisor),
        "ball_dead_band_mm" => float(&mut c.ball_dead_band_mm),
        "robot_dead_band_mm" => float(&mut c.robot_dead_band_mm),
        "push_heading_tail" => float(&mut c.push_heading_tail),
        "lp_bounds" => choice(name, value, &BOUNDS).map(|v| c.lp_bounds = v),
        "lp_scope" => choice(name, value, &SCOPES).map(|v| c.lp_scope = v),
        "lp_criteria" => choice(name, value, &CRITERIA).map(|v| c.lp_criteria = v),
        "lp_approach_weight" => choice(name, value, &WEIGHTS).map(|v| c.lp_approach_weight = v),
        _ => Err(PyTypeError::new_err(format!(
            "LearningConfig has no constant '{name}'; the constants are {}",
            NAMES.join(", ")
        ))),
    }
}

/// Every constant of learning (thesis Table 3.2, §3.3, §3.4); defaults are the thesis's.
///
/// Keyword arguments set constants (an unknown one is a ``TypeError`` listing them all); the
/// whole config is checked once, here, and a value out of range is a ``ValueError`` naming the
/// constant, the value and what it may be. Instances are immutable: ``replace`` makes a
/// changed copy. They compare, hash and pickle by value.
///
/// ``hold_lp=True`` holds every demonstrator's LP at ``initial_lp`` throughout a trial (the
/// uniform-LP ablation). ``imitator_weighting`` is ``"even"`` (every demonstration counts the
/// same for the imitator, the thesis) or ``"lp"``: a demonstration by member m counts with
/// weight ``LP_m / max_k LP_k`` (all 1 if every LP is 0), scaling the imitator's frequency
/// and permanency gains from it in phase 2 (the LPs of that moment; decay is not scaled) and
/// its samples in the improved control's world model (the final LPs); or ``"lp_gain"``: the
/// same, each member weighed by how far its LP rose above ``initial_lp``,
/// ``(LP_m − LP₀)⁺ / max_k (LP_k − LP₀)⁺`` (all 1 if none rose). ``world_weighting`` names
/// the parts of the improved control's world model those weights reach: ``"outcome"`` (the
/// default) none, each sample counting by the outcome it led to alone; ``"intent"`` the push
/// region and the states' values, while the ball's response (physics, the same whoever
/// pushes) learns from every demonstration at full weight; ``"every"`` all three.
///
/// Examples
/// --------
/// >>> config = LearningConfig(permanency_step=0.03)
/// >>> config.permanency_step, config.lp_bounds
/// (0.03, 'soft')
/// >>> config.replace(lp_bounds="clamp") == LearningConfig(permanency_step=0.03, lp_bounds="clamp")
/// True
/// >>> LearningConfig(initial_lp=1.5)
/// Traceback (most recent call last):
/// ...
/// ValueError: config: initial_lp = 1.5 must be in [0, 1]
#[pyclass(name = "LearningConfig", module = "polymimic", frozen, subclass)]
pub struct PyLearningConfig {
    pub(crate) config: LearningConfig,
}

impl PyLearningConfig {
    fn build(changes: Option<&Bound<'_, PyDict>>, base: &LearningConfig) -> PyResult<LearningConfig> {
        let mut config = base.clone();
        if let Some(changes) = changes {
            for (key, value) in changes.iter() {
                let name: String = key.extract()?;
                set(&mut config, &name, &value)?;
            }
        }
        config.check().map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(config)
    }

    /// The value of constant `name` as Python data.
    fn value<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let c = &self.config;
        let float = |x: f64| Ok(x.into_pyobject(py)?.into_any());
        match name {
            "ball_min_samples" => Ok(c.ball_min_samples.into_pyobject(py)?.into_any()),
            "hold_lp" => Ok(PyBool::new(py, c.hold_lp).to_owned().into_any()),
            "prefer_sooner_goals" => Ok(PyBool::new(py, c.prefer_sooner_goals).to_owned().into_any()),
            "imitator_weighting" => Ok(PyString::new(py, name_of(&WEIGHTINGS, c.imitator_weighting)).into_any()),
            "world_weighting" => Ok(PyString::new(py, name_of(&WORLD_WEIGHTINGS, c.world_weighting)).into_any()),
            "lp_bounds" => Ok(PyString::new(py, name_of(&BOUNDS, c.lp_bounds)).into_any()),
            "lp_scope" => Ok(PyString::new(py, name_of(&SCOPES, c.lp_scope)).into_any()),
            "lp_criteria" => Ok(PyString::new(py, name_of(&CRITERIA, c.lp_criteria)).into_any()),
            "lp_approach_weight" => Ok(PyString::new(py, name_of(&WEIGHTS, c.lp_approach_weight)).into_any()),
            "creation_threshold" => float(c.creation_threshold),
            "default_permanency" => float(c.default_permanency),
            "permanency_threshold" => float(c.permanency_threshold),
            "deletion_threshold" => float(c.deletion_threshold),
            "min_frequency" => float(c.min_frequency),
            "decay_step" => float(c.decay_step),
            "permanency_step" => float(c.permanency_step),
            "initial_lp" => float(c.initial_lp),
            "imitator_lp" => float(c.imitator_lp),
            "lp_goal" => float(c.lp_goal),
            "lp_own_goal_weight" => float(c.lp_own_goal_weight),
            "lp_ball_to_goal" => float(c.lp_ball_to_goal),
            "lp_robot_to_ball" => float(c.lp_robot_to_ball),
            "lp_event" => float(c.lp_event),
            "match_distance_mm" => float(c.match_distance_mm),
            "match_rotation_deg" => float(c.match_rotation_deg),
            "ball_angle_tolerance_deg" => float(c.ball_angle_tolerance_deg),
            "ball_max_angle_sd_deg" => float(c.ball_max_angle_sd_deg),
            "ball_moved_mm" => float(c.ball_moved_mm),
            "prediction_noise_divisor" => float(c.prediction_noise_divisor),
            "ball_dead_band_mm" => float(c.ball_dead_band_mm),
            "robot_dead_band_mm" => float(c.robot_dead_band_mm),
            "push_heading_tail" => float(c.push_heading_tail),
            _ => Err(PyTypeError::new_err(format!("LearningConfig has no constant '{name}'"))),
        }
    }

    fn dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for name in NAMES {
            out.set_item(name, self.value(py, name)?)?;
        }
        Ok(out)
    }
}

/// The config a call was given, or the defaults.
pub(crate) fn config_or_default(config: Option<&Bound<'_, PyLearningConfig>>) -> LearningConfig {
    config.map_or_else(LearningConfig::default, |c| c.get().config.clone())
}

#[pymethods]
impl PyLearningConfig {
    #[new]
    #[pyo3(signature = (**constants))]
    fn new(constants: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        Ok(Self { config: Self::build(constants, &LearningConfig::default())? })
    }

    /// A copy with the constants given changed, checked again.
    ///
    /// >>> LearningConfig().replace(decay_step=0.01).decay_step
    /// 0.01
    #[pyo3(signature = (**changes))]
    fn replace<'py>(slf: &Bound<'py, Self>, changes: Option<&Bound<'py, PyDict>>) -> PyResult<Bound<'py, PyAny>> {
        let values = slf.get().dict(slf.py())?;
        if let Some(changes) = changes {
            Self::build(Some(changes), &slf.get().config)?;
            values.update(changes.as_mapping())?;
        }
        slf.get_type().call((), Some(&values))
    }

    /// Every constant by name, in order: plain Python floats, an int and strings.
    ///
    /// >>> list(LearningConfig().to_dict())[:2]
    /// ['creation_threshold', 'default_permanency']
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.dict(py)
    }

    #[classmethod]
    fn _from_dict<'py>(cls: &Bound<'py, PyType>, values: &Bound<'py, PyDict>) -> PyResult<Bound<'py, PyAny>> {
        cls.call((), Some(values))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let values = slf.get().dict(slf.py())?;
        Ok((slf.get_type().getattr("_from_dict")?, PyTuple::new(slf.py(), [values])?))
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.config == other.config
    }

    fn __hash__(&self) -> u64 {
        let mut hasher = DefaultHasher::new();
        self.config.to_json().hash(&mut hasher);
        hasher.finish()
    }

    fn __repr__(slf: &Bound<'_, Self>) -> PyResult<String> {
        let py = slf.py();
        let parts: Vec<String> = NAMES
            .iter()
            .map(|name| Ok(format!("{name}={}", slf.get().value(py, name)?.repr()?)))
            .collect::<PyResult<_>>()?;
        Ok(format!("{}({})", slf.get_type().name()?, parts.join(", ")))
    }

    #[getter]
    fn creation_threshold(&self) -> f64 {
        self.config.creation_threshold
    }
    #[getter]
    fn default_permanency(&self) -> f64 {
        self.config.default_permanency
    }
    #[getter]
    fn permanency_threshold(&self) -> f64 {
        self.config.permanency_threshold
    }
    #[getter]
    fn deletion_threshold(&self) -> f64 {
        self.config.deletion_threshold
    }
    #[getter]
    fn min_frequency(&self) -> f64 {
        self.config.min_frequency
    }
    #[getter]
    fn decay_step(&self) -> f64 {
        self.config.decay_step
    }
    #[getter]
    fn permanency_step(&self) -> f64 {
        self.config.permanency_step
    }
    #[getter]
    fn initial_lp(&self) -> f64 {
        self.config.initial_lp
    }
    #[getter]
    fn imitator_lp(&self) -> f64 {
        self.config.imitator_lp
    }
    /// Whether every demonstrator's LP is held at `initial_lp` throughout a trial.
    #[getter]
    fn hold_lp(&self) -> bool {
        self.config.hold_lp
    }
    /// Whether, under the improved control, of two predicted goals the sooner rates better.
    #[getter]
    fn prefer_sooner_goals(&self) -> bool {
        self.config.prefer_sooner_goals
    }
    /// `"even"`, `"lp"` or `"lp_gain"`.
    #[getter]
    fn imitator_weighting(&self) -> &'static str {
        name_of(&WEIGHTINGS, self.config.imitator_weighting)
    }
    /// `"outcome"`, `"intent"` or `"every"`: the parts of the improved control's world model
    /// the imitator weighting reaches.
    #[getter]
    fn world_weighting(&self) -> &'static str {
        name_of(&WORLD_WEIGHTINGS, self.config.world_weighting)
    }
    #[getter]
    fn lp_goal(&self) -> f64 {
        self.config.lp_goal
    }
    /// How many times `lp_goal` an own goal lowers the LP by.
    #[getter]
    fn lp_own_goal_weight(&self) -> f64 {
        self.config.lp_own_goal_weight
    }
    #[getter]
    fn lp_ball_to_goal(&self) -> f64 {
        self.config.lp_ball_to_goal
    }
    #[getter]
    fn lp_robot_to_ball(&self) -> f64 {
        self.config.lp_robot_to_ball
    }
    #[getter]
    fn lp_event(&self) -> f64 {
        self.config.lp_event
    }
    #[getter]
    fn match_distance_mm(&self) -> f64 {
        self.config.match_distance_mm
    }
    #[getter]
    fn match_rotation_deg(&self) -> f64 {
        self.config.match_rotation_deg
    }
    #[getter]
    fn ball_angle_tolerance_deg(&self) -> f64 {
        self.config.ball_angle_tolerance_deg
    }
    #[getter]
    fn ball_min_samples(&self) -> usize {
        self.config.ball_min_samples
    }
    #[getter]
    fn ball_max_angle_sd_deg(&self) -> f64 {
        self.config.ball_max_angle_sd_deg
    }
    #[getter]
    fn ball_moved_mm(&self) -> f64 {
        self.config.ball_moved_mm
    }
    #[getter]
    fn prediction_noise_divisor(&self) -> f64 {
        self.config.prediction_noise_divisor
    }
    #[getter]
    fn ball_dead_band_mm(&self) -> f64 {
        self.config.ball_dead_band_mm
    }
    #[getter]
    fn robot_dead_band_mm(&self) -> f64 {
        self.config.robot_dead_band_mm
    }
    /// The share of pushing headings the improved control's push region leaves out at each end.
    #[getter]
    fn push_heading_tail(&self) -> f64 {
        self.config.push_heading_tail
    }
    #[getter]
    fn lp_bounds(&self) -> &'static str {
        name_of(&BOUNDS, self.config.lp_bounds)
    }
    #[getter]
    fn lp_scope(&self) -> &'static str {
        name_of(&SCOPES, self.config.lp_scope)
    }
    #[getter]
    fn lp_criteria(&self) -> &'static str {
        name_of(&CRITERIA, self.config.lp_criteria)
    }
    #[getter]
    fn lp_approach_weight(&self) -> &'static str {
        name_of(&WEIGHTS, self.config.lp_approach_weight)
    }
}
