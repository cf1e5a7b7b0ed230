//! `polymimic.Codebook`: the LBG codebook behind a small class.

use std::path::PathBuf;

use numpy::{PyArray1, PyArray2};
use polymimic_vq::{Codebook, LbgParams};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::convert::{floats, matrix, non_negative, read_model, reduce_to_json, write_atomically};
use crate::errors::{vq_error, vq_params_error};

/// A vector-quantisation codebook: codewords and nearest-codeword encoding.
///
/// The recogniser quantises each representation of the tracker's frames with one (thesis
/// §3.1.3). `Codebook.fit` grows it by LBG: from the points' mean, every codeword splits in two and
/// k-means (Lloyd) refines them, until there are `size`; `encode` finds each point's nearest
/// codeword with a k-d tree.
///
/// Parameters
/// ----------
/// centroids : array_like of shape (k, d)
///     The codewords, for a codebook you already have (`fit` grows one from points).
///
/// Attributes
/// ----------
/// centroids : ndarray of shape (k, d)
///     The codewords.
/// distortion_ : float
///     Mean squared distance of the training points to their nearest codewords at the end of the
///     last `fit` or `refine`.
/// n_iter_ : int
///     Lloyd iterations of the last `fit` (over every size) or `refine`.
///
/// Examples
/// --------
/// >>> import numpy as np, polymimic
/// >>> points = np.random.default_rng(0).normal(size=(1000, 3))
/// >>> codebook = polymimic.Codebook.fit(points, size=8, seed=0)
/// >>> codebook.centroids.shape, codebook.encode(points[:4]).shape
/// ((8, 3), (4,))
#[pyclass(name = "Codebook", module = "polymimic", frozen)]
pub struct PyCodebook {
    codebook: Codebook,
}

impl PyCodebook {
    pub(crate) fn wrap(codebook: Codebook) -> Self {
        Self { codebook }
    }
}

/// Row-major points of an `(n, d)` array.
fn points(value: &Bound<'_, PyAny>) -> PyResult<(Vec<f64>, usize)> {
    let (data, shape) = floats(value, "points", 2)?;
    Ok((data, shape[1]))
}

#[pymethods]
impl PyCodebook {
    /// A codebook with the given `(k, d)` codewords.
    #[new]
    fn new(centroids: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (data, shape) = floats(centroids, "centroids", 2)?;
        let codebook = Codebook::from_codewords(data, shape[1]).map_err(vq_params_error)?;
        Ok(Self { codebook })
    }

    /// Grows a codebook of `size` codewords on `(n, d)` points by LBG.
    ///
    /// Parameters
    /// ----------
    /// points : array_like of shape (n, d)
    ///     The training points (finite).
    /// size : int
    ///     Codewords to grow, at least 1 (the thesis's 512 by default).
    /// tol : float
    ///     Each Lloyd refinement stops when the distortion falls by less than this share.
    /// max_iter : int
    ///     Most Lloyd iterations per refinement.
    /// seed : int
    ///     Seeds the perturbation that splits codewords.
    /// split_epsilon : float
    ///     How far apart, relative to the data's scale, a split puts the two new codewords.
    ///
    /// Returns
    /// -------
    /// Codebook
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For points that are not a finite 2-D array, or a parameter out of range.
    #[classmethod]
    #[pyo3(signature = (points, *, size=512, tol=1e-4, max_iter=100, seed=0, split_epsilon=1e-3))]
    #[allow(clippy::too_many_arguments)]
    fn fit(
        _cls: &Bound<'_, PyType>,
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        size: i64,
        tol: f64,
        max_iter: i64,
        seed: i64,
        split_epsilon: f64,
    ) -> PyResult<Self> {
        let (data, dim) = self::points(points)?;
        let mut params = LbgParams::new(non_negative("size", size)?);
        params.tol = tol;
        params.max_iter = non_negative("max_iter", max_iter)?;
        params.seed = non_negative("seed", seed)? as u64;
        params.split_epsilon = split_epsilon;
        let codebook = py.detach(|| Codebook::fit(&data, dim, params)).map_err(vq_params_error)?;
        Ok(Self { codebook })
    }

    /// Lloyd iterations from these codewords on `points`; returns a new codebook.
    #[pyo3(signature = (points, *, tol=0.0, max_iter=300))]
    fn refine(&self, py: Python<'_>, points: &Bound<'_, PyAny>, tol: f64, max_iter: i64) -> PyResult<Self> {
        let (data, dim) = self::points(points)?;
        let max_iter = non_negative("max_iter", max_iter)?;
        let mut codebook = self.codebook.clone();
        py.detach(|| codebook.refine(&data, dim, tol, max_iter)).map_err(vq_params_error)?;
        Ok(Self { codebook })
    }

    /// The index of the nearest codeword of every point (int64 array).
    fn encode<'py>(&self, py: Python<'py>, points: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray1<i64>>> {
        let (data, dim) = self::points(points)?;
        let codes = py.detach(|| self.codebook.encode(&data, dim)).map_err(vq_params_error)?;
        Ok(PyArray1::from_vec(py, codes.into_iter().map(i64::from).collect()))
    }

    /// Mean squared distance of `points` to their nearest codewords.
    fn distortion(&self, py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<f64> {
        let (data, dim) = self::points(points)?;
        py.detach(|| self.codebook.distortion(&data, dim)).map_err(vq_params_error)
    }

    /// The `(k, d)` codewords.
    #[getter]
    fn centroids<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        matrix(py, self.codebook.codewords().to_vec(), self.codebook.len(), self.codebook.dim())
    }

    /// Number of codewords, k.
    #[getter]
    fn size(&self) -> usize {
        self.codebook.len()
    }

    /// Dimension of every codeword, d.
    #[getter]
    fn dim(&self) -> usize {
        self.codebook.dim()
    }

    /// Distortion on the training points at the end of the last fit or refine.
    #[getter]
    fn distortion_(&self) -> f64 {
        self.codebook.report().distortion
    }

    /// Lloyd iterations of the last fit (over every size) or refine.
    #[getter]
    fn n_iter_(&self) -> usize {
        self.codebook.report().lloyd_iterations
    }

    fn __len__(&self) -> usize {
        self.codebook.len()
    }

    /// Writes the codebook to `path` (JSON, versioned).
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn save(&self, path: PathBuf) -> PyResult<()> {
        let text = self.codebook.to_json().map_err(vq_error)?;
        write_atomically(&path, &text)
    }

    /// Reads a codebook written by `save`.
    #[classmethod]
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn load(_cls: &Bound<'_, PyType>, path: PathBuf) -> PyResult<Self> {
        Ok(Self { codebook: read_model(&path, Codebook::from_json)? })
    }

    #[staticmethod]
    fn _from_json(text: &str) -> PyResult<Self> {
        Ok(Self { codebook: Codebook::from_json(text).map_err(vq_error)? })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        reduce_to_json(slf, slf.get().codebook.to_json().map_err(vq_error)?)
    }

    fn __repr__(&self) -> String {
        format!("Codebook(size={}, dim={})", self.codebook.len(), self.codebook.dim())
    }
}
