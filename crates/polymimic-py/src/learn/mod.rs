//! Learning from Python: typed configs, segmented demonstrations, trial results and the
//! imitator's policy in; the shared selections of the experiments (the Average demonstrator,
//! net goals, the LP order) out.

mod config;
mod player;
mod policy;
mod segments;
mod trial;

use polymimic_field::{BodyKind, Outcome};
use polymimic_learn::{
    AverageSearch, Ending, LaboratoryError, MotionTable, PhaseOne, Setting, TrialRecord,
    lp_order_hits as count_lp_order_hits, net_goals as count_net_goals, onto_setting, run_trial,
    spare_attempts as spares,
};
use polymimic_types::{Pose, TrackedFrame};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyList;

pub use config::PyLearningConfig;
pub use player::PyImitatorPlayer;
pub use policy::PyImitatorPolicy;
pub use segments::PySegmentedDemonstrations;
pub use trial::{PyModelResult, PyTrialResult};

use crate::bodies::Body;
use crate::convert::{non_negative, one_of};
use crate::errors::laboratory_error;
use crate::perceive::PyPrimitiveRecognizer;
use config::config_or_default;
use segments::batch;

/// The recogniser's Table 3.1 as the learner's motion table.
fn motion_table(recognizer: &PyPrimitiveRecognizer) -> PyResult<MotionTable> {
    MotionTable::new(recognizer.recognizer.motion_stats()).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// One learning trial on segmented demonstrations, each brought onto the field of `body` (the
/// imitator's); the recogniser's Table 3.1 moves the predictions. Returns every model's result
/// and the imitator's final model.
#[pyfunction]
#[pyo3(signature = (demonstrations, ordering, recognizer, *, config=None, phase_one="by-model", seed=0,
                    body=Body(BodyKind::Lego)),
       text_signature = "(demonstrations, ordering, recognizer, *, config=None, phase_one='by-model', seed=0, body='lego')")]
#[allow(clippy::needless_pass_by_value)] // pyo3 extracts the ordering by value
pub fn learning_trial(
    py: Python<'_>,
    demonstrations: &Bound<'_, PyAny>,
    ordering: Vec<String>,
    recognizer: &PyPrimitiveRecognizer,
    config: Option<&Bound<'_, PyLearningConfig>>,
    phase_one: &str,
    seed: i64,
    body: Body,
) -> PyResult<PyTrialResult> {
    let given = batch(demonstrations)?;
    let demos = onto_setting(&given, &Setting::of_imitator(body.0));
    let config = config_or_default(config);
    let phase_one =
        one_of("phase_one", phase_one, &[("by-model", PhaseOne::ByModel), ("interleaved", PhaseOne::Interleaved)])?;
    let motion = motion_table(recognizer)?;
    let seed = non_negative("seed", seed)? as u64;
    let result = py
        .detach(|| run_trial(&demos, &ordering, &motion, &config, phase_one, seed))
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(PyTrialResult::wrap(TrialRecord::of(&result, seed)))
}

/// The thesis's Average demonstrator (§4.4.2), as `Laboratory::average_demonstrator` chooses
/// it: trials with seeds `first_seed` … `first_seed + max_trials - 1` on `demonstrations`
/// (phase one by model, in `ordering`), each imitator driven by the thesis's rule with its
/// trial's seed; the one whose net goals lie nearest the middle of the Poor's and the Expert's,
/// strictly between. The candidates are imitators of `body`, learning on its field. Returns its
/// trial and its attempts (as `ImitatorPolicy.evaluate` gives them).
#[pyfunction]
#[pyo3(signature = (demonstrations, recognizer, *, ordering, poor_net_goals, expert_net_goals,
                    per_configuration, first_seed, max_trials, config=None, field_config=None,
                    body=Body(BodyKind::Lego)),
       text_signature = "(demonstrations, recognizer, *, ordering, poor_net_goals, expert_net_goals, per_configuration, first_seed, max_trials, config=None, field_config=None, body='lego')")]
#[allow(clippy::too_many_arguments, clippy::needless_pass_by_value)] // pyo3 extracts by value
pub fn average_demonstrator<'py>(
    py: Python<'py>,
    demonstrations: &Bound<'py, PyAny>,
    recognizer: &PyPrimitiveRecognizer,
    ordering: Vec<String>,
    poor_net_goals: i64,
    expert_net_goals: i64,
    per_configuration: i64,
    first_seed: i64,
    max_trials: i64,
    config: Option<&Bound<'py, PyLearningConfig>>,
    field_config: Option<&str>,
    body: Body,
) -> PyResult<(PyTrialResult, Bound<'py, PyList>)> {
    let given = batch(demonstrations)?;
    let demos = onto_setting(&given, &Setting::of_imitator(body.0));
    let config = config_or_default(config);
    let motion = motion_table(recognizer)?;
    let field = crate::field::field_config(field_config)?;
    let first = non_negative("first_seed", first_seed)? as u64;
    let trials = non_negative("max_trials", max_trials)? as u64;
    let search = AverageSearch {
        motion: &motion,
        config: &config,
        field: &field,
        body: body.0,
        per_configuration: non_negative("per_configuration", per_configuration)?,
        poor_net_goals,
        expert_net_goals,
    };
    let chosen = py
        .detach(|| {
            let candidates = (first..first + trials).map(|seed| {
                let trial = run_trial(&demos, &ordering, &motion, &config, PhaseOne::ByModel, seed)?;
                Ok::<_, LaboratoryError>((seed, trial))
            });
            search.choose(candidates)
        })
        .map_err(laboratory_error)?;
    let attempts = policy::attempt_list(py, &chosen.attempts)?;
    Ok((PyTrialResult::wrap(TrialRecord::of(&chosen.trial, chosen.seed)), attempts))
}

/// Goals less own goals over outcomes (`"goal"`, `"own_goal"`, `"ball_out"`, `"robot_out"`,
/// `"time_up"`); any other name is a ValueError.
#[pyfunction]
#[allow(clippy::needless_pass_by_value)] // pyo3 extracts the outcomes by value
pub fn net_goals(outcomes: Vec<String>) -> PyResult<i64> {
    let table =
        [Outcome::Goal, Outcome::OwnGoal, Outcome::BallOut, Outcome::RobotOut, Outcome::TimeUp].map(|o| (o.name(), o));
    let endings = outcomes
        .iter()
        .enumerate()
        .map(|(i, name)| one_of(&format!("outcome {i}"), name, &table).map(Ending::from))
        .collect::<PyResult<Vec<_>>>()?;
    Ok(count_net_goals(endings))
}

/// Trials whose demonstrators' final LPs rise strictly along `order` (least skilled first).
#[pyfunction]
#[allow(clippy::needless_pass_by_value)] // pyo3 extracts the lists by value
pub fn lp_order_hits(trials: Vec<PyRef<'_, PyTrialResult>>, order: Vec<String>) -> usize {
    let records: Vec<&TrialRecord> = trials.iter().map(|t| &*t.record).collect();
    let order: Vec<&str> = order.iter().map(String::as_str).collect();
    count_lp_order_hits(&records, &order)
}

/// Attempts made beyond `per_configuration`, to stand in for any whose tracking is lost.
#[pyfunction]
pub fn spare_attempts(per_configuration: i64) -> PyResult<usize> {
    Ok(spares(non_negative("per_configuration", per_configuration)?))
}

/// The (configuration, episode seed) of every attempt an evaluation under `seed` makes, in
/// order: what `ImitatorPolicy.evaluate` plays, so other policies can meet the same attempts.
#[pyfunction]
#[pyo3(signature = (attempts_per_configuration, *, seed))]
pub fn attempt_seeds(attempts_per_configuration: i64, seed: u64) -> PyResult<Vec<(u8, u64)>> {
    let n = non_negative("attempts_per_configuration", attempts_per_configuration)?;
    Ok(polymimic_learn::attempt_seeds(n, seed)
        .into_iter()
        .map(|(configuration, s)| (crate::starts::configuration_number(configuration), s))
        .collect())
}

/// Observations `(n, 5)` (robot x, y (mm), heading (rad), ball x, y (mm)) recorded by the body
/// `recorded_by` on its field, brought onto the field of an imitator of body `imitator` by the
/// learner's one correspondence.
#[pyfunction]
#[allow(clippy::needless_pass_by_value)] // pyo3 extracts the bodies by value
pub fn observations_onto<'py>(
    py: Python<'py>,
    observations: &Bound<'py, PyAny>,
    recorded_by: Body,
    imitator: Body,
) -> PyResult<Bound<'py, numpy::PyArray2<f64>>> {
    let (from, to) = (Setting::of_body(recorded_by.0), Setting::of_imitator(imitator.0));
    let (values, shape) = crate::convert::floats(observations, "observations", 2)?;
    if shape[1] != 5 {
        return Err(PyValueError::new_err(format!(
            "observations must have 5 columns (robot_x_mm, robot_y_mm, robot_theta_rad, ball_x_mm, ball_y_mm), got {}",
            shape[1]
        )));
    }
    let mapped: Vec<f64> = values
        .chunks_exact(5)
        .flat_map(|row| {
            let seen = TrackedFrame { robot: Pose::new(row[0], row[1], row[2]), ball_x_mm: row[3], ball_y_mm: row[4] };
            let on = from.frame_onto(&to, &seen);
            [on.robot.x_mm(), on.robot.y_mm(), on.robot.theta_rad(), on.ball_x_mm, on.ball_y_mm]
        })
        .collect();
    crate::convert::matrix(py, mapped, shape[0], 5)
}
