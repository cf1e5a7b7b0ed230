//! hmmlearn's `CategoricalHMM` on both sides of `DiscreteHMM.from_hmmlearn` and `to_hmmlearn`:
//! what a peer model must be to be read, the seed its `random_state` carries over as, and a peer
//! built from a model's probabilities.

use numpy::PyArray1;
use polymimic_hmm::DiscreteHmm;
use pyo3::exceptions::{PyImportError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::matrix;
use crate::errors::{NotFittedError, hmm_error};

/// Refuses anything but an `hmmlearn.hmm.CategoricalHMM` that has its probabilities.
pub(super) fn check_fitted_categorical(model: &Bound<'_, PyAny>) -> PyResult<()> {
    let py = model.py();
    let categorical = py.import("hmmlearn.hmm").and_then(|m| m.getattr("CategoricalHMM"));
    if !categorical.is_ok_and(|class| model.is_instance(&class).unwrap_or(false)) {
        let kind = model.get_type().name().map_or_else(|_| "?".to_owned(), |n| n.to_string());
        return Err(PyTypeError::new_err(format!(
            "from_hmmlearn takes a fitted hmmlearn.hmm.CategoricalHMM, got a {kind}"
        )));
    }
    for name in ["startprob_", "transmat_", "emissionprob_"] {
        if !model.hasattr(name)? {
            return Err(NotFittedError::new_err(format!(
                "the CategoricalHMM is not fitted: it has no {name} (fit it, or set its parameters, first)"
            )));
        }
    }
    Ok(())
}

/// A seed from an hmmlearn model's `random_state`: an integer as it is, 0 for None, and a
/// `numpy.random.RandomState` or `Generator` drawn from once through a copy, which leaves the
/// model's own state untouched.
pub(super) fn seed_of(random_state: &Bound<'_, PyAny>) -> PyResult<i64> {
    if random_state.is_none() {
        return Ok(0);
    }
    if let Ok(seed) = random_state.extract::<i64>() {
        return Ok(seed);
    }
    let py = random_state.py();
    let draw = if random_state.hasattr("integers")? {
        "integers"
    } else if random_state.hasattr("randint")? {
        "randint"
    } else {
        return Err(PyValueError::new_err(format!(
            "the CategoricalHMM's random_state must be an int, None, a RandomState or a Generator to carry over, \
             got {random_state}: pass seed="
        )));
    };
    let copy = py.import("copy")?.call_method1("deepcopy", (random_state,))?;
    copy.call_method1(draw, (0_i64, 1_i64 << 62))?.extract()
}

/// `model` as a `hmmlearn.hmm.CategoricalHMM` (scaling implementation) with the same
/// probabilities, `n_iter`, `tol` and `random_state`, and `init_params=""` so that fitting starts
/// from them. Without hmmlearn an `ImportError`; a model without probabilities is refused only
/// after the peer is built, as reading its `startprob_` would be.
pub(super) fn categorical_hmm<'py>(py: Python<'py>, model: &DiscreteHmm) -> PyResult<Bound<'py, PyAny>> {
    let hmm = py
        .import("hmmlearn.hmm")
        .map_err(|_| PyImportError::new_err("to_hmmlearn needs hmmlearn: pip install hmmlearn"))?;
    let p = model.params();
    let kwargs = PyDict::new(py);
    kwargs.set_item("n_components", p.n_states)?;
    kwargs.set_item("n_features", p.n_symbols)?;
    kwargs.set_item("n_iter", p.max_iter)?;
    kwargs.set_item("tol", p.tol)?;
    kwargs.set_item("random_state", p.seed)?;
    kwargs.set_item("init_params", "")?;
    kwargs.set_item("params", "ste")?;
    kwargs.set_item("implementation", "scaling")?;
    let peer = hmm.getattr("CategoricalHMM")?.call((), Some(&kwargs))?;
    let probabilities = model.probabilities().map_err(hmm_error)?;
    let (n, m) = (probabilities.n_states, probabilities.n_symbols);
    peer.setattr("startprob_", PyArray1::from_vec(py, probabilities.startprob.clone()))?;
    peer.setattr("transmat_", matrix(py, probabilities.transmat.clone(), n, n)?)?;
    peer.setattr("emissionprob_", matrix(py, probabilities.emissionprob.clone(), n, m)?)?;
    Ok(peer)
}
