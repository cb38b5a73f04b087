//! The user's text as a message shows it: tokens and paths cut to
//! [`MAX_SHOWN_TOKEN`] and [`MAX_SHOWN_PATH`] characters, control characters
//! written as escapes, so that a hostile input never floods or drives the
//! terminal.

use std::borrow::Cow;
use std::path::Path;

use super::{MAX_SHOWN_PATH, MAX_SHOWN_TOKEN};

/// A token of the scene text as a message shows it: whole up to
/// `MAX_SHOWN_TOKEN` characters, else its first ones and an ellipsis (cut on
/// a character boundary), so a multi-megabyte token never fills a terminal.
pub fn shown(token: &str) -> Cow<'_, str> {
    let cut = match token.char_indices().nth(MAX_SHOWN_TOKEN) {
        Some((end, _)) => Cow::Owned(format!("{}…", &token[..end])),
        None => Cow::Borrowed(token),
    };
    match printable(&cut, false) {
        Cow::Borrowed(_) => cut,
        Cow::Owned(escaped) => Cow::Owned(escaped),
    }
}

/// `text` with its control characters (escape sequences, carriage returns,
/// bells of a hostile file) written as escapes (`\u{1b}`), so that a
/// message shows what the file holds and never drives the terminal; line
/// breaks are kept when `keep_lines`.
pub fn printable(text: &str, keep_lines: bool) -> Cow<'_, str> {
    let control = |c: char| c.is_control() && !(keep_lines && c == '\n');
    if !text.chars().any(control) {
        return Cow::Borrowed(text);
    }
    let mut escaped = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if control(c) {
            escaped.extend(c.escape_default());
        } else {
            escaped.push(c);
        }
    }
    Cow::Owned(escaped)
}

/// A path as a message shows it: whole up to `MAX_SHOWN_PATH` characters,
/// else its first and last ones with an ellipsis between (cut on character
/// boundaries): the start says where it is, the end names the file.
pub fn shown_path(path: &Path) -> String {
    let lossy = path.to_string_lossy();
    let text = printable(&lossy, false);
    let count = text.chars().count();
    if count <= MAX_SHOWN_PATH {
        return text.into_owned();
    }
    let head = (MAX_SHOWN_PATH - 1) / 2;
    let tail = MAX_SHOWN_PATH - 1 - head;
    let start: String = text.chars().take(head).collect();
    let end: String = text.chars().skip(count - tail).collect();
    format!("{start}…{end}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_tokens_are_cut_on_a_character_boundary() {
        assert_eq!(shown("radius"), "radius");
        let exact = "é".repeat(MAX_SHOWN_TOKEN);
        assert_eq!(shown(&exact), exact.as_str());
        let long = "é".repeat(MAX_SHOWN_TOKEN + 1);
        let cut = shown(&long);
        assert_eq!(cut.chars().count(), MAX_SHOWN_TOKEN + 1);
        assert!(cut.ends_with('…'));
    }

    #[test]
    fn long_paths_keep_their_start_and_end() {
        assert_eq!(shown_path(Path::new("mesh/bunny.obj")), "mesh/bunny.obj");
        let exact = "é".repeat(MAX_SHOWN_PATH);
        assert_eq!(shown_path(Path::new(&exact)), exact);
        let long = format!("/start/{}/end.obj", "é".repeat(10_000));
        let cut = shown_path(Path::new(&long));
        assert_eq!(cut.chars().count(), MAX_SHOWN_PATH);
        assert!(
            cut.starts_with("/start/") && cut.ends_with("é/end.obj"),
            "{cut}"
        );
        assert_eq!(cut.matches('…').count(), 1);
    }
}
