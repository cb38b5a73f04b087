//! Syntax only: text -> tokens (nom) -> a `Document` tree built with an explicit stack.

use std::path::Path;

use nom::IResult;
use nom::branch::alt;
use nom::bytes::complete::{tag, take_till, take_till1, take_while1};
use nom::character::complete::one_of;
use nom::combinator::{map, value};
use nom::multi::many0_count;
use nom::sequence::pair;

use crate::limits::MAX_NESTING;
use crate::limits::shown;
use crate::scene::ast::{Block, Document, Item, ItemKind};
use crate::scene::error::{Diagnostic, Location, SceneError};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Token<'a> {
    Punct(char),
    Text(&'a str),
}

fn is_punct(c: char) -> bool {
    matches!(c, '{' | '}' | '[' | ']')
}

/// Whitespace (`\r` included) and `#` / `//` comments to the end of the line.
fn skip_blank(input: &str) -> IResult<&str, usize> {
    many0_count(alt((
        value((), take_while1(char::is_whitespace)),
        value(
            (),
            pair(alt((tag("#"), tag("//"))), take_till(|c| c == '\n')),
        ),
    )))(input)
}

fn token(input: &str) -> IResult<&str, Token<'_>> {
    alt((
        map(one_of("{}[]"), Token::Punct),
        map(
            take_till1(|c: char| c.is_whitespace() || is_punct(c)),
            Token::Text,
        ),
    ))(input)
}

/// Maps byte offsets to 1-based line and column (columns count characters).
///
/// Lines are found by binary search in the line starts; columns are counted
/// on from the previous offset located on the same line, so locating every
/// token of a file in order takes time linear in its length, however long
/// its lines are.
struct LineIndex<'a> {
    text: &'a str,
    /// Offsets of line starts; `u32` (4 bytes a line: a file of short lines
    /// has one every two bytes), since [`parse`] refuses longer texts.
    starts: Vec<u32>,
    /// The last offset located, its line and its column.
    previous: (usize, usize, usize),
}

impl<'a> LineIndex<'a> {
    fn new(text: &'a str) -> Self {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| (i + 1) as u32));
        LineIndex {
            text,
            starts,
            previous: (0, 1, 1),
        }
    }

    fn locate(&mut self, offset: usize) -> Location {
        let line = self
            .starts
            .partition_point(|&s| s as usize <= offset)
            .max(1);
        let start = self.starts.get(line - 1).map_or(0, |&s| s as usize);
        let (previous_offset, previous_line, previous_column) = self.previous;
        let (from, column) = if previous_line == line && previous_offset <= offset {
            (previous_offset, previous_column)
        } else {
            (start, 1)
        };
        let column = column + self.text.get(from..offset).map_or(0, |s| s.chars().count());
        self.previous = (offset, line, column);
        Location {
            line: line as u32,
            column: column as u32,
        }
    }
}

/// A number is what `f64` parsing fully accepts and contains a digit
/// (so `inf` and `nan` stay words).
pub fn as_number(text: &str) -> Option<f64> {
    if !text.bytes().any(|b| b.is_ascii_digit()) {
        return None;
    }
    text.parse::<f64>().ok()
}

struct Frame {
    name: String,
    location: Location,
    items: Vec<Item>,
}

fn error(file: &Path, location: Location, message: String) -> SceneError {
    SceneError::At(Diagnostic {
        file: file.to_path_buf(),
        location,
        message,
    })
}

/// Parses scene text into a syntax tree. `file` is only used in messages.
/// A leading byte order mark is skipped (columns are counted after it).
pub fn parse(text: &str, file: &Path) -> Result<Document, SceneError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if u32::try_from(text.len()).is_err() {
        return Err(error(
            file,
            Location::default(),
            format!("{} bytes of text, more than a scene can hold", text.len()),
        ));
    }
    let mut lines = LineIndex::new(text);
    let mut stack = vec![Frame {
        name: String::new(),
        location: Location::default(),
        items: Vec::new(),
    }];
    let mut list: Option<(Location, Vec<f64>)> = None;
    let mut rest = text;
    loop {
        let (after_blank, _) = skip_blank(rest).unwrap_or((rest, 0));
        if after_blank.is_empty() {
            break;
        }
        let location = lines.locate(text.len() - after_blank.len());
        let Ok((after, tok)) = token(after_blank) else {
            return Err(error(file, location, "unreadable token".into()));
        };
        rest = after;
        if let Some((_, numbers)) = list.as_mut() {
            match tok {
                Token::Punct(']') => {
                    if let Some((start, numbers)) = list.take()
                        && let Some(frame) = stack.last_mut()
                    {
                        frame.items.push(Item {
                            location: start,
                            kind: ItemKind::List(numbers.into_boxed_slice()),
                        });
                    }
                }
                Token::Text(t) => match as_number(t) {
                    Some(n) => numbers.push(n),
                    None => {
                        return Err(error(
                            file,
                            location,
                            format!("expected a number or ']' in a list, found '{}'", shown(t)),
                        ));
                    }
                },
                Token::Punct(c) => {
                    return Err(error(
                        file,
                        location,
                        format!("expected a number or ']' in a list, found '{c}'"),
                    ));
                }
            }
            continue;
        }
        match tok {
            Token::Punct('{') => {
                if stack.len() > MAX_NESTING {
                    return Err(error(
                        file,
                        location,
                        format!("blocks nested deeper than {MAX_NESTING} levels"),
                    ));
                }
                let top = stack.last_mut();
                let named = top.and_then(|frame| match frame.items.last() {
                    Some(Item {
                        kind: ItemKind::Word(_),
                        ..
                    }) => frame.items.pop(),
                    _ => None,
                });
                let (name, at) = match named {
                    Some(Item {
                        kind: ItemKind::Word(w),
                        location,
                    }) => (w.into_string(), location),
                    _ => (String::new(), location),
                };
                stack.push(Frame {
                    name,
                    location: at,
                    items: Vec::new(),
                });
            }
            Token::Punct('}') => {
                if stack.len() < 2 {
                    return Err(error(file, location, "unmatched '}'".into()));
                }
                if let Some(mut frame) = stack.pop()
                    && let Some(parent) = stack.last_mut()
                {
                    frame.items.shrink_to_fit();
                    parent.items.push(Item {
                        location: frame.location,
                        kind: ItemKind::Block(Box::new(Block {
                            name: frame.name,
                            items: frame.items,
                            close: location,
                        })),
                    });
                }
            }
            Token::Punct('[') => list = Some((location, Vec::new())),
            Token::Punct(c) => {
                return Err(error(file, location, format!("unmatched '{c}'")));
            }
            Token::Text(t) => {
                let kind = match as_number(t) {
                    Some(n) => ItemKind::Number(n),
                    None => ItemKind::Word(t.into()),
                };
                if let Some(frame) = stack.last_mut() {
                    frame.items.push(Item { location, kind });
                }
            }
        }
    }
    if let Some((start, _)) = list {
        return Err(error(file, start, "'[' is never closed".into()));
    }
    if stack.len() > 1
        && let Some(frame) = stack.last()
    {
        let what = if frame.name.is_empty() {
            "'{'".to_string()
        } else {
            format!("block '{}'", shown(&frame.name))
        };
        return Err(error(
            file,
            frame.location,
            format!("{what} is never closed (missing '}}')"),
        ));
    }
    let items = stack.pop().map(|f| f.items).unwrap_or_default();
    Ok(Document { items })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_item_of_the_syntax_tree_took_72_bytes() {
        // A scene of numbers has an item per two bytes of text.
        assert!(std::mem::size_of::<Item>() <= 32);
    }

    fn doc(text: &str) -> Document {
        parse(text, Path::new("t.txt")).expect("parses")
    }

    fn err_at(text: &str) -> (u32, u32, String) {
        match parse(text, Path::new("t.txt")) {
            Err(SceneError::At(d)) => (d.location.line, d.location.column, d.message),
            other => panic!("expected an error, got {other:?}"),
        }
    }

    #[test]
    fn numbers_in_all_forms() {
        let d = doc("-.5 .5 2e-05 3.85091e-17 7 inf nan -");
        let kinds: Vec<_> = d.items.iter().map(|i| i.kind.clone()).collect();
        assert_eq!(kinds[0], ItemKind::Number(-0.5));
        assert_eq!(kinds[2], ItemKind::Number(2e-5));
        assert_eq!(kinds[4], ItemKind::Number(7.0));
        assert_eq!(kinds[5], ItemKind::Word("inf".into()));
        assert_eq!(kinds[6], ItemKind::Word("nan".into()));
        assert_eq!(kinds[7], ItemKind::Word("-".into()));
    }

    #[test]
    fn glued_braces_split_and_blocks_take_names() {
        let d = doc("Material { shininess 20}\r\nSphere{center 1 2 3}");
        assert_eq!(d.items.len(), 2);
        let b = d.items[0].block().expect("block");
        assert_eq!(b.name, "Material");
        assert_eq!(b.items[1].number(), Some(20.0));
        assert_eq!(
            b.close,
            Location {
                line: 1,
                column: 24
            }
        );
        assert_eq!(d.items[1].location, Location { line: 2, column: 1 });
    }

    #[test]
    fn comments_are_skipped() {
        let d = doc("# a comment\nA 1 // another { \n// x\nB");
        assert_eq!(d.items.len(), 3);
        assert_eq!(d.items[2].word(), Some("B"));
        assert_eq!(d.items[2].location.line, 4);
    }

    #[test]
    fn bracket_lists() {
        let d = doc("controls [ 0 1 0 ] [.5 .8 0]");
        assert_eq!(d.items[1].kind, ItemKind::List(vec![0.0, 1.0, 0.0].into()));
        assert_eq!(d.items[2].kind, ItemKind::List(vec![0.5, 0.8, 0.0].into()));
        assert_eq!(err_at("[ 1 x ]").0, 1);
        assert_eq!(err_at("a\n [ 1 2").1, 2);
    }

    #[test]
    fn unbalanced_braces_have_locations() {
        assert_eq!(err_at("A {\n  B { }\n").0, 1);
        let (line, column, message) = err_at("A { }\n  }");
        assert_eq!((line, column), (2, 3));
        assert!(message.contains("unmatched"));
        let (line, column, _) = err_at("A { }\n  Group {\n x 1 ");
        assert_eq!((line, column), (2, 3));
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let text = "{".repeat(100_000);
        assert!(err_at(&text).2.contains("nested"));
        let ok = format!("{}{}", "a {".repeat(100), "}".repeat(100));
        assert_eq!(doc(&ok).items.len(), 1);
    }

    #[test]
    fn non_ascii_columns_count_characters() {
        let d = doc("副本 x");
        assert_eq!(d.items[1].location, Location { line: 1, column: 4 });
    }
}
