//! Warnings of one kind counted after the first few: a file of five
//! million stray numbers gives five warnings about them and one line
//! counting the rest, not five million stored and printed messages.
//!
//! A warning's kind is its message with every quoted part (`'…'`) and
//! every number (`#`) blanked: "unexpected number 3 in Group, skipped" and
//! "unexpected number 4 in Group, skipped" are of one kind, while an
//! unknown field and an unknown block are not.

use std::collections::HashMap;

use crate::limits::MAX_WARNINGS_PER_KIND;
use crate::scene::error::Location;

/// How many warnings of each kind were seen, and where the first one not
/// kept was.
#[derive(Debug, Default)]
pub struct WarningTally {
    kinds: HashMap<String, Tally>,
}

#[derive(Debug)]
struct Tally {
    seen: usize,
    first_omitted: Option<Location>,
}

impl WarningTally {
    /// Counts a warning; whether it is among the first
    /// [`MAX_WARNINGS_PER_KIND`] of its kind (to be kept).
    pub fn admit(&mut self, message: &str, location: Location) -> bool {
        let tally = self.kinds.entry(kind_of(message)).or_insert(Tally {
            seen: 0,
            first_omitted: None,
        });
        tally.seen += 1;
        if tally.seen <= MAX_WARNINGS_PER_KIND {
            return true;
        }
        tally.first_omitted.get_or_insert(location);
        false
    }

    /// One warning per kind with some not kept, at the first not kept,
    /// in the order of their places in the file.
    pub fn summaries(&self) -> Vec<(Location, String)> {
        let mut lines: Vec<(Location, String)> = self
            .kinds
            .iter()
            .filter_map(|(kind, tally)| {
                // Only a kind past the limit has a first omitted warning.
                let at = tally.first_omitted?;
                let omitted = tally.seen - MAX_WARNINGS_PER_KIND;
                Some((
                    at,
                    format!("{omitted} more warnings like \"{kind}\" from here on (not shown)"),
                ))
            })
            .collect();
        lines.sort_by_key(|(at, _)| (at.line, at.column));
        lines
    }
}

/// `message` with its quoted parts and numbers blanked (see the module).
fn kind_of(message: &str) -> String {
    let mut kind = String::with_capacity(message.len());
    let mut quoted = false;
    let mut in_number = false;
    for c in message.chars() {
        if quoted {
            if c == '\'' {
                quoted = false;
                kind.push_str("…'");
            }
            continue;
        }
        if c == '\'' {
            quoted = true;
            kind.push(c);
            continue;
        }
        let numeric = c.is_ascii_digit() || (in_number && matches!(c, '.' | 'e' | '-' | '+'));
        if numeric {
            if !in_number {
                kind.push('#');
            }
            in_number = true;
            continue;
        }
        in_number = false;
        kind.push(c);
    }
    if quoted {
        kind.push('…');
    }
    kind
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_quoted_words_are_blanked() {
        assert_eq!(
            kind_of("unexpected number 3.5e-2 in Group, skipped"),
            "unexpected number # in Group, skipped"
        );
        assert_eq!(
            kind_of("unknown field 'sparkle' in Background, skipped"),
            "unknown field '…' in Background, skipped"
        );
        assert_ne!(
            kind_of("unknown field 'a' in Material, skipped"),
            kind_of("unknown block 'a' in Material, skipped")
        );
    }

    /// Found by the fuzz target `scene_text` (every input with a warning):
    /// the count of omitted warnings was taken for every kind, and for a
    /// kind within the limit it underflowed, a panic wherever overflow is
    /// checked (debug builds, the fuzz targets).
    #[test]
    fn a_kind_within_the_limit_underflowed_its_omitted_count() {
        let mut tally = WarningTally::default();
        let at = |line| Location { line, column: 1 };
        for line in 1..=MAX_WARNINGS_PER_KIND as u32 {
            assert!(tally.admit(&format!("unexpected number {line} in Group"), at(line)));
        }
        assert!(tally.admit("unknown field 'x' in Material", at(100)));
        assert!(tally.summaries().is_empty());
    }

    #[test]
    fn a_kind_is_counted_after_the_first_few() {
        let mut tally = WarningTally::default();
        let at = |line| Location { line, column: 1 };
        let kept = (1..=1000)
            .filter(|&line| tally.admit(&format!("unexpected number {line} in Group"), at(line)))
            .count();
        assert_eq!(kept, MAX_WARNINGS_PER_KIND);
        assert!(tally.admit("unknown field 'x' in Material", at(2000)));
        let summaries = tally.summaries();
        assert_eq!(summaries.len(), 1);
        let (location, message) = &summaries[0];
        assert_eq!(location.line as usize, MAX_WARNINGS_PER_KIND + 1);
        assert!(message.starts_with(&format!("{} more", 1000 - MAX_WARNINGS_PER_KIND)));
    }
}
