//! Commands as Python writes them: a primitive's name, any command's name or its id, or a
//! wheeled body's (left, right) wheel speeds.

use polymimic_field::{Command, WheelSpeeds, command_table};
use polymimic_types::Primitive;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyList, PyString, PyTuple};

use crate::errors::field_param_error;

const EXPECTED: &str = "a primitive name (forward, backward, left, right, stop), a command name or a command id \
                        (see polymimic.command_table()), or (left_mm_s, right_mm_s) wheel speeds";

/// The command `value` names: a primitive name ("forward"), a command name of any language
/// ("arc_left_tight_fast", "Walk Forward"), an integer id, or a `(left_mm_s, right_mm_s)` pair
/// of wheel speeds. A `ValueError` for a name or id no language has or speeds out of range, a
/// `TypeError` for anything else.
pub fn parse_command(value: &Bound<'_, PyAny>) -> PyResult<Command> {
    if value.is_instance_of::<PyTuple>() || value.is_instance_of::<PyList>() {
        return wheel_speeds(value);
    }
    if let Ok(name) = value.cast::<PyString>() {
        let name = name.to_cow()?;
        let name = name.as_ref();
        return command_named(name);
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

fn wheel_speeds(value: &Bound<'_, PyAny>) -> PyResult<Command> {
    let pair: Vec<Bound<'_, PyAny>> = value.extract()?;
    let number = |v: &Bound<'_, PyAny>| -> PyResult<f64> {
        if v.is_instance_of::<PyBool>() {
            Err(not_a_command(value)?)
        } else {
            v.extract::<f64>().or(Err(not_a_command(value)?))
        }
    };
    match pair.as_slice() {
        [left, right] => {
            let speeds = WheelSpeeds::new(number(left)?, number(right)?).map_err(field_param_error)?;
            Ok(Command::Wheels(speeds))
        }
        _ => Err(not_a_command(value)?),
    }
}

fn command_named(name: &str) -> PyResult<Command> {
    if let Some(p) = Primitive::from_name(name) {
        return Ok(Command::Primitive(p));
    }
    match command_table().into_iter().find(|c| c.name == name) {
        Some(row) => Command::from_id(row.id).map_err(field_param_error),
        None => Err(PyValueError::new_err(format!("unknown command {name:?}; expected {EXPECTED}"))),
    }
}

fn not_a_command(value: &Bound<'_, PyAny>) -> PyResult<PyErr> {
    let kind = value.get_type().name()?;
    Ok(PyTypeError::new_err(format!("a command must be {EXPECTED}; got {} ({kind})", value.repr()?)))
}
