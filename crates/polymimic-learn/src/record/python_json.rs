//! JSON text exactly as Python's `json.dumps` writes it with its default settings: `", "` and
//! `": "` between items, every float as Python's `repr` (the shortest digits that read back
//! the same, exponent form below 1e-4 and from 1e16), `NaN` and `Infinity` for the values
//! strict JSON lacks, and every character outside ASCII escaped. Trial files written by earlier
//! versions were made that way, so writing them the same way keeps them byte for byte.

use std::fmt::Write;

/// Appends `x` as Python's `repr(float)` writes it.
pub fn push_float(out: &mut String, x: f64) {
    if x.is_nan() {
        out.push_str("NaN");
        return;
    }
    if x.is_infinite() {
        out.push_str(if x > 0.0 { "Infinity" } else { "-Infinity" });
        return;
    }
    // Rust's `{:e}` gives the shortest digits that read back as `x`, as `d.ddde±x`. Where two
    // strings of that length read back as `x` (`x` halfway between them), Python writes the
    // nearer, ties to even: the correctly rounded one, which Rust's fixed precision gives.
    let shortest = format!("{x:e}");
    let length = shortest.split_once('e').map_or(0, |(m, _)| m.chars().filter(char::is_ascii_digit).count());
    let rounded = format!("{:.*e}", length.saturating_sub(1), x);
    let scientific = if rounded.parse::<f64>() == Ok(x) { rounded } else { shortest };
    let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let (negative, mantissa) = mantissa.strip_prefix('-').map_or((false, mantissa), |m| (true, m));
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let n = digits.len() as i32;
    // Python's decimal point position: x = 0.d1d2… × 10^point.
    let point = exponent + 1;
    if negative {
        out.push('-');
    }
    if point <= -4 || point > 16 {
        out.push_str(&digits[..1]);
        if n > 1 {
            out.push('.');
            out.push_str(&digits[1..]);
        }
        let shown = point - 1;
        let _ = write!(out, "e{}{:02}", if shown < 0 { '-' } else { '+' }, shown.unsigned_abs());
    } else if point <= 0 {
        out.push_str("0.");
        out.extend(std::iter::repeat_n('0', point.unsigned_abs() as usize));
        out.push_str(&digits);
    } else if point >= n {
        out.push_str(&digits);
        out.extend(std::iter::repeat_n('0', (point - n) as usize));
        out.push_str(".0");
    } else {
        out.push_str(&digits[..point as usize]);
        out.push('.');
        out.push_str(&digits[point as usize..]);
    }
}

/// Appends `text` as a JSON string, escaped as `json.dumps(..., ensure_ascii=True)` does.
pub fn push_string(out: &mut String, text: &str) {
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            ' '..='~' => out.push(c),
            _ => {
                let mut units = [0u16; 2];
                for unit in c.encode_utf16(&mut units) {
                    let _ = write!(out, "\\u{unit:04x}");
                }
            }
        }
    }
    out.push('"');
}

/// Writes one JSON object: `{"key": value, ...}`, each value written by its closure.
pub struct Object<'a> {
    out: &'a mut String,
    first: bool,
}

impl<'a> Object<'a> {
    pub fn new(out: &'a mut String) -> Self {
        out.push('{');
        Self { out, first: true }
    }

    /// The key, then the value `write` appends.
    pub fn field(&mut self, key: &str, write: impl FnOnce(&mut String)) -> &mut Self {
        if !self.first {
            self.out.push_str(", ");
        }
        self.first = false;
        push_string(self.out, key);
        self.out.push_str(": ");
        write(self.out);
        self
    }

    pub fn end(&mut self) {
        self.out.push('}');
    }
}

/// Appends `[a, b, ...]`, each item written by `write`.
pub fn push_list<T>(out: &mut String, items: &[T], mut write: impl FnMut(&mut String, &T)) {
    out.push('[');
    for (i, item) in items.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        write(out, item);
    }
    out.push(']');
}

#[cfg(test)]
mod tests {
    use super::*;

    fn float(x: f64) -> String {
        let mut s = String::new();
        push_float(&mut s, x);
        s
    }

    #[test]
    fn floats_read_as_python_writes_them() {
        // Each pair checked against CPython's repr.
        for (x, python) in [
            (0.0, "0.0"),
            (-0.0, "-0.0"),
            (1.0, "1.0"),
            (0.5, "0.5"),
            (0.1, "0.1"),
            (0.9, "0.9"),
            (123.456, "123.456"),
            (1e-4, "0.0001"),
            (1e-5, "1e-05"),
            (1.5e-5, "1.5e-05"),
            (1e15, "1000000000000000.0"),
            (1e16, "1e+16"),
            (1.25e17, "1.25e+17"),
            (2.5e-300, "2.5e-300"),
            (1e300, "1e+300"),
            (0.8369656826815547, "0.8369656826815547"),
            (-6.193254309454831, "-6.193254309454831"),
            (0.500239961602048, "0.500239961602048"),
            (5e-324, "5e-324"),
            (562_949_953_421_312.25, "562949953421312.2"),
            (562_949_953_421_312.75, "562949953421312.8"),
            (f64::MAX, "1.7976931348623157e+308"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-Infinity"),
        ] {
            assert_eq!(float(x), python, "{x:e}");
        }
    }

    #[test]
    fn strings_escape_as_python_ensure_ascii_does() {
        let mut s = String::new();
        push_string(&mut s, "a\"b\\c\nd\u{1}é😀\u{7f}");
        assert_eq!(s, "\"a\\\"b\\\\c\\nd\\u0001\\u00e9\\ud83d\\ude00\\u007f\"");
    }

    #[test]
    fn objects_and_lists_use_pythons_separators() {
        let mut s = String::new();
        Object::new(&mut s)
            .field("a", |o| push_list(o, &[1.0, 2.5], |o, x| push_float(o, *x)))
            .field("b", |o| o.push_str("[]"))
            .end();
        assert_eq!(s, r#"{"a": [1.0, 2.5], "b": []}"#);
    }
}
