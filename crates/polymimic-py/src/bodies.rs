//! `polymimic.Body`: the body a robot has, one value built once (from a built-in body's name,
//! a described wheeled body or its TOML table) and passed whole — its kind, primitive set, field
//! and reach all read off it.

use polymimic_field::body::{LEGO, TINY, WheeledParams};
use polymimic_field::{BodyKind, FieldGeometry, FieldSize};
use polymimic_learn::{imitator_reach_mm, reach_mm};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{IntoPyDict, PyString, PyTuple, PyType};

use crate::errors::field_param_error;

/// The built-in bodies, by name.
const BUILT_IN: [(&str, BodyKind); 3] =
    [("lego", BodyKind::Lego), ("tiny", BodyKind::Tiny), ("humanoid", BodyKind::Humanoid)];

/// The body argument of the native functions: a `polymimic.Body`, a built-in body's name, or a
/// `polymimic.bodies.WheeledBody` (which hands over its constants as JSON).
#[derive(Debug, Clone, Copy)]
pub struct Body(pub BodyKind);

impl<'a, 'py> FromPyObject<'a, 'py> for Body {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(body) = obj.cast::<PyBody>() {
            return Ok(Self(body.get().kind));
        }
        if let Ok(name) = obj.cast::<PyString>() {
            return built_in(&name.to_cow()?).map(Self);
        }
        if obj.hasattr("_native_body")? {
            return PyBody::new(&obj.to_owned()).map(|body| Self(body.kind));
        }
        Err(PyTypeError::new_err(format!("body must be a polymimic.Body or a body's name, got {}", obj.repr()?)))
    }
}

/// The body argument of the native functions that keep the body to hand back (a policy's
/// `body`): a `polymimic.Body` as it is (so a body of one's own keeps the description it was
/// made from), a built-in body's name or a described wheeled body made one.
#[derive(Debug)]
pub struct BodyValue(pub Py<PyBody>);

impl<'a, 'py> FromPyObject<'a, 'py> for BodyValue {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(body) = obj.cast::<PyBody>() {
            return Ok(Self(body.to_owned().unbind()));
        }
        let body = if obj.hasattr("_native_body")? {
            PyBody::new(&obj.to_owned())?
        } else {
            PyBody::of(obj.extract::<Body>()?.0)
        };
        Ok(Self(Py::new(obj.py(), body)?))
    }
}

impl BodyValue {
    /// The Lego robot, the default body.
    pub fn lego(py: Python<'_>) -> PyResult<Self> {
        Ok(Self(Py::new(py, PyBody::of(BodyKind::Lego))?))
    }

    /// The body's kind, as the field and the learner take it.
    pub fn kind(&self) -> BodyKind {
        self.0.get().kind
    }
}

/// The built-in body `name`, or a `ValueError` listing the known ones and how to describe one's own.
fn built_in(name: &str) -> PyResult<BodyKind> {
    BUILT_IN.iter().find(|(n, _)| *n == name).map(|(_, kind)| *kind).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown body {name:?}: the built-in bodies are {}; describe a body of your own with \
             polymimic.bodies.WheeledBody(name, length_mm=…, width_mm=…, wheel_base_mm=…, top_wheel_speed_mm_s=…) \
             (or a [bodies.{name}] table) and make it a polymimic.Body",
            BUILT_IN.map(|(n, _)| n).join(", ")
        ))
    })
}

/// A body: one of the built-in ones by name (``"lego"``, ``"tiny"``, ``"humanoid"``), or a
/// :class:`polymimic.bodies.WheeledBody` of your own (a wheeled body equal to the Lego or the tiny robot
/// is that body, bit for bit). Everything that asks which body also learns from it which field
/// it plays on, which primitives it has and how far it reaches for the ball.
///
/// >>> lego = Body("lego")
/// >>> lego.kind, lego.field.length_mm, lego.reach_mm, Body("tiny").primitive_set
/// ('lego', 1020.0, 120.0, 'wheeled')
/// >>> Body("robot")
/// Traceback (most recent call last):
/// ...
/// ValueError: unknown body "robot": the built-in bodies are lego, tiny, humanoid; describe a body of your own with polymimic.bodies.WheeledBody(name, length_mm=…, width_mm=…, wheel_base_mm=…, top_wheel_speed_mm_s=…) (or a [bodies.robot] table) and make it a polymimic.Body
#[pyclass(name = "Body", module = "polymimic", frozen)]
pub struct PyBody {
    pub(crate) kind: BodyKind,
    /// The `polymimic.WheeledBody` a body of the user's was made from.
    description: Option<Py<PyAny>>,
}

impl PyBody {
    /// The body of `kind`: a built-in one, or a body of one's own whose description is made
    /// again from its constants when asked for.
    pub(crate) const fn of(kind: BodyKind) -> Self {
        Self { kind, description: None }
    }
}

#[pymethods]
impl PyBody {
    #[new]
    #[pyo3(text_signature = "(body)")]
    fn new(body: &Bound<'_, PyAny>) -> PyResult<Self> {
        if let Ok(given) = body.cast::<PyBody>() {
            let given = given.get();
            return Ok(Self {
                kind: given.kind,
                description: given.description.as_ref().map(|d| d.clone_ref(body.py())),
            });
        }
        if let Ok(name) = body.cast::<PyString>() {
            return Ok(Self::of(built_in(&name.to_cow()?)?));
        }
        let Ok(native) = body.getattr("_native_body") else {
            return Err(PyTypeError::new_err(format!(
                "body must be a built-in body's name or a polymimic.bodies.WheeledBody, got {}",
                body.repr()?
            )));
        };
        let (json, field): (String, String) = native.call0()?.extract()?;
        let params = WheeledParams::from_json(&json).map_err(field_param_error)?;
        let field = match field.as_str() {
            "large" => FieldGeometry::of(FieldSize::Large),
            "small" => FieldGeometry::of(FieldSize::Small),
            sizes => FieldGeometry::from_json(sizes).map_err(field_param_error)?,
        };
        let kind = match (params.name, params) {
            ("lego", params) if params == LEGO && field == FieldGeometry::of(FieldSize::Large) => BodyKind::Lego,
            ("tiny", params) if params == TINY && field == FieldGeometry::of(FieldSize::Small) => BodyKind::Tiny,
            (name, _) if BUILT_IN.iter().any(|(n, _)| *n == name) => {
                return Err(PyValueError::new_err(format!(
                    "body name {name:?} is a built-in body's; give your body a name of its own"
                )));
            }
            _ => BodyKind::Wheeled(params, field),
        };
        let description = matches!(kind, BodyKind::Wheeled(..)).then(|| body.clone().unbind());
        Ok(Self { kind, description })
    }

    /// A body from its TOML table (``[bodies.<name>]``; see
    /// :meth:`polymimic.bodies.WheeledBody.from_table`), a ``ValueError`` naming ``where`` and the key
    /// for anything unknown or out of range.
    ///
    /// >>> Body.from_table("cart", {"length_mm": 90, "width_mm": 80, "wheel_base_mm": 70,
    /// ...                          "top_wheel_speed_mm_s": 60}).field.length_mm
    /// 1020.0
    #[classmethod]
    #[pyo3(signature = (name, table, *, r#where=""))]
    fn from_table(_cls: &Bound<'_, PyType>, name: &str, table: &Bound<'_, PyAny>, r#where: &str) -> PyResult<Self> {
        let py = table.py();
        let wheeled = py.import("polymimic.bodies")?.getattr("WheeledBody")?;
        let description =
            wheeled.call_method("from_table", (name, table), Some(&[("where", r#where)].into_py_dict(py)?))?;
        Self::new(&description)
    }

    /// The body's name: a built-in body's, or the one its description gives.
    #[getter]
    fn name(&self) -> &'static str {
        self.kind.name()
    }

    /// What kind of body: ``"lego"``, ``"tiny"``, ``"humanoid"`` (the built-in ones) or
    /// ``"wheeled"`` (a two-wheeled robot of your own).
    #[getter]
    fn kind(&self) -> &'static str {
        match self.kind {
            BodyKind::Wheeled(..) => "wheeled",
            built_in => built_in.name(),
        }
    }

    /// Which primitive set it moves with: ``"wheeled"`` (forward, backward, left, right, stop) or
    /// ``"humanoid"`` (those, its side-steps and its kick).
    #[getter]
    fn primitive_set(&self) -> &'static str {
        if self.kind.is_wheeled() { "wheeled" } else { "humanoid" }
    }

    /// Its own primitives' names, in the set's order.
    #[getter]
    fn primitives(&self) -> Vec<&'static str> {
        self.kind.primitive_set().primitives().iter().map(|p| p.name()).collect()
    }

    /// The field it plays on, as a :class:`polymimic.bodies.Field`.
    #[getter]
    fn field<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let f = self.kind.field();
        py.import("polymimic.bodies")?.getattr("Field")?.call1((
            f.length_mm,
            f.width_mm,
            f.goal_mouth_mm,
            f.ball_diameter_mm,
        ))
    }

    /// How far from its centre it moves the ball as a demonstrator, mm: the ball's radius beyond
    /// a wheeled body's front (half its length), or beyond the humanoid's kicking foot at full
    /// reach. The learner's correspondence between bodies keeps a touch a touch.
    #[getter]
    fn reach_mm(&self) -> f64 {
        reach_mm(self.kind)
    }

    /// How far from its centre it moves the ball as an imitator, mm: the ball's radius beyond its
    /// front (the humanoid walks into the ball, even over its own set with a kick).
    #[getter]
    fn imitating_reach_mm(&self) -> f64 {
        imitator_reach_mm(self.kind)
    }

    /// The :class:`polymimic.bodies.WheeledBody` describing it: a body of your own's, the Lego's and the
    /// tiny robot's constants (:data:`polymimic.bodies.THESIS_BODIES`); ``None`` for the humanoid.
    #[getter]
    fn description<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        if let Some(description) = &self.description {
            return Ok(description.bind(py).clone());
        }
        let bodies = py.import("polymimic.bodies")?;
        match self.kind {
            BodyKind::Wheeled(params, field) => {
                let sizes = format!(
                    "{{\"length_mm\": {:?}, \"width_mm\": {:?}, \"goal_mouth_mm\": {:?}, \"ball_diameter_mm\": {:?}}}",
                    field.length_mm, field.width_mm, field.goal_mouth_mm, field.ball_diameter_mm
                );
                bodies.getattr("WheeledBody")?.call_method1("_from_native", (params.to_json(), sizes))
            }
            built_in => bodies.getattr("THESIS_BODIES")?.call_method1("get", (built_in.name(),)),
        }
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyBody>().is_ok_and(|o| o.get().kind == self.kind)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        self.kind.name().hash(&mut hasher);
        if let BodyKind::Wheeled(params, field) = self.kind {
            params.to_json().hash(&mut hasher);
            for size in [field.length_mm, field.width_mm, field.goal_mouth_mm, field.ball_diameter_mm] {
                size.to_bits().hash(&mut hasher);
            }
        }
        hasher.finish()
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let made_from = match slf.get().kind {
            BodyKind::Wheeled(..) => slf.get().description(py)?,
            built_in => PyString::new(py, built_in.name()).into_any(),
        };
        Ok((slf.get_type().into_any(), PyTuple::new(py, [made_from])?))
    }

    fn __repr__(&self) -> String {
        match self.kind {
            BodyKind::Wheeled(params, field) => format!(
                "Body('{}': wheeled, {:?} × {:?} mm on a {:?} × {:?} mm field)",
                params.name, params.length_mm, params.width_mm, field.length_mm, field.width_mm
            ),
            built_in => format!("Body('{}')", built_in.name()),
        }
    }
}

/// The constants of the thesis's two wheeled bodies, as JSON by name.
#[pyfunction]
pub fn thesis_wheeled_bodies() -> Vec<(&'static str, String)> {
    [LEGO, TINY].iter().map(|p| (p.name, p.to_json())).collect()
}
