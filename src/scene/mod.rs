//! Scene files: text -> syntax tree (`parse`) -> built scene (`build`).

pub mod ast;
pub mod build;
pub mod error;
pub mod model;
pub mod parse;
pub mod summary;

use std::path::{Path, PathBuf};

use crate::scene::error::SceneError;
use crate::scene::model::{Dialect, Scene};

pub use build::build;
pub use parse::parse;
pub use summary::summary;

/// How to read a scene file.
#[derive(Clone, Debug, Default)]
pub struct LoadOptions {
    /// Directory that relative paths resolve against first (`--base`).
    pub base: Option<PathBuf>,
    /// Force a dialect instead of detecting it (`--dialect`).
    pub dialect: Option<Dialect>,
    /// Turn warnings into errors (`--strict`).
    pub strict: bool,
}

/// Reads, parses and builds a scene file. Bytes that are not UTF-8 are decoded lossily.
pub fn load_scene(path: &Path, options: &LoadOptions) -> Result<Scene, SceneError> {
    let bytes = std::fs::read(path).map_err(|error| SceneError::Io {
        file: path.to_path_buf(),
        error,
    })?;
    let text = String::from_utf8_lossy(&bytes);
    let document = parse(&text, path)?;
    build(&document, path, options)
}
