//! Reading the items of a block in order: numbers, vectors, words, with located errors.

use crate::math::Vec3;
use crate::scene::ast::{Block, Item, ItemKind};
use crate::scene::build::Context;
use crate::scene::error::{Location, SceneError};

/// A position in a list of items (a block body or the document).
pub struct Cursor<'a> {
    items: &'a [Item],
    position: usize,
    /// Where the list ends (the closing brace), for "expected ... after" errors.
    end: Location,
}

impl<'a> Cursor<'a> {
    pub fn new(items: &'a [Item], end: Location) -> Self {
        Cursor {
            items,
            position: 0,
            end,
        }
    }

    pub fn of(block: &'a Block) -> Self {
        Cursor::new(&block.items, block.close)
    }

    pub fn peek(&self) -> Option<&'a Item> {
        self.items.get(self.position)
    }

    pub fn peek_number(&self) -> Option<f64> {
        self.peek().and_then(Item::number)
    }

    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> Option<&'a Item> {
        let item = self.items.get(self.position)?;
        self.position += 1;
        Some(item)
    }

    /// Location of the next item, or of the end of the list.
    pub fn here(&self) -> Location {
        self.peek().map_or(self.end, |item| item.location)
    }

    fn found(&self) -> String {
        self.peek()
            .map_or_else(|| "'}'".to_string(), Item::describe)
    }

    /// One finite number after `key`.
    pub fn number(&mut self, context: &Context, key: &str) -> Result<f64, SceneError> {
        match self.peek_number() {
            Some(n) if n.is_finite() => {
                self.position += 1;
                Ok(n)
            }
            Some(_) => Err(context.error(
                self.here(),
                format!("the number after '{key}' is too large"),
            )),
            None => Err(context.error(
                self.here(),
                format!(
                    "expected a {}number after '{key}', found {}",
                    if self.peek().is_some_and(Item::is_non_finite_word) {
                        "finite "
                    } else {
                        ""
                    },
                    self.found()
                ),
            )),
        }
    }

    pub fn vec3(&mut self, context: &Context, key: &str) -> Result<Vec3, SceneError> {
        let x = self.number(context, key)?;
        let y = self.number(context, key)?;
        let z = self.number(context, key)?;
        Ok(Vec3::new(x, y, z))
    }

    /// A whole number (`32`, `32.0`) in `i64` range; `32.5` is an error, as
    /// the file cannot mean a fraction of a pixel or of a material index.
    pub fn integer(&mut self, context: &Context, key: &str) -> Result<i64, SceneError> {
        let at = self.here();
        let n = self.number(context, key)?;
        if n.fract() != 0.0 {
            return Err(context.error(
                at,
                format!("expected a whole number after '{key}', found {n}"),
            ));
        }
        if n.abs() > 1e15 {
            return Err(context.error(at, format!("the integer after '{key}' is out of range")));
        }
        Ok(n as i64)
    }

    /// A word (a path or a name) after `key`.
    pub fn word(&mut self, context: &Context, key: &str) -> Result<&'a str, SceneError> {
        match self.peek().map(|item| &item.kind) {
            Some(ItemKind::Word(w)) => {
                self.position += 1;
                Ok(w)
            }
            _ => Err(context.error(
                self.here(),
                format!("expected a word after '{key}', found {}", self.found()),
            )),
        }
    }

    /// Consumes the run of numbers and lists that follows; returns the numbers.
    pub fn take_numbers(&mut self) -> Vec<f64> {
        let mut numbers = Vec::new();
        while let Some(item) = self.peek() {
            match &item.kind {
                ItemKind::Number(n) => numbers.push(*n),
                ItemKind::List(list) => numbers.extend_from_slice(list),
                _ => break,
            }
            self.position += 1;
        }
        numbers
    }

    /// The next item if it is a block.
    pub fn next_block(&mut self) -> Option<&'a Block> {
        let block = self.peek()?.block()?;
        self.position += 1;
        Some(block)
    }
}
