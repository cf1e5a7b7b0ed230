//! `polymimic.ImitatorPolicy`: a trial's imitator driving its body on the field.

use std::sync::Arc;

use polymimic_field::BodyKind;
use polymimic_learn::{
    Attempt, ControlMode, ForwardModel, ImitatorPolicy, ImitatorWeighting, LearningConfig, MotionTable, Pitch,
    Practice, Refines, Setting, StartAt, WorldModel, demonstration_weights, onto_setting,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use super::config::{PyLearningConfig, config_or_default, weighting_name};
use super::motion_table;
use super::player::PyImitatorPlayer;
use super::segments::batch;
use super::trial::PyTrialResult;
use crate::bodies::{BodyValue, PyBody};
use crate::convert::{Seed, non_negative, one_of};
use crate::perceive::PyPrimitiveRecognizer;
use crate::starts::{StartArg, start_dict};

/// Attempts as Python dictionaries: ``frames``, ``outcome``, ``configuration``, ``seed`` and the
/// ``behaviours`` executed.
pub(crate) fn attempt_list<'py>(py: Python<'py>, attempts: &[Attempt]) -> PyResult<Bound<'py, PyList>> {
    let out = PyList::empty(py);
    for attempt in attempts {
        let item = PyDict::new(py);
        item.set_item("frames", crate::field::frames_array(py, &attempt.frames)?)?;
        item.set_item("outcome", attempt.outcome.name())?;
        item.set_item("configuration", attempt.configuration.map(crate::starts::configuration_number))?;
        item.set_item("start", start_dict(py, attempt.configuration, &attempt.start)?)?;
        item.set_item("seed", attempt.seed)?;
        item.set_item("behaviours", attempt.behaviours.clone())?;
        out.append(item)?;
    }
    Ok(out)
}

/// The imitator's final model driving ``body`` (default the Lego robot) on that body's field.
///
/// ``control="thesis"`` is the thesis's rule (§3.4): behaviours whose preconditions hold
/// (else all) predict their outcome with their own ball statistics, and the best by the
/// learning-preference criteria runs primitive by primitive, stopping before leaving the
/// field. ``control="improved"`` learns from ``demonstrations`` (those the imitator watched,
/// segmented) how the ball responds to each primitive, how good each state is and where the
/// scoring demonstrations pushed from, and chooses again after every primitive. With
/// ``config.imitator_weighting == "lp"`` each demonstration's samples weigh
/// ``LP / max LP`` of its demonstrator's model in ``trial`` (the final LPs); a demonstration
/// whose demonstrator has no model there is a ``ValueError``. The improved control learns the
/// ball's response from the demonstrations played on the imitator's field only.
/// ``unlearned`` names parts the demonstrations do not teach (an ablation), each left as the
/// imitator's self-observation alone would: ``"ball_response"`` (the ball stays),
/// ``"state_value"`` (every state worth 0), ``"push_region"`` (no region to route to) and
/// ``"behaviours"`` (the imitator's primitives, none chained).
#[pyclass(name = "ImitatorPolicy", module = "polymimic", frozen, subclass)]
pub struct PyImitatorPolicy {
    model: Arc<ForwardModel>,
    motion: MotionTable,
    config: LearningConfig,
    mode: ControlMode,
    /// The body as it was given (a body of one's own keeps its description).
    body: Py<PyBody>,
    /// Shared by the policies [`Self::for_trial`] makes from this one.
    world: Option<Arc<WorldModel>>,
}

#[pymethods]
impl PyImitatorPolicy {
    #[new]
    #[pyo3(
        signature = (trial, *, recognizer, config=None, control="thesis", demonstrations=None, body=None,
                     practice=None, practice_weight=1.0, refines=None, unlearned=None),
        text_signature = "(trial, *, recognizer, config=None, control='thesis', demonstrations=None, body='lego', practice=None, practice_weight=1.0, refines=None, unlearned=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        trial: &PyTrialResult,
        recognizer: &PyPrimitiveRecognizer,
        config: Option<&Bound<'_, PyLearningConfig>>,
        control: &str,
        demonstrations: Option<&Bound<'_, PyAny>>,
        body: Option<BodyValue>,
        practice: Option<&Bound<'_, PyAny>>,
        practice_weight: f64,
        refines: Option<Vec<String>>,
        unlearned: Option<Vec<String>>,
    ) -> PyResult<Self> {
        let body_value = match body {
            Some(given) => given,
            None => BodyValue::lego(py)?,
        };
        let body = body_value.kind();
        let (unlearned, own_behaviours_only) = unlearned_parts(unlearned.as_deref().unwrap_or(&[]))?;
        let pitch = Pitch::of_body(body);
        let mode =
            one_of("control mode", control, &[("thesis", ControlMode::Thesis), ("improved", ControlMode::Improved)])?;
        let config = config_or_default(config);
        let motion = motion_table(recognizer)?;
        let model = if own_behaviours_only {
            // What self-observation alone gives the imitator: its own primitives, none chained.
            let primitives: Vec<_> = motion.primitives().collect();
            Arc::new(ForwardModel::of_primitives("imitator", config.imitator_lp, true, &primitives, &config))
        } else {
            trial.imitator_forward_model()?
        };
        let world = match (mode, demonstrations) {
            (ControlMode::Thesis, _) => None,
            (ControlMode::Improved, None) => {
                return Err(PyValueError::new_err(
                    "the improved control learns from the demonstrations the imitator watched: pass demonstrations=",
                ));
            }
            (ControlMode::Improved, Some(items)) => {
                let given = batch(items)?;
                let demos = onto_setting(&given, &Setting::of_imitator(body));
                let weights = match config.imitator_weighting {
                    ImitatorWeighting::Even => Vec::new(),
                    weighting => {
                        let lps: Vec<(String, f64)> =
                            trial.record.models.iter().map(|m| (m.name.clone(), m.lp)).collect();
                        demonstration_weights(&demos, &lps, weighting, config.initial_lp)
                            .map_err(crate::errors::learn_params_error)?
                    }
                };
                let own = practice.map(batch).transpose()?;
                let own = own.as_deref().map(|own| onto_setting(own, &Setting::of_imitator(body)));
                let practice = Practice {
                    attempts: own.as_deref().unwrap_or(&[]),
                    weight: at_least_zero("practice_weight", practice_weight)?,
                    refines: refined_parts(refines.as_deref())?,
                };
                Some(Arc::new(py.detach(|| {
                    WorldModel::learn_practised(&demos, &weights, &practice, &pitch, &motion, &config)
                        .without(unlearned)
                })))
            }
        };
        Ok(Self { model, motion, config, mode, body: body_value.0, world })
    }

    /// Attempts from each start (by default the thesis's configurations 1 and 2; a chosen
    /// start is ``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``), played by the
    /// stepped player; one dict per attempt with `frames`, `outcome`, `configuration` (None for
    /// a chosen start), `start`, `seed` and the `behaviours` executed.
    #[pyo3(signature = (attempts_per_configuration, *, seed=0, field_config=None, starts=None))]
    fn evaluate<'py>(
        &self,
        py: Python<'py>,
        attempts_per_configuration: i64,
        seed: u64,
        field_config: Option<&str>,
        starts: Option<Vec<StartArg>>,
    ) -> PyResult<Bound<'py, PyList>> {
        let attempts = non_negative("attempts_per_configuration", attempts_per_configuration)?;
        let field = crate::field::field_config(field_config)?;
        let policy = self.view();
        let results = match starts {
            None => py.detach(|| policy.evaluate(attempts, &field, seed)),
            Some(starts) => {
                let starts: Vec<StartAt> = starts.into_iter().map(|s| s.0).collect();
                py.detach(|| policy.evaluate_from(&starts, attempts, &field, seed))
            }
        }
        .map_err(crate::errors::field_error)?;
        attempt_list(py, &results)
    }

    /// ``n`` valid attempts of the imitator from ``configuration``, recorded as a
    /// demonstrator's are (episode seeds from ``seed`` as a Python policy's; attempts whose
    /// tracking was lost replaced): dicts like :func:`polymimic.record`'s.
    #[pyo3(signature = (*, configuration, n, seed=Seed(0), field_config=None),
           text_signature = "($self, *, configuration, n, seed=0, field_config=None)")]
    fn record<'py>(
        &self,
        py: Python<'py>,
        configuration: i64,
        n: i64,
        seed: Seed,
        field_config: Option<&str>,
    ) -> PyResult<Bound<'py, PyList>> {
        let (configuration, n) = (crate::starts::configuration(configuration)?, crate::field::positive("n", n)?);
        let field = crate::field::field_config(field_config)?;
        let policy = self.view();
        let recorded =
            py.detach(|| policy.record(configuration, n, seed.0, &field)).map_err(crate::errors::field_error)?;
        let out = PyList::empty(py);
        for r in &recorded {
            out.append(crate::field::recording(py, &r.frames, r.outcome, r.configuration, r.seed)?)?;
        }
        Ok(out)
    }

    /// A player of this imitator, stepped one tracker reading at a time (see
    /// :class:`polymimic.ImitatorPlayer`); call its ``reset`` first.
    fn player(slf: Py<Self>) -> PyImitatorPlayer {
        PyImitatorPlayer::new(slf)
    }

    /// The same control driving ``trial``'s imitator, with what this one learned from the
    /// demonstrations (the improved control's ball response, state values and routes) shared
    /// rather than learned again: the policy ``ImitatorPolicy(trial, ...)`` with this one's
    /// arguments would make, sooner. Under ``imitator_weighting="lp"`` or ``"lp_gain"`` what the
    /// improved control learns depends on the trial's LPs, so that is a ``ValueError``: make a
    /// new policy.
    fn for_trial(&self, py: Python<'_>, trial: &PyTrialResult) -> PyResult<Self> {
        if self.world.is_some() && self.config.imitator_weighting != ImitatorWeighting::Even {
            return Err(PyValueError::new_err(format!(
                "for_trial: under imitator_weighting=\"{}\" the improved control learns from the demonstrations by the trial's LPs; make a new ImitatorPolicy for each trial",
                weighting_name(self.config.imitator_weighting)
            )));
        }
        Ok(Self {
            model: trial.imitator_forward_model()?,
            motion: self.motion.clone(),
            config: self.config.clone(),
            mode: self.mode,
            body: self.body.clone_ref(py),
            world: self.world.clone(),
        })
    }

    /// `"thesis"` or `"improved"`.
    #[getter]
    fn control(&self) -> &'static str {
        match self.mode {
            ControlMode::Thesis => "thesis",
            ControlMode::Improved => "improved",
        }
    }

    /// The body the imitator drives, a :class:`polymimic.Body` (the one it was made with).
    #[getter]
    fn body(&self, py: Python<'_>) -> Py<PyBody> {
        self.body.clone_ref(py)
    }

    /// How many behaviours the model holds.
    fn __len__(&self) -> usize {
        self.model.behaviours.len()
    }

    fn __repr__(&self) -> String {
        format!("ImitatorPolicy({})", self.describe())
    }
}

impl PyImitatorPolicy {
    /// The control over this policy's parts.
    pub(crate) fn view(&self) -> ImitatorPolicy<'_> {
        ImitatorPolicy {
            model: &self.model,
            motion: &self.motion,
            config: &self.config,
            body: self.body_kind(),
            mode: self.mode,
            world: self.world.as_deref(),
        }
    }

    /// The body the imitator drives.
    pub(crate) fn body_kind(&self) -> BodyKind {
        self.body.get().kind
    }

    /// Control, body and size, as the reprs show them.
    pub(crate) fn describe(&self) -> String {
        format!(
            "control={:?}, body={:?}, behaviours={}",
            self.control(),
            self.body_kind().name(),
            self.model.behaviours.len()
        )
    }
}

/// The parts of the world model practice refines, by name (None: the ball's response and the
/// states' values).
fn refined_parts(names: Option<&[String]>) -> PyResult<Refines> {
    let Some(names) = names else {
        return Ok(Refines { ball_response: true, state_value: true, push_region: false });
    };
    let mut refines = Refines { ball_response: false, state_value: false, push_region: false };
    for name in names {
        match name.as_str() {
            "ball_response" => refines.ball_response = true,
            "state_value" => refines.state_value = true,
            "push_region" => refines.push_region = true,
            other => {
                return Err(PyValueError::new_err(format!(
                    "refines: {other:?} is no part of the world model (ball_response, state_value, push_region)"
                )));
            }
        }
    }
    Ok(refines)
}

/// The parts ``unlearned`` names, learned from no demonstration (the ablation of what each
/// brings): of the world model, and whether the behaviours are the imitator's primitives alone.
fn unlearned_parts(names: &[String]) -> PyResult<(Refines, bool)> {
    let mut parts = Refines { ball_response: false, state_value: false, push_region: false };
    let mut behaviours = false;
    for name in names {
        match name.as_str() {
            "ball_response" => parts.ball_response = true,
            "state_value" => parts.state_value = true,
            "push_region" => parts.push_region = true,
            "behaviours" => behaviours = true,
            other => {
                return Err(PyValueError::new_err(format!(
                    "unlearned: {other:?} is no part learned from demonstrations (ball_response, state_value, push_region, behaviours)"
                )));
            }
        }
    }
    Ok((parts, behaviours))
}

fn at_least_zero(name: &str, value: f64) -> PyResult<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(PyValueError::new_err(format!("{name} must be a finite number of at least 0, got {value}")))
    }
}
