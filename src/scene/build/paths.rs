//! Resolving relative paths of meshes and textures against the usual coursework layout.

use std::path::{Path, PathBuf};

use crate::limits::shown_path;
use crate::scene::LoadOptions;

/// Candidate locations of `relative`, in the order they are tried: `--base` if given,
/// else the scene file's grand-parent; then the scene's own directory; then the
/// working directory.
pub fn candidates(relative: &str, scene_file: &Path, options: &LoadOptions) -> Vec<PathBuf> {
    let path = Path::new(relative);
    if path.is_absolute() {
        return vec![path.to_path_buf()];
    }
    let scene_dir = scene_file.parent().unwrap_or(Path::new(""));
    let mut dirs = Vec::new();
    match &options.base {
        Some(base) => dirs.push(base.clone()),
        None => dirs.push(scene_dir.parent().unwrap_or(Path::new("")).to_path_buf()),
    }
    dirs.push(scene_dir.to_path_buf());
    dirs.push(PathBuf::new());
    let mut out: Vec<PathBuf> = Vec::new();
    for dir in dirs {
        let candidate = dir.join(path);
        if !out.contains(&candidate) {
            out.push(candidate);
        }
    }
    out
}

/// The first candidate that is a file, else the first that exists (a
/// directory or a device, which its reader refuses by name), or the list
/// of tried paths.
pub fn resolve(
    relative: &str,
    scene_file: &Path,
    options: &LoadOptions,
) -> Result<PathBuf, Vec<PathBuf>> {
    let tried = candidates(relative, scene_file, options);
    let file = tried.iter().find(|p| p.is_file());
    match file.or_else(|| tried.iter().find(|p| p.exists())) {
        Some(found) => Ok(found.clone()),
        None => Err(tried),
    }
}

/// The message for a `what` (`mesh`, `texture`, ...) named `relative`
/// that no candidate holds: "not found", or that its name is too long for
/// the file system (which every lookup then refuses), with the paths tried.
pub fn missing(what: &str, relative: &str, tried: &[PathBuf]) -> String {
    let too_long = tried.iter().any(|path| {
        std::fs::symlink_metadata(path)
            .is_err_and(|e| e.kind() == std::io::ErrorKind::InvalidFilename)
    });
    let reason = if too_long {
        "has a name too long for the file system"
    } else {
        "not found"
    };
    format!(
        "{what} '{}' {reason} (tried {})",
        shown_path(Path::new(relative)),
        describe_tried(tried)
    )
}

/// "a, b or c" for messages.
pub fn describe_tried(tried: &[PathBuf]) -> String {
    tried
        .iter()
        .map(|p| format!("'{}'", shown_path(p)))
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grand_parent_then_scene_dir_then_cwd() {
        let c = candidates(
            "mesh/a.obj",
            Path::new("root/testcases/s.txt"),
            &LoadOptions::default(),
        );
        assert_eq!(
            c,
            vec![
                PathBuf::from("root/mesh/a.obj"),
                PathBuf::from("root/testcases/mesh/a.obj"),
                PathBuf::from("mesh/a.obj"),
            ]
        );
        let options = LoadOptions {
            base: Some(PathBuf::from("b")),
            ..LoadOptions::default()
        };
        assert_eq!(
            candidates("x", Path::new("r/t/s.txt"), &options)[0],
            PathBuf::from("b/x")
        );
    }
}
