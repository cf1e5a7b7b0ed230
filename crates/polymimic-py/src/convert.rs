//! numpy and Python values in and out, with the checks that give clear errors.

use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicU32, Ordering};

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::PyTypeInfo;
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyOverflowError, PyPermissionError, PyTypeError, PyValueError,
};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyList, PyTuple};

use crate::errors::ModelFileError;

/// A whole number ≥ 0 given as a Python int, with a ValueError naming `name` otherwise.
pub fn non_negative(name: &str, value: i64) -> PyResult<usize> {
    usize::try_from(value).map_err(|_| PyValueError::new_err(format!("{name} must be ≥ 0, got {value}")))
}

/// A field seed: any Python int in [0, 2**64), as the field's seeds are u64 (numpy integers
/// too). A bool or a non-integer is a `TypeError`; an int out of range a `ValueError` naming
/// the seed and the range, not Python's bare `OverflowError`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Seed(pub u64);

impl<'a, 'py> FromPyObject<'a, 'py> for Seed {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        let not_an_integer =
            || Ok::<_, PyErr>(PyTypeError::new_err(format!("seed must be an integer, got {}", obj.repr()?)));
        if obj.is_instance_of::<PyBool>() {
            return Err(not_an_integer()?);
        }
        match obj.extract::<u64>() {
            Ok(seed) => Ok(Self(seed)),
            Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => Err(PyValueError::new_err(format!(
                "seed must be in 0..{} (0 ≤ seed < 2**64), got {}",
                u64::MAX,
                obj.repr()?
            ))),
            Err(_) => Err(not_an_integer()?),
        }
    }
}

fn asarray<'py>(value: &Bound<'py, PyAny>, dtype: Option<&str>) -> PyResult<Bound<'py, PyAny>> {
    let numpy = value.py().import("numpy")?;
    match dtype {
        None => numpy.call_method1("asarray", (value,)),
        // Contiguous, so that strided views (a field of a structured array, whose stride is not
        // a multiple of 8 bytes) are copied into plain memory before Rust reads them.
        Some(dtype) => numpy.call_method1("ascontiguousarray", (value, dtype)),
    }
}

fn shape_text(array: &Bound<'_, PyAny>) -> PyResult<String> {
    Ok(array.getattr("shape")?.repr()?.to_string())
}

/// One 1-D sequence of integer symbols, checked against `n_symbols`. `what` names it in
/// errors ("sequence 3").
pub fn symbols(value: &Bound<'_, PyAny>, what: &str, n_symbols: usize) -> PyResult<Vec<u32>> {
    // Fast path: the int64 arrays numpy makes by default need no conversion at all.
    if let Ok(array) = value.cast::<PyArray1<i64>>()
        && let Ok(values) = array.to_vec()
    {
        return checked_symbols(values.into_iter(), what, n_symbols);
    }
    let array = asarray(value, None)?;
    let ndim: usize = array.getattr("ndim")?.extract()?;
    if ndim != 1 {
        return Err(PyValueError::new_err(format!(
            "{what} must be a 1-D array of symbols, got shape {}",
            shape_text(&array)?
        )));
    }
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    if kind != "i" && kind != "u" {
        let dtype = array.getattr("dtype")?.str()?.to_string();
        return Err(PyTypeError::new_err(format!("{what} has dtype {dtype}; symbols must be integers")));
    }
    let array = array.call_method1("astype", ("int64",))?;
    let array: PyReadonlyArray1<i64> = array.extract()?;
    checked_symbols(array.as_array().iter().copied(), what, n_symbols)
}

fn checked_symbols(values: impl ExactSizeIterator<Item = i64>, what: &str, n_symbols: usize) -> PyResult<Vec<u32>> {
    if values.len() == 0 {
        return Err(PyValueError::new_err(format!("{what} is empty")));
    }
    values
        .enumerate()
        .map(|(position, symbol)| {
            if symbol < 0 || symbol as u64 >= n_symbols as u64 {
                Err(PyValueError::new_err(format!(
                    "{what} holds symbol {symbol} at position {position}; symbols must be in 0..{n_symbols}"
                )))
            } else {
                Ok(symbol as u32)
            }
        })
        .collect()
}

/// A list (or any iterable) of sequences.
pub fn symbol_sequences(value: &Bound<'_, PyAny>, n_symbols: usize) -> PyResult<Vec<Vec<u32>>> {
    if value.hasattr("ndim")? && value.getattr("ndim")?.extract::<usize>()? == 1 {
        return Err(PyTypeError::new_err(
            "sequences must be a list of 1-D arrays (one per sequence), got a single 1-D array; wrap it in a list",
        ));
    }
    let list = PyList::type_object(value.py())
        .call1((value,))
        .map_err(|_| PyTypeError::new_err("sequences must be a list of 1-D integer arrays"))?;
    let list = list.cast_into::<PyList>()?;
    if list.is_empty() {
        return Err(PyValueError::new_err("sequences is empty: give at least one sequence"));
    }
    list.iter().enumerate().map(|(i, s)| symbols(&s, &format!("sequence {i}"), n_symbols)).collect()
}

/// A float64 array of the given rank, as a row-major vector and its shape.
pub fn floats(value: &Bound<'_, PyAny>, name: &str, rank: usize) -> PyResult<(Vec<f64>, Vec<usize>)> {
    let array = asarray(value, None)?;
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        let dtype = array.getattr("dtype")?.str()?.to_string();
        return Err(PyTypeError::new_err(format!("{name} has dtype {dtype}; expected real numbers")));
    }
    let array = asarray(&array, Some("float64"))?;
    let ndim: usize = array.getattr("ndim")?.extract()?;
    if ndim != rank {
        return Err(PyValueError::new_err(format!("{name} must be {rank}-D, got shape {}", shape_text(&array)?)));
    }
    if rank == 1 {
        let array: PyReadonlyArray1<f64> = array.extract()?;
        Ok((array.as_array().to_vec(), array.shape().to_vec()))
    } else {
        let array: PyReadonlyArray2<f64> = array.extract()?;
        Ok((array.as_array().iter().copied().collect(), array.shape().to_vec()))
    }
}

/// Columns of tracker frames: from a structured array, the named fields (its time `t_s`, where
/// it has one, checked to run forward); from a 2-D float array, its first `columns.len()`
/// columns in that order. Returns rows of `columns.len()`.
pub fn frame_columns(value: &Bound<'_, PyAny>, what: &str, columns: &[&str]) -> PyResult<Vec<Vec<f64>>> {
    let array = asarray(value, None)?;
    let names = array.getattr("dtype")?.getattr("names")?;
    let width = columns.len();
    let table = if names.is_none() {
        let (data, shape) = floats(&array, what, 2)?;
        if shape[1] < width {
            return Err(PyValueError::new_err(format!(
                "{what} has {} columns; expected at least {width} ({})",
                shape[1],
                columns.join(", ")
            )));
        }
        data.chunks_exact(shape[1]).map(|row| row[..width].to_vec()).collect()
    } else {
        let names: Vec<String> = names.extract()?;
        if names.iter().any(|n| n == "t_s") {
            time_runs_forward(&floats(&array.get_item("t_s")?, what, 1)?.0, what)?;
        }
        let mut fields = Vec::with_capacity(width);
        for &column in columns {
            if !names.iter().any(|n| n == column) {
                return Err(PyValueError::new_err(format!(
                    "{what} has no field {column:?} (fields: {})",
                    names.join(", ")
                )));
            }
            fields.push(floats(&array.get_item(column)?, what, 1)?.0);
        }
        let rows = fields.first().map_or(0, Vec::len);
        (0..rows).map(|r| fields.iter().map(|f| f[r]).collect()).collect()
    };
    Ok(table)
}

/// Refuses frames whose time (`t_s`) is unknown or runs backwards, naming the first such frame:
/// a tracker's frames come in the order they were seen.
fn time_runs_forward(t_s: &[f64], what: &str) -> PyResult<()> {
    if let Some(i) = t_s.iter().position(|t| !t.is_finite()) {
        return Err(PyValueError::new_err(format!("{what}: frame {i} has t_s {}; every frame needs its time", t_s[i])));
    }
    match t_s.windows(2).position(|pair| pair[1] < pair[0]) {
        Some(i) => Err(PyValueError::new_err(format!(
            "{what}: frame {} has t_s {} s, before frame {}'s {} s; time must not run backwards",
            i + 1,
            t_s[i + 1],
            i,
            t_s[i]
        ))),
        None => Ok(()),
    }
}

/// A row-major vector as a 2-D array.
pub fn matrix<T: numpy::Element>(
    py: Python<'_>,
    values: Vec<T>,
    rows: usize,
    cols: usize,
) -> PyResult<Bound<'_, numpy::PyArray2<T>>> {
    PyArray1::from_vec(py, values).reshape([rows, cols])
}

/// An `OSError` of the kind Python raises for `error`, naming `path` as Python's own do.
pub fn io_error(path: &Path, error: &std::io::Error) -> PyErr {
    let args = (error.raw_os_error().unwrap_or(0), error.to_string(), path.display().to_string());
    match error.kind() {
        std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(args),
        std::io::ErrorKind::PermissionDenied => PyPermissionError::new_err(args),
        std::io::ErrorKind::IsADirectory => PyIsADirectoryError::new_err(args),
        _ => PyOSError::new_err(args),
    }
}

/// Writes `text` to `path` through a temporary file beside it (named as the Python side names
/// its own, `.<name>.<8 hex>.tmp.<ext>`, so a stage that finds one left by a crash removes it),
/// flushed to disk and renamed over `path`: a crash never leaves a half-written model behind.
pub fn write_atomically(path: &Path, text: &str) -> PyResult<()> {
    static WRITES: AtomicU32 = AtomicU32::new(0);
    let name = path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let extension = path.extension().map_or_else(String::new, |e| format!(".{}", e.to_string_lossy()));
    let tag = std::process::id().rotate_left(16) ^ WRITES.fetch_add(1, Ordering::Relaxed);
    let temporary = path.with_file_name(format!(".{name}.{tag:08x}.tmp{extension}"));
    let written = (|| {
        let mut file = std::fs::OpenOptions::new().write(true).create_new(true).open(&temporary)?;
        file.write_all(text.as_bytes())?;
        file.sync_all()?;
        std::fs::rename(&temporary, path)
    })();
    if let Err(error) = written {
        let _ = std::fs::remove_file(&temporary);
        return Err(io_error(path, &error));
    }
    Ok(())
}

/// Reads a saved model's text, naming the file when it is missing or not text.
pub fn read_text(path: &Path) -> PyResult<String> {
    let bytes = std::fs::read(path).map_err(|error| io_error(path, &error))?;
    String::from_utf8(bytes)
        .map_err(|_| ModelFileError::new_err(format!("{} is not a polymimic file (not UTF-8 text)", path.display())))
}

/// The option named `value` of a string parameter, or a ValueError naming the parameter and
/// every name it takes.
pub fn one_of<T: Copy>(parameter: &str, value: &str, options: &[(&str, T)]) -> PyResult<T> {
    options.iter().find(|(name, _)| *name == value).map(|&(_, option)| option).ok_or_else(|| {
        let names: Vec<String> = options.iter().map(|(name, _)| format!("{name:?}")).collect();
        PyValueError::new_err(format!("{parameter} must be {}, got {value:?}", names.join(" or ")))
    })
}

/// Reads and parses a saved model; a file that does not parse is a `ModelFileError` naming it.
pub fn read_model<T, E: std::fmt::Display>(path: &Path, parse: impl FnOnce(&str) -> Result<T, E>) -> PyResult<T> {
    parse(&read_text(path)?).map_err(|e| ModelFileError::new_err(format!("{}: {e}", path.display())))
}

/// What `__reduce__` returns for a class that rebuilds itself from its JSON with `_from_json`.
pub fn reduce_to_json<'py, T: pyo3::PyClass>(
    slf: &Bound<'py, T>,
    json: String,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
    Ok((slf.as_any().get_type().getattr("_from_json")?, PyTuple::new(slf.py(), [json])?))
}

/// A 1-D array of whole numbers (any integer dtype), as `i64`.
pub fn integers(value: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<i64>> {
    let array = asarray(value, None)?;
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    if kind != "i" && kind != "u" {
        let dtype = array.getattr("dtype")?.str()?.to_string();
        return Err(PyTypeError::new_err(format!("{name} has dtype {dtype}; expected whole numbers")));
    }
    let ndim: usize = array.getattr("ndim")?.extract()?;
    if ndim != 1 {
        return Err(PyValueError::new_err(format!("{name} must be 1-D, got shape {}", shape_text(&array)?)));
    }
    let array = asarray(&array, Some("int64"))?;
    let array: PyReadonlyArray1<i64> = array.extract()?;
    Ok(array.as_array().to_vec())
}
