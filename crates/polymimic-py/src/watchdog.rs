//! A watchdog that interrupts a Python call running past its deadline, by raising
//! `TimeoutError` in the calling thread (the interpreter's asynchronous exception): the only
//! way to stop a Python function from outside without killing the process. Code stuck in C (a
//! blocking read) is interrupted when it next returns to Python.

use std::os::raw::c_ulong;
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use pyo3::PyTypeInfo;
use pyo3::exceptions::PyTimeoutError;
use pyo3::prelude::*;

#[derive(Default)]
struct Watch {
    /// When the running call must have returned (None between calls).
    deadline: Option<Instant>,
    /// Number of the running call.
    call: u64,
    /// The call that was interrupted, if any.
    interrupted: Option<u64>,
    /// The interpreter's id of the thread making the calls.
    thread_ident: c_ulong,
    stop: bool,
}

type Shared = Arc<(Mutex<Watch>, Condvar)>;

fn lock(shared: &Shared) -> MutexGuard<'_, Watch> {
    shared.0.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Watches the calls one thread makes; dropping it stops its thread, which must happen with the
/// GIL released (the thread may be waiting for it).
pub struct Watchdog {
    shared: Shared,
    timeout: Duration,
    thread: Option<JoinHandle<()>>,
}

impl Watchdog {
    /// A watchdog for calls made from the current thread, each allowed `timeout`.
    pub fn new(py: Python<'_>, timeout: Duration) -> PyResult<Self> {
        let thread_ident = py.import("threading")?.call_method0("get_ident")?.extract()?;
        let shared: Shared = Arc::new((Mutex::new(Watch { thread_ident, ..Watch::default() }), Condvar::new()));
        let watched = Arc::clone(&shared);
        let thread = std::thread::Builder::new()
            .name("polymimic-watchdog".into())
            .spawn(move || watch(&watched, timeout))
            .map_err(|e| pyo3::exceptions::PyOSError::new_err(format!("cannot start the policy's watchdog: {e}")))?;
        Ok(Self { shared, timeout, thread: Some(thread) })
    }

    /// Run `call` (under the GIL) against the deadline: what it returned, and whether it was
    /// interrupted.
    pub fn run<T>(&self, gil: Python<'_>, call: impl FnOnce() -> T) -> (T, bool) {
        let number = {
            let mut w = lock(&self.shared);
            w.call += 1;
            // The timeout is bounded (see `MAX_TIMEOUT`), so the deadline cannot overflow.
            w.deadline = Instant::now().checked_add(self.timeout);
            w.call
        };
        let result = call();
        let mut w = lock(&self.shared);
        w.deadline = None;
        let interrupted = w.interrupted == Some(number);
        if interrupted {
            // The call may have returned before the exception reached it: withdraw it.
            // Withdrawing cannot fail in a way the caller could act on.
            let _ = set_async_exception(gil, w.thread_ident, None);
        }
        (result, interrupted)
    }
}

impl Drop for Watchdog {
    fn drop(&mut self) {
        lock(&self.shared).stop = true;
        self.shared.1.notify_all();
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The watchdog's thread: sleeps until the running call's deadline, and interrupts the call if
/// it is still the one running then. Calls start without waking it: it wakes at least once a
/// timeout, which bounds how late an interruption comes (under two timeouts).
fn watch(shared: &Shared, timeout: Duration) {
    let mut w = lock(shared);
    loop {
        if w.stop {
            return;
        }
        let now = Instant::now();
        match w.deadline {
            Some(deadline) if deadline <= now => {
                let (call, ident, timeout_again) = (w.call, w.thread_ident, timeout);
                drop(w);
                // The GIL before the lock, as the calling thread takes them.
                Python::attach(|py| {
                    let mut w = lock(shared);
                    if w.deadline.is_some() && w.call == call {
                        let timeout = PyTimeoutError::type_object(py);
                        // One thread must have taken it (the interpreter counts them).
                        if set_async_exception(py, ident, Some(timeout.as_any())).is_ok_and(|n| n == 1) {
                            w.interrupted = Some(call);
                        }
                        // Again after another timeout, should the policy catch this one and go on.
                        w.deadline = Instant::now().checked_add(timeout_again);
                    }
                });
                w = lock(shared);
            }
            Some(deadline) => w = shared.1.wait_timeout(w, deadline - now).unwrap_or_else(PoisonError::into_inner).0,
            None => w = shared.1.wait_timeout(w, timeout).unwrap_or_else(PoisonError::into_inner).0,
        }
    }
}

/// Raise `exception` in the thread `ident` when it next runs Python code (None withdraws a
/// pending one), through `ctypes`, so that the crate needs no `unsafe`; how many threads it
/// reached.
fn set_async_exception(py: Python<'_>, ident: c_ulong, exception: Option<&Bound<'_, PyAny>>) -> PyResult<i64> {
    let ctypes = py.import("ctypes")?;
    let thread = ctypes.getattr("c_ulong")?.call1((ident,))?;
    let exception = match exception {
        Some(e) => ctypes.getattr("py_object")?.call1((e,))?,
        None => py.None().into_bound(py),
    };
    ctypes.getattr("pythonapi")?.getattr("PyThreadState_SetAsyncExc")?.call1((thread, exception))?.extract()
}
