//! Saved models are JSON envelopes `{"format": …, "version": …, "payload": …}`: readable by
//! people and other tools, and checked on load so that a file of another kind or of a newer
//! version is refused with a message instead of being misread.

use serde::Serialize;
use serde::de::DeserializeOwned;

/// `payload` wrapped with its format name and version.
///
/// # Errors
/// Only if `payload` cannot be represented as JSON (a map with non-string keys).
pub fn to_envelope<T: Serialize>(format: &str, version: u32, payload: &T) -> Result<String, String> {
    let value = serde_json::json!({ "format": format, "version": version, "payload": payload });
    serde_json::to_string(&value).map_err(|e| e.to_string())
}

/// The payload of an envelope written by [`to_envelope`] with the same format and version.
///
/// # Errors
/// Text that is not JSON, another format, another version, or a payload of the wrong shape;
/// the message says which.
pub fn from_envelope<T: DeserializeOwned>(text: &str, format: &str, version: u32) -> Result<T, String> {
    let mut value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("not a saved polymimic file ({e})"))?;
    let found_format = value.get("format").and_then(serde_json::Value::as_str);
    if found_format != Some(format) {
        let found = found_format.map_or_else(|| "no format".to_owned(), |f| format!("{f:?}"));
        return Err(format!("expected format {format:?}, found {found}"));
    }
    match value.get("version").and_then(serde_json::Value::as_u64) {
        Some(v) if v == u64::from(version) => {}
        Some(v) => {
            return Err(format!("format version {v} is not supported (this polymimic reads version {version})"));
        }
        None => return Err("no format version".to_owned()),
    }
    let payload = value.get_mut("payload").map(serde_json::Value::take).ok_or("no payload")?;
    serde_json::from_value(payload).map_err(|e| format!("payload: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_floats_exactly() {
        let payload = vec![0.1_f64, 1.0 / 3.0, 1e-300, f64::MAX];
        let text = to_envelope("x", 1, &payload).unwrap();
        assert_eq!(from_envelope::<Vec<f64>>(&text, "x", 1).unwrap(), payload);
    }

    #[test]
    fn names_what_is_wrong() {
        let text = to_envelope("x", 2, &[1]).unwrap();
        assert_eq!(
            from_envelope::<Vec<u8>>(&text, "x", 1).unwrap_err(),
            "format version 2 is not supported (this polymimic reads version 1)"
        );
        assert_eq!(from_envelope::<Vec<u8>>(&text, "y", 2).unwrap_err(), "expected format \"y\", found \"x\"");
        assert!(from_envelope::<Vec<u8>>("{", "x", 1).unwrap_err().starts_with("not a saved polymimic file"));
        assert!(from_envelope::<String>(&text, "x", 2).unwrap_err().starts_with("payload:"));
        assert_eq!(from_envelope::<Vec<u8>>("{}", "x", 1).unwrap_err(), "expected format \"x\", found no format");
    }
}
