//! User-facing errors and warnings with a file, line and column.

use std::fmt;
use std::path::PathBuf;

use crate::limits::{printable, shown_path};

/// A position in a scene file (1-based line and column).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Location {
    pub line: u32,
    pub column: u32,
}

/// A message about a place in a file: `scene.txt:12:7: expected a number after 'radius'`.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    pub file: PathBuf,
    pub location: Location,
    pub message: String,
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: {}",
            shown_path(&self.file),
            self.location.line,
            self.location.column,
            printable(&self.message, true)
        )
    }
}

/// Why a scene could not be read.
#[derive(Debug)]
pub enum SceneError {
    /// The file could not be read at all, or was refused before reading
    /// (a directory, a device, larger than `limits::MAX_SCENE_BYTES`); the
    /// message names the file.
    Io { file: PathBuf, message: String },
    /// A syntax or build error at a place in the file.
    At(Diagnostic),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Io { message, .. } => f.write_str(message),
            SceneError::At(diagnostic) => diagnostic.fmt(f),
        }
    }
}

impl std::error::Error for SceneError {}
