//! The simulated field: recording demonstrations and self-observation, and an episode a
//! policy steps through.

use numpy::{PyArray1, PyArray2};
use polymimic_field::{
    BodyKind, Configuration, Demonstrator, Episode, EpisodeSetup, FieldConfig, Frame, LapseRate, Outcome,
    THESIS_TABLE_3_1, command_table, record_on, self_observation_of_set,
};
use polymimic_types::{Pose, Primitive, PrimitiveSet};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::sync::Mutex;

use crate::bodies::Body;
use crate::command::parse_command;
use crate::convert::{Seed, matrix, non_negative};
use crate::errors::{field_error, field_param_error};
use crate::starts::{StartArg, configuration_number};
use polymimic_learn::StartAt;

/// Columns of the frame arrays handed to Python.
pub const FRAME_COLUMNS: [&str; 7] =
    ["t_s", "robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm", "command"];

fn frame_row(f: &Frame) -> [f64; 7] {
    [f.t_s, f.robot_x_mm, f.robot_y_mm, f.robot_theta_rad, f.ball_x_mm, f.ball_y_mm, f64::from(f.command)]
}

pub(crate) fn frames_array<'py>(py: Python<'py>, frames: &[Frame]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    matrix(py, frames.iter().flat_map(frame_row).collect(), frames.len(), 7)
}

pub(crate) fn field_config(json: Option<&str>) -> PyResult<FieldConfig> {
    let config = match json {
        None => FieldConfig::default(),
        Some(text) => FieldConfig::from_json(text).map_err(|e| PyValueError::new_err(format!("field config: {e}")))?,
    };
    config.check().map_err(|e| PyValueError::new_err(format!("field config: {e}")))?;
    Ok(config)
}

pub(crate) fn positive(name: &str, value: i64) -> PyResult<usize> {
    match non_negative(name, value)? {
        0 => Err(PyValueError::new_err(format!("{name} must be at least 1, got 0"))),
        n => Ok(n),
    }
}

/// Valid demonstrations of one demonstrator from one configuration, run in parallel, the
/// demonstrator lapsing at rate `lapse` (docs/guides/crowd.md).
#[pyfunction]
#[pyo3(signature = (demonstrator, *, configuration, n, seed=Seed(0), lapse=0.0, config=None, body=None),
       text_signature = "(demonstrator, *, configuration, n, seed=0, lapse=0.0, config=None, body=None)")]
#[allow(clippy::too_many_arguments)] // the keywords of `polymimic.record`
pub fn record_demonstrations<'py>(
    py: Python<'py>,
    demonstrator: &str,
    configuration: i64,
    n: i64,
    seed: Seed,
    lapse: f64,
    config: Option<&str>,
    body: Option<Body>,
) -> PyResult<Bound<'py, PyList>> {
    let who = Demonstrator::from_name(demonstrator).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let body = body.map_or(who.body(), |b| b.0);
    let (configuration, n) = (crate::starts::configuration(configuration)?, positive("n", n)?);
    let (lapse, config) = (LapseRate::new(lapse).map_err(field_param_error)?, field_config(config)?);
    let demonstrations =
        py.detach(|| record_on(who, body, configuration, n, seed.0, lapse, &config)).map_err(field_error)?;
    let out = PyList::empty(py);
    for d in &demonstrations {
        let item = recording(py, &d.frames, d.outcome, d.configuration, d.seed)?;
        item.set_item("demonstrator", d.demonstrator.name())?;
        out.append(item)?;
    }
    Ok(out)
}

/// One recorded episode as Python gets it: its frames, outcome, configuration and seed.
pub(crate) fn recording<'py>(
    py: Python<'py>,
    frames: &[Frame],
    outcome: Outcome,
    configuration: Configuration,
    seed: u64,
) -> PyResult<Bound<'py, PyDict>> {
    let item = PyDict::new(py);
    item.set_item("frames", frames_array(py, frames)?)?;
    item.set_item("outcome", outcome.name())?;
    item.set_item("configuration", configuration_number(configuration))?;
    item.set_item("seed", seed)?;
    Ok(item)
}

/// One-second primitives of an imitator (the Lego unless `body` says otherwise) alone on its
/// field: `(frames, primitive names)`.
#[pyfunction]
#[pyo3(signature = (n_per_primitive, *, seed=Seed(0), config=None, body=None, primitives="wheeled"),
       text_signature = "(n_per_primitive, *, seed=0, config=None, body=None, primitives='wheeled')")]
pub fn record_self_observation<'py>(
    py: Python<'py>,
    n_per_primitive: i64,
    seed: Seed,
    config: Option<&str>,
    body: Option<Body>,
    primitives: &str,
) -> PyResult<(Bound<'py, PyList>, Vec<&'static str>)> {
    let n = positive("n_per_primitive", n_per_primitive)?;
    let config = field_config(config)?;
    let body = body.map_or(BodyKind::Lego, |b| b.0);
    let set = primitive_set(primitives, body.primitive_set())?;
    let sequences = py.detach(|| self_observation_of_set(body, set, n, seed.0, &config)).map_err(field_error)?;
    let frames = PyList::empty(py);
    for s in &sequences {
        frames.append(frames_array(py, &s.frames)?)?;
    }
    Ok((frames, sequences.iter().map(|s| s.primitive.name()).collect()))
}

/// The primitive set `name`: `"wheeled"`, or `"own"`, the body's `own`.
pub(crate) fn primitive_set(name: &str, own: PrimitiveSet) -> PyResult<PrimitiveSet> {
    match name {
        "own" => Ok(own),
        "wheeled" => Ok(PrimitiveSet::Wheeled),
        other => Err(PyValueError::new_err(format!("primitives must be 'wheeled' or 'own', got {other:?}"))),
    }
}

/// Every command of every controller with its equivalent imitator primitive.
#[pyfunction]
pub fn commands(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let out = PyList::empty(py);
    for info in command_table() {
        let row = PyDict::new(py);
        row.set_item("id", info.id)?;
        row.set_item("name", info.name)?;
        row.set_item("language", format!("{:?}", info.language).to_lowercase())?;
        row.set_item("primitive", info.primitive.name())?;
        out.append(row)?;
    }
    Ok(out)
}

/// The name of the command that has `body` execute `primitive` (a primitive's name): the
/// primitive itself on a wheeled body, its walking, turning or waiting equivalent on the
/// humanoid.
#[pyfunction]
pub fn primitive_command(primitive: &str, body: Body) -> PyResult<&'static str> {
    let p = Primitive::from_name(primitive).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown primitive {primitive:?}; expected one of forward, backward, left, right, stop"
        ))
    })?;
    Ok(polymimic_field::controller::primitive_command(p, body.0).name())
}

/// The thesis's Table 3.1 as stored by the field's calibration.
#[pyfunction]
pub fn thesis_table_3_1(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let out = PyDict::new(py);
    for s in THESIS_TABLE_3_1 {
        let row = PyDict::new(py);
        row.set_item("distance_mean_mm", s.distance_mean_mm)?;
        row.set_item("distance_sd_mm", s.distance_sd_mm)?;
        row.set_item("rotation_mean_deg", s.rotation_mean_deg)?;
        row.set_item("rotation_sd_deg", s.rotation_sd_deg)?;
        out.set_item(s.primitive.name(), row)?;
    }
    Ok(out)
}

/// The default field configuration, as JSON.
#[pyfunction]
pub fn default_field_config() -> String {
    FieldConfig::default().to_json_in_full()
}

/// Checks a field configuration given as JSON (every value in range); returns it in full.
#[pyfunction]
pub fn check_field_config(config: &str) -> PyResult<String> {
    Ok(field_config(Some(config))?.to_json_in_full())
}

/// An episode on the field, stepped one tracker frame at a time by a policy.
///
/// The simulated field (rapier2d) with a body, the ball and the overhead tracker at 30 frames a
/// second, from field configuration 1 or 2 (thesis Fig. 4.4). `run` plays a list of commands,
/// `step` one at a time; `frames` holds every tracker frame so far as a `(k, 7)` array (time,
/// robot x, y, θ, ball x, y, command), millimetres, radians and seconds.
#[pyclass(name = "Episode", module = "polymimic", frozen)]
pub struct PyEpisode {
    episode: Mutex<Episode>,
}

impl PyEpisode {
    fn with<T>(&self, f: impl FnOnce(&mut Episode) -> T) -> T {
        f(&mut self.episode.lock().unwrap_or_else(std::sync::PoisonError::into_inner))
    }
}

#[pymethods]
impl PyEpisode {
    /// A new episode: `body` on the field of its size, in `configuration` 1 or 2 (or alone,
    /// without a ball, when `configuration` is None), or from a chosen `start`
    /// (``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``, or 1 or 2) instead.
    #[new]
    #[pyo3(signature = (body=Body(BodyKind::Lego), *, configuration=Some(1), seed=Seed(0), config=None, start=None),
           text_signature = "(body='lego', *, configuration=1, seed=0, config=None, start=None)")]
    fn new(
        body: Body,
        configuration: Option<i64>,
        seed: Seed,
        config: Option<&str>,
        start: Option<StartArg>,
    ) -> PyResult<Self> {
        let body = body.0;
        let config = field_config(config)?;
        let setup = match (start, configuration) {
            (Some(StartArg(StartAt::Chosen(start))), _) => {
                EpisodeSetup::starting(body, start, &config).map_err(field_param_error)?
            }
            (Some(StartArg(StartAt::Configuration(c))), _) => EpisodeSetup::configuration(body, c, &config),
            (None, Some(number)) => EpisodeSetup::configuration(body, crate::starts::configuration(number)?, &config),
            (None, None) => EpisodeSetup::alone(body),
        };
        let episode = Episode::new(&setup, &config, seed.0).map_err(field_error)?;
        Ok(Self { episode: Mutex::new(episode) })
    }

    /// Sends one command for one tracker frame; returns the frame recorded and the outcome
    /// (None while the episode goes on). `command` is a primitive name, a command name or id.
    fn step<'py>(
        &self,
        py: Python<'py>,
        command: &Bound<'py, PyAny>,
    ) -> PyResult<(Bound<'py, PyArray1<f64>>, Option<&'static str>)> {
        let command = parse_command(command)?;
        let result = self.with(|e| e.step(command)).map_err(field_error)?;
        Ok((
            PyArray1::from_vec(py, frame_row(&result.frame).to_vec()),
            result.outcome.map(polymimic_field::Outcome::name),
        ))
    }

    /// Sends a whole list of commands (one per frame) in Rust with the GIL released, stopping
    /// early if the episode ends; returns the frames recorded and the outcome.
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the list by value
    fn run<'py>(
        &self,
        py: Python<'py>,
        commands: Vec<Bound<'py, PyAny>>,
    ) -> PyResult<(Bound<'py, PyArray2<f64>>, Option<&'static str>)> {
        let commands = commands.iter().map(parse_command).collect::<PyResult<Vec<_>>>()?;
        let (frames, outcome) = py
            .detach(|| {
                self.with(|e| {
                    let first = e.frames().len();
                    // The first command steps even a finished episode, so that it refuses as
                    // `step` does; the rest stop where the episode ends.
                    for (i, &command) in commands.iter().enumerate() {
                        if i > 0 && e.is_finished() {
                            break;
                        }
                        e.step(command)?;
                    }
                    Ok((e.frames()[first..].to_vec(), e.outcome()))
                })
            })
            .map_err(field_error)?;
        Ok((frames_array(py, &frames)?, outcome.map(polymimic_field::Outcome::name)))
    }

    /// The command that runs `primitive` (a name of the body's primitive set) on this body now:
    /// on the humanoid a kick is the foot on the side of the ball it sees.
    fn command_for(&self, primitive: &str) -> PyResult<&'static str> {
        let seen = self.with(|e| e.observation());
        let set = seen.body.primitive_set();
        let Some(p) = Primitive::from_name(primitive).filter(|p| set.contains(*p)) else {
            let names: Vec<&str> = set.primitives().iter().map(|p| p.name()).collect();
            return Err(PyValueError::new_err(format!(
                "unknown primitive {primitive:?} for the {} body; expected one of {}",
                seen.body.name(),
                names.join(", ")
            )));
        };
        Ok(polymimic_field::controller::primitive_command_seeing(p, &seen).name())
    }

    /// Puts the robot at a pose (the experimenter's hand).
    fn place_robot(&self, x_mm: f64, y_mm: f64, theta_rad: f64) -> PyResult<()> {
        self.with(|e| e.place_robot(Pose::new(x_mm, y_mm, theta_rad))).map_err(field_error)
    }

    /// Every frame so far, `(k, 7)`.
    #[getter]
    fn frames<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let frames = self.with(|e| e.frames().to_vec());
        frames_array(py, &frames)
    }

    /// What the robot's controller sees now: time, robot pose, ball (None if not seen), and
    /// the field: its (length, width), goal mouth and ball, mm.
    fn observation<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let seen = self.with(|e| e.observation());
        let out = PyDict::new(py);
        out.set_item("t_s", seen.t_s)?;
        out.set_item("robot", (seen.robot.x_mm(), seen.robot.y_mm(), seen.robot.theta_rad()))?;
        out.set_item("ball", seen.ball.map(|b| (b.x_mm(), b.y_mm())))?;
        out.set_item("field", (seen.field.length_mm, seen.field.width_mm))?;
        out.set_item("goal_mouth_mm", seen.field.goal_mouth_mm)?;
        out.set_item("ball_diameter_mm", seen.field.ball_diameter_mm)?;
        Ok(out)
    }

    /// How the episode ended (`"goal"`, `"own_goal"`, `"ball_out"`, `"robot_out"` or
    /// `"time_up"`), or None while it runs.
    #[getter]
    fn outcome(&self) -> Option<&'static str> {
        self.with(|e| e.outcome().map(polymimic_field::Outcome::name))
    }

    /// Whether the episode has ended (`outcome` then says how).
    #[getter]
    fn finished(&self) -> bool {
        self.with(|e| e.is_finished())
    }

    /// False once tracking was lost.
    #[getter]
    fn valid(&self) -> bool {
        self.with(|e| e.is_valid())
    }
}
