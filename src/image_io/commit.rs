//! Putting written outputs in place as one unit: an image and its sidecar
//! are both replaced, or neither is.
//!
//! Every target that exists is first kept under a temporary name (a hard
//! link, or a copy where the file system has none); then the temporaries are
//! renamed over their targets in the order given, the file that marks a
//! complete output (the image) last. If a rename fails, the targets already
//! replaced get their kept version back (or are removed if they were new),
//! so the old files are as they were. The registry of temporaries is held
//! throughout: a signal waits for the renames, never cuts them.

use std::fs;
use std::path::{Path, PathBuf};

use super::atomic::{PendingFile, temporary_sibling};
use crate::interrupt::{self, Registry};

/// Renames every written file over its target, in order, all or none.
pub fn commit_together(mut files: Vec<PendingFile>) -> Result<(), String> {
    if let Some(unwritten) = files.iter().find(|f| !f.is_written()) {
        return Err(format!(
            "{}: nothing was written to it",
            unwritten.path().display()
        ));
    }
    let mut registry = interrupt::lock();
    let mut kept: Vec<Option<PathBuf>> = Vec::with_capacity(files.len());
    for file in &files {
        match keep_old(&mut registry, file) {
            Ok(old) => kept.push(old),
            Err(error) => {
                discard(&mut registry, kept.iter().flatten());
                return Err(error);
            }
        }
    }
    for index in 0..files.len() {
        let file = &files[index];
        copy_permissions(file.target(), file.temporary());
        if let Err(e) = fs::rename(file.temporary(), file.target()) {
            let restored = restore(&files[..index], &kept[..index]);
            discard(&mut registry, kept.iter().flatten());
            let mut message = format!("{}: cannot write: {e}", file.path().display());
            if index > 0 {
                message.push_str(match restored {
                    Ok(()) => "; the files written before it were put back as they were",
                    Err(_) => "; the files written before it could not all be put back",
                });
            }
            return Err(message);
        }
    }
    for file in &mut files {
        file.disown(&mut registry);
    }
    discard(&mut registry, kept.iter().flatten());
    Ok(())
}

/// Keeps the current content of `file`'s target under a temporary name, if
/// it exists.
fn keep_old(registry: &mut Registry, file: &PendingFile) -> Result<Option<PathBuf>, String> {
    let target = file.target();
    if !target.exists() {
        return Ok(None);
    }
    let directory = file.temporary().parent().unwrap_or(Path::new("."));
    let name = target.file_name().unwrap_or_default();
    let old = temporary_sibling(directory, name);
    registry.register(&old);
    let kept = fs::hard_link(target, &old).or_else(|_| fs::copy(target, &old).map(|_| ()));
    match kept {
        Ok(()) => Ok(Some(old)),
        Err(e) => {
            let _ = fs::remove_file(&old);
            registry.unregister(&old);
            Err(format!(
                "{}: cannot keep the old file while replacing it: {e}",
                file.path().display()
            ))
        }
    }
}

/// Puts back the kept versions of the targets of `files` (already replaced),
/// last first; a target that did not exist is removed.
fn restore(files: &[PendingFile], kept: &[Option<PathBuf>]) -> std::io::Result<()> {
    let mut result = Ok(());
    for (file, old) in files.iter().zip(kept).rev() {
        let undone = match old {
            Some(old) => fs::rename(old, file.target()),
            None => fs::remove_file(file.target()),
        };
        result = result.and(undone);
    }
    result
}

/// Removes the kept versions (still registered), once they are not needed.
fn discard<'a>(registry: &mut Registry, kept: impl Iterator<Item = &'a PathBuf>) {
    for old in kept {
        let _ = fs::remove_file(old);
        registry.unregister(old);
    }
}

/// Gives the new file the permissions of the one it replaces (if any).
fn copy_permissions(target: &Path, temporary: &Path) {
    if let Ok(metadata) = fs::metadata(target) {
        let _ = fs::set_permissions(temporary, metadata.permissions());
    }
}
