//! `polymimic.PrimitiveRecognizer`: the HMM bank and the segmenter.

use std::path::PathBuf;

use numpy::{PyArray1, PyArray2};
use polymimic_perceive::{
    Emissions, LabelledSequence, PrimitiveHmm, Recognizer, RecognizerConfig, Representation, Segment, SegmenterConfig,
    segment, segment_many,
};
use polymimic_types::{Pose, Primitive, PrimitiveSet, TrackedFrame};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple, PyType};

use crate::convert::{frame_columns, matrix, non_negative, one_of, read_model, reduce_to_json, write_atomically};
use crate::errors::perceive_error;
use crate::hmm::PyDiscreteHmm;
use crate::vq::PyCodebook;

const POSE_COLUMNS: [&str; 3] = ["robot_x_mm", "robot_y_mm", "robot_theta_rad"];
const FRAME_COLUMNS: [&str; 5] = ["robot_x_mm", "robot_y_mm", "robot_theta_rad", "ball_x_mm", "ball_y_mm"];

/// Recognises the imitator's primitives in tracker frames and segments demonstrations.
///
/// One codebook per representation and one HMM per moving primitive of the imitator's set, each
/// reading one-second sequences of frames through its own representation (thesis §3.1); a
/// sequence that barely moves is `stop`. `segment` cuts a demonstration into segments it names
/// (thesis §3.2.2). Train one with `PrimitiveRecognizer.train`, or with
/// `polymimic.recognition.train_recognizer` from self-observation sequences.
///
/// Examples
/// --------
/// >>> import polymimic
/// >>> from polymimic import recognition
/// >>> recognizer = recognition.train_recognizer(polymimic.self_observation(20, seed=1), codebook_size=16)
/// >>> recognizer.moving
/// ['forward', 'backward', 'left', 'right']
/// >>> frames = polymimic.record("expert", configuration=1, n=1, seed=0)[0].frames
/// >>> sorted(recognizer.segment(frames))
/// ['end', 'first_frame', 'label', 'last_frame', 'scores', 'start']
#[pyclass(name = "PrimitiveRecognizer", module = "polymimic", frozen)]
pub struct PyPrimitiveRecognizer {
    pub(crate) recognizer: Recognizer,
}

fn poses(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Pose>> {
    Ok(frame_columns(value, what, &POSE_COLUMNS)?.into_iter().map(|r| Pose::new(r[0], r[1], r[2])).collect())
}

fn tracked_frames(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<TrackedFrame>> {
    Ok(frame_columns(value, what, &FRAME_COLUMNS)?
        .into_iter()
        .map(|r| TrackedFrame { robot: Pose::new(r[0], r[1], r[2]), ball_x_mm: r[3], ball_y_mm: r[4] })
        .collect())
}

fn primitive(name: &str) -> PyResult<Primitive> {
    Primitive::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Primitive::ALL.iter().map(|p| p.name()).collect();
        PyValueError::new_err(format!("unknown primitive {name:?}; expected one of {}", names.join(", ")))
    })
}

fn representations(name: &str) -> PyResult<(Representation, Representation)> {
    one_of(
        "representation",
        name,
        &[
            ("thesis", (Representation::Positional, Representation::Rotational)),
            ("egocentric", (Representation::Egocentric, Representation::Egocentric)),
        ],
    )
}

/// The segmenter's keywords, in the order a signature would list them; each one left out takes
/// `SegmenterConfig::default()`, the defaults' one home.
const SEGMENTER_KEYWORDS: [&str; 5] =
    ["min_frames", "stop_distance_mm", "stop_rotation_deg", "limit_sds", "gap_margin"];

/// The segmenter's settings as `segment` and `segment_many` take them (`**settings`), read the
/// way pyo3 reads a signature: an unknown keyword is a `TypeError` naming it, then each value's
/// type is checked in [`SEGMENTER_KEYWORDS`] order, before the frames; the range of `min_frames`
/// is checked after them, by [`Self::config`].
struct SegmenterSettings {
    min_frames: Option<i64>,
    config: SegmenterConfig,
}

impl SegmenterSettings {
    fn extract(method: &str, settings: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut out = Self { min_frames: None, config: SegmenterConfig::default() };
        let Some(settings) = settings else { return Ok(out) };
        for key in settings.keys() {
            let key: String = key.extract()?;
            if !SEGMENTER_KEYWORDS.contains(&key.as_str()) {
                return Err(PyTypeError::new_err(format!(
                    "PrimitiveRecognizer.{method}() got an unexpected keyword argument '{key}'"
                )));
            }
        }
        if let Some(value) = settings.get_item("min_frames")? {
            out.min_frames = Some(value.extract()?);
        }
        let c = &mut out.config;
        for (name, slot) in [
            ("stop_distance_mm", &mut c.stop_distance_mm),
            ("stop_rotation_deg", &mut c.stop_rotation_deg),
            ("limit_sds", &mut c.limit_sds),
            ("gap_margin", &mut c.gap_margin),
        ] {
            if let Some(value) = settings.get_item(name)? {
                *slot = value.extract()?;
            }
        }
        Ok(out)
    }

    fn config(self) -> PyResult<SegmenterConfig> {
        let mut config = self.config;
        if let Some(min_frames) = self.min_frames {
            config.min_frames = non_negative("min_frames", min_frames)?;
        }
        Ok(config)
    }
}

/// Segments as columns: labels, frame ranges, end frames and the scores of the recogniser's
/// `set`, one column per moving primitive of it.
pub(crate) fn segment_columns<'py>(
    py: Python<'py>,
    segments: &[Segment],
    set: PrimitiveSet,
) -> PyResult<Bound<'py, PyDict>> {
    let n_scores = set.moving().len();
    let k = segments.len();
    let out = PyDict::new(py);
    out.set_item("label", PyList::new(py, segments.iter().map(|s| s.label.name()))?)?;
    out.set_item("first_frame", PyArray1::from_vec(py, segments.iter().map(|s| s.first_frame as i64).collect()))?;
    out.set_item("last_frame", PyArray1::from_vec(py, segments.iter().map(|s| s.last_frame as i64).collect()))?;
    out.set_item("start", matrix(py, segments.iter().flat_map(|s| frame_row(&s.start)).collect(), k, 5)?)?;
    out.set_item("end", matrix(py, segments.iter().flat_map(|s| frame_row(&s.end)).collect(), k, 5)?)?;
    let scores = segments.iter().flat_map(|s| s.scores[..n_scores].to_vec()).collect();
    out.set_item("scores", matrix(py, scores, k, n_scores)?)?;
    Ok(out)
}

pub(crate) fn frame_row(frame: &TrackedFrame) -> [f64; 5] {
    [frame.robot.x_mm(), frame.robot.y_mm(), frame.robot.theta_rad(), frame.ball_x_mm, frame.ball_y_mm]
}

impl PyPrimitiveRecognizer {
    fn n_moving(&self) -> usize {
        self.recognizer.primitive_set().moving().len()
    }
}

#[pymethods]
impl PyPrimitiveRecognizer {
    /// Trains the codebooks and an HMM per moving primitive of `primitives` (`"wheeled"`, the
    /// four, or `"humanoid"`, the humanoid's seven) on self-observation sequences.
    #[classmethod]
    #[pyo3(signature = (sequences, labels, *, n_states=1, codebook_size=512, links=2, max_iter=100, tol=1e-4,
                        representation="thesis", emissions="discrete", emission_floor=1e-8, min_variance=0.01, seed=0,
                        primitives="wheeled"))]
    #[allow(clippy::too_many_arguments, clippy::needless_pass_by_value)] // pyo3 extracts by value
    fn train(
        _cls: &Bound<'_, PyType>,
        py: Python<'_>,
        sequences: &Bound<'_, PyAny>,
        labels: Vec<String>,
        n_states: i64,
        codebook_size: i64,
        links: i64,
        max_iter: i64,
        tol: f64,
        representation: &str,
        emissions: &str,
        emission_floor: f64,
        min_variance: f64,
        seed: i64,
        primitives: &str,
    ) -> PyResult<Self> {
        let set = PrimitiveSet::from_name(primitives).ok_or_else(|| {
            PyValueError::new_err(format!("primitives must be 'wheeled' or 'humanoid', got {primitives:?}"))
        })?;
        let emissions =
            one_of("emissions", emissions, &[("discrete", Emissions::Discrete), ("gaussian", Emissions::Gaussian)])?;
        let sequences: Vec<Bound<'_, PyAny>> = sequences.try_iter()?.collect::<PyResult<_>>()?;
        if sequences.len() != labels.len() {
            return Err(PyValueError::new_err(format!(
                "{} sequences but {} labels: give one label per sequence",
                sequences.len(),
                labels.len()
            )));
        }
        let training = sequences
            .iter()
            .zip(&labels)
            .enumerate()
            .map(|(i, (s, label))| {
                Ok(LabelledSequence { primitive: primitive(label)?, poses: poses(s, &format!("sequence {i}"))? })
            })
            .collect::<PyResult<Vec<_>>>()?;
        let (forward_backward, left_right) = representations(representation)?;
        let config = RecognizerConfig {
            n_states: non_negative("n_states", n_states)?,
            links: non_negative("links", links)?,
            codebook_size: non_negative("codebook_size", codebook_size)?,
            max_iter: non_negative("max_iter", max_iter)?,
            tol,
            emission_floor,
            emissions,
            min_variance,
            forward_backward_representation: forward_backward,
            left_right_representation: left_right,
            seed: non_negative("seed", seed)? as u64,
            primitives: set,
            ..RecognizerConfig::default()
        };
        let recognizer = py.detach(|| Recognizer::train(&training, config)).map_err(perceive_error)?;
        Ok(Self { recognizer })
    }

    /// log-likelihoods of its moving primitives (`moving`: forward, backward, left and right,
    /// then the humanoid's) for one sequence of frames.
    fn log_likelihoods<'py>(&self, py: Python<'py>, frames: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let poses = poses(frames, "frames")?;
        let scores = self.recognizer.log_likelihoods(&poses).map_err(perceive_error)?;
        Ok(PyArray1::from_vec(py, scores[..self.n_moving()].to_vec()))
    }

    /// `(k, m)` log-likelihoods of many sequences under its `m` moving primitives, in parallel.
    fn log_likelihoods_many<'py>(
        &self,
        py: Python<'py>,
        sequences: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let all: Vec<Vec<Pose>> = sequences
            .try_iter()?
            .enumerate()
            .map(|(i, s)| poses(&s?, &format!("sequence {i}")))
            .collect::<PyResult<_>>()?;
        let refs: Vec<&[Pose]> = all.iter().map(Vec::as_slice).collect();
        let scores = py.detach(|| self.recognizer.log_likelihoods_many(&refs)).map_err(perceive_error)?;
        let (count, n_moving) = (scores.len(), self.n_moving());
        matrix(py, scores.into_iter().flat_map(|s| s[..n_moving].to_vec()).collect(), count, n_moving)
    }

    /// The set of primitives it recognises: `"wheeled"` or `"humanoid"`.
    #[getter]
    fn primitive_set(&self) -> &'static str {
        self.recognizer.primitive_set().name()
    }

    /// Its moving primitives, in the order of its scores' columns.
    #[getter]
    fn moving(&self) -> Vec<&'static str> {
        self.recognizer.primitive_set().moving().iter().map(|p| p.name()).collect()
    }

    /// The moving primitive whose HMM scores the frames highest.
    fn classify(&self, frames: &Bound<'_, PyAny>) -> PyResult<&'static str> {
        let poses = poses(frames, "frames")?;
        Ok(self.recognizer.classify(&poses).map_err(perceive_error)?.name())
    }

    /// Segments a demonstration; returns columns: `label` (list of str), `first_frame`,
    /// `last_frame` (int arrays), `start` and `end` (`(k, 5)` frames) and `scores` (`(k, m)`, a
    /// column per moving primitive).
    /// Settings, keyword-only: `min_frames=10`, `stop_distance_mm=1.0`, `stop_rotation_deg=20.0`,
    /// `limit_sds=2.0`, `gap_margin=2.0`.
    #[pyo3(signature = (frames, **settings))]
    fn segment<'py>(
        &self,
        py: Python<'py>,
        frames: &Bound<'py, PyAny>,
        settings: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let settings = SegmenterSettings::extract("segment", settings)?;
        let frames = tracked_frames(frames, "demonstration")?;
        let config = settings.config()?;
        let segments = py.detach(|| segment(&frames, &self.recognizer, &config)).map_err(perceive_error)?;
        segment_columns(py, &segments, self.recognizer.primitive_set())
    }

    /// `segment` for many demonstrations, in parallel, with the same settings; one dictionary
    /// of columns each.
    #[pyo3(signature = (demonstrations, **settings))]
    fn segment_many<'py>(
        &self,
        py: Python<'py>,
        demonstrations: &Bound<'py, PyAny>,
        settings: Option<&Bound<'py, PyDict>>,
    ) -> PyResult<Bound<'py, PyList>> {
        let settings = SegmenterSettings::extract("segment_many", settings)?;
        let all: Vec<Vec<TrackedFrame>> = demonstrations
            .try_iter()?
            .enumerate()
            .map(|(i, d)| tracked_frames(&d?, &format!("demonstration {i}")))
            .collect::<PyResult<_>>()?;
        let refs: Vec<&[TrackedFrame]> = all.iter().map(Vec::as_slice).collect();
        let config = settings.config()?;
        let segmented = py.detach(|| segment_many(&refs, &self.recognizer, &config)).map_err(perceive_error)?;
        let out = PyList::empty(py);
        for segments in &segmented {
            out.append(segment_columns(py, segments, self.recognizer.primitive_set())?)?;
        }
        Ok(out)
    }

    /// Table 3.1 of the training set: per primitive, distance and rotation mean and sd.
    fn motion_stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for s in self.recognizer.motion_stats() {
            let row = PyDict::new(py);
            row.set_item("count", s.count)?;
            row.set_item("distance_mean_mm", s.distance_mean_mm)?;
            row.set_item("distance_sd_mm", s.distance_sd_mm)?;
            row.set_item("rotation_mean_deg", s.rotation_mean_deg)?;
            row.set_item("rotation_sd_deg", s.rotation_sd_deg)?;
            if let Some(sideways) = s.sideways {
                row.set_item("sideways_mean_mm", sideways.mean_mm)?;
                row.set_item("sideways_sd_mm", sideways.sd_mm)?;
            }
            out.set_item(s.primitive.name(), row)?;
        }
        Ok(out)
    }

    /// The HMM of a moving primitive.
    fn hmm(&self, primitive: &str) -> PyResult<PyDiscreteHmm> {
        let wanted = self::primitive(primitive)?;
        self.recognizer
            .models()
            .iter()
            .find(|m| m.primitive == wanted)
            .ok_or_else(|| PyValueError::new_err("stop has no HMM: it is recognised by the lack of motion"))
            .and_then(|m| match &m.hmm {
                PrimitiveHmm::Discrete(hmm) => Ok(PyDiscreteHmm::wrap(hmm.clone())),
                PrimitiveHmm::Gaussian(_) => {
                    Err(PyValueError::new_err("this recogniser's models are Gaussian; only discrete ones are exposed"))
                }
            })
    }

    /// The codebook a primitive's HMM reads through.
    fn codebook(&self, primitive: &str) -> PyResult<PyCodebook> {
        let representation = self.recognizer.config().representation_of(self::primitive(primitive)?);
        let codebook = self.recognizer.codebook(representation).cloned();
        codebook.map(PyCodebook::wrap).ok_or_else(|| PyValueError::new_err("no codebook for that primitive"))
    }

    /// The representation each primitive's HMM reads (`positional`, `rotational`, `egocentric`).
    #[getter]
    fn representations<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for m in self.recognizer.models() {
            let name = match m.representation {
                Representation::Positional => "positional",
                Representation::Rotational => "rotational",
                Representation::Egocentric => "egocentric",
            };
            out.set_item(m.primitive.name(), name)?;
        }
        Ok(out)
    }

    /// `"discrete"` (codebook symbols) or `"gaussian"` (continuous points).
    #[getter]
    fn emissions(&self) -> &'static str {
        match self.recognizer.config().emissions {
            Emissions::Discrete => "discrete",
            Emissions::Gaussian => "gaussian",
        }
    }

    /// States of each primitive's HMM.
    #[getter]
    fn n_states(&self) -> usize {
        self.recognizer.config().n_states
    }

    /// Codewords of each representation's codebook (the HMMs' alphabet size).
    #[getter]
    fn codebook_size(&self) -> usize {
        self.recognizer.config().codebook_size
    }

    /// Writes the recogniser to `path` (JSON, versioned).
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn save(&self, path: PathBuf) -> PyResult<()> {
        write_atomically(&path, &self.recognizer.to_json().map_err(perceive_error)?)
    }

    /// Reads a recogniser written by `save`.
    #[classmethod]
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn load(_cls: &Bound<'_, PyType>, path: PathBuf) -> PyResult<Self> {
        Ok(Self { recognizer: read_model(&path, Recognizer::from_json)? })
    }

    #[staticmethod]
    fn _from_json(text: &str) -> PyResult<Self> {
        Ok(Self { recognizer: Recognizer::from_json(text).map_err(perceive_error)? })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        reduce_to_json(slf, slf.get().recognizer.to_json().map_err(perceive_error)?)
    }

    fn __repr__(&self) -> String {
        let c = self.recognizer.config();
        format!("PrimitiveRecognizer(n_states={}, codebook_size={})", c.n_states, c.codebook_size)
    }
}
