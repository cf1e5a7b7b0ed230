//! Damaged copies of a valid saved file, for property tests that every reader of saved models
//! and configs refuses them with an `Err` (or reads a valid value) and never panics.
//!
//! Four kinds of damage, one strategy each: [`truncated`] (the text cut anywhere),
//! [`flipped`] (a few bytes flipped or replaced), [`reshaped`] (a key or element removed, or a
//! value replaced by another JSON type, an extreme number, a wrong-length array, a copy of
//! another part of the file, a nudged number — inside embedded JSON strings too, as the
//! recogniser stores its codebooks and HMMs) and [`arbitrary`] (junk, deep nesting, or an
//! envelope of the right format around an arbitrary payload).
//!
//! ```
//! use proptest::prelude::*;
//! use proptest::test_runner::TestRunner;
//!
//! let valid = r#"{"format":"x","version":1,"payload":[1,2,3]}"#;
//! let mut runner = TestRunner::new(polymimic_damage::config());
//! runner
//!     .run(&polymimic_damage::reshaped(valid), |text| {
//!         let _ = serde_json::from_str::<serde_json::Value>(&text);
//!         Ok(())
//!     })
//!     .unwrap();
//! ```

use std::sync::Arc;

use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::Config;
use serde_json::{Value, json};

/// Cases per property unless the `PROPTEST_CASES` environment variable says otherwise.
pub const DEFAULT_CASES: u32 = 256;

/// [`DEFAULT_CASES`] cases, or as many as `PROPTEST_CASES` asks for.
#[must_use]
pub fn config() -> Config {
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(DEFAULT_CASES);
    Config::with_cases(cases)
}

/// `valid` cut at any byte (on a character boundary), from empty to whole.
pub fn truncated(valid: &str) -> impl Strategy<Value = String> + use<> {
    let valid = valid.to_owned();
    any::<Index>().prop_map(move |at| {
        let mut end = at.index(valid.len() + 1);
        while !valid.is_char_boundary(end) {
            end -= 1;
        }
        valid[..end].to_owned()
    })
}

/// Bytes that matter to JSON, to put in place of a byte of the file.
const SYNTAX_BYTES: &[u8] = b"\"{}[],:0123456789-+.eE \\nulltrue\x00\xff";

/// `valid` with one to four bytes flipped by a bit or replaced by a byte that matters to JSON
/// (read back lossily: the readers take text).
pub fn flipped(valid: &str) -> impl Strategy<Value = String> + use<> {
    let valid = valid.as_bytes().to_vec();
    let edit = prop_oneof![
        (0u8..8).prop_map(|bit| ByteEdit::Flip(1 << bit)),
        proptest::sample::select(SYNTAX_BYTES).prop_map(ByteEdit::Put),
    ];
    proptest::collection::vec((any::<Index>(), edit), 1..=4).prop_map(move |edits| {
        let mut bytes = valid.clone();
        if !bytes.is_empty() {
            for (at, edit) in edits {
                let i = at.index(bytes.len());
                match edit {
                    ByteEdit::Flip(mask) => bytes[i] ^= mask,
                    ByteEdit::Put(b) => bytes[i] = b,
                }
            }
        }
        String::from_utf8_lossy(&bytes).into_owned()
    })
}

#[derive(Debug, Clone, Copy)]
enum ByteEdit {
    Flip(u8),
    Put(u8),
}

/// One step from a JSON value to one of its parts.
#[derive(Debug, Clone, PartialEq)]
enum Step {
    Key(String),
    At(usize),
    /// Into a string that holds JSON (an embedded saved file).
    Inner,
}

/// What to do to the part of the file a path leads to.
#[derive(Debug, Clone)]
pub enum Edit {
    /// Remove the key or array element (the whole file becomes `null`).
    Remove,
    /// Put this value in its place.
    Replace(Value),
    /// Put a copy of another part of the file (picked by the index) in its place.
    CopyFrom(Index),
    /// Wrap it in an array: `x` becomes `[x]`.
    Wrap,
    /// Make an array one longer (its last element again), or a scalar an array of two.
    Lengthen,
    /// Add this to a number.
    Nudge(f64),
}

/// Values of every JSON type, extreme numbers, and arrays of wrong lengths and depths.
#[must_use]
pub fn replacements() -> Vec<Value> {
    let too_big_for_u64: Value = serde_json::from_str("18446744073709551616").unwrap_or(Value::Null);
    vec![
        Value::Null,
        json!(true),
        json!(false),
        json!(0),
        json!(-1),
        json!(1),
        json!(2),
        json!(3),
        json!(0.5),
        json!(-0.0),
        json!(1e-300),
        json!(5e-324),
        json!(1e308),
        json!(-1e308),
        json!(f64::MAX),
        json!(1_u64 << 32),
        json!(1_u64 << 62),
        json!(1_u64 << 63),
        json!(u64::MAX),
        json!(i64::MIN),
        too_big_for_u64,
        json!(""),
        json!("x"),
        json!("inf"),
        json!("-inf"),
        json!("NaN"),
        json!("ergodic"),
        json!("left-right"),
        json!([]),
        json!([[]]),
        json!([0]),
        json!([1.0]),
        json!([0.5, 0.5]),
        json!([1.0, 0.0, 0.0]),
        json!([[0.5, 0.5], [1.0]]),
        json!([null]),
        json!({}),
        json!({"kind": "ergodic"}),
        json!({"kind": "left-right", "links": 1_000_000}),
        json!({"kind": "left-right", "links": u64::MAX}),
    ]
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        2 => Just(Edit::Remove),
        6 => proptest::sample::select(replacements()).prop_map(Edit::Replace),
        2 => any::<Index>().prop_map(Edit::CopyFrom),
        1 => Just(Edit::Wrap),
        1 => Just(Edit::Lengthen),
        2 => prop_oneof![-1.0..1.0, -1e-6..1e-6, Just(1e300), Just(-1e300)].prop_map(Edit::Nudge),
    ]
}

/// `valid` (JSON) with one or two of its parts removed, replaced or reshaped.
///
/// # Panics
/// If `valid` is not JSON: the strategy starts from a valid file.
pub fn reshaped(valid: &str) -> impl Strategy<Value = String> + use<> {
    let root: Value = serde_json::from_str(valid).expect("a valid file is JSON");
    let mut all = Vec::new();
    paths(&root, &mut Vec::new(), &mut all);
    let (root, all) = (Arc::new(root), Arc::new(all));
    proptest::collection::vec((any::<Index>(), edit()), 1..=2).prop_map(move |edits| {
        let mut value = (*root).clone();
        for (at, edit) in edits {
            let path = &all[at.index(all.len())];
            let edit = match edit {
                Edit::CopyFrom(from) => Edit::Replace(get(&root, &all[from.index(all.len())]).unwrap_or(Value::Null)),
                other => other,
            };
            apply(&mut value, path, &edit);
        }
        value.to_string()
    })
}

/// Every path in `value` (the root's too), depth first, going into strings that hold JSON.
fn paths(value: &Value, prefix: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    out.push(prefix.clone());
    let mut visit = |step: Step, child: &Value, prefix: &mut Vec<Step>| {
        prefix.push(step);
        paths(child, prefix, out);
        prefix.pop();
    };
    match value {
        Value::Object(map) => map.iter().for_each(|(k, v)| visit(Step::Key(k.clone()), v, prefix)),
        Value::Array(items) => items.iter().enumerate().for_each(|(i, v)| visit(Step::At(i), v, prefix)),
        Value::String(text) => {
            if let Ok(inner @ (Value::Object(_) | Value::Array(_))) = serde_json::from_str::<Value>(text) {
                visit(Step::Inner, &inner, prefix);
            }
        }
        _ => {}
    }
}

fn get(value: &Value, path: &[Step]) -> Option<Value> {
    match path {
        [] => Some(value.clone()),
        [Step::Inner, rest @ ..] => get(&serde_json::from_str(value.as_str()?).ok()?, rest),
        [Step::Key(k), rest @ ..] => get(value.get(k)?, rest),
        [Step::At(i), rest @ ..] => get(value.get(i)?, rest),
    }
}

fn apply(value: &mut Value, path: &[Step], edit: &Edit) {
    match path {
        [] => match edit {
            Edit::Remove | Edit::CopyFrom(_) => *value = Value::Null,
            Edit::Replace(x) => *value = x.clone(),
            Edit::Wrap => *value = Value::Array(vec![value.take()]),
            Edit::Lengthen => match value {
                Value::Array(items) => {
                    if let Some(last) = items.last().cloned() {
                        items.push(last);
                    }
                }
                other => *other = Value::Array(vec![other.clone(), other.take()]),
            },
            Edit::Nudge(by) => {
                if let Some(x) = value.as_f64() {
                    *value = serde_json::Number::from_f64(x + by).map_or(Value::Null, Value::Number);
                }
            }
        },
        [Step::Inner, rest @ ..] => {
            if let Value::String(text) = value {
                if let Ok(mut inner) = serde_json::from_str::<Value>(text) {
                    apply(&mut inner, rest, edit);
                    *text = inner.to_string();
                }
            }
        }
        [Step::Key(k)] if matches!(edit, Edit::Remove) => {
            if let Value::Object(map) = value {
                map.remove(k);
            }
        }
        [Step::At(i)] if matches!(edit, Edit::Remove) => {
            if let Value::Array(items) = value {
                if *i < items.len() {
                    items.remove(*i);
                }
            }
        }
        [Step::Key(k), rest @ ..] => {
            if let Some(child) = value.get_mut(k) {
                apply(child, rest, edit);
            }
        }
        [Step::At(i), rest @ ..] => {
            if let Some(child) = value.get_mut(i) {
                apply(child, rest, edit);
            }
        }
    }
}

/// Any JSON value, up to four levels deep.
pub fn json_value() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::from),
        any::<i64>().prop_map(Value::from),
        any::<u64>().prop_map(Value::from),
        any::<f64>()
            .prop_filter_map("JSON has no NaN or infinity", |x| serde_json::Number::from_f64(x).map(Value::Number)),
        "[a-z_.-]{0,12}".prop_map(Value::from),
    ];
    leaf.prop_recursive(4, 64, 8, |inner| {
        prop_oneof![
            proptest::collection::vec(inner.clone(), 0..8).prop_map(Value::Array),
            proptest::collection::btree_map("[a-z_]{1,12}", inner, 0..8)
                .prop_map(|map| Value::Object(map.into_iter().collect())),
        ]
    })
}

/// Junk: any text, JSON-looking noise, brackets nested thousands deep, or an envelope of
/// `format` version 1 around an arbitrary payload.
pub fn arbitrary(format: &str) -> impl Strategy<Value = String> + use<> {
    let format = format.to_owned();
    prop_oneof![
        any::<String>(),
        "[\\[\\]{}:,\"0-9a-z.eE+ -]{0,64}",
        (1_usize..20_000).prop_map(|depth| "[".repeat(depth) + &"]".repeat(depth)),
        (1_usize..20_000).prop_map(|depth| "{\"a\":".repeat(depth)),
        json_value().prop_map(move |payload| json!({"format": format, "version": 1, "payload": payload}).to_string()),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_reach_into_embedded_json() {
        let root = json!({"a": [1, 2], "b": "{\"c\": [3]}"});
        let mut all = Vec::new();
        paths(&root, &mut Vec::new(), &mut all);
        let inner = vec![Step::Key("b".into()), Step::Inner, Step::Key("c".into()), Step::At(0)];
        assert!(all.contains(&inner));
        let mut value = root.clone();
        apply(&mut value, &inner, &Edit::Replace(json!("x")));
        assert_eq!(value, json!({"a": [1, 2], "b": "{\"c\":[\"x\"]}"}));
        apply(&mut value, &[Step::Key("a".into()), Step::At(0)], &Edit::Remove);
        assert_eq!(value["a"], json!([2]));
    }

    #[test]
    fn config_reads_the_number_of_cases_from_the_environment_or_defaults() {
        let expected = std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(DEFAULT_CASES);
        assert_eq!(config().cases, expected);
    }
}
