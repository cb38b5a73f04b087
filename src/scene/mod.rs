//! Scene files: text -> syntax tree -> built scene.

pub mod error;
pub mod model;

use std::path::{Path, PathBuf};

use crate::scene::error::SceneError;
use crate::scene::model::{Dialect, Scene};

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

/// Reads, parses and builds a scene file.
pub fn load_scene(_path: &Path, _options: &LoadOptions) -> Result<Scene, SceneError> {
    todo!("scene helper")
}
