//! The syntax tree of a scene file: words, numbers, blocks and bracket lists, with spans.

use crate::limits::shown;
use crate::scene::error::Location;

/// One item of a document or of a block body.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    pub location: Location,
    pub kind: ItemKind,
}

///
/// Kept to 24 bytes (an [`Item`] to 32), since a scene of numbers holds one
/// item per two bytes of text: words and lists are boxed slices, blocks
/// boxed (see `limits::MAX_SCENE_BYTES`).
#[derive(Clone, Debug, PartialEq)]
pub enum ItemKind {
    /// A bare word (keyword, path, name).
    Word(Box<str>),
    /// Anything Rust's `f64` parser fully accepts (with at least one digit).
    Number(f64),
    /// `name { items }`; `name` is empty for a brace that follows no word.
    Block(Box<Block>),
    /// `[ numbers ]`.
    List(Box<[f64]>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    pub name: String,
    pub items: Vec<Item>,
    /// Where the closing `}` is.
    pub close: Location,
}

/// A parsed file: the top-level items.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    pub items: Vec<Item>,
}

impl Item {
    pub fn word(&self) -> Option<&str> {
        match &self.kind {
            ItemKind::Word(w) => Some(w),
            _ => None,
        }
    }

    pub fn number(&self) -> Option<f64> {
        match self.kind {
            ItemKind::Number(n) => Some(n),
            _ => None,
        }
    }

    pub fn block(&self) -> Option<&Block> {
        match &self.kind {
            ItemKind::Block(b) => Some(b),
            _ => None,
        }
    }

    /// A word Rust reads as a number that is not finite (`nan`, `inf`,
    /// `-Infinity`): where a number is expected, the message says "finite".
    pub fn is_non_finite_word(&self) -> bool {
        self.word()
            .and_then(|w| w.parse::<f64>().ok())
            .is_some_and(|n| !n.is_finite())
    }

    /// A short description for messages.
    pub fn describe(&self) -> String {
        match &self.kind {
            ItemKind::Word(w) => format!("'{}'", shown(w)),
            ItemKind::Number(n) => format!("number {n}"),
            ItemKind::Block(b) => format!("block '{}'", shown(&b.name)),
            ItemKind::List(_) => "a [ ] list".to_string(),
        }
    }
}

impl Document {
    /// Calls `visit` on every word and block name of the tree (iteratively).
    pub fn for_each_word(&self, visit: &mut impl FnMut(&str, &[Item], usize)) {
        let mut stack: Vec<&[Item]> = vec![&self.items];
        while let Some(items) = stack.pop() {
            for (index, item) in items.iter().enumerate() {
                match &item.kind {
                    ItemKind::Word(w) => visit(w, items, index),
                    ItemKind::Block(b) => {
                        visit(&b.name, items, index);
                        stack.push(&b.items);
                    }
                    _ => {}
                }
            }
        }
    }
}
