//! `polymimic.SegmentedDemonstrations`: demonstrations as the learner takes them, checked once
//! on the way in from Python and then shared (behind an `Arc`) by every trial and policy.
// The docstrings are Python's: their examples quote Python lists, not Rust doc links.
#![allow(clippy::doc_link_with_quotes)]

use std::sync::Arc;

use polymimic_field::Outcome;
use polymimic_learn::{Ending, Pitch, SegmentedDemonstration, Setting};
use polymimic_perceive::{Label, NO_SCORES, Pose, Primitive, PrimitiveSet, Segment, TrackedFrame};
use pyo3::exceptions::{PyIndexError, PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{IntoPyDict, PyDict, PyIterator, PyList, PyString, PyTuple};

use crate::bodies::Body;
use crate::convert::{floats, integers};
use crate::perceive::segment_columns;

const OUTCOMES: [Outcome; 5] = [Outcome::Goal, Outcome::OwnGoal, Outcome::BallOut, Outcome::RobotOut, Outcome::TimeUp];
const PITCHES: [(&str, Pitch); 2] = [("large", Pitch::LARGE), ("small", Pitch::SMALL)];
const STATE_COLUMNS: [&str; 5] = ["robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"];

/// Segmented demonstrations: who demonstrated, how each ended, on which field, and its
/// segments (as :meth:`PrimitiveRecognizer.segment` gives them).
///
/// Built from dictionaries with ``demonstrator``, ``outcome`` (a field outcome: ``"goal"``,
/// ``"own_goal"``, ``"ball_out"``, ``"robot_out"``, ``"time_up"``), ``pitch`` (``"large"`` or
/// ``"small"``) and ``segments`` (columns ``label``, ``first_frame``, ``last_frame``, ``start``
/// and ``end`` of shape ``(k, 5)`` and, optionally, ``scores`` of shape ``(k, 4)``), every value
/// is checked once, here: a bad one is a ``ValueError`` naming the demonstration, the field,
/// the value and what is allowed. ``frame_counts`` (one per demonstration) also checks that
/// every segment lies inside its demonstration. The batch is immutable and shared, not copied,
/// by every trial and policy it is given to; indexing gives a demonstration back read-only
/// (mappings that refuse assignment, labels as a tuple, arrays that refuse writes), so what
/// was checked cannot change; ``dict(item)`` and the columns' copies make a new one to edit
/// and check again. Batches add and pickle.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> state = np.zeros((1, 5))
/// >>> segments = {"label": ["forward"], "first_frame": np.array([0]), "last_frame": np.array([9]),
/// ...             "start": state, "end": state}
/// >>> batch = SegmentedDemonstrations([{"demonstrator": "expert", "outcome": "goal", "pitch": "large",
/// ...                                   "segments": segments}])
/// >>> len(batch), batch.outcomes, batch[0]["segments"]["label"]
/// (1, ['goal'], ('forward',))
/// >>> batch[0]["segments"]["label"] = ["jump"]
/// Traceback (most recent call last):
/// ...
/// TypeError: 'mappingproxy' object does not support item assignment
/// >>> SegmentedDemonstrations([{"demonstrator": "expert", "outcome": "own-goal", "pitch": "large",
/// ...                           "segments": segments}])
/// Traceback (most recent call last):
/// ...
/// ValueError: demonstration 0: outcome 'own-goal' is not one of 'goal', 'own_goal', 'ball_out', 'robot_out', 'time_up'
#[pyclass(name = "SegmentedDemonstrations", module = "polymimic", frozen, sequence)]
pub struct PySegmentedDemonstrations {
    pub(crate) demonstrations: Arc<[SegmentedDemonstration]>,
    outcomes: Arc<[Outcome]>,
}

/// A pitch as the Python side writes it: a thesis field's name, or its sizes as JSON.
fn pitch_name(pitch: &Pitch) -> String {
    PITCHES.iter().find(|(_, p)| p == pitch).map_or_else(
        || {
            format!(
                "{{\"length_mm\": {:?}, \"width_mm\": {:?}, \"goal_mouth_mm\": {:?}}}",
                pitch.length_mm, pitch.width_mm, pitch.goal_mouth_mm
            )
        },
        |(name, _)| (*name).to_owned(),
    )
}

/// A pitch from its name or its sizes as JSON (`{"length_mm", "width_mm", "goal_mouth_mm"}`).
pub fn pitch_from(text: &str, what: &str) -> PyResult<Pitch> {
    if let Some((_, p)) = PITCHES.iter().find(|(n, _)| *n == text) {
        return Ok(*p);
    }
    Pitch::from_json(text).ok_or_else(|| {
        PyValueError::new_err(format!(
            "{what}: pitch '{text}' is not one of {} nor a field's sizes as JSON {{\"length_mm\": …, \"width_mm\": …, \
             \"goal_mouth_mm\": …}} (positive, the mouth no wider than the field)",
            quoted(PITCHES.map(|(n, _)| n))
        ))
    })
}

fn quoted(names: impl IntoIterator<Item = &'static str>) -> String {
    names.into_iter().map(|n| format!("'{n}'")).collect::<Vec<_>>().join(", ")
}

/// One checked demonstration and its outcome. `what` is "demonstration i".
fn demonstration(
    item: &Bound<'_, PyAny>,
    what: &str,
    frame_count: Option<usize>,
) -> PyResult<(SegmentedDemonstration, Outcome)> {
    let get = |key: &str| -> PyResult<Bound<'_, PyAny>> {
        item.get_item(key).map_err(|_| PyValueError::new_err(format!("{what}: no {key:?} given")))
    };
    let text = |key: &str| -> PyResult<String> {
        let value = get(key)?;
        value.extract::<String>().map_err(|_| {
            PyTypeError::new_err(format!(
                "{what}: {key} must be a string, got {}",
                value.repr().map_or_else(|_| "?".into(), |r| r.to_string())
            ))
        })
    };
    let demonstrator = text("demonstrator")?;
    let outcome_name = text("outcome")?;
    let outcome = OUTCOMES.into_iter().find(|o| o.name() == outcome_name).ok_or_else(|| {
        PyValueError::new_err(format!(
            "{what}: outcome '{outcome_name}' is not one of {}",
            quoted(OUTCOMES.map(Outcome::name))
        ))
    })?;
    let (pitch, reach_mm) = match item.get_item("body") {
        Ok(body) if !body.is_none() => setting_of(item, &body, what)?,
        _ => (pitch_from(&text("pitch")?, what)?, reach(item, what)?),
    };
    let segments = segments(&get("segments")?, what, frame_count)?;
    Ok((SegmentedDemonstration { demonstrator, pitch, reach_mm, ending: Ending::from(outcome), segments }, outcome))
}

/// The field and reach of an item given by its `body` (a `polymimic.Body`), demonstrating or,
/// with `"imitating": True`, imitating.
fn setting_of(item: &Bound<'_, PyAny>, body: &Bound<'_, PyAny>, what: &str) -> PyResult<(Pitch, Option<f64>)> {
    let body: Body = body.extract().map_err(|e| PyTypeError::new_err(format!("{what}: body: {e}")))?;
    let imitating = match item.get_item("imitating") {
        Ok(value) => value.extract::<bool>().map_err(|_| {
            PyTypeError::new_err(format!(
                "{what}: imitating must be True or False, got {}",
                value.repr().map_or_else(|_| "?".into(), |r| r.to_string())
            ))
        })?,
        Err(_) => false,
    };
    let setting = if imitating { Setting::of_imitator(body.0) } else { Setting::of_body(body.0) };
    Ok((setting.pitch, setting.reach_mm))
}

/// The optional `reach_mm` of an item: how far from its centre its demonstrator's body moves
/// the ball, a positive number of millimetres (`None` or absent where unknown).
fn reach(item: &Bound<'_, PyAny>, what: &str) -> PyResult<Option<f64>> {
    let Ok(value) = item.get_item("reach_mm") else { return Ok(None) };
    if value.is_none() {
        return Ok(None);
    }
    match value.extract::<f64>() {
        Ok(mm) if mm.is_finite() && mm > 0.0 && !value.is_instance_of::<pyo3::types::PyBool>() => Ok(Some(mm)),
        _ => Err(PyValueError::new_err(format!(
            "{what}: reach_mm must be a positive number of millimetres or None, got {}",
            value.repr().map_or_else(|_| "?".into(), |r| r.to_string())
        ))),
    }
}

fn label(name: &str, what: &str) -> PyResult<Label> {
    if name == "gap" {
        return Ok(Label::Gap);
    }
    Primitive::from_name(name).map(Label::Primitive).ok_or_else(|| {
        let allowed = quoted(Primitive::ALL.map(Primitive::name).into_iter().chain(["gap"]));
        PyValueError::new_err(format!("{what}: label '{name}' is not one of {allowed}"))
    })
}

/// The set of the recogniser that scored `segments`, read off the scores: only the humanoid's
/// scores the slots past the wheeled four.
fn scored_by(segments: &[Segment]) -> PrimitiveSet {
    let wheeled = PrimitiveSet::Wheeled.moving().len();
    let beyond = segments.iter().any(|s| s.scores[wheeled..].iter().any(|v| *v != f64::NEG_INFINITY));
    if beyond { PrimitiveSet::Humanoid } else { PrimitiveSet::Wheeled }
}

fn states(value: &Bound<'_, PyAny>, what: &str, key: &str, k: usize) -> PyResult<Vec<TrackedFrame>> {
    let (data, shape) = floats(value, &format!("{what}: {key}"), 2)?;
    if shape != [k, 5] {
        return Err(PyValueError::new_err(format!(
            "{what}: {key} has shape {shape:?}; expected [{k}, 5] (one row of robot x, y, θ and ball x, y per label)"
        )));
    }
    data.chunks_exact(5)
        .enumerate()
        .map(|(j, r)| {
            if let Some(c) = r.iter().position(|v| !v.is_finite()) {
                return Err(PyValueError::new_err(format!(
                    "{what}: segment {j}: {key} {} = {}; states must be finite",
                    STATE_COLUMNS[c], r[c]
                )));
            }
            Ok(TrackedFrame { robot: Pose::new(r[0], r[1], r[2]), ball_x_mm: r[3], ball_y_mm: r[4] })
        })
        .collect()
}

fn segments(columns: &Bound<'_, PyAny>, what: &str, frame_count: Option<usize>) -> PyResult<Vec<Segment>> {
    let get = |key: &str| -> PyResult<Bound<'_, PyAny>> {
        columns.get_item(key).map_err(|_| PyValueError::new_err(format!("{what}: segments has no column {key:?}")))
    };
    let labels: Vec<String> = get("label")?
        .extract()
        .map_err(|_| PyTypeError::new_err(format!("{what}: segments label must be a list of strings")))?;
    let k = labels.len();
    let first = integers(&get("first_frame")?, &format!("{what}: first_frame"))?;
    let last = integers(&get("last_frame")?, &format!("{what}: last_frame"))?;
    for (key, column) in [("first_frame", &first), ("last_frame", &last)] {
        if column.len() != k {
            return Err(PyValueError::new_err(format!("{what}: {key} has {} values for {k} labels", column.len())));
        }
    }
    let start = states(&get("start")?, what, "start", k)?;
    let end = states(&get("end")?, what, "end", k)?;
    let scores = match columns.get_item("scores") {
        Err(_) => vec![NO_SCORES; k],
        Ok(value) if value.is_none() => vec![NO_SCORES; k],
        Ok(value) => {
            let (data, shape) = floats(&value, &format!("{what}: scores"), 2)?;
            let columns: Vec<usize> = PrimitiveSet::ALL.iter().map(|set| set.moving().len()).collect();
            if shape.len() != 2 || shape[0] != k || !columns.contains(&shape[1]) {
                return Err(PyValueError::new_err(format!(
                    "{what}: scores has shape {shape:?}; expected [{k}, 4] (a wheeled recogniser's) or [{k}, 7] (the humanoid's)"
                )));
            }
            data.chunks_exact(shape[1])
                .map(|r| std::array::from_fn(|i| r.get(i).copied().unwrap_or(f64::NEG_INFINITY)))
                .collect()
        }
    };
    (0..k)
        .map(|j| {
            let at = format!("{what}: segment {j}");
            let frame = |key: &str, value: i64| -> PyResult<usize> {
                let index = usize::try_from(value).map_err(|_| {
                    PyValueError::new_err(format!("{at}: {key} {value} is negative; frame indices are ≥ 0"))
                })?;
                match frame_count {
                    Some(n) if index >= n => Err(PyValueError::new_err(format!(
                        "{at}: {key} {value} is outside the demonstration's {n} frames (0..{n})"
                    ))),
                    _ => Ok(index),
                }
            };
            let (first_frame, last_frame) = (frame("first_frame", first[j])?, frame("last_frame", last[j])?);
            if first_frame > last_frame {
                return Err(PyValueError::new_err(format!(
                    "{at}: first_frame {first_frame} is after last_frame {last_frame}; a segment ends where or after it starts"
                )));
            }
            Ok(Segment {
                label: label(&labels[j], &at)?,
                first_frame,
                last_frame,
                start: start[j],
                end: end[j],
                scores: scores[j],
            })
        })
        .collect()
}

impl PySegmentedDemonstrations {
    fn from_parts(demonstrations: Vec<SegmentedDemonstration>, outcomes: Vec<Outcome>) -> Self {
        Self { demonstrations: demonstrations.into(), outcomes: outcomes.into() }
    }

    /// Demonstration `i` as a dictionary the constructor takes (a copy of it).
    fn item<'py>(&self, py: Python<'py>, i: usize) -> PyResult<Bound<'py, PyDict>> {
        let d = &self.demonstrations[i];
        let out = PyDict::new(py);
        out.set_item("demonstrator", &d.demonstrator)?;
        out.set_item("outcome", self.outcomes[i].name())?;
        out.set_item("segments", segment_columns(py, &d.segments, scored_by(&d.segments))?)?;
        out.set_item("pitch", pitch_name(&d.pitch))?;
        out.set_item("reach_mm", d.reach_mm)?;
        Ok(out)
    }

    /// Every demonstration as `each` gives it, in order.
    fn items<'py, T: IntoPyObject<'py>>(
        &self,
        py: Python<'py>,
        each: impl Fn(&Self, Python<'py>, usize) -> PyResult<T>,
    ) -> PyResult<Bound<'py, PyList>> {
        let items = PyList::empty(py);
        for i in 0..self.demonstrations.len() {
            items.append(each(self, py, i)?)?;
        }
        Ok(items)
    }

    /// Demonstration `i` as a read-only view: mappings that refuse assignment and deletion,
    /// labels as a tuple, arrays that refuse writes. What was checked cannot change behind the
    /// learner's back, even in a copy a user might take for the batch itself.
    fn read_only_item<'py>(&self, py: Python<'py>, i: usize) -> PyResult<Bound<'py, PyAny>> {
        let proxy = py.import("types")?.getattr("MappingProxyType")?;
        let item = self.item(py, i)?;
        let columns =
            item.get_item("segments")?.ok_or_else(|| PyKeyError::new_err("segments"))?.cast_into::<PyDict>()?;
        for (key, column) in columns.iter() {
            if column.is_instance_of::<PyList>() {
                columns.set_item(key, PyTuple::new(py, column.cast_into::<PyList>()?.iter())?)?;
            } else {
                column.call_method("setflags", (), Some(&[("write", false)].into_py_dict(py)?))?;
            }
        }
        item.set_item("segments", proxy.call1((columns,))?)?;
        proxy.call1((item,))
    }
}

#[pymethods]
impl PySegmentedDemonstrations {
    #[new]
    #[pyo3(signature = (demonstrations, *, frame_counts=None))]
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the counts by value
    fn new(demonstrations: &Bound<'_, PyAny>, frame_counts: Option<Vec<i64>>) -> PyResult<Self> {
        let items: Vec<Bound<'_, PyAny>> = demonstrations
            .try_iter()
            .map_err(|_| PyTypeError::new_err("demonstrations must be an iterable of dictionaries"))?
            .collect::<PyResult<_>>()?;
        if let Some(counts) = &frame_counts {
            if counts.len() != items.len() {
                return Err(PyValueError::new_err(format!(
                    "{} frame_counts for {} demonstrations: give one per demonstration",
                    counts.len(),
                    items.len()
                )));
            }
        }
        let mut demos = Vec::with_capacity(items.len());
        let mut outcomes = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let what = format!("demonstration {i}");
            let count = match frame_counts.as_ref().map(|c| c[i]) {
                None => None,
                Some(n) => Some(
                    usize::try_from(n)
                        .map_err(|_| PyValueError::new_err(format!("{what}: frame count {n} is negative")))?,
                ),
            };
            let (demo, outcome) = demonstration(item, &what, count)?;
            demos.push(demo);
            outcomes.push(outcome);
        }
        Ok(Self::from_parts(demos, outcomes))
    }

    /// The batches one after another.
    ///
    /// >>> len(SegmentedDemonstrations.concat([SegmentedDemonstrations([]), SegmentedDemonstrations([])]))
    /// 0
    #[staticmethod]
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the list by value
    fn concat(batches: Vec<PyRef<'_, Self>>) -> Self {
        let demos = batches.iter().flat_map(|b| b.demonstrations.iter().cloned()).collect();
        let outcomes = batches.iter().flat_map(|b| b.outcomes.iter().copied()).collect();
        Self::from_parts(demos, outcomes)
    }

    fn __add__(&self, other: &Self) -> Self {
        let demos = self.demonstrations.iter().chain(other.demonstrations.iter()).cloned().collect();
        let outcomes = self.outcomes.iter().chain(other.outcomes.iter()).copied().collect();
        Self::from_parts(demos, outcomes)
    }

    fn __len__(&self) -> usize {
        self.demonstrations.len()
    }

    /// Demonstration `index`, read-only, with the keys and columns the constructor takes.
    fn __getitem__<'py>(&self, py: Python<'py>, index: isize) -> PyResult<Bound<'py, PyAny>> {
        let n = self.demonstrations.len() as isize;
        let i = if index < 0 { index + n } else { index };
        if !(0..n).contains(&i) {
            return Err(PyIndexError::new_err(format!("demonstration {index} of {n}")));
        }
        self.read_only_item(py, i as usize)
    }

    /// Every demonstration, read-only, in order.
    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyIterator>> {
        self.items(py, Self::read_only_item)?.try_iter()
    }

    /// Who demonstrated each.
    #[getter]
    fn demonstrators(&self) -> Vec<String> {
        self.demonstrations.iter().map(|d| d.demonstrator.clone()).collect()
    }

    /// How each ended.
    #[getter]
    fn outcomes(&self) -> Vec<&'static str> {
        self.outcomes.iter().map(|o| o.name()).collect()
    }

    /// The field each was played on: ``"large"``, ``"small"`` or its sizes as JSON.
    #[getter]
    fn pitches(&self) -> Vec<String> {
        self.demonstrations.iter().map(|d| pitch_name(&d.pitch)).collect()
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.demonstrations == other.demonstrations && self.outcomes == other.outcomes
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let items = slf.get().items(slf.py(), Self::item)?;
        Ok((slf.get_type().into_any(), PyTuple::new(slf.py(), [items])?))
    }

    fn __repr__(&self) -> String {
        let mut counts: Vec<(&str, usize)> = Vec::new();
        for d in self.demonstrations.iter() {
            match counts.iter_mut().find(|(who, _)| *who == d.demonstrator) {
                Some((_, n)) => *n += 1,
                None => counts.push((&d.demonstrator, 1)),
            }
        }
        let who: Vec<String> = counts.iter().map(|(w, n)| format!("{w} {n}")).collect();
        format!("SegmentedDemonstrations({} demonstrations: {})", self.demonstrations.len(), who.join(", "))
    }
}

/// `value` as a batch: a batch as it is (shared), or dictionaries checked into one.
pub(crate) fn batch(value: &Bound<'_, PyAny>) -> PyResult<Arc<[SegmentedDemonstration]>> {
    if let Ok(batch) = value.cast::<PySegmentedDemonstrations>() {
        return Ok(Arc::clone(&batch.get().demonstrations));
    }
    if value.is_instance_of::<PyString>() {
        return Err(PyTypeError::new_err("demonstrations must be SegmentedDemonstrations, not a string"));
    }
    Ok(PySegmentedDemonstrations::new(value, None)?.demonstrations)
}
