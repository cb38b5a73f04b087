//! User-facing errors and warnings with a file, line and column.

use std::fmt;
use std::path::PathBuf;

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
            self.file.display(),
            self.location.line,
            self.location.column,
            self.message
        )
    }
}

/// Why a scene could not be read.
#[derive(Debug)]
pub enum SceneError {
    /// The file could not be read at all.
    Io {
        file: PathBuf,
        error: std::io::Error,
    },
    /// A syntax or build error at a place in the file.
    At(Diagnostic),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Io { file, error } => write!(f, "{}: {}", file.display(), error),
            SceneError::At(diagnostic) => diagnostic.fmt(f),
        }
    }
}

impl std::error::Error for SceneError {}
