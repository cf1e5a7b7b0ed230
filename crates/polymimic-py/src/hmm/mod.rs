//! `polymimic.DiscreteHMM`: the core HMM behind a scikit-learn-like class; its keyword arguments
//! become the core's parameters in arguments.rs, and hmmlearn's model is read and built in
//! hmmlearn.rs.

use std::path::PathBuf;
use std::sync::RwLock;

use numpy::{PyArray1, PyArray2};
use polymimic_hmm::{DiscreteHmm, HmmError, HmmParams, Init, Topology};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::convert::{
    floats, matrix, non_negative, one_of, read_model, reduce_to_json, symbol_sequences, symbols, write_atomically,
};
use crate::errors::hmm_error;

mod arguments;
mod hmmlearn;

/// Sampled symbols and hidden states, each `(n, length)`.
type SymbolsAndStates<'py> = (Bound<'py, PyArray2<i64>>, Bound<'py, PyArray2<i64>>);

/// A discrete hidden Markov model trained by scaled Baum-Welch over many sequences at once.
///
/// The thesis's recogniser holds one per moving primitive (thesis §3.1.3–3.1.4): a left-right
/// model whose states each link to themselves and the next `links` states (thesis Fig. 3.10), or
/// an ergodic one. Training starts from the temporal split of every sequence into `n_states`
/// pieces (thesis Fig. 3.11) or from parameters you give (`from_params`, `fit(init="given")`).
///
/// Parameters
/// ----------
/// n_states : int
///     Hidden states, at least 1.
/// n_symbols : int
///     Size of the symbol alphabet: every sequence holds integers in `0..n_symbols`.
/// topology : {"left-right", "ergodic"}
///     Which transitions may be non-zero.
/// links : int
///     For a left-right model, how many states ahead each state may move (2: itself, the next
///     and the one after). Ignored for an ergodic model.
/// max_iter : int
///     Most Baum-Welch re-estimations per `fit`.
/// tol : float
///     A fit stops when the log-likelihood gains less than this; `-inf` runs exactly `max_iter`.
/// emission_floor : float
///     Every emission probability is floored here (and rows renormalised), so an unseen symbol
///     does not make a sequence impossible.
/// seed : int
///     Seeds the random transitions a fit starts from and `sample`'s default stream.
///
/// Attributes
/// ----------
/// startprob_ : ndarray of shape (n_states,)
///     Initial state probabilities (after `fit` or `from_params`).
/// transmat_ : ndarray of shape (n_states, n_states)
///     Transition probabilities; row i is P(next state | state i).
/// emissionprob_ : ndarray of shape (n_states, n_symbols)
///     Emission probabilities; row i is P(symbol | state i).
/// history_ : ndarray of shape (n_iterations,)
///     The training data's log-likelihood before each re-estimation of the last fit.
/// converged_ : bool
///     Whether the last fit stopped because the gain fell below `tol`.
///
/// Raises
/// ------
/// ValueError
///     For a parameter out of range (the message names it).
///
/// Examples
/// --------
/// >>> import numpy as np, polymimic
/// >>> model = polymimic.DiscreteHMM(2, 3, seed=1).fit([np.array([0, 0, 1, 2, 2]), np.array([0, 1, 2])])
/// >>> model.transmat_.shape, model.emissionprob_.shape
/// ((2, 2), (2, 3))
#[pyclass(name = "DiscreteHMM", module = "polymimic", frozen)]
pub struct PyDiscreteHmm {
    model: RwLock<DiscreteHmm>,
}

impl PyDiscreteHmm {
    pub(crate) fn wrap(model: DiscreteHmm) -> Self {
        Self { model: RwLock::new(model) }
    }

    /// A copy of the model: work happens on copies, so the GIL can be released and a failed
    /// call leaves the model as it was.
    fn snapshot(&self) -> DiscreteHmm {
        self.model.read().unwrap_or_else(std::sync::PoisonError::into_inner).clone()
    }

    fn with_model<T>(&self, f: impl FnOnce(&DiscreteHmm) -> T) -> T {
        f(&self.model.read().unwrap_or_else(std::sync::PoisonError::into_inner))
    }

    fn n_symbols(&self) -> usize {
        self.with_model(|m| m.params().n_symbols)
    }
}

#[pymethods]
impl PyDiscreteHmm {
    #[new]
    #[pyo3(signature = (n_states, n_symbols, *, topology="left-right", links=2, max_iter=100, tol=1e-4, emission_floor=1e-8, seed=0))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        n_states: i64,
        n_symbols: i64,
        topology: &str,
        links: i64,
        max_iter: i64,
        tol: f64,
        emission_floor: f64,
        seed: i64,
    ) -> PyResult<Self> {
        let params = arguments::params(n_states, n_symbols, topology, links, max_iter, tol, emission_floor, seed)?;
        let valid = params.check().map_err(|e| hmm_error(e.into()))?;
        Ok(Self::wrap(DiscreteHmm::new(valid)))
    }

    /// A model with the probabilities you give, ready to score, decode, sample or train further.
    ///
    /// Parameters
    /// ----------
    /// startprob : array_like of shape (n_states,)
    /// transmat : array_like of shape (n_states, n_states)
    /// emissionprob : array_like of shape (n_states, n_symbols)
    ///     Probabilities; each (row) must sum to 1.
    /// topology : {"left-right", "ergodic"}, optional
    ///     Without it (and without `links`), the topology `transmat` implies: left-right with as many
    ///     links as its longest forward jump where it starts in state 0 and never moves back, ergodic
    ///     otherwise. Giving `links` alone names a left-right model.
    /// links, max_iter, tol, emission_floor, seed
    ///     As for the constructor.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     If the shapes disagree, a probability is negative or a row does not sum to 1.
    #[classmethod]
    #[pyo3(signature = (startprob, transmat, emissionprob, *, topology=None, links=None, max_iter=100, tol=1e-4, emission_floor=1e-8, seed=0))]
    #[allow(clippy::too_many_arguments)]
    fn from_params(
        _cls: &Bound<'_, PyType>,
        startprob: &Bound<'_, PyAny>,
        transmat: &Bound<'_, PyAny>,
        emissionprob: &Bound<'_, PyAny>,
        topology: Option<&str>,
        links: Option<i64>,
        max_iter: i64,
        tol: f64,
        emission_floor: f64,
        seed: i64,
    ) -> PyResult<Self> {
        let (start, start_shape) = floats(startprob, "startprob", 1)?;
        let (trans, trans_shape) = floats(transmat, "transmat", 2)?;
        let (emit, emit_shape) = floats(emissionprob, "emissionprob", 2)?;
        let n = start_shape[0];
        if trans_shape != [n, n] {
            return Err(PyValueError::new_err(format!(
                "transmat has shape {trans_shape:?} but startprob has {n} states: expected [{n}, {n}]"
            )));
        }
        if emit_shape[0] != n {
            return Err(PyValueError::new_err(format!(
                "emissionprob has shape {emit_shape:?} but startprob has {n} states: expected [{n}, n_symbols]"
            )));
        }
        let mut params =
            arguments::params(n as i64, emit_shape[1] as i64, "ergodic", 0, max_iter, tol, emission_floor, seed)?;
        params.topology = match (topology, links) {
            (None, None) => Topology::implied_by(&start, &trans, n),
            // Links are a left-right model's; giving them names the topology.
            (None, Some(links)) => arguments::topology("left-right", links)?,
            (Some(name), links) => arguments::topology(name, links.unwrap_or(2))?,
        };
        let valid = params.check().map_err(|e| hmm_error(e.into()))?;
        let model = DiscreteHmm::from_probabilities(valid, start, trans, emit).map_err(|e| hmm_error(e.into()))?;
        Ok(Self::wrap(model))
    }

    /// Trains the model by scaled Baum-Welch on many sequences of any lengths; returns the model.
    ///
    /// Parameters
    /// ----------
    /// sequences : iterable of array_like of int
    ///     One-dimensional sequences of symbols in `0..n_symbols`.
    /// init : {"segments", "given"}
    ///     `"segments"` starts from the temporal split of every sequence into `n_states` pieces
    ///     (state i counts the symbols of piece i, floored at `emission_floor`) and random
    ///     transitions that respect the topology; `"given"` starts from the model's current
    ///     probabilities (those of `from_params`, or of an earlier fit).
    ///
    /// Returns
    /// -------
    /// DiscreteHMM
    ///     The model itself, fitted (`startprob_`, `transmat_`, `emissionprob_`, `history_`,
    ///     `converged_`).
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     If a sequence is empty or holds a symbol outside `0..n_symbols` (the message names the
    ///     sequence and position); the model is left as it was.
    /// NotFittedError
    ///     For `init="given"` on a model that has no probabilities yet.
    #[pyo3(signature = (sequences, *, init="segments"))]
    fn fit<'py>(slf: Bound<'py, Self>, sequences: &Bound<'py, PyAny>, init: &str) -> PyResult<Bound<'py, Self>> {
        let init = one_of("init", init, &[("segments", Init::Segments), ("given", Init::Given)])?;
        let this = slf.get();
        let sequences = symbol_sequences(sequences, this.n_symbols())?;
        let mut model = this.snapshot();
        slf.py()
            .detach(|| {
                let refs: Vec<&[u32]> = sequences.iter().map(Vec::as_slice).collect();
                model.fit(&refs, init)
            })
            .map_err(hmm_error)?;
        *this.model.write().unwrap_or_else(std::sync::PoisonError::into_inner) = model;
        Ok(slf)
    }

    /// log P(sequence | model).
    fn score(&self, py: Python<'_>, sequence: &Bound<'_, PyAny>) -> PyResult<f64> {
        let seq = symbols(sequence, "sequence", self.n_symbols())?;
        let model = self.snapshot();
        py.detach(|| model.score(&seq)).map_err(hmm_error)
    }

    /// log P(sequence | model) of each sequence. `impossible="raise"` raises on a sequence of
    /// probability zero; `impossible="-inf"` scores it -inf.
    #[pyo3(signature = (sequences, *, impossible="raise"))]
    fn score_samples<'py>(
        &self,
        py: Python<'py>,
        sequences: &Bound<'py, PyAny>,
        impossible: &str,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let raise = one_of("impossible", impossible, &[("raise", true), ("-inf", false)])?;
        let sequences = symbol_sequences(sequences, self.n_symbols())?;
        let model = self.snapshot();
        let scores = py
            .detach(|| {
                let refs: Vec<&[u32]> = sequences.iter().map(Vec::as_slice).collect();
                model.score_many(&refs)
            })
            .map_err(hmm_error)?;
        let mut out = Vec::with_capacity(scores.len());
        for (index, score) in scores.into_iter().enumerate() {
            match score {
                Ok(log_p) => out.push(log_p),
                Err(position) if raise => return Err(hmm_error(HmmError::ImpossibleSequence { index, position })),
                Err(_) => out.push(f64::NEG_INFINITY),
            }
        }
        Ok(PyArray1::from_vec(py, out))
    }

    /// The Viterbi state path (int64 array) and its log-probability.
    fn decode<'py>(&self, py: Python<'py>, sequence: &Bound<'py, PyAny>) -> PyResult<(Bound<'py, PyArray1<i64>>, f64)> {
        let seq = symbols(sequence, "sequence", self.n_symbols())?;
        let model = self.snapshot();
        let (path, log_p) = py.detach(|| model.decode(&seq)).map_err(hmm_error)?;
        Ok((PyArray1::from_vec(py, path.into_iter().map(|s| s as i64).collect()), log_p))
    }

    /// The posterior of every state at every step, γ_t(i) = P(q_t = i | O): a `(T, n_states)`
    /// array whose rows sum to 1 (hmmlearn's `predict_proba`).
    fn predict_proba<'py>(&self, py: Python<'py>, sequence: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let seq = symbols(sequence, "sequence", self.n_symbols())?;
        let model = self.snapshot();
        let gammas = py.detach(|| model.posteriors(&seq)).map_err(hmm_error)?;
        let n_states = model.params().n_states;
        matrix(py, gammas.into_iter().flatten().collect(), seq.len(), n_states)
    }

    /// A model from a fitted `hmmlearn.hmm.CategoricalHMM`: its probabilities exactly, its
    /// `n_iter` and `tol`, and the topology its `startprob_` and `transmat_` imply (see
    /// `from_params`). The seed is `seed`, else the model's `random_state`: an integer as it is,
    /// 0 for None, and for a `RandomState` (what fitting leaves there) or a `Generator` the
    /// first draw of a copy of it, so the same state gives the same seed and the model's own
    /// state is left as it was.
    #[classmethod]
    #[pyo3(signature = (model, *, seed=None))]
    fn from_hmmlearn(cls: &Bound<'_, PyType>, model: &Bound<'_, PyAny>, seed: Option<i64>) -> PyResult<Self> {
        hmmlearn::check_fitted_categorical(model)?;
        let seed = match seed {
            Some(seed) => seed,
            None => hmmlearn::seed_of(&model.getattr("random_state")?)?,
        };
        Self::from_params(
            cls,
            &model.getattr("startprob_")?,
            &model.getattr("transmat_")?,
            &model.getattr("emissionprob_")?,
            None,
            None,
            model.getattr("n_iter")?.extract()?,
            model.getattr("tol")?.extract()?,
            HmmParams::new(1, 1).emission_floor,
            seed,
        )
    }

    /// The model as a `hmmlearn.hmm.CategoricalHMM` (scaling implementation), ready to score,
    /// decode or train further: the same probabilities, `n_iter`, `tol` and `random_state`,
    /// with `init_params=""` so that fitting starts from them.
    fn to_hmmlearn<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        hmmlearn::categorical_hmm(py, &self.snapshot())
    }

    /// `n` sequences of `length` symbols and their hidden states, as two `(n, length)` arrays.
    #[pyo3(signature = (n, length, *, seed=0))]
    fn sample<'py>(&self, py: Python<'py>, n: i64, length: i64, seed: i64) -> PyResult<SymbolsAndStates<'py>> {
        let (count, len, seed) = (non_negative("n", n)?, non_negative("length", length)?, non_negative("seed", seed)?);
        let (symbols, states) = self.with_model(|m| m.sample(count, len, seed as u64)).map_err(hmm_error)?;
        let flat_symbols = symbols.into_iter().flatten().map(i64::from).collect();
        let flat_states = states.into_iter().flatten().map(|s| s as i64).collect();
        Ok((matrix(py, flat_symbols, count, len)?, matrix(py, flat_states, count, len)?))
    }

    /// Initial state probabilities, shape `(n_states,)`.
    ///
    /// Raises `NotFittedError` before the model has probabilities.
    #[getter]
    fn startprob_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let start = self.with_model(|m| m.probabilities().map(|p| p.startprob.clone())).map_err(hmm_error)?;
        Ok(PyArray1::from_vec(py, start))
    }

    /// Transition probabilities, shape `(n_states, n_states)`; row i is P(next state | state i).
    ///
    /// Raises `NotFittedError` before the model has probabilities.
    #[getter]
    fn transmat_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (trans, n) =
            self.with_model(|m| m.probabilities().map(|p| (p.transmat.clone(), p.n_states))).map_err(hmm_error)?;
        matrix(py, trans, n, n)
    }

    /// Emission probabilities, shape `(n_states, n_symbols)`; row i is P(symbol | state i).
    ///
    /// Raises `NotFittedError` before the model has probabilities.
    #[getter]
    fn emissionprob_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (emit, n, m) = self
            .with_model(|m| m.probabilities().map(|p| (p.emissionprob.clone(), p.n_states, p.n_symbols)))
            .map_err(hmm_error)?;
        matrix(py, emit, n, m)
    }

    /// Log-likelihood of the training data before each re-estimation of the last fit.
    #[getter]
    fn history_<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.with_model(|m| m.history().to_vec()))
    }

    /// Whether the last fit stopped because the log-likelihood gain fell below `tol` (False
    /// before any fit, and for a fit that ran out of `max_iter`).
    #[getter]
    fn converged_(&self) -> bool {
        self.with_model(DiscreteHmm::converged)
    }

    /// Number of hidden states.
    #[getter]
    fn n_states(&self) -> usize {
        self.with_model(|m| m.params().n_states)
    }

    /// Size of the symbol alphabet: symbols are `0..n_symbols`.
    #[getter(n_symbols)]
    fn get_n_symbols(&self) -> usize {
        self.n_symbols()
    }

    /// `"left-right"` or `"ergodic"`.
    #[getter]
    fn topology(&self) -> &'static str {
        self.with_model(|m| match m.params().topology {
            Topology::LeftRight { .. } => "left-right",
            Topology::Ergodic => "ergodic",
        })
    }

    /// How many states ahead a left-right model's states may move; None for an ergodic model.
    #[getter]
    fn links(&self) -> Option<usize> {
        self.with_model(|m| match m.params().topology {
            Topology::LeftRight { links } => Some(links),
            Topology::Ergodic => None,
        })
    }

    /// Most Baum-Welch re-estimations per fit.
    #[getter]
    fn max_iter(&self) -> usize {
        self.with_model(|m| m.params().max_iter)
    }

    /// The log-likelihood gain below which a fit stops (`-inf`: run `max_iter`).
    #[getter]
    fn tol(&self) -> f64 {
        self.with_model(|m| m.params().tol)
    }

    /// The floor of every emission probability.
    #[getter]
    fn emission_floor(&self) -> f64 {
        self.with_model(|m| m.params().emission_floor)
    }

    /// The seed of the random start and of `sample`'s default stream.
    #[getter]
    fn seed(&self) -> u64 {
        self.with_model(|m| m.params().seed)
    }

    /// Writes the model to `path` (JSON, versioned).
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn save(&self, path: PathBuf) -> PyResult<()> {
        let text = self.with_model(DiscreteHmm::to_json).map_err(hmm_error)?;
        write_atomically(&path, &text)
    }

    /// Reads a model written by `save`.
    #[classmethod]
    #[allow(clippy::needless_pass_by_value)] // pyo3 extracts the path by value
    fn load(_cls: &Bound<'_, PyType>, path: PathBuf) -> PyResult<Self> {
        Ok(Self::wrap(read_model(&path, DiscreteHmm::from_json)?))
    }

    #[staticmethod]
    fn _from_json(text: &str) -> PyResult<Self> {
        Ok(Self::wrap(DiscreteHmm::from_json(text).map_err(hmm_error)?))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        reduce_to_json(slf, slf.get().with_model(DiscreteHmm::to_json).map_err(hmm_error)?)
    }

    fn __repr__(&self) -> String {
        self.with_model(|m| {
            let p = m.params();
            let topology = match p.topology {
                Topology::LeftRight { links } => format!("topology='left-right', links={links}"),
                Topology::Ergodic => "topology='ergodic'".to_owned(),
            };
            let state = if m.probabilities().is_ok() { "" } else { ", unfitted" };
            format!("DiscreteHMM(n_states={}, n_symbols={}, {topology}{state})", p.n_states, p.n_symbols)
        })
    }
}
