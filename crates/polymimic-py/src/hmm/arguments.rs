//! The constructor's keyword arguments as the core model's parameters, each checked by name.

use polymimic_hmm::{HmmParams, Topology};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::convert::non_negative;

/// The topology Python names `name`; `links` counts only for a left-right model.
pub(super) fn topology(name: &str, links: i64) -> PyResult<Topology> {
    match name {
        "left-right" => Ok(Topology::LeftRight { links: non_negative("links", links)? }),
        "ergodic" => Ok(Topology::Ergodic),
        other => Err(PyValueError::new_err(format!("topology must be \"left-right\" or \"ergodic\", got {other:?}"))),
    }
}

/// Every constructor argument as the core's parameters: counts and the seed refused when
/// negative, the topology by its name (ranges are the core's `check`).
#[allow(clippy::too_many_arguments)]
pub(super) fn params(
    n_states: i64,
    n_symbols: i64,
    topology_name: &str,
    links: i64,
    max_iter: i64,
    tol: f64,
    emission_floor: f64,
    seed: i64,
) -> PyResult<HmmParams> {
    let mut params = HmmParams::new(non_negative("n_states", n_states)?, non_negative("n_symbols", n_symbols)?);
    params.topology = topology(topology_name, links)?;
    params.max_iter = non_negative("max_iter", max_iter)?;
    params.tol = tol;
    params.emission_floor = emission_floor;
    params.seed = non_negative("seed", seed)? as u64;
    Ok(params)
}
