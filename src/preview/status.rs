//! What the page shows beside the image: the render's progress, the scene's
//! error and warnings, and the encoding the command line asked for; as JSON.

use std::fmt::Write as _;

/// The state of the render, as posted on the [`super::board::Board`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Status {
    /// The scene file, as given on the command line.
    pub scene: String,
    pub width: u32,
    pub height: u32,
    /// Samples per pixel in the film now, and the most it will get.
    pub spp: f64,
    pub spp_target: u32,
    /// Seconds of rendering since the render (re)started.
    pub seconds: f64,
    pub samples_per_second: f64,
    /// Which render this is: 1 for the first, one more on each restart.
    pub render: u64,
    /// Counts the frames posted, so that the page fetches each new one once.
    pub frame: u64,
    /// All `spp_target` samples are in.
    pub done: bool,
    /// The located message of a scene that does not load (the image shown
    /// is then the last good one).
    pub error: Option<String>,
    pub warnings: Vec<String>,
    /// The encoding of `--exposure`, `--tonemap` and `--gamma`: where the
    /// page's controls start.
    pub exposure: f64,
    pub tonemap: &'static str,
    pub gamma: Option<f64>,
}

impl Status {
    pub fn to_json(&self) -> String {
        let mut json = String::from("{");
        let _ = write!(
            json,
            "\"scene\": {}, \"width\": {}, \"height\": {}, \"spp\": {}, \"spp_target\": {}, \
             \"seconds\": {}, \"samples_per_second\": {}, \"render\": {}, \"frame\": {}, \
             \"done\": {}, \"error\": {}, \"warnings\": [{}], \"exposure\": {}, \
             \"tonemap\": {}, \"gamma\": {}",
            string(&self.scene),
            self.width,
            self.height,
            number(self.spp),
            self.spp_target,
            number(self.seconds),
            number(self.samples_per_second),
            self.render,
            self.frame,
            self.done,
            self.error.as_deref().map_or("null".to_string(), string),
            self.warnings
                .iter()
                .map(|w| string(w))
                .collect::<Vec<_>>()
                .join(", "),
            number(self.exposure),
            string(self.tonemap),
            self.gamma.map_or("null".to_string(), number),
        );
        json.push('}');
        json
    }
}

/// A finite number as JSON (`null` for NaN and infinities, which JSON lacks).
fn number(value: f64) -> String {
    if value.is_finite() {
        format!("{value}")
    } else {
        "null".to_string()
    }
}

/// A JSON string: quotes, backslashes and control characters escaped.
pub fn string(text: &str) -> String {
    let mut quoted = String::with_capacity(text.len() + 2);
    quoted.push('"');
    for c in text.chars() {
        match c {
            '"' => quoted.push_str("\\\""),
            '\\' => quoted.push_str("\\\\"),
            '\n' => quoted.push_str("\\n"),
            '\r' => quoted.push_str("\\r"),
            '\t' => quoted.push_str("\\t"),
            // `<` escaped too: the text can never close a script element.
            c if (c as u32) < 0x20 || c == '<' || c == '\u{2028}' || c == '\u{2029}' => {
                let _ = write!(quoted, "\\u{:04x}", c as u32);
            }
            c => quoted.push(c),
        }
    }
    quoted.push('"');
    quoted
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strings_are_escaped_and_numbers_that_json_lacks_are_null() {
        assert_eq!(string("a\"b\\c\nd\u{1}<"), r#""a\"b\\c\nd\u0001\u003c""#);
        assert_eq!(number(f64::NAN), "null");
        assert_eq!(number(f64::INFINITY), "null");
        assert_eq!(number(2.5), "2.5");
        let status = Status {
            error: Some("s.txt:3:7: expected a number".to_string()),
            warnings: vec!["w1".to_string(), "w\"2".to_string()],
            tonemap: "none",
            ..Status::default()
        };
        let json = status.to_json();
        assert!(
            json.contains(r#""error": "s.txt:3:7: expected a number""#),
            "{json}"
        );
        assert!(json.contains(r#""warnings": ["w1", "w\"2"]"#), "{json}");
        assert!(json.contains(r#""gamma": null"#), "{json}");
        assert!(json.starts_with('{') && json.ends_with('}'));
    }
}
