//! Scene files: text -> syntax tree (`parse`) -> built scene (`build`).

pub mod ast;
pub mod build;
pub mod error;
pub mod model;
pub mod parse;

use std::path::{Path, PathBuf};

use crate::limits::{MAX_SCENE_BYTES, read_within};
use crate::scene::error::SceneError;
use crate::scene::model::{Dialect, Scene};

pub use build::build;
pub use parse::parse;

/// How to read a scene file.
#[derive(Clone, Debug, Default)]
pub struct LoadOptions {
    /// Directory that relative paths resolve against first (`--base`).
    pub base: Option<PathBuf>,
    /// Force a dialect instead of detecting it (`--dialect`).
    pub dialect: Option<Dialect>,
    /// Turn warnings into errors (`--strict`).
    pub strict: bool,
    /// What a texture or mesh file that is not found becomes (`--missing-assets`).
    pub missing_assets: MissingAssets,
    /// Memory the camera's image and a decoded texture may take (`--max-memory`).
    pub memory_budget: crate::limits::MemoryBudget,
}

/// What a scene's missing texture or mesh file becomes.
///
/// With [`MissingAssets::Placeholder`] a missing colour texture is the
/// 8x8 magenta and grey checker of [`crate::texture::Texture::placeholder`],
/// a missing normal or height map is left out (a checker would tilt the
/// normals at random), a missing mesh is left out of the scene; each with a
/// warning at the place that names the file. A missing `.mtl` (and a
/// missing image of a `.mtl`) is a warning either way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MissingAssets {
    /// A missing file is an error at the place that names it.
    #[default]
    Error,
    /// A missing file is replaced or left out, with a warning.
    Placeholder,
}

impl MissingAssets {
    pub const ALL: [MissingAssets; 2] = [MissingAssets::Error, MissingAssets::Placeholder];

    pub fn name(self) -> &'static str {
        match self {
            MissingAssets::Error => "error",
            MissingAssets::Placeholder => "placeholder",
        }
    }

    pub fn from_name(name: &str) -> Option<MissingAssets> {
        MissingAssets::ALL.into_iter().find(|m| m.name() == name)
    }
}

/// Reads, parses and builds a scene file. Bytes that are not UTF-8 are
/// decoded lossily. A directory, a device or a file over
/// [`MAX_SCENE_BYTES`] is refused before it is read.
pub fn load_scene(path: &Path, options: &LoadOptions) -> Result<Scene, SceneError> {
    let bytes =
        read_within(path, MAX_SCENE_BYTES, "limits::MAX_SCENE_BYTES").map_err(|message| {
            SceneError::Io {
                file: path.to_path_buf(),
                message,
            }
        })?;
    let started = std::time::Instant::now();
    let text = String::from_utf8_lossy(&bytes);
    let document = parse(&text, path)?;
    let parse_seconds = started.elapsed().as_secs_f64();
    let mut scene = build(&document, path, options)?;
    scene.load.parse_seconds = parse_seconds;
    scene.load.source_hash = fnv1a(&bytes);
    Ok(scene)
}

/// The 64-bit FNV-1a hash: small, stable across platforms and versions.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &byte| {
        (hash ^ byte as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_utf8_files_and_missing_files_are_errors_not_panics() {
        let dir = std::env::temp_dir().join(format!("pt-load-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let file = dir.join("bad.txt");
        std::fs::write(&file, b"PerspectiveCamera { width 2 height 2 \xff\xfe }").expect("write");
        let scene = load_scene(&file, &LoadOptions::default()).expect("lossy decoding");
        assert_eq!(scene.warnings.len(), 1);
        let missing = load_scene(&dir.join("none.txt"), &LoadOptions::default());
        assert!(matches!(missing, Err(SceneError::Io { .. })));
    }

    #[test]
    fn deeply_nested_groups_build() {
        let depth = crate::limits::MAX_NESTING - 2;
        let text = format!(
            "PerspectiveCamera {{ width 2 height 2 }}\nGroup {{ {} Sphere {{ center 0 0 0 radius 1 }} {} }}",
            "Transform { Translate 1 0 0 Group { ".repeat(depth / 2),
            "} }".repeat(depth / 2)
        );
        let document = parse(&text, Path::new("deep.txt")).expect("parses");
        let scene =
            build(&document, Path::new("deep.txt"), &LoadOptions::default()).expect("builds");
        let mut leaves = 0;
        scene.root.for_each_leaf(&mut |_| leaves += 1);
        assert_eq!(leaves, 1);
    }
}
