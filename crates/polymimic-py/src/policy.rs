//! Python demonstrators (docs/guides/own-data.md): a policy written in Python drives a body on the Rust
//! field, called with the GIL held only for the call, under a watchdog for calls that hang.

use std::time::Duration;

use polymimic_field::{
    BodyKind, Command, ControllerPolicy, DecisionRate, Demonstrator, EpisodeStart, FieldConfig, FieldError,
    Observation, Policy, PolicyFailure, PolicyFault, record_policy,
};
use pyo3::exceptions::{PyException, PyTimeoutError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::bodies::Body;
use crate::command::parse_command;
use crate::convert::Seed;
use crate::errors::{PolicyError, field_error, field_param_error};
use crate::field::{field_config, positive, recording};
use crate::starts::{configuration, configuration_number};
use crate::watchdog::Watchdog;

/// The shortest and longest a policy may be given to answer, s.
const MIN_TIMEOUT_S: f64 = 0.001;
const MAX_TIMEOUT_S: f64 = 86_400.0;

/// The tracker's latest reading, as a Python policy gets it.
#[pyclass(name = "Reading", module = "polymimic", frozen, get_all)]
pub struct PyReading {
    /// Episode time, s.
    pub(crate) t_s: f64,
    /// Index of the frame about to be recorded.
    pub(crate) frame: usize,
    /// The robot's tracked x, mm (origin at the field's centre, +x toward the target goal).
    pub(crate) robot_x_mm: f64,
    /// The robot's tracked y, mm.
    pub(crate) robot_y_mm: f64,
    /// The robot's tracked heading, rad.
    pub(crate) robot_theta_rad: f64,
    /// The tracked ball's x, mm (NaN when the robot cannot see it: a humanoid sees only ahead).
    pub(crate) ball_x_mm: f64,
    /// The tracked ball's y, mm (NaN when the robot cannot see it).
    pub(crate) ball_y_mm: f64,
    /// The field's length, mm.
    pub(crate) field_length_mm: f64,
    /// The field's width, mm.
    pub(crate) field_width_mm: f64,
    /// The width of the goal mouths, mm.
    pub(crate) goal_mouth_mm: f64,
}

#[pymethods]
impl PyReading {
    /// Whether the robot sees the ball.
    #[getter]
    fn ball_seen(&self) -> bool {
        !self.ball_x_mm.is_nan()
    }

    fn __repr__(&self) -> String {
        format!(
            "Reading(t_s={:.3}, robot=({:.1}, {:.1}, {:.3}), ball=({:.1}, {:.1}))",
            self.t_s, self.robot_x_mm, self.robot_y_mm, self.robot_theta_rad, self.ball_x_mm, self.ball_y_mm
        )
    }
}

impl From<&Observation> for PyReading {
    fn from(o: &Observation) -> Self {
        let (ball_x_mm, ball_y_mm) = o.ball.map_or((f64::NAN, f64::NAN), |b| (b.x_mm(), b.y_mm()));
        Self {
            t_s: o.t_s,
            frame: o.frame_index,
            robot_x_mm: o.robot.x_mm(),
            robot_y_mm: o.robot.y_mm(),
            robot_theta_rad: o.robot.theta_rad(),
            ball_x_mm,
            ball_y_mm,
            field_length_mm: o.field.length_mm,
            field_width_mm: o.field.width_mm,
            goal_mouth_mm: o.field.goal_mouth_mm,
        }
    }
}

/// A Python policy: `act(reading) -> command`, and `reset(episode)` before every episode.
struct PythonPolicy {
    act: Py<PyAny>,
    reset: Option<Py<PyAny>>,
    /// Dropped with the GIL released (its thread may be waiting for it).
    watchdog: Option<Watchdog>,
}

impl PythonPolicy {
    /// Call `f` under the GIL and the watchdog; a timeout becomes a `TimeoutError`.
    fn call<T>(&self, f: impl FnOnce(Python<'_>) -> PyResult<T>) -> PyResult<T> {
        Python::attach(|py| match &self.watchdog {
            None => f(py),
            Some(w) => match w.run(py, || f(py)) {
                (result, false) => result,
                // The TimeoutError that struck, with its traceback, shows where the policy hung.
                (Err(e), true) if e.is_instance_of::<PyTimeoutError>(py) => Err(e),
                (_, true) => Err(PyTimeoutError::new_err("the call did not return in time")),
            },
        })
    }
}

impl Policy for PythonPolicy {
    type Error = PyErr;

    fn reset(&mut self, start: &EpisodeStart) -> PyResult<()> {
        let Some(reset) = &self.reset else { return Ok(()) };
        self.call(|py| {
            let info = PyDict::new(py);
            info.set_item("attempt", start.attempt)?;
            info.set_item("configuration", configuration_number(start.configuration))?;
            info.set_item("seed", start.seed)?;
            info.set_item("body", start.body.name())?;
            reset.call1(py, (info,)).map(drop)
        })
    }

    fn act(&mut self, reading: &Observation) -> PyResult<Command> {
        self.call(|py| {
            let answer = self.act.call1(py, (PyReading::from(reading),))?;
            parse_command(answer.bind(py))
        })
    }
}

/// A failure, in words a user can act on: who, which attempt, when; the policy's own exception
/// as the cause.
fn policy_error(
    py: Python<'_>,
    name: &str,
    body: BodyKind,
    configuration: i64,
    failure: PolicyFailure<PyErr>,
    timeout_s: f64,
) -> PyErr {
    let at = format!(
        "attempt {} of configuration {configuration} (seed {}) at t = {:.2} s",
        failure.attempt, failure.seed, failure.t_s
    );
    match failure.cause {
        // Ctrl-C and exits are not the policy's failures: they go on as they were raised.
        PolicyFault::Policy(cause) if !cause.is_instance_of::<PyException>(py) => cause,
        PolicyFault::Policy(cause) => {
            let what = if cause.is_instance_of::<PyTimeoutError>(py) {
                format!("did not answer within {timeout_s} s")
            } else {
                format!(
                    "failed with {}",
                    cause.value(py).repr().map_or_else(|_| "an exception".into(), |r| r.to_string())
                )
            };
            let error = PolicyError::new_err(format!("policy '{name}' on the {} body {what} in {at}", body.name()));
            error.set_cause(py, Some(cause));
            error
        }
        PolicyFault::Field(FieldError::Param(e)) => {
            PolicyError::new_err(format!("policy '{name}' in {at}: {}", field_param_error(e).value(py)))
        }
        PolicyFault::Field(e) => field_error(e),
    }
}

/// Valid demonstrations of a Python policy on one body from one configuration, recorded one
/// after the other; each a dict like `record_demonstrations`' items.
#[pyfunction]
#[pyo3(signature = (act, reset, *, name, body, configuration, n, seed=Seed(0), decision_hz=30.0, timeout_s=None, config=None),
       text_signature = "(act, reset, *, name, body, configuration, n, seed=0, decision_hz=30.0, timeout_s=None, config=None)")]
#[allow(clippy::too_many_arguments)] // the keywords of `polymimic.record` for a policy
pub fn record_python_policy<'py>(
    py: Python<'py>,
    act: Py<PyAny>,
    reset: Option<Py<PyAny>>,
    name: &str,
    body: Body,
    configuration: i64,
    n: i64,
    seed: Seed,
    decision_hz: f64,
    timeout_s: Option<f64>,
    config: Option<&str>,
) -> PyResult<Bound<'py, PyList>> {
    let body = body.0;
    let asked_configuration = configuration;
    let (configuration, n) = (self::configuration(configuration)?, positive("n", n)?);
    let rate = DecisionRate::from_hz(decision_hz).map_err(field_param_error)?;
    let config = field_config(config)?;
    let timeout = match timeout_s {
        None => None,
        Some(t) if (MIN_TIMEOUT_S..=MAX_TIMEOUT_S).contains(&t) => Some(Duration::from_secs_f64(t)),
        Some(t) => {
            return Err(PyValueError::new_err(format!(
                "timeout_s must be between {MIN_TIMEOUT_S} s and {MAX_TIMEOUT_S} s (a day), or None; got {t:?}"
            )));
        }
    };
    let watchdog = timeout.map(|t| Watchdog::new(py, t)).transpose()?;
    let mut policy = PythonPolicy { act, reset, watchdog };
    let recorded = py.detach(move || {
        let recorded = record_policy(&mut policy, body, configuration, n, seed.0, rate, &config);
        // The watchdog's thread may be waiting for the GIL: stop it while it is free.
        drop(policy);
        recorded
    });
    let recordings = recorded
        .map_err(|f| policy_error(py, name, body, asked_configuration, f, timeout_s.unwrap_or(f64::INFINITY)))?;
    let out = PyList::empty(py);
    for r in &recordings {
        out.append(recording(py, &r.frames, r.outcome, r.configuration, r.seed)?)?;
    }
    Ok(out)
}

/// A built-in demonstrator's controller recorded through the policy path at `decision_hz`: the
/// same episodes and seeds a Python policy gets, for comparing the two (`benches/python_policy_vs_rust.py`).
#[pyfunction]
#[pyo3(signature = (demonstrator, *, configuration, n, seed=Seed(0), decision_hz=30.0),
       text_signature = "(demonstrator, *, configuration, n, seed=0, decision_hz=30.0)")]
pub fn record_builtin_at_rate(
    py: Python<'_>,
    demonstrator: &str,
    configuration: i64,
    n: i64,
    seed: Seed,
    decision_hz: f64,
) -> PyResult<Vec<usize>> {
    let who = Demonstrator::from_name(demonstrator).map_err(field_param_error)?;
    let (configuration, n) = (self::configuration(configuration)?, positive("n", n)?);
    let rate = DecisionRate::from_hz(decision_hz).map_err(field_param_error)?;
    let config = FieldConfig::default();
    let recorded = py.detach(|| {
        record_policy(
            &mut ControllerPolicy::new(who, config.humanoid),
            who.body(),
            configuration,
            n,
            seed.0,
            rate,
            &config,
        )
    });
    let recordings = recorded.map_err(|f| match f.cause {
        PolicyFault::Field(e) => field_error(e),
        PolicyFault::Policy(never) => match never {},
    })?;
    Ok(recordings.iter().map(|r| r.frames.len()).collect())
}
