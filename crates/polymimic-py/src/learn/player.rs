//! `polymimic.ImitatorPlayer`: a trained imitator stepped one tracker reading at a time.

use polymimic_field::{Configuration, Observation, Start};
use polymimic_learn::{StartAt, Stepping};
use polymimic_types::{Point, Pose, Primitive};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};

use super::policy::PyImitatorPolicy;
use crate::convert::Seed;
use crate::policy::PyReading;
use crate::starts::{StartArg, start_dict};

/// A trained imitator as an owned, stateful player: :meth:`reset` starts an episode and
/// :meth:`act` takes one tracker reading and answers the command to send until the next (a
/// primitive is held for one second, decisions falling on a one-second grid from the
/// episode's first reading). It keeps what the control keeps between decisions: the thesis
/// control's behaviour in progress and its random generator (seeded by the episode seed), and
/// the ball where it was last seen at a decision (the start's ball until then). Made by
/// :meth:`polymimic.ImitatorPolicy.player`.
#[pyclass(name = "ImitatorPlayer", module = "polymimic")]
pub struct PyImitatorPlayer {
    policy: Py<PyImitatorPolicy>,
    stepping: Option<Stepping>,
    start: StartAt,
    seed: u64,
}

impl PyImitatorPlayer {
    pub(crate) fn new(policy: Py<PyImitatorPolicy>) -> Self {
        Self { policy, stepping: None, start: StartAt::Configuration(Configuration::One), seed: 0 }
    }

    fn begin(&mut self, start: StartAt, seed: u64) -> PyResult<()> {
        let policy = self.policy.get();
        let body = policy.body_kind();
        let chosen = match start {
            StartAt::Configuration(c) => Start::of(c, body),
            StartAt::Chosen(s) => {
                s.check(body).map_err(crate::errors::field_param_error)?;
                s
            }
        };
        self.stepping = Some(policy.view().start(&chosen, seed));
        (self.start, self.seed) = (start, seed);
        Ok(())
    }
}

/// The episode in progress, or a `FieldRunError` saying to reset first.
fn in_progress(stepping: &mut Option<Stepping>) -> PyResult<&mut Stepping> {
    stepping.as_mut().ok_or_else(|| {
        crate::errors::FieldRunError::new_err("call reset() first: the player needs the episode's start and seed")
    })
}

#[pymethods]
impl PyImitatorPlayer {
    /// Start an episode.
    ///
    /// ``episode`` is what :func:`polymimic.record` passes a demonstrator (a dict with the
    /// episode's ``configuration`` and ``seed``); otherwise ``start`` (1, 2 or ``{"robot": (x_mm,
    /// y_mm, theta_rad), "ball": (x_mm, y_mm)}``, default 1) and ``seed`` (the episode seed,
    /// whose draws the thesis control makes; default 0). Raises ``ValueError`` for a start off
    /// the body's field or with the ball on the robot.
    #[pyo3(signature = (episode=None, *, start=None, seed=None))]
    fn reset(
        &mut self,
        episode: Option<&Bound<'_, PyDict>>,
        start: Option<StartArg>,
        seed: Option<Seed>,
    ) -> PyResult<()> {
        let (start, seed) = match episode {
            Some(info) => {
                if start.is_some() || seed.is_some() {
                    return Err(PyValueError::new_err("reset: give an episode dict or start=/seed=, not both"));
                }
                let get = |key: &str| -> PyResult<Bound<'_, PyAny>> {
                    info.get_item(key)?.ok_or_else(|| {
                        PyValueError::new_err(format!(
                            "reset: the episode dict has no '{key}' (it needs 'configuration' and 'seed')"
                        ))
                    })
                };
                let start: StartArg = match info.get_item("start")? {
                    Some(s) => s.extract()?,
                    None => get("configuration")?.extract()?,
                };
                (start.0, get("seed")?.extract::<Seed>()?.0)
            }
            None => (start.map_or(StartAt::Configuration(Configuration::One), |s| s.0), seed.map_or(0, |s| s.0)),
        };
        self.begin(start, seed)
    }

    /// The command to send after ``reading`` until the next one: a :class:`polymimic.Reading`
    /// or six numbers ``(t_s, robot_x_mm, robot_y_mm, robot_theta_rad, ball_x_mm, ball_y_mm)``
    /// (float64; NaN where the tracker lost it). Returns the command's name (a primitive's on a
    /// wheeled body, ``"forward"`` …; the humanoid's own, ``"Walk Forward"``, ``"Kick Left"`` …).
    fn act(&mut self, reading: &Bound<'_, PyAny>) -> PyResult<&'static str> {
        let observation = self.observation(reading)?;
        let policy = self.policy.get().view();
        Ok(policy.act(in_progress(&mut self.stepping)?, &observation).name())
    }

    /// One decision now from the robot's pose and the ball (NaN where not seen): the primitive
    /// to run for the next second, as its index in the body's primitive set (the action
    /// :class:`polymimic.env.PenaltyKickEnv` takes). No time grid: every call decides.
    fn decide(
        &mut self,
        robot_x_mm: f64,
        robot_y_mm: f64,
        robot_theta_rad: f64,
        ball_x_mm: f64,
        ball_y_mm: f64,
    ) -> PyResult<usize> {
        let policy = self.policy.get();
        let body = policy.body_kind();
        let robot = Pose::new(robot_x_mm, robot_y_mm, robot_theta_rad);
        let ball = Point::new(ball_x_mm, ball_y_mm);
        let seen = Observation {
            t_s: 0.0,
            frame_index: 0,
            robot,
            ball: ball.is_finite().then_some(ball),
            field: body.field(),
            body,
        };
        let primitive: Primitive = policy.view().decide(in_progress(&mut self.stepping)?, &seen);
        Ok(primitive.index())
    }

    /// What was executed this episode, in order, as letters: whole behaviours by the thesis's
    /// rule, single primitives by the improved one.
    #[getter]
    fn executed(&self) -> Vec<String> {
        self.stepping.as_ref().map(|s| s.executed().to_vec()).unwrap_or_default()
    }

    /// The episode's start (``configuration``: 1, 2 or None for a chosen one; ``robot``;
    /// ``ball``) and ``seed``.
    #[getter]
    fn episode<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let body = self.policy.get().body_kind();
        let (configuration, start) = match self.start {
            StartAt::Configuration(c) => (Some(c), Start::of(c, body)),
            StartAt::Chosen(s) => (None, s),
        };
        let out = start_dict(py, configuration, &start)?;
        out.set_item("seed", self.seed)?;
        Ok(out)
    }

    fn __repr__(&self) -> String {
        format!("ImitatorPlayer({})", self.policy.get().describe())
    }
}

impl PyImitatorPlayer {
    fn observation(&self, reading: &Bound<'_, PyAny>) -> PyResult<Observation> {
        let body = self.policy.get().body_kind();
        let numbers: [f64; 6] = if let Ok(r) = reading.cast::<PyReading>() {
            let r = r.get();
            [r.t_s, r.robot_x_mm, r.robot_y_mm, r.robot_theta_rad, r.ball_x_mm, r.ball_y_mm]
        } else {
            let not_a_reading = || -> PyResult<PyErr> {
                Ok(PyTypeError::new_err(format!(
                    "a reading is a polymimic.Reading or six numbers (t_s, robot_x_mm, robot_y_mm, robot_theta_rad, ball_x_mm, ball_y_mm); got {}",
                    reading.repr()?
                )))
            };
            if reading.is_instance_of::<pyo3::types::PyString>() {
                return Err(not_a_reading()?);
            }
            let Ok(items) = reading.extract::<Vec<Bound<'_, PyAny>>>() else { return Err(not_a_reading()?) };
            if items.len() != 6 || items.iter().any(PyAnyMethods::is_instance_of::<PyBool>) {
                return Err(not_a_reading()?);
            }
            let values =
                items.iter().map(|v| v.extract::<f64>().or(Err(not_a_reading()?))).collect::<PyResult<Vec<f64>>>()?;
            [values[0], values[1], values[2], values[3], values[4], values[5]]
        };
        let [t_s, x, y, theta, bx, by] = numbers;
        if !t_s.is_finite() {
            return Err(PyValueError::new_err(format!(
                "a reading's time must be a finite number of seconds, got {t_s}"
            )));
        }
        let ball = Point::new(bx, by);
        Ok(Observation {
            t_s,
            frame_index: 0,
            robot: Pose::new(x, y, theta),
            ball: ball.is_finite().then_some(ball),
            field: body.field(),
            body,
        })
    }
}
