//! Commands as Python writes them: a primitive's name, any command's name or its id.

use polymimic_field::{Command, command_table};
use polymimic_types::Primitive;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyString};

const EXPECTED: &str = "a primitive name (forward, backward, left, right, stop), a command name or a command id \
                        (see polymimic.command_table())";

/// The command `value` names: a primitive name ("forward"), a command name of any language
/// ("arc_left_tight_fast", "Walk Forward") or an integer id. A `ValueError` for a name or id no
/// language has, a `TypeError` for anything else.
pub fn parse_command(value: &Bound<'_, PyAny>) -> PyResult<Command> {
    if let Ok(name) = value.cast::<PyString>() {
        let name = name.to_cow()?;
        let name = name.as_ref();
        return command_named(name)
            .ok_or_else(|| PyValueError::new_err(format!("unknown command {name:?}; expected {EXPECTED}")));
    }
    if value.is_instance_of::<PyBool>() {
        return Err(not_a_command(value)?);
    }
    let Ok(id) = value.extract::<i64>() else {
        return Err(not_a_command(value)?);
    };
    u16::try_from(id)
        .ok()
        .and_then(|id| Command::from_id(id).ok())
        .ok_or_else(|| PyValueError::new_err(format!("unknown command id {id}; expected {EXPECTED}")))
}

fn command_named(name: &str) -> Option<Command> {
    if let Some(p) = Primitive::from_name(name) {
        return Some(Command::Primitive(p));
    }
    command_table().into_iter().find(|c| c.name == name).and_then(|c| Command::from_id(c.id).ok())
}

fn not_a_command(value: &Bound<'_, PyAny>) -> PyResult<PyErr> {
    let kind = value.get_type().name()?;
    Ok(PyTypeError::new_err(format!("a command must be {EXPECTED}; got {} ({kind})", value.repr()?)))
}
