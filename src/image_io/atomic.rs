//! Atomic file replacement: write a temporary sibling, then rename it over the target.
//!
//! The temporary file `.<name>.tmp-<pid>-<n>` lives in the destination's directory
//! so the final `rename` stays on one file system and is atomic. On any failure the
//! temporary file is removed and an existing destination is left untouched.

use std::fs::{self, File};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Distinguishes temporary files of concurrent writes within one process.
static NEXT_TEMPORARY: AtomicU64 = AtomicU64::new(0);

/// Writes `bytes` to `path` atomically, creating the parent directory if missing.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let shown = path.display();
    let file_name = path
        .file_name()
        .ok_or_else(|| format!("{shown}: not a file path"))?;
    if path.is_dir() {
        return Err(format!("{shown}: is a directory"));
    }
    let directory = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&directory)
        .map_err(|e| format!("{}: cannot create directory: {e}", directory.display()))?;

    let mut temporary_name = std::ffi::OsString::from(".");
    temporary_name.push(file_name);
    temporary_name.push(format!(
        ".tmp-{}-{}",
        std::process::id(),
        NEXT_TEMPORARY.fetch_add(1, Ordering::Relaxed)
    ));
    let temporary = directory.join(temporary_name);

    let result = write_new(&temporary, bytes)
        .and_then(|()| fs::rename(&temporary, path))
        .map_err(|e| format!("{shown}: cannot write: {e}"));
    if result.is_err() {
        // The temporary may not exist (creation failed); nothing more to do then.
        let _ = fs::remove_file(&temporary);
    }
    result
}

/// Creates `path` (which must not exist), writes `bytes` and flushes them to disk.
fn write_new(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut file = File::create_new(path)?;
    file.write_all(bytes)?;
    file.sync_all()
}
