//! Many episodes stepped at once from Python: the engine of `PenaltyKickVectorEnv`.

use std::sync::Mutex;

use numpy::{PyArray1, PyArray2};
use polymimic_field::{BodyKind, EpisodeBatch, Outcome};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::bodies::{Body, PyBody};
use crate::convert::{matrix, non_negative};
use crate::errors::field_error;
use crate::field::field_config;
use crate::starts::{StartArg, configuration};
use polymimic_learn::StartAt;

/// An outcome's index in `polymimic.field.OUTCOMES`.
fn outcome_code(outcome: Outcome) -> i8 {
    match outcome {
        Outcome::Goal => 0,
        Outcome::OwnGoal => 1,
        Outcome::BallOut => 2,
        Outcome::RobotOut => 3,
        Outcome::TimeUp => 4,
    }
}

/// What every slot shows after a step: observations `(n, 5)` float32 (robot x, y, θ, ball x,
/// y; the ball NaN where unseen), time (s), outcome (−1 while running, else its index in
/// `polymimic.field.OUTCOMES`) and whether tracking held.
type Status<'py> =
    (Bound<'py, PyArray2<f32>>, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<i8>>, Bound<'py, PyArray1<bool>>);

#[pyclass(name = "EpisodeBatch", module = "polymimic", frozen)]
pub struct PyEpisodeBatch {
    batch: Mutex<EpisodeBatch>,
}

impl PyEpisodeBatch {
    fn with<T>(&self, f: impl FnOnce(&mut EpisodeBatch) -> T) -> T {
        f(&mut self.batch.lock().unwrap_or_else(std::sync::PoisonError::into_inner))
    }
}

#[pymethods]
impl PyEpisodeBatch {
    /// `n` slots of `body`'s penalty kick (the Lego robot's by default), on its field; each
    /// step holds one primitive for `frames_per_action` tracker frames in every slot (on the
    /// humanoid, the primitive's walking, turning or waiting equivalent).
    #[new]
    #[pyo3(signature = (n, *, frames_per_action=30, config=None, body=Body(BodyKind::Lego)),
           text_signature = "(n, *, frames_per_action=30, config=None, body='lego')")]
    fn new(n: i64, frames_per_action: i64, config: Option<&str>, body: Body) -> PyResult<Self> {
        let config = field_config(config)?;
        let batch =
            EpisodeBatch::new(non_negative("n", n)?, non_negative("frames_per_action", frames_per_action)?, &config)
                .map_err(field_error)?
                .with_body(body.0);
        Ok(Self { batch: Mutex::new(batch) })
    }

    /// The body every slot drives, a :class:`polymimic.Body`.
    #[getter]
    fn body(&self) -> PyBody {
        PyBody::of(self.with(|b| b.body()))
    }

    fn __len__(&self) -> usize {
        self.with(|b| b.len())
    }

    /// Starts slot `index` afresh from `configuration` (1 or 2), or from a chosen `start`
    /// (``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``), with episode `seed`.
    #[pyo3(signature = (index, *, configuration=None, seed, start=None))]
    fn reset(&self, index: i64, configuration: Option<i64>, seed: u64, start: Option<StartArg>) -> PyResult<()> {
        let index = non_negative("index", index)?;
        match (start, configuration) {
            (Some(StartArg(StartAt::Chosen(start))), None) => self.with(|b| b.reset_at(index, start, seed)),
            (Some(StartArg(StartAt::Configuration(c))), None) => self.with(|b| b.reset(index, c, seed)),
            (None, Some(number)) => {
                let configuration = self::configuration(number)?;
                self.with(|b| b.reset(index, configuration, seed))
            }
            _ => return Err(PyValueError::new_err("reset: give configuration= or start=, one of them")),
        }
        .map_err(field_error)
    }

    /// Holds `actions[i]` (an index into the body's primitive set: 0 forward … 4 stop, and on
    /// the humanoid 5 side-step left, 6 side-step right, 7 kick) in slot `i`, every slot at once with the GIL
    /// released; a slot whose action is −1 is left as it is. Returns what every slot shows then.
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the list by value
    fn step<'py>(&self, py: Python<'py>, actions: Vec<i64>) -> PyResult<Status<'py>> {
        let body = self.with(|b| b.body());
        let set = body.primitive_set();
        let primitives = actions
            .iter()
            .enumerate()
            .map(|(i, &a)| match a {
                -1 => Ok(None),
                _ => {
                    usize::try_from(a).ok().and_then(|a| set.primitives().get(a).copied()).map(Some).ok_or_else(|| {
                        PyValueError::new_err(format!(
                            "actions[{i}] = {a}: an action is an integer in 0..{} (the {} body's primitives; −1: none)",
                            set.primitives().len() - 1,
                            body.name()
                        ))
                    })
                }
            })
            .collect::<PyResult<Vec<_>>>()?;
        py.detach(|| self.with(|b| b.step(&primitives))).map_err(field_error)?;
        self.status(py)
    }

    /// What every slot shows now (a slot never started shows NaN and outcome −1).
    fn status<'py>(&self, py: Python<'py>) -> PyResult<Status<'py>> {
        let (observations, t_s, outcomes, valid) = self.with(|b| {
            let n = b.len();
            let (mut observations, mut t_s) = (Vec::with_capacity(5 * n), Vec::with_capacity(n));
            let (mut outcomes, mut valid) = (Vec::with_capacity(n), Vec::with_capacity(n));
            for slot in b.episodes() {
                let Some(episode) = slot else {
                    observations.extend([f32::NAN; 5]);
                    t_s.push(f64::NAN);
                    outcomes.push(-1);
                    valid.push(false);
                    continue;
                };
                let seen = episode.observation();
                let (ball_x, ball_y) = seen.ball.map_or((f64::NAN, f64::NAN), |p| (p.x_mm(), p.y_mm()));
                // As the single environment casts its float64 reading to float32.
                observations.extend(
                    [seen.robot.x_mm(), seen.robot.y_mm(), seen.robot.theta_rad(), ball_x, ball_y].map(|v| v as f32),
                );
                t_s.push(seen.t_s);
                outcomes.push(episode.outcome().map_or(-1, outcome_code));
                valid.push(episode.is_valid());
            }
            (observations, t_s, outcomes, valid)
        });
        let n = t_s.len();
        Ok((
            matrix(py, observations, n, 5)?,
            PyArray1::from_vec(py, t_s),
            PyArray1::from_vec(py, outcomes),
            PyArray1::from_vec(py, valid),
        ))
    }
}
