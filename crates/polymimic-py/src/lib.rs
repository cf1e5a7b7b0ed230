//! Python bindings of polymimic: conversions and error mapping only; the algorithms live in
//! the core crates.

mod bodies;
mod command;
mod convert;
mod errors;
mod field;
mod field_batch;
mod hmm;
mod learn;
mod perceive;
mod policy;
mod starts;
mod vq;
mod watchdog;

use pyo3::prelude::*;

#[pymodule]
mod _native {
    use super::{PyModule, PyModuleMethods, PyResult, errors};
    use pyo3::{Bound, PyTypeInfo};

    #[pymodule_export]
    use super::bodies::{PyBody, thesis_wheeled_bodies};
    #[pymodule_export]
    use super::field::{
        PyEpisode, check_field_config, commands, default_field_config, primitive_command, record_demonstrations,
        record_self_observation, thesis_table_3_1,
    };
    #[pymodule_export]
    use super::field_batch::PyEpisodeBatch;
    #[pymodule_export]
    use super::hmm::PyDiscreteHmm;
    #[pymodule_export]
    use super::learn::{
        PyImitatorPlayer, PyImitatorPolicy, PyLearningConfig, PyModelResult, PySegmentedDemonstrations, PyTrialResult,
        attempt_seeds, average_demonstrator, learning_trial, lp_order_hits, net_goals, observations_onto,
        spare_attempts,
    };
    #[pymodule_export]
    use super::perceive::PyPrimitiveRecognizer;
    #[pymodule_export]
    use super::policy::{PyReading, record_builtin_at_rate, record_python_policy};
    #[pymodule_export]
    use super::vq::PyCodebook;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        let py = m.py();
        m.add("PolymimicError", errors::PolymimicError::type_object(py))?;
        m.add("NotFittedError", errors::NotFittedError::type_object(py))?;
        m.add("ImpossibleSequenceError", errors::ImpossibleSequenceError::type_object(py))?;
        m.add("ModelFileError", errors::ModelFileError::type_object(py))?;
        m.add("FieldRunError", errors::FieldRunError::type_object(py))?;
        m.add("PolicyError", errors::PolicyError::type_object(py))?;
        m.add("FRAME_COLUMNS", super::field::FRAME_COLUMNS.to_vec())?;
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        Ok(())
    }
}
