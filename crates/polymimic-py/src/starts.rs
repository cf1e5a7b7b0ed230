//! Where an attempt starts, as Python writes it: configuration 1 or 2, or a chosen start
//! ``{"robot": (x_mm, y_mm, theta_rad), "ball": (x_mm, y_mm)}``.

use polymimic_field::{Configuration, Start};
use polymimic_learn::StartAt;
use polymimic_types::{Point, Pose};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyTuple};

const EXPECTED: &str =
    "1 or 2 (the thesis's configurations) or {\"robot\": (x_mm, y_mm, theta_rad), \"ball\": (x_mm, y_mm)}";

/// One of the thesis's two configurations, by its number.
pub(crate) fn configuration(number: i64) -> PyResult<Configuration> {
    match number {
        1 => Ok(Configuration::One),
        2 => Ok(Configuration::Two),
        other => Err(PyValueError::new_err(format!("configuration must be 1 or 2, got {other}"))),
    }
}

/// A configuration's number, as Python writes it.
pub(crate) fn configuration_number(configuration: Configuration) -> u8 {
    match configuration {
        Configuration::One => 1,
        Configuration::Two => 2,
    }
}

/// A start as Python wrote it, named `what` in errors.
pub struct StartArg(pub StartAt);

impl<'a, 'py> FromPyObject<'a, 'py> for StartArg {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(table) = obj.cast::<PyDict>() {
            return chosen(&table).map(|s| Self(StartAt::Chosen(s)));
        }
        if obj.is_instance_of::<PyBool>() {
            return Err(PyTypeError::new_err(format!("a start must be {EXPECTED}; got {}", obj.repr()?)));
        }
        match obj.extract::<i64>() {
            Ok(number) => configuration(number).map(|c| Self(StartAt::Configuration(c))),
            Err(_) => Err(PyTypeError::new_err(format!("a start must be {EXPECTED}; got {}", obj.repr()?))),
        }
    }
}

fn chosen(table: &Bound<'_, PyDict>) -> PyResult<Start> {
    for key in table.keys() {
        let name: String = key.extract().unwrap_or_default();
        if name != "robot" && name != "ball" {
            return Err(PyValueError::new_err(format!(
                "unknown key {} in a start; expected 'robot' (x_mm, y_mm, theta_rad) and 'ball' (x_mm, y_mm)",
                key.repr()?
            )));
        }
    }
    let numbers = |key: &str, n: usize| -> PyResult<Vec<f64>> {
        let Some(value) = table.get_item(key)? else {
            return Err(PyValueError::new_err(format!("a start needs '{key}'; expected {EXPECTED}")));
        };
        let bad = || -> PyResult<PyErr> {
            Ok(PyValueError::new_err(format!("a start's '{key}' must be {n} numbers, got {}", value.repr()?)))
        };
        let Ok(items) = value.extract::<Vec<Bound<'_, PyAny>>>() else { return Err(bad()?) };
        if items.len() != n || items.iter().any(PyAnyMethods::is_instance_of::<PyBool>) {
            return Err(bad()?);
        }
        items.iter().map(|v| v.extract::<f64>().or(Err(bad()?))).collect()
    };
    let robot = numbers("robot", 3)?;
    let ball = numbers("ball", 2)?;
    Ok(Start { robot: Pose::new(robot[0], robot[1], robot[2]), ball: Point::new(ball[0], ball[1]) })
}

/// A start as Python reads it: the configuration's number (None for a chosen start) and the
/// start itself as ``{"robot": (x, y, θ), "ball": (x, y)}``.
pub fn start_dict<'py>(
    py: Python<'py>,
    configuration: Option<Configuration>,
    start: &Start,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("configuration", configuration.map(Configuration::number))?;
    out.set_item("robot", PyTuple::new(py, [start.robot.x_mm(), start.robot.y_mm(), start.robot.theta_rad()])?)?;
    out.set_item("ball", PyTuple::new(py, [start.ball.x_mm(), start.ball.y_mm()])?)?;
    Ok(out)
}
