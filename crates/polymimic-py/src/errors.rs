//! Every core error becomes a Python exception here, and only here.
//!
//! Bad arguments are `ValueError`; failures that depend on the data meeting a model derive
//! from `polymimic.PolymimicError`.

use polymimic_field::{FieldError, FieldParamError};
use polymimic_hmm::HmmError;
use polymimic_learn::{LaboratoryError, LearnError, LearnParamsError};
use polymimic_perceive::PerceiveError;
use polymimic_vq::{VqError, VqParamsError};
use pyo3::PyErr;
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyValueError};

create_exception!(polymimic, PolymimicError, PyException, "Base class of every polymimic error.");
create_exception!(
    polymimic,
    NotFittedError,
    PolymimicError,
    "A model was used before it was fitted or given parameters."
);
create_exception!(
    polymimic,
    ImpossibleSequenceError,
    PolymimicError,
    "A sequence has probability zero under the model."
);
create_exception!(
    polymimic,
    ModelFileError,
    PolymimicError,
    "A saved file is corrupt, of another kind, or of an unsupported version."
);

#[allow(clippy::needless_pass_by_value)] // used as `map_err(hmm_error)`
pub fn hmm_error(error: HmmError) -> PyErr {
    let message = error.to_string();
    match error {
        HmmError::Params(_) => PyValueError::new_err(message),
        HmmError::ImpossibleSequence { .. } => ImpossibleSequenceError::new_err(message),
        HmmError::NotFitted => NotFittedError::new_err(message),
        HmmError::Corrupt(_) => ModelFileError::new_err(message),
    }
}

#[allow(clippy::needless_pass_by_value)] // used as `map_err(vq_params_error)`
pub fn vq_params_error(error: VqParamsError) -> PyErr {
    PyValueError::new_err(error.to_string())
}

pub fn vq_error(error: VqError) -> PyErr {
    match error {
        VqError::Params(e) => vq_params_error(e),
        VqError::Corrupt(_) => ModelFileError::new_err(error.to_string()),
    }
}

#[allow(clippy::needless_pass_by_value)] // used as `map_err(perceive_error)`
pub fn perceive_error(error: PerceiveError) -> PyErr {
    match error {
        PerceiveError::Hmm(e) => hmm_error(e),
        PerceiveError::Corrupt(_) => ModelFileError::new_err(error.to_string()),
        _ => PyValueError::new_err(error.to_string()),
    }
}

create_exception!(
    polymimic,
    FieldRunError,
    PolymimicError,
    "A simulation could not run: a finished episode stepped, a command the body cannot execute, too many lost recordings."
);

create_exception!(
    polymimic,
    PolicyError,
    PolymimicError,
    "A Python demonstrator failed: it raised (its exception is the cause), answered with something that is not a command of its body, or did not answer in time."
);

#[allow(clippy::needless_pass_by_value)] // used as `map_err(field_param_error)`
pub fn field_param_error(error: FieldParamError) -> PyErr {
    PyValueError::new_err(error.to_string())
}

#[allow(clippy::needless_pass_by_value)] // used as `map_err(field_error)`
pub fn field_error(error: FieldError) -> PyErr {
    match error {
        FieldError::Param(e) => field_param_error(e),
        other => FieldRunError::new_err(other.to_string()),
    }
}

#[allow(clippy::needless_pass_by_value)] // used as `map_err(learn_params_error)`
pub fn learn_params_error(error: LearnParamsError) -> PyErr {
    PyValueError::new_err(error.to_string())
}

pub fn learn_error(error: LearnError) -> PyErr {
    match error {
        LearnError::Params(e) => learn_params_error(e),
        LearnError::Corrupt(_) => ModelFileError::new_err(error.to_string()),
    }
}

#[allow(clippy::needless_pass_by_value)] // used as `map_err(laboratory_error)`
pub fn laboratory_error(error: LaboratoryError) -> PyErr {
    match error {
        LaboratoryError::Field(e) => field_error(e),
        LaboratoryError::Perceive(e) => perceive_error(e),
        LaboratoryError::Learn(e) => learn_error(e),
        LaboratoryError::NoAverage { .. } => PolymimicError::new_err(error.to_string()),
    }
}
