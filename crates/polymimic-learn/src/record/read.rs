//! JSON read in file order (a trial's models come in its ordering), with the key path of the
//! first thing that does not parse, so a damaged or truncated file is reported where it breaks.

use std::cell::RefCell;
use std::fmt;

use serde::de::{self, DeserializeSeed, MapAccess, SeqAccess, Visitor};

/// A JSON value, objects kept in file order.
#[derive(Debug, Clone, PartialEq)]
pub enum Json {
    Null,
    Bool(bool),
    /// A number written without a fraction or exponent.
    Int(i128),
    Float(f64),
    Str(String),
    List(Vec<Json>),
    Object(Vec<(String, Json)>),
}

impl Json {
    /// What the value is, for messages.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Json::Null => "null".to_owned(),
            Json::Bool(b) => b.to_string(),
            Json::Int(i) => i.to_string(),
            Json::Float(x) => x.to_string(),
            Json::Str(s) if s.chars().count() > 40 => format!("a string of {} characters", s.chars().count()),
            Json::Str(s) => format!("{s:?}"),
            Json::List(items) => format!("a list of {}", items.len()),
            Json::Object(_) => "an object".to_owned(),
        }
    }
}

/// Joins a key path: `models.expert.lp_history[3]`.
#[must_use]
pub fn join(path: &[String]) -> String {
    let mut out = String::new();
    for part in path {
        if !(out.is_empty() || part.starts_with('[')) {
            out.push('.');
        }
        out.push_str(part);
    }
    out
}

struct Seed<'a> {
    path: &'a RefCell<Vec<String>>,
    failed_at: &'a RefCell<Option<String>>,
}

impl Seed<'_> {
    fn child(&self) -> Seed<'_> {
        Seed { path: self.path, failed_at: self.failed_at }
    }

    fn mark<E>(&self, error: E) -> E {
        let mut failed = self.failed_at.borrow_mut();
        if failed.is_none() {
            *failed = Some(join(&self.path.borrow()));
        }
        error
    }
}

impl<'de> DeserializeSeed<'de> for Seed<'_> {
    type Value = Json;

    fn deserialize<D: de::Deserializer<'de>>(self, deserializer: D) -> Result<Json, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Seed<'_> {
    type Value = Json;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_unit<E>(self) -> Result<Json, E> {
        Ok(Json::Null)
    }

    fn visit_bool<E>(self, v: bool) -> Result<Json, E> {
        Ok(Json::Bool(v))
    }

    fn visit_i64<E>(self, v: i64) -> Result<Json, E> {
        Ok(Json::Int(i128::from(v)))
    }

    fn visit_u64<E>(self, v: u64) -> Result<Json, E> {
        Ok(Json::Int(i128::from(v)))
    }

    fn visit_f64<E>(self, v: f64) -> Result<Json, E> {
        Ok(Json::Float(v))
    }

    fn visit_str<E>(self, v: &str) -> Result<Json, E> {
        Ok(Json::Str(v.to_owned()))
    }

    fn visit_string<E>(self, v: String) -> Result<Json, E> {
        Ok(Json::Str(v))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Json, A::Error> {
        let mut items = Vec::new();
        loop {
            self.path.borrow_mut().push(format!("[{}]", items.len()));
            let next = seq.next_element_seed(self.child()).map_err(|e| self.mark(e));
            self.path.borrow_mut().pop();
            match next? {
                Some(item) => items.push(item),
                None => return Ok(Json::List(items)),
            }
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Json, A::Error> {
        let mut entries: Vec<(String, Json)> = Vec::new();
        while let Some(key) = map.next_key::<String>().map_err(|e| self.mark(e))? {
            self.path.borrow_mut().push(key.clone());
            let value = if entries.iter().any(|(k, _)| *k == key) {
                Err(self.mark(de::Error::custom("the key appears twice")))
            } else {
                map.next_value_seed(self.child()).map_err(|e| self.mark(e))
            };
            self.path.borrow_mut().pop();
            entries.push((key, value?));
        }
        Ok(Json::Object(entries))
    }
}

/// Parses `text`; on failure, the key path where it broke (empty at the top) and why.
///
/// # Errors
/// Text that is not one JSON value.
pub fn parse(text: &str) -> Result<Json, (String, String)> {
    let path = RefCell::new(Vec::new());
    let failed_at = RefCell::new(None);
    let mut deserializer = serde_json::Deserializer::from_str(text);
    let value = Seed { path: &path, failed_at: &failed_at }
        .deserialize(&mut deserializer)
        .and_then(|v| deserializer.end().map(|()| v));
    value.map_err(|e| {
        let why = if e.is_eof() { format!("the text ends early ({e})") } else { e.to_string() };
        (failed_at.into_inner().unwrap_or_default(), why)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn objects_keep_file_order_and_numbers_their_kind() {
        let value = parse(r#"{"b": 1, "a": [1.5, true, null, "x"]}"#).unwrap();
        assert_eq!(
            value,
            Json::Object(vec![
                ("b".to_owned(), Json::Int(1)),
                (
                    "a".to_owned(),
                    Json::List(vec![Json::Float(1.5), Json::Bool(true), Json::Null, Json::Str("x".to_owned())])
                ),
            ])
        );
    }

    #[test]
    fn a_truncated_text_names_where_it_ends() {
        let (at, why) = parse(r#"{"models": {"expert": {"lp_history": [0.5, 0.6"#).unwrap_err();
        assert_eq!(at, "models.expert.lp_history[2]");
        assert!(why.contains("ends early"), "{why}");
    }

    #[test]
    fn a_repeated_key_is_refused() {
        let (at, why) = parse(r#"{"seed": 1, "seed": 2}"#).unwrap_err();
        assert_eq!((at.as_str(), why.contains("twice")), ("seed", true));
    }
}
