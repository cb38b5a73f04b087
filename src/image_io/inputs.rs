//! Refusing an output that is one of the run's inputs (the scene, a mesh, a
//! texture, a `.mtl`), compared by file identity (device and inode), so that
//! `./scene.bmp`, another spelling or a hard link of an input is caught; and
//! two outputs of one run on the same file (one would replace the other).

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

/// Where an output's target is: its canonical path (the folder exists once
/// the output is reserved), so that `m.exr`, `./m.exr` and a link to it are
/// one place.
fn location(target: &Path) -> Option<std::path::PathBuf> {
    if let Ok(path) = std::fs::canonicalize(target) {
        return Some(path);
    }
    let name = target.file_name()?;
    let folder = match target.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    std::fs::canonicalize(folder).ok().map(|f| f.join(name))
}

/// An error if two of `outputs` would write the same file (the same path
/// in another spelling, or the same existing file under two names).
pub fn refuse_shared_outputs(outputs: &[&PendingFile]) -> Result<(), String> {
    for (index, first) in outputs.iter().enumerate() {
        for second in &outputs[index + 1..] {
            let same_place = location(first.target())
                .is_some_and(|place| location(second.target()).as_ref() == Some(&place));
            let same_file = identity(first.target())
                .is_some_and(|file| identity(second.target()).as_ref() == Some(&file));
            if same_place || same_file {
                return Err(format!(
                    "{} and {} are the same file: each output of a command needs its own",
                    first.path().display(),
                    second.path().display()
                ));
            }
        }
    }
    Ok(())
}
