//! Bodies as Python names them: a thesis body by name, or a wheeled body described as data
//! (`polymimic.bodies.WheeledBody`, which hands over its constants as JSON).

use polymimic_field::body::WheeledParams;
use polymimic_field::{BodyKind, FieldGeometry, FieldSize};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;

use crate::errors::field_param_error;

/// A body argument: "lego", "tiny", "humanoid", or an object with `_native_body()` returning
/// `(constants as JSON, "large" | "small" | the field's sizes as JSON)`.
#[derive(Debug, Clone, Copy)]
pub struct Body(pub BodyKind);

impl<'a, 'py> FromPyObject<'a, 'py> for Body {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(name) = obj.cast::<PyString>() {
            return match &*name.to_cow()? {
                "lego" => Ok(Self(BodyKind::Lego)),
                "tiny" => Ok(Self(BodyKind::Tiny)),
                "humanoid" => Ok(Self(BodyKind::Humanoid)),
                other => Err(PyValueError::new_err(format!(
                    "body must be \"lego\", \"tiny\", \"humanoid\" or a polymimic.bodies.WheeledBody, got {other:?}"
                ))),
            };
        }
        let Ok(native) = obj.getattr("_native_body") else {
            return Err(PyTypeError::new_err(format!(
                "body must be a body's name or a polymimic.bodies.WheeledBody, got {}",
                obj.repr()?
            )));
        };
        let (json, field): (String, String) = native.call0()?.extract()?;
        let params = WheeledParams::from_json(&json).map_err(field_param_error)?;
        let field = match field.as_str() {
            "large" => FieldGeometry::of(FieldSize::Large),
            "small" => FieldGeometry::of(FieldSize::Small),
            sizes => FieldGeometry::from_json(sizes).map_err(field_param_error)?,
        };
        Ok(Self(BodyKind::Wheeled(params, field)))
    }
}

/// The constants of the thesis's two wheeled bodies, as JSON by name.
#[pyfunction]
pub fn thesis_wheeled_bodies() -> Vec<(&'static str, String)> {
    [polymimic_field::body::LEGO, polymimic_field::body::TINY].iter().map(|p| (p.name, p.to_json())).collect()
}
