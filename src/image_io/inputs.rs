//! Refusing an output that is one of the run's inputs (the scene, a mesh, a
//! texture, a `.mtl`), compared by file identity (device and inode), so that
//! `./scene.bmp`, another spelling or a hard link of an input is caught.

use std::path::Path;

use super::atomic::PendingFile;

/// The identity of an existing file (symlinks followed), if it exists.
#[cfg(unix)]
fn identity(path: &Path) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    std::fs::metadata(path).ok().map(|m| (m.dev(), m.ino()))
}

/// Where there are no inode numbers: the canonical path.
#[cfg(not(unix))]
fn identity(path: &Path) -> Option<std::path::PathBuf> {
    std::fs::canonicalize(path).ok()
}

/// An error if an output's target is the same file as one of `inputs`, each
/// given with what it is (`"the scene"`, `"an asset of the scene"`, ...).
pub fn refuse_inputs(outputs: &[&PendingFile], inputs: &[(&str, &Path)]) -> Result<(), String> {
    for output in outputs {
        let Some(written) = identity(output.target()) else {
            continue;
        };
        for (role, input) in inputs {
            if identity(input).as_ref() == Some(&written) {
                return Err(format!(
                    "{}: is {role} ({}); refusing to overwrite an input",
                    output.path().display(),
                    input.display()
                ));
            }
        }
    }
    Ok(())
}
