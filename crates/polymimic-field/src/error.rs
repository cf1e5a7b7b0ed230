//! Errors: bad parameters (the caller's fault, checked up front) apart from run-time failures.

use thiserror::Error;

/// A parameter the caller passed is out of range or inconsistent.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FieldParamError {
    /// A numeric parameter is outside its allowed range (or not finite).
    #[error("parameter `{name}` = {value} is out of range: {expected}")]
    OutOfRange {
        /// Parameter name.
        name: &'static str,
        /// The offending value.
        value: f64,
        /// What is allowed, in words.
        expected: &'static str,
    },
    /// A command id that no command language defines.
    #[error("unknown command id {0}")]
    UnknownCommand(u16),
    /// The id frames record wheel speeds by: it names no speeds.
    #[error(
        "command id {0} stands for wheel speeds, not for a command: send the speeds themselves, (left_mm_s, right_mm_s)"
    )]
    WheelSpeedsHaveNoId(u16),
    /// Wheel speeds beyond what the body's wheels reach.
    #[error("wheel speeds ({left_mm_s}, {right_mm_s}) mm/s exceed the {body} body's top speed of {top_mm_s} mm/s")]
    BeyondTopSpeed {
        /// Left wheel, mm/s.
        left_mm_s: f64,
        /// Right wheel, mm/s.
        right_mm_s: f64,
        /// The body's top wheel speed, mm/s.
        top_mm_s: f64,
        /// Body name.
        body: &'static str,
    },
    /// A command the body cannot execute (a humanoid kick sent to a wheeled robot, …).
    #[error("command `{command}` cannot drive the {body} body")]
    CommandNotSupported {
        /// Command name.
        command: &'static str,
        /// Body name.
        body: &'static str,
    },
    /// A built-in controller asked to drive a body it has no commands for.
    #[error("the {controller} controller cannot drive the {body} body")]
    ControllerNotSupported {
        /// The controller's demonstrator.
        controller: &'static str,
        /// Body name.
        body: &'static str,
    },
    /// A start puts the ball on (under) the robot.
    #[error(
        "the ball at ({x_mm:.1}, {y_mm:.1}) mm overlaps the {body} robot by {overlap_mm:.1} mm: start it clear of the robot's footprint"
    )]
    BallUnderRobot {
        /// Ball x, mm.
        x_mm: f64,
        /// Ball y, mm.
        y_mm: f64,
        /// Body name.
        body: &'static str,
        /// How far the ball reaches into the footprint, mm.
        overlap_mm: f64,
    },
    /// A pose or ball position lies outside the field.
    #[error("{what} at ({x_mm:.1}, {y_mm:.1}) mm is outside the field")]
    OutsideField {
        /// What was placed.
        what: &'static str,
        /// x, mm.
        x_mm: f64,
        /// y, mm.
        y_mm: f64,
    },
    /// A demonstrator name that does not exist.
    #[error("unknown demonstrator `{0}`")]
    UnknownDemonstrator(String),
    /// A count (of substeps, of frames) that is not a whole number, or is negative.
    #[error("parameter `{name}` = {value} is not a count: {expected}")]
    NotACount {
        /// Parameter name.
        name: &'static str,
        /// The offending value, as written.
        value: String,
        /// What is allowed, in words.
        expected: &'static str,
    },
    /// Malformed JSON for a config.
    #[error("invalid JSON: {0}")]
    Json(String),
}

/// Anything that can go wrong in the field.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FieldError {
    /// Invalid input; nothing was simulated.
    #[error(transparent)]
    Param(#[from] FieldParamError),
    /// `Episode::step` was called after the episode ended.
    #[error("the episode has already ended ({0})")]
    EpisodeFinished(&'static str),
    /// Too many demonstrations were invalid (lost tracking) to collect the requested number.
    #[error("only {valid} of {requested} valid demonstrations after {attempts} attempts")]
    RetriesExhausted {
        /// Valid demonstrations collected.
        valid: usize,
        /// Valid demonstrations requested.
        requested: usize,
        /// Attempts made.
        attempts: usize,
    },
    /// A batch was stepped before every one of its episodes was started.
    #[error("episode {index} of the batch has not been started: reset it before stepping")]
    NotStarted {
        /// The first slot without an episode.
        index: usize,
    },
    /// The physics produced a non-finite state (should never happen; reported, not panicked).
    #[error("the simulation diverged: {0}")]
    Diverged(&'static str),
}

/// Check that `value` is finite and within `[lo, hi]`.
pub(crate) fn check_range(
    name: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    expected: &'static str,
) -> Result<(), FieldParamError> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(())
    } else {
        Err(FieldParamError::OutOfRange { name, value, expected })
    }
}

/// Refuses, by key, a count in a config's JSON object that is not a whole number from 0 to
/// `u32::MAX` (`counts`: each key with what is allowed), before serde reads it: serde's own
/// message names the type and a column, not the key. Malformed JSON is left to serde.
pub(crate) fn check_counts(json: &str, counts: &[(&'static str, &'static str)]) -> Result<(), FieldParamError> {
    let Ok(serde_json::Value::Object(values)) = serde_json::from_str::<serde_json::Value>(json) else {
        return Ok(());
    };
    for &(name, expected) in counts {
        if let Some(value) = values.get(name)
            && value.as_u64().is_none_or(|v| v > u64::from(u32::MAX))
        {
            return Err(FieldParamError::NotACount { name, value: value.to_string(), expected });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_refused_by_key_unless_whole_and_not_negative() {
        let counts = [("n", "a whole number")];
        assert_eq!(check_counts(r#"{"n": 3, "x": -1}"#, &counts), Ok(()));
        for bad in ["-1", "2.5", "\"8\"", "4294967296"] {
            let error = check_counts(&format!(r#"{{"n": {bad}}}"#), &counts).expect_err(bad);
            assert_eq!(error.to_string(), format!("parameter `n` = {bad} is not a count: a whole number"));
        }
        assert_eq!(check_counts("{", &counts), Ok(()), "left to serde");
    }

    #[test]
    fn check_range_rejects_nan_and_bounds() {
        assert!(check_range("a", 0.5, 0.0, 1.0, "[0, 1]").is_ok());
        assert!(check_range("a", f64::NAN, 0.0, 1.0, "[0, 1]").is_err());
        assert!(check_range("a", 1.5, 0.0, 1.0, "[0, 1]").is_err());
    }

    #[test]
    fn param_errors_convert_into_field_errors() {
        let e: FieldError = FieldParamError::UnknownCommand(7).into();
        assert_eq!(e.to_string(), "unknown command id 7");
    }
}
